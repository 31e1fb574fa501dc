// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
// OpenMesh's meshes through CGAL's graph traits: the same bases and the same
// deformations as on Surface_mesh and Polyhedron_3.
//
// Without CGAL_USE_OM_POINTS, CGAL's vertex point map of an OpenMesh mesh
// converts to Epick points and writes through float, whatever the scalar of
// the mesh; with it, the points of the map are OpenMesh's own (here
// OpenMesh::Vec3d, or Vec3f for the default traits), read and written as
// they are. It must come before CGAL's OpenMesh headers.
#define CGAL_USE_OM_POINTS

#include "test_meshes.h"

#include <CGAL/boost/graph/graph_traits_PolyMesh_ArrayKernelT.h>
#include <CGAL/boost/graph/graph_traits_TriMesh_ArrayKernelT.h>

#include <CGAL/Dual_mesh_laplacian.h>
#include <CGAL/Manifold_harmonics_basis.h>
#include <CGAL/Spectral_surface_mesh_deformation.h>

#include <catch2/catch.hpp>

#include <Eigen/Geometry>

#include <type_traits>
#include <vector>

using namespace test_meshes;

namespace {

struct Double_traits : public OpenMesh::DefaultTraits
{
  typedef OpenMesh::Vec3d Point;
  typedef OpenMesh::Vec3d Normal;
};
typedef OpenMesh::TriMesh_ArrayKernelT<Double_traits> Tri_mesh;
typedef OpenMesh::PolyMesh_ArrayKernelT<Double_traits> Poly_mesh;
typedef OpenMesh::TriMesh_ArrayKernelT<> Float_tri_mesh;

static_assert(std::is_same<CGAL::Spectral_surface_mesh_deformation<Tri_mesh>::Point, OpenMesh::Vec3d>::value,
              "the points of the deformation are OpenMesh's own");

const double pi = 3.14159265358979323846;

// Vertices in the order of the soup, faces with the soup's vertex order.
template <class Mesh>
Mesh to_openmesh(const Soup& soup)
{
  Mesh mesh;
  std::vector<typename Mesh::VertexHandle> handles;
  for(const Point& p : soup.points)
    handles.push_back(mesh.add_vertex(typename Mesh::Point(p.x(), p.y(), p.z())));
  for(const auto& t : soup.triangles)
    mesh.add_face(handles[t[0]], handles[t[1]], handles[t[2]]);
  return mesh;
}

// Any mesh type: points read by index, rows in the order of the initialized
// vertex index map (the order of the soup for all four mesh types). Through
// the property map: CGAL's get(vertex_point, mesh, v) for OpenMesh returns an
// Epick point, which does not compile with CGAL_USE_OM_POINTS.
template <class Mesh>
Eigen::MatrixXd positions_of(const Mesh& mesh)
{
  auto index = CGAL::get_initialized_vertex_index_map(mesh);
  const auto vpm = get(CGAL::vertex_point, mesh);
  Eigen::MatrixXd x(num_vertices(mesh), 3);
  for(auto v : vertices(mesh))
  {
    const auto& p = get(vpm, v);
    x.row(get(index, v)) << double(p[0]), double(p[1]), double(p[2]);
  }
  return x;
}

// The ends of test_meshes::bar are the control vertices; the top is turned
// by 60° about x and moved along x.
template <class Deformation, class Mesh>
Eigen::MatrixXd bend_bar(Mesh& mesh)
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
  Deformation deformation(mesh);
  const auto vpm = get(CGAL::vertex_point, mesh);
  std::vector<vertex_descriptor> top;
  for(vertex_descriptor v : vertices(mesh))
  {
    const double z = get(vpm, v)[2];
    deformation.insert_roi_vertex(v);
    if(z < 0.2)
      deformation.insert_control_vertex(v);
    if(z > 4.8)
      top.push_back(v);
  }
  deformation.insert_control_vertices(top.begin(), top.end());
  if constexpr(Deformation::has_basis)
    deformation.set_number_of_frequencies(40);
  const Eigen::Quaterniond q(Eigen::AngleAxisd(pi / 3, Eigen::Vector3d::UnitX()));
  deformation.rotate(top.begin(), top.end(), Eigen::Vector3d(0, 0, 5), q);
  deformation.translate(top.begin(), top.end(), Eigen::Vector3d(0.5, 0, 0));
  deformation.deform(10, 0.0);
  INFO(deformation.deform_report().message);
  REQUIRE(deformation.deform_report().success);
  return positions_of(mesh);
}

template <CGAL::Spectral_deformation_algorithm_tag TAG, class Mesh>
using Deformation = CGAL::Spectral_surface_mesh_deformation<Mesh, CGAL::Default, CGAL::Default, TAG>;

template <CGAL::Spectral_deformation_algorithm_tag TAG>
void check_same_deformation()
{
  const Soup soup = bar(12, 2);
  Surface_mesh sm = to_mesh<Surface_mesh>(soup);
  Polyhedron poly = to_mesh<Polyhedron>(soup);
  Tri_mesh tri = to_openmesh<Tri_mesh>(soup);
  Poly_mesh polygonal = to_openmesh<Poly_mesh>(soup);
  const Eigen::MatrixXd rest = positions_of(sm);
  REQUIRE(positions_of(tri) == rest);

  const Eigen::MatrixXd a = bend_bar<Deformation<TAG, Surface_mesh>>(sm);
  const Eigen::MatrixXd b = bend_bar<Deformation<TAG, Polyhedron>>(poly);
  const Eigen::MatrixXd c = bend_bar<Deformation<TAG, Tri_mesh>>(tri);
  const Eigen::MatrixXd d = bend_bar<Deformation<TAG, Poly_mesh>>(polygonal);
  REQUIRE((a - rest).cwiseAbs().maxCoeff() > 0.4); // it did deform
  CHECK((a - b).cwiseAbs().maxCoeff() <= 1e-12);
  CHECK((a - c).cwiseAbs().maxCoeff() <= 1e-12);
  CHECK((a - d).cwiseAbs().maxCoeff() <= 1e-12);
}

} // namespace

TEST_CASE("OpenMesh: the same basis as Surface_mesh and Polyhedron_3", "[openmesh][basis]")
{
  const Soup soup = bumpy_plane(14);
  const CGAL::Manifold_harmonics_basis<Surface_mesh> a(to_mesh<Surface_mesh>(soup), 20);
  const CGAL::Manifold_harmonics_basis<Polyhedron> b(to_mesh<Polyhedron>(soup), 20);
  const CGAL::Manifold_harmonics_basis<Tri_mesh> c(to_openmesh<Tri_mesh>(soup), 20);
  const CGAL::Manifold_harmonics_basis<Poly_mesh> d(to_openmesh<Poly_mesh>(soup), 20);
  REQUIRE(a.eigenvalues().size() == 20);
  CHECK((a.eigenvalues() - b.eigenvalues()).cwiseAbs().maxCoeff() <= 1e-12 * a.eigenvalues().maxCoeff());
  CHECK((a.eigenvalues() - c.eigenvalues()).cwiseAbs().maxCoeff() <= 1e-12 * a.eigenvalues().maxCoeff());
  CHECK((a.eigenvalues() - d.eigenvalues()).cwiseAbs().maxCoeff() <= 1e-12 * a.eigenvalues().maxCoeff());
  CHECK((a.basis() - c.basis()).cwiseAbs().maxCoeff() < 1e-10);
  CHECK((a.basis() - d.basis()).cwiseAbs().maxCoeff() < 1e-10);
  CHECK((a.mass() - c.mass()).cwiseAbs().maxCoeff() <= 1e-15);
}

TEST_CASE("OpenMesh: the same dual Laplacian coordinates as Surface_mesh", "[openmesh][dual]")
{
  const Soup soup = bar(8, 2);
  const CGAL::Dual_mesh_laplacian<Surface_mesh> a(to_mesh<Surface_mesh>(soup));
  const CGAL::Dual_mesh_laplacian<Poly_mesh> b(to_openmesh<Poly_mesh>(soup));
  REQUIRE(a.number_of_rows() == b.number_of_rows());
  REQUIRE(a.number_of_rows() > 0);
  // Per face, whatever vertex the face starts at.
  CHECK((a.rest_coordinates().heights - b.rest_coordinates().heights).cwiseAbs().maxCoeff() <= 1e-12);
}

TEST_CASE("OpenMesh: the same spectral deformation as Surface_mesh and Polyhedron_3", "[openmesh][deformation]")
{
  check_same_deformation<CGAL::SPECTRAL_DUAL_LAPLACIAN>();
}

TEST_CASE("OpenMesh: the same linear spectral deformation as Surface_mesh and Polyhedron_3",
          "[openmesh][deformation]")
{
  check_same_deformation<CGAL::SPECTRAL_LINEAR>();
}

TEST_CASE("OpenMesh: the same spatial deformation as Surface_mesh and Polyhedron_3", "[openmesh][spatial]")
{
  check_same_deformation<CGAL::SPATIAL_DUAL_LAPLACIAN>();
}

TEST_CASE("OpenMesh with float points: the double result rounded to float", "[openmesh][deformation]")
{
  // Coordinates that float holds exactly, so that both meshes start alike;
  // the targets too, set as they are.
  Soup soup = bar(12, 2);
  for(Point& p : soup.points)
    p = Point(float(p.x()), float(p.y()), float(p.z()));
  Surface_mesh sm = to_mesh<Surface_mesh>(soup);
  Float_tri_mesh om = to_openmesh<Float_tri_mesh>(soup);
  REQUIRE(positions_of(om) == positions_of(sm));

  auto run = [](auto& mesh, auto tag) {
    typedef typename decltype(tag)::type Deformation;
    typedef typename Deformation::Point Point;
    Deformation deformation(mesh);
    deformation.set_number_of_frequencies(40);
    const Eigen::Matrix3d rotation = Eigen::AngleAxisd(pi / 3, Eigen::Vector3d::UnitX()).toRotationMatrix();
    const auto vpm = get(CGAL::vertex_point, mesh);
    for(auto v : vertices(mesh))
    {
      const auto& p = get(vpm, v);
      const Eigen::Vector3d x(p[0], p[1], p[2]);
      deformation.insert_roi_vertex(v);
      if(x.z() < 0.2)
        deformation.insert_control_vertex(v);
      if(x.z() > 4.8)
      {
        const Eigen::Vector3d y = rotation * (x - Eigen::Vector3d(0, 0, 5)) + Eigen::Vector3d(0.5, 0, 5);
        deformation.insert_control_vertex(v);
        deformation.set_target_position(v, Point(float(y.x()), float(y.y()), float(y.z())));
      }
    }
    deformation.deform(10, 0.0);
    REQUIRE(deformation.deform_report().success);
    return positions_of(mesh);
  };
  struct Sm_tag { typedef CGAL::Spectral_surface_mesh_deformation<Surface_mesh> type; };
  struct Om_tag { typedef CGAL::Spectral_surface_mesh_deformation<Float_tri_mesh> type; };
  static_assert(std::is_same<Om_tag::type::Point, OpenMesh::Vec3f>::value);
  const Eigen::MatrixXd rest = positions_of(sm);
  const Eigen::MatrixXd a = run(sm, Sm_tag());
  const Eigen::MatrixXd b = run(om, Om_tag());
  REQUIRE((a - rest).cwiseAbs().maxCoeff() > 0.5);
  // Half a unit in the last place of a float below 8 is 2^-21.
  CHECK((a - b).cwiseAbs().maxCoeff() <= std::ldexp(1.0, -21));
  CHECK((a - b).cwiseAbs().maxCoeff() > 0.0); // the float mesh does round
}

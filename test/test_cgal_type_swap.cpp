// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Programs written for CGAL::Surface_mesh_deformation, with CGAL's template
// arguments, compile after the class name is swapped, and deform exactly as
// the default instantiation does. The arguments that must not compile are
// checked by test/compile_fail/template_arguments.cpp.
#include "test_meshes.h"

// Deformations with other traits than the compiled core holds.
#include <CGAL/Spectral_deformation/Pipelines_from_headers.h>
#include <CGAL/Spectral_surface_mesh_deformation.h>
#include <CGAL/Spectral_deformation/Partition_of_unity_eigensolver_traits.h>
#include <CGAL/Spectral_deformation/Spectra_eigensolver_traits.h>
#include <CGAL/Spectral_deformation/arap_energy.h>

#include <CGAL/Deformation_Eigen_polar_closest_rotation_traits_3.h>
#include <CGAL/Eigen_solver_traits.h>
#include <CGAL/Surface_mesh_deformation.h>
#include <CGAL/Weights/cotangent_weights.h>

#include <catch2/catch.hpp>

#include <Eigen/Geometry>

#include <boost/property_map/function_property_map.hpp>

#include <type_traits>
#include <vector>

using namespace test_meshes;
namespace internal = CGAL::Spectral_deformation::internal;

namespace {

typedef boost::graph_traits<Surface_mesh>::halfedge_descriptor SM_halfedge;
typedef CGAL::Spectral_surface_mesh_deformation<Surface_mesh> Reference;

// A weight calculator written as in CGAL's manual: a model of
// SurfaceMeshDeformationWeights with a template call operator.
struct Uniform_weight
{
  typedef Surface_mesh Triangle_mesh;
  template <class VertexPointMap>
  double operator()(SM_halfedge, Surface_mesh&, VertexPointMap) const
  {
    return 1.0;
  }
};

// One that is not default constructible, as in CGAL's example that reads the
// weights from a map: a program hands an instance to the constructor.
struct Weight_from_value
{
  explicit Weight_from_value(double w) : weight(w) {}
  template <class VertexPointMap>
  double operator()(SM_halfedge, const Surface_mesh&, VertexPointMap) const
  {
    return weight;
  }
  double weight;
};

// CGAL's default sparse solver of Surface_mesh_deformation.
typedef CGAL::Eigen_solver_traits<
    Eigen::SparseLU<CGAL::Eigen_sparse_matrix<double>::EigenType, Eigen::COLAMDOrdering<int>>>
    Cgal_sparse_solver;

template <auto TAG, class WC = CGAL::Default, class ST = CGAL::Default, class CR = CGAL::Default>
using Swapped = CGAL::Spectral_surface_mesh_deformation<Surface_mesh, CGAL::Default, CGAL::Default, TAG, WC, ST, CR>;

const double pi = 3.14159265358979323846;

template <class T>
struct Type_tag
{
  typedef T type;
};

// The body of a CGAL program: the ends of the bar are the control vertices,
// the top is turned by 60° about x and moved. Returns the positions.
template <class Deformation>
Eigen::MatrixXd bend_bar(Deformation& deformation, Surface_mesh& mesh)
{
  typedef typename Deformation::vertex_descriptor vertex_descriptor;
  std::vector<vertex_descriptor> top;
  for(vertex_descriptor v : vertices(mesh))
  {
    const double z = mesh.point(v).z();
    deformation.insert_roi_vertex(v);
    if(z < 0.2)
      deformation.insert_control_vertex(v);
    if(z > 4.8)
      top.push_back(v);
  }
  deformation.insert_control_vertices(top.begin(), top.end());
  const Eigen::Quaterniond q(Eigen::AngleAxisd(pi / 3, Eigen::Vector3d::UnitX()));
  deformation.rotate(top.begin(), top.end(), Eigen::Vector3d(0, 0, 5), q);
  deformation.translate(top.begin(), top.end(), Eigen::Vector3d(0.5, 0, 0));
  deformation.deform(10, 0.0);
  Eigen::MatrixXd x(mesh.number_of_vertices(), 3);
  for(vertex_descriptor v : vertices(mesh))
    x.row(v.idx()) << mesh.point(v).x(), mesh.point(v).y(), mesh.point(v).z();
  return x;
}

template <class Deformation>
Eigen::MatrixXd bend_bar_with()
{
  Surface_mesh mesh = to_mesh<Surface_mesh>(bar(12, 2));
  Deformation deformation(mesh);
  if constexpr(Deformation::has_basis)
    deformation.set_number_of_frequencies(40);
  const Eigen::MatrixXd x = bend_bar(deformation, mesh);
  INFO(deformation.deform_report().message);
  REQUIRE(deformation.deform_report().success);
  return x;
}

Eigen::MatrixXd rest_positions()
{
  const Surface_mesh mesh = to_mesh<Surface_mesh>(bar(12, 2));
  Eigen::MatrixXd x(mesh.number_of_vertices(), 3);
  for(auto v : vertices(mesh))
    x.row(v.idx()) << mesh.point(v).x(), mesh.point(v).y(), mesh.point(v).z();
  return x;
}

} // namespace

TEST_CASE("type swap: CGAL's algorithm tags select the iterated spectral algorithm", "[type_swap]")
{
  static_assert(Swapped<CGAL::ORIGINAL_ARAP>::algorithm == CGAL::SPECTRAL_DUAL_LAPLACIAN);
  static_assert(Swapped<CGAL::SPOKES_AND_RIMS>::algorithm == CGAL::SPECTRAL_DUAL_LAPLACIAN);
  static_assert(Swapped<CGAL::SRE_ARAP>::algorithm == CGAL::SPECTRAL_DUAL_LAPLACIAN);
  static_assert(Swapped<CGAL::SRE_ARAP>::is_cgal_algorithm_tag);
  // The package's own tags still select themselves.
  static_assert(Swapped<CGAL::SPECTRAL_DUAL_LAPLACIAN>::algorithm == CGAL::SPECTRAL_DUAL_LAPLACIAN);
  static_assert(Swapped<CGAL::SPECTRAL_LINEAR>::algorithm == CGAL::SPECTRAL_LINEAR);
  static_assert(Swapped<CGAL::SPATIAL_DUAL_LAPLACIAN>::algorithm == CGAL::SPATIAL_DUAL_LAPLACIAN);
  static_assert(!Swapped<CGAL::SPATIAL_DUAL_LAPLACIAN>::has_basis);
  static_assert(!Reference::is_cgal_algorithm_tag);

  const Eigen::MatrixXd reference = bend_bar_with<Reference>();
  // The reference deforms: equal results would otherwise prove nothing.
  REQUIRE((reference - rest_positions()).cwiseAbs().maxCoeff() > 0.5);
  CHECK(bend_bar_with<Swapped<CGAL::ORIGINAL_ARAP>>() == reference);
  CHECK(bend_bar_with<Swapped<CGAL::SPOKES_AND_RIMS>>() == reference);
  CHECK(bend_bar_with<Swapped<CGAL::SRE_ARAP>>() == reference);
  // The linear algorithm, which a CGAL tag does not select, differs.
  CHECK((bend_bar_with<Swapped<CGAL::SPECTRAL_LINEAR>>() - reference).cwiseAbs().maxCoeff() > 1e-3);
}

TEST_CASE("type swap: a weight calculator at the position of ET is not used", "[type_swap]")
{
  typedef CGAL::Weights::Cotangent_weight<Surface_mesh> Cotangent;            // CGAL's default for ORIGINAL_ARAP, SRE_ARAP
  typedef CGAL::Weights::Single_cotangent_weight<Surface_mesh> Half_cotangent; // for SPOKES_AND_RIMS
  static_assert(internal::Deformation::Is_weight_calculator<Cotangent, Surface_mesh>::value);
  static_assert(internal::Deformation::Is_weight_calculator<Half_cotangent, Surface_mesh>::value);
  static_assert(internal::Deformation::Is_weight_calculator<Uniform_weight, Surface_mesh>::value);
  static_assert(internal::Deformation::Is_weight_calculator<Weight_from_value, Surface_mesh>::value);
  // Eigensolver traits are not mistaken for weight calculators, nor the reverse.
  static_assert(!internal::Deformation::Is_weight_calculator<CGAL::Block_lanczos_eigensolver_traits<>, Surface_mesh>::value);
  static_assert(!internal::Deformation::Is_eigensolver_traits<Cotangent>::value);
  static_assert(internal::Deformation::Is_eigensolver_traits<CGAL::Spectra_eigensolver_traits<>>::value);

  static_assert(internal::Deformation::Is_eigensolver_traits<CGAL::Partition_of_unity_eigensolver_traits<>>::value);
  static_assert(!internal::Deformation::Is_weight_calculator<CGAL::Partition_of_unity_eigensolver_traits<>, Surface_mesh>::value);

  // The default eigensolver is the approximate basis, and so is the one a
  // weight calculator at its position leaves.
  static_assert(std::is_same<Reference::Eigensolver_traits, CGAL::Partition_of_unity_eigensolver_traits<>>::value);
  typedef Swapped<CGAL::SPOKES_AND_RIMS, Half_cotangent> With_default_weights;
  static_assert(With_default_weights::has_unused_weight_calculator);
  static_assert(std::is_same<With_default_weights::Eigensolver_traits, Reference::Eigensolver_traits>::value);
  // Eigensolver traits at that position are still used.
  typedef Swapped<CGAL::SPECTRAL_DUAL_LAPLACIAN, CGAL::Spectra_eigensolver_traits<>> With_spectra;
  static_assert(!With_spectra::has_unused_weight_calculator);
  static_assert(std::is_same<With_spectra::Eigensolver_traits, CGAL::Spectra_eigensolver_traits<>>::value);

  const Eigen::MatrixXd reference = bend_bar_with<Reference>();
  CHECK(bend_bar_with<With_default_weights>() == reference);
  CHECK(bend_bar_with<Swapped<CGAL::ORIGINAL_ARAP, Cotangent>>() == reference);
  CHECK(bend_bar_with<Swapped<CGAL::SRE_ARAP, Uniform_weight>>() == reference);
}

TEST_CASE("type swap: CGAL's sparse solver and closest rotation traits are accepted", "[type_swap]")
{
  typedef Swapped<CGAL::SPOKES_AND_RIMS, CGAL::Default, Cgal_sparse_solver,
                  CGAL::Deformation_Eigen_polar_closest_rotation_traits_3>
      With_cgal_solvers;
  static_assert(internal::Deformation::Sparse_solver_argument<Cgal_sparse_solver>::is_cgal_solver_traits);
  static_assert(std::is_same<With_cgal_solvers::Sparse_solver_traits, Reference::Sparse_solver_traits>::value);
  static_assert(std::is_same<With_cgal_solvers::Spatial_solver_traits, Reference::Spatial_solver_traits>::value);
  // The package's own sparse solver traits at that position are used.
  typedef CGAL::Eigen_sparse_spd_solver_traits<Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>> Eigen_ldlt;
  static_assert(std::is_same<Swapped<CGAL::SPECTRAL_DUAL_LAPLACIAN, CGAL::Default,
                                    Eigen_ldlt>::Sparse_solver_traits,
                             Eigen_ldlt>::value);
  CHECK(bend_bar_with<With_cgal_solvers>() == bend_bar_with<Reference>());
}

TEST_CASE("type swap: a CGAL program with every template argument and a weight calculator object",
          "[type_swap]")
{
  typedef boost::property_map<Surface_mesh, CGAL::vertex_point_t>::type Vertex_point_map;
  typedef CGAL::GetInitializedVertexIndexMap<Surface_mesh>::type Vertex_index_map;
  typedef CGAL::GetInitializedHalfedgeIndexMap<Surface_mesh>::type Hedge_index_map;

  // The same program text compiles with CGAL's class and with this one.
  auto run = [](auto tag) {
    typedef typename decltype(tag)::type Deformation;
    Surface_mesh mesh = to_mesh<Surface_mesh>(bar(12, 2));
    Deformation deformation(mesh, CGAL::get_initialized_vertex_index_map(mesh),
                            CGAL::get_initialized_halfedge_index_map(mesh), get(CGAL::vertex_point, mesh),
                            Weight_from_value(2.0));
    deformation.set_sre_arap_alpha(0.02);
    return bend_bar(deformation, mesh);
  };
  typedef CGAL::Surface_mesh_deformation<Surface_mesh, Vertex_index_map, Hedge_index_map, CGAL::SRE_ARAP,
                                         Weight_from_value, Cgal_sparse_solver,
                                         CGAL::Deformation_Eigen_polar_closest_rotation_traits_3, Vertex_point_map>
      Cgal_class;
  typedef CGAL::Spectral_surface_mesh_deformation<Surface_mesh, Vertex_index_map, Hedge_index_map, CGAL::SRE_ARAP,
                                                  Weight_from_value, Cgal_sparse_solver,
                                                  CGAL::Deformation_Eigen_polar_closest_rotation_traits_3,
                                                  Vertex_point_map>
      Swapped_class;
  static_assert(Swapped_class::has_unused_weight_calculator);

  const Eigen::MatrixXd arap = run(Type_tag<Cgal_class>());
  const Eigen::MatrixXd spectral = run(Type_tag<Swapped_class>());

  // The swapped program gives exactly the default deformation (100
  // frequencies, as the program does not set them).
  Surface_mesh mesh = to_mesh<Surface_mesh>(bar(12, 2));
  Reference reference(mesh);
  CHECK(spectral == bend_bar(reference, mesh));
  // Both classes bring the top to its target (rotated about x, moved along x).
  const Eigen::MatrixXd rest = rest_positions();
  const Eigen::Matrix3d rotation = Eigen::AngleAxisd(pi / 3, Eigen::Vector3d::UnitX()).toRotationMatrix();
  for(Eigen::Index i = 0; i < rest.rows(); ++i)
    if(rest(i, 2) > 4.8)
    {
      const Eigen::RowVector3d target =
          (rotation * (rest.row(i).transpose() - Eigen::Vector3d(0, 0, 5)) + Eigen::Vector3d(0.5, 0, 5))
              .transpose();
      CHECK((spectral.row(i) - target).norm() < 1e-9);
      CHECK((arap.row(i) - target).norm() < 1e-9);
    }
}

// arap_energy(): analytic values on any mesh type. A rigid motion costs
// nothing; a scaling by s changes every edge by the factor s with the best
// rotation the identity, so the normalized energy is (s - 1)² exactly.
template <class Mesh>
void check_arap_energy_of(const Mesh& mesh)
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
  const auto rest = get(CGAL::vertex_point, mesh);
  const Eigen::Matrix3d turn = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  auto moved = [&](double scale) {
    return boost::make_function_property_map<vertex_descriptor>([&, scale](vertex_descriptor v) {
      const Point& p = get(rest, v);
      const Eigen::Vector3d x = scale * (turn * Eigen::Vector3d(p.x(), p.y(), p.z())) + Eigen::Vector3d(4, -1, 2);
      return Point(x.x(), x.y(), x.z());
    });
  };
  CHECK(CGAL::arap_energy(mesh, rest) < 1e-24);
  CHECK(CGAL::arap_energy(mesh, moved(1.0)) < 1e-24);
  CHECK(CGAL::arap_energy(mesh, moved(1.5)) == Approx(0.25).epsilon(1e-12));
  CHECK(CGAL::arap_energy(mesh, moved(0.8)) == Approx(0.04).epsilon(1e-12));
}

TEST_CASE("arap_energy(): zero for a rigid motion, (s - 1)² for a scaling, on Surface_mesh and Polyhedron_3",
          "[type_swap]")
{
  const Soup soup = bumpy_plane(12);
  check_arap_energy_of(to_mesh<Surface_mesh>(soup));
  check_arap_energy_of(to_mesh<Polyhedron>(soup));
  // The same value on both types for a deformation that is not a similarity.
  Surface_mesh bent = to_mesh<Surface_mesh>(soup);
  Polyhedron bent_polyhedron = to_mesh<Polyhedron>(soup);
  auto bend = [](const Point& p) { return Point(p.x(), p.y(), p.z() + 0.3 * p.x() * p.x()); };
  const auto sm_rest = get(CGAL::vertex_point, bent);
  const auto poly_rest = get(CGAL::vertex_point, bent_polyhedron);
  typedef boost::graph_traits<Surface_mesh>::vertex_descriptor SM_vertex;
  typedef boost::graph_traits<Polyhedron>::vertex_descriptor Poly_vertex;
  const double on_surface_mesh = CGAL::arap_energy(
      bent, boost::make_function_property_map<SM_vertex>([&](SM_vertex v) { return bend(get(sm_rest, v)); }));
  const double on_polyhedron = CGAL::arap_energy(
      bent_polyhedron,
      boost::make_function_property_map<Poly_vertex>([&](Poly_vertex v) { return bend(get(poly_rest, v)); }));
  CHECK(on_surface_mesh > 1e-4);
  CHECK(on_polyhedron == Approx(on_surface_mesh).epsilon(1e-12));
}

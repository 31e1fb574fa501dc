// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include "test_meshes.h"

#include <CGAL/Spectral_surface_mesh_deformation.h>
#include <CGAL/Spectral_deformation/internal/Deformation/Clustered_rotations.h>
#include <CGAL/Spectral_deformation/internal/Deformation/arap_energy.h>

#include <catch2/catch.hpp>

#include <Eigen/Geometry>

#include <cmath>
#include <set>
#include <vector>

using namespace test_meshes;
namespace internal = CGAL::Spectral_deformation::internal;
typedef boost::graph_traits<Surface_mesh>::vertex_descriptor SM_vertex;
typedef CGAL::Spectral_surface_mesh_deformation<Surface_mesh> Spectral;

namespace {

const double pi = 3.14159265358979323846;

Eigen::MatrixXd positions_of(const Surface_mesh& mesh)
{
  Eigen::MatrixXd x(num_vertices(mesh), 3);
  for(auto v : vertices(mesh))
  {
    const Point& p = mesh.point(v);
    x.row(v.idx()) << p.x(), p.y(), p.z();
  }
  return x;
}

double diagonal_of(const Eigen::MatrixXd& x)
{
  return (x.colwise().maxCoeff() - x.colwise().minCoeff()).norm();
}

// The bar of test_meshes, ends fixed (z < 0.3) and moved (z > 4.7) by
// `top_motion` (a rotation about `axis` through `center`), deformed with
// `patches` rotation patches (0: the full iteration).
Eigen::MatrixXd deform_bar(std::size_t patches, const Eigen::Matrix3d& top_rotation,
                           const Eigen::Vector3d& center, unsigned int iterations = 10)
{
  Surface_mesh mesh = to_mesh<Surface_mesh>(bar(24, 3));
  Spectral deformation(mesh);
  deformation.insert_roi_vertices(vertices(mesh).begin(), vertices(mesh).end());
  std::vector<SM_vertex> top;
  for(auto v : vertices(mesh))
  {
    const double z = mesh.point(v).z();
    if(z < 0.3 || z > 4.7)
      deformation.insert_control_vertex(v);
    if(z > 4.7)
      top.push_back(v);
  }
  deformation.set_number_of_frequencies(60);
  deformation.set_rotation_patches(patches);
  for(SM_vertex v : top)
  {
    const Point& p = mesh.point(v);
    const Eigen::Vector3d q = center + top_rotation * (Eigen::Vector3d(p.x(), p.y(), p.z()) - center);
    deformation.set_target_position(v, Point(q[0], q[1], q[2]));
  }
  deformation.deform(iterations, 0.0);
  INFO(deformation.deform_report().message);
  REQUIRE(deformation.deform_report().success);
  return positions_of(mesh);
}

} // namespace

TEST_CASE("rotation patches are connected, cover every dual vertex, one surface each", "[patches]")
{
  const Soup soup = two_spheres(3);
  const internal::Triangle_arrays arrays =
      internal::extract_triangle_arrays(to_mesh<Surface_mesh>(soup), CGAL::parameters::default_values());
  const internal::Dual_mesh_operator dual(arrays.triangles, arrays.number_of_vertices());
  const internal::Positions centroids = dual.centroids(arrays.positions);
  const std::vector<int>& row_faces = dual.row_faces();
  for(std::size_t count : {1, 7, 40, 300})
  {
    const std::vector<int> patch = internal::cluster_dual_rows(dual, centroids, count);
    REQUIRE(patch.size() == row_faces.size());
    const int patches = *std::max_element(patch.begin(), patch.end()) + 1;
    INFO(count << " requested, " << patches << " made");
    // At least one per sphere; no more than asked for, unless a sphere got none.
    CHECK(patches >= 2);
    CHECK(static_cast<std::size_t>(patches) <= (std::max<std::size_t>)(count, 2));
    std::vector<int> sizes(static_cast<std::size_t>(patches), 0);
    std::vector<std::set<bool>> sides(static_cast<std::size_t>(patches));
    for(std::size_t r = 0; r < patch.size(); ++r)
    {
      ++sizes[static_cast<std::size_t>(patch[r])];
      sides[static_cast<std::size_t>(patch[r])].insert(centroids(row_faces[r], 0) > 1.5);
    }
    for(int p = 0; p < patches; ++p)
    {
      CHECK(sizes[static_cast<std::size_t>(p)] > 0);
      CHECK(sides[static_cast<std::size_t>(p)].size() == 1); // never across the gap
    }
    // Connected: a breadth-first search inside each patch reaches all of it.
    std::vector<int> row_of_face(static_cast<std::size_t>(dual.number_of_faces()), -1);
    for(std::size_t r = 0; r < row_faces.size(); ++r)
      row_of_face[static_cast<std::size_t>(row_faces[r])] = static_cast<int>(r);
    std::vector<char> reached(patch.size(), 0);
    int components = 0;
    for(std::size_t r0 = 0; r0 < patch.size(); ++r0)
    {
      if(reached[r0])
        continue;
      ++components;
      std::vector<int> queue{static_cast<int>(r0)};
      reached[r0] = 1;
      for(std::size_t head = 0; head < queue.size(); ++head)
        for(int j = 0; j < 3; ++j)
        {
          const int g = dual.neighbours()(row_faces[static_cast<std::size_t>(queue[head])], j);
          const int s = g < 0 ? -1 : row_of_face[static_cast<std::size_t>(g)];
          if(s >= 0 && !reached[static_cast<std::size_t>(s)] && patch[static_cast<std::size_t>(s)] == patch[r0])
          {
            reached[static_cast<std::size_t>(s)] = 1;
            queue.push_back(s);
          }
        }
    }
    CHECK(components == patches);
  }
}

TEST_CASE("one rotation patch per dual vertex is the full iteration; fewer patches approach it",
          "[deformation][patches]")
{
  const Eigen::Matrix3d bend = Eigen::AngleAxisd(pi / 3, Eigen::Vector3d::UnitX()).toRotationMatrix();
  const Eigen::Vector3d center(0, 0, 5.0);
  const Eigen::MatrixXd full = deform_bar(0, bend, center);
  const Eigen::MatrixXd rest = deform_bar(0, Eigen::Matrix3d::Identity(), center, 1);
  const double diagonal = diagonal_of(rest);

  const Eigen::MatrixXd every_row = deform_bar(1000000, bend, center);
  const double exact = (every_row - full).rowwise().norm().maxCoeff() / diagonal;
  INFO("one patch per dual vertex: largest distance to the full iteration " << exact);
  CHECK(exact < 1e-9);

  double previous = std::numeric_limits<double>::infinity();
  for(std::size_t patches : {8, 64, 512})
  {
    const Eigen::MatrixXd result = deform_bar(patches, bend, center);
    const double distance = (result - full).rowwise().norm().maxCoeff() / diagonal;
    INFO(patches << " patches: largest distance to the full iteration " << distance);
    CHECK(distance < previous);
    previous = distance;
  }
  CHECK(previous < 1e-2);
}

TEST_CASE("rotation patches reproduce a rigid motion of all constraints", "[deformation][patches]")
{
  const Eigen::Matrix3d turn = Eigen::AngleAxisd(2.0, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  Surface_mesh mesh = to_mesh<Surface_mesh>(bar(24, 3));
  const Eigen::MatrixXd before = positions_of(mesh);
  Spectral deformation(mesh);
  deformation.insert_roi_vertices(vertices(mesh).begin(), vertices(mesh).end());
  std::vector<SM_vertex> controls;
  for(auto v : vertices(mesh))
    if(mesh.point(v).z() < 0.3 || mesh.point(v).z() > 4.7)
      controls.push_back(v);
  deformation.insert_control_vertices(controls.begin(), controls.end());
  deformation.set_number_of_frequencies(60);
  deformation.set_rotation_patches(30);
  deformation.rotate(controls.begin(), controls.end(), Eigen::Vector3d(0, 0, 0), Eigen::Quaterniond(turn));
  // Converged, as the full iteration needs to be to reproduce it.
  deformation.deform(2000, 1e-13);
  REQUIRE(deformation.deform_report().success);
  CHECK(deformation.deform_report().converged);
  const Eigen::MatrixXd expected = before * turn.transpose();
  CHECK((positions_of(mesh) - expected).rowwise().norm().maxCoeff() < 1e-8 * diagonal_of(before));
}

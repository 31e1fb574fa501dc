// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include "test_meshes.h"

#include <CGAL/Spectral_deformation/internal/Deformation/Spatial_dual_laplacian_solver.h>
#include <CGAL/Spectral_deformation/arap_energy.h>

#include <catch2/catch.hpp>

#include <cmath>

using namespace test_meshes;
namespace internal = CGAL::Spectral_deformation::internal;
typedef internal::Deformation::Spatial_dual_laplacian_solver<> Solver;

// Exact constraints for weight 0, soft ones with the weight otherwise.
void preprocess(Solver& solver, const std::vector<int>& constrained, double weight)
{
  if(weight > 0)
    solver.preprocess_soft(constrained, weight);
  else
    solver.preprocess_exact(constrained);
}
typedef Solver::Positions Positions;

namespace {

template <class Mesh>
internal::Mesh::Triangle_arrays arrays_of(const Mesh& mesh)
{
  return internal::Mesh::extract_triangle_arrays(mesh, CGAL::parameters::default_values());
}

// Vertices of the bar with z below `low` or above `high`.
std::vector<int> ends_of_bar(const internal::Mesh::Triangle_arrays& bar, double low, double high)
{
  std::vector<int> ends;
  for(Eigen::Index i = 0; i < bar.number_of_vertices(); ++i)
    if(bar.positions(i, 2) < low || bar.positions(i, 2) > high)
      ends.push_back(int(i));
  return ends;
}

Positions rows_of(const Positions& x, const std::vector<int>& indices)
{
  Positions result(Eigen::Index(indices.size()), 3);
  for(std::size_t k = 0; k < indices.size(); ++k)
    result.row(Eigen::Index(k)) = x.row(indices[k]);
  return result;
}

Eigen::Matrix3d rotation(double angle, const Eigen::Vector3d& axis)
{
  return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
}

// The bar twisted by `angle` about its axis: the top end turns, the bottom stays.
Positions twisted_targets(const internal::Mesh::Triangle_arrays& bar, const std::vector<int>& ends,
                          double angle)
{
  Positions targets = rows_of(bar.positions, ends);
  const Eigen::Matrix3d R = rotation(angle, Eigen::Vector3d::UnitZ());
  for(Eigen::Index k = 0; k < targets.rows(); ++k)
    if(targets(k, 2) > 2.5)
      targets.row(k) = (R * targets.row(k).transpose()).transpose();
  return targets;
}

} // namespace

TEST_CASE("spatial solver: no motion returns the input", "[spatial]")
{
  const internal::Mesh::Triangle_arrays bar = arrays_of(to_mesh<Surface_mesh>(test_meshes::bar(16, 3)));
  const std::vector<int> ends = ends_of_bar(bar, 0.01, 4.99);
  for(double weight : {0.0, 1.0})
  {
    Solver solver(bar);
    REQUIRE_NOTHROW(preprocess(solver, ends, weight));
    Positions result;
    REQUIRE_NOTHROW(solver.solve(rows_of(bar.positions, ends), bar.positions, result, 10, 1e-12));
    CHECK((result - bar.positions).cwiseAbs().maxCoeff() < 1e-10);
  }
}

TEST_CASE("spatial solver: a rigid motion of all constraints moves the mesh rigidly", "[spatial]")
{
  const internal::Mesh::Triangle_arrays bar = arrays_of(to_mesh<Surface_mesh>(test_meshes::bar(16, 3)));
  const std::vector<int> ends = ends_of_bar(bar, 0.01, 4.99);
  const Eigen::Matrix3d R = rotation(1.0, Eigen::Vector3d(1, 2, 0.5));
  const Eigen::RowVector3d t(0.3, -1.0, 2.0);
  const Positions moved = ((bar.positions * R.transpose()).rowwise() + t).eval();

  Solver solver(bar);
  REQUIRE_NOTHROW(preprocess(solver, ends, 0.0));
  Positions result;
  const internal::Deformation::Iteration_report report =
      solver.solve(rows_of(moved, ends), bar.positions, result, 1000, 1e-15);
  INFO("iterations " << report.iterations << ", last step " << report.last_step);
  CHECK((result - moved).norm() / moved.norm() <= 1e-8);
}

TEST_CASE("spatial solver: iterations lower the ARAP energy of a twist", "[spatial]")
{
  const internal::Mesh::Triangle_arrays bar = arrays_of(to_mesh<Surface_mesh>(test_meshes::bar(24, 3)));
  const std::vector<int> ends = ends_of_bar(bar, 0.01, 4.99);
  const Positions targets = twisted_targets(bar, ends, 2.0 * 3.14159265358979 / 3.0); // 120°
  Solver solver(bar);
  REQUIRE_NOTHROW(preprocess(solver, ends, 0.0));
  Positions linear, iterated;
  REQUIRE_NOTHROW(solver.solve(targets, bar.positions, linear, 0, 0.0));
  const internal::Deformation::Iteration_report report = solver.solve(targets, bar.positions, iterated, 100, 1e-6);
  const double e_linear = internal::Deformation::arap_energy(bar, linear);
  const double e_iterated = internal::Deformation::arap_energy(bar, iterated);
  INFO("ARAP energy linear " << e_linear << ", iterated " << e_iterated << " after "
                             << report.iterations << " iterations");
  CHECK(e_iterated < 0.5 * e_linear);
  // Hard constraints land exactly.
  CHECK((rows_of(iterated, ends) - targets).cwiseAbs().maxCoeff() == 0.0);
}

TEST_CASE("spatial solver: bumpy plane with an open boundary", "[spatial]")
{
  const internal::Mesh::Triangle_arrays plane = arrays_of(to_mesh<Surface_mesh>(bumpy_plane(20)));
  std::vector<int> constrained;
  for(Eigen::Index i = 0; i < plane.number_of_vertices(); ++i)
    if(plane.positions(i, 1) < 0.06 || plane.positions(i, 1) > 0.94)
      constrained.push_back(int(i));
  Positions targets = rows_of(plane.positions, constrained);
  const Eigen::Matrix3d R = rotation(0.8, Eigen::Vector3d::UnitX());
  for(Eigen::Index k = 0; k < targets.rows(); ++k)
    if(targets(k, 1) > 0.5)
      targets.row(k) = (R * (targets.row(k).transpose() - Eigen::Vector3d(0, 0.5, 0)) +
                        Eigen::Vector3d(0, 0.5, 0.4))
                           .transpose();
  for(double weight : {0.0, 10.0})
  {
    Solver solver(plane);
    REQUIRE_NOTHROW(preprocess(solver, constrained, weight));
    Positions linear, iterated;
    REQUIRE_NOTHROW(solver.solve(targets, plane.positions, linear, 0, 0.0));
    REQUIRE_NOTHROW(solver.solve(targets, plane.positions, iterated, 50, 1e-7));
    CHECK(iterated.allFinite());
    CHECK(internal::Deformation::arap_energy(plane, iterated) < internal::Deformation::arap_energy(plane, linear));
    const double residual = (rows_of(iterated, constrained) - targets).rowwise().norm().maxCoeff();
    INFO("weight " << weight << ": largest constraint residual " << residual);
    if(weight == 0.0)
      CHECK(residual == 0.0);
    else
      CHECK(residual < 0.05);
  }
}

TEST_CASE("spatial solver: soft constraints tighten as the weight grows", "[spatial]")
{
  const internal::Mesh::Triangle_arrays bar = arrays_of(to_mesh<Surface_mesh>(test_meshes::bar(16, 3)));
  const std::vector<int> ends = ends_of_bar(bar, 0.01, 4.99);
  const Positions targets = twisted_targets(bar, ends, 1.0);
  double previous = std::numeric_limits<double>::infinity();
  for(double weight : {0.1, 1.0, 10.0, 100.0})
  {
    Solver solver(bar);
    REQUIRE_NOTHROW(preprocess(solver, ends, weight));
    Positions result;
    REQUIRE_NOTHROW(solver.solve(targets, bar.positions, result, 20, 1e-8));
    const double residual = (rows_of(result, ends) - targets).norm();
    CHECK(residual < previous);
    previous = residual;
  }
}

TEST_CASE("spatial solver: same numbers on Surface_mesh and Polyhedron_3", "[spatial]")
{
  const Soup soup = test_meshes::bar(12, 2);
  const internal::Mesh::Triangle_arrays a = arrays_of(to_mesh<Surface_mesh>(soup));
  const internal::Mesh::Triangle_arrays b = arrays_of(to_mesh<Polyhedron>(soup));
  const std::vector<int> ends = ends_of_bar(a, 0.01, 4.99);
  Solver solver_a(a), solver_b(b);
  REQUIRE_NOTHROW(preprocess(solver_a, ends, 0.0));
  REQUIRE_NOTHROW(preprocess(solver_b, ends, 0.0));
  Positions ra, rb;
  REQUIRE_NOTHROW(solver_a.solve(twisted_targets(a, ends, 1.5), a.positions, ra, 10, 0.0));
  REQUIRE_NOTHROW(solver_b.solve(twisted_targets(b, ends, 1.5), b.positions, rb, 10, 0.0));
  CHECK((ra - rb).cwiseAbs().maxCoeff() == 0.0);
}

TEST_CASE("spatial solver: clear failures", "[spatial][errors]")
{
  const internal::Mesh::Triangle_arrays spheres = arrays_of(to_mesh<Surface_mesh>(two_spheres(2)));
  Solver solver(spheres);
  CHECK_THROWS_AS(solver.preprocess_exact({}), CGAL::Spectral_deformation_error);
  CHECK_THROWS_AS(solver.preprocess_exact({0, int(spheres.number_of_vertices())}),
                  CGAL::Spectral_deformation_error);
  CHECK_THROWS_AS(solver.preprocess_soft({0, 1}, 0.0), CGAL::Spectral_deformation_error);
  // Only the first sphere is constrained: the second one is free to float.
  CHECK_THROWS_WITH(solver.preprocess_exact({0, 1, 2}), Catch::Contains("component"));

  const internal::Mesh::Triangle_arrays bar = arrays_of(to_mesh<Surface_mesh>(test_meshes::bar(8, 2)));
  Solver bar_solver(bar);
  Positions result = Positions::Zero(1, 3);
  CHECK_THROWS_WITH(bar_solver.solve(Positions::Zero(1, 3), bar.positions, result, 1, 0.0),
                    Catch::Contains("not preprocessed"));
  const std::vector<int> ends = ends_of_bar(bar, 0.01, 4.99);
  REQUIRE_NOTHROW(bar_solver.preprocess_exact(ends));
  Positions bad = rows_of(bar.positions, ends);
  bad(0, 0) = std::nan("");
  CHECK_THROWS_WITH(bar_solver.solve(bad, bar.positions, result, 5, 0.0), Catch::Contains("finite"));
  CHECK(result == Positions::Zero(1, 3)); // untouched
}

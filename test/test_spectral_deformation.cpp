// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include "test_meshes.h"

// Other traits than the compiled core holds, besides the defaults.
#include <CGAL/Spectral_deformation/Pipelines_from_headers.h>
#include <CGAL/Spectral_surface_mesh_deformation.h>
#include <CGAL/Spectral_deformation/IO/deformation_selection.h>
#include <CGAL/Spectral_deformation/internal/Deformation/Constraint_products.h>
#include <CGAL/Spectral_deformation/arap_energy.h>
#include <CGAL/Spectral_deformation/internal/Deformation/Face_patches.h>
#include <CGAL/Spectral_deformation/internal/Basis/basis_in_region_order.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/subdivision_method_3.h>
#include <CGAL/Surface_mesh_deformation.h>

#include <catch2/catch.hpp>

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <sstream>

#ifdef _OPENMP
#include <omp.h>
#endif

using namespace test_meshes;
namespace internal = CGAL::Spectral_deformation::internal;
typedef boost::graph_traits<Surface_mesh>::vertex_descriptor SM_vertex;
typedef CGAL::Spectral_surface_mesh_deformation<Surface_mesh> Spectral;
typedef CGAL::Spectral_surface_mesh_deformation<Surface_mesh, CGAL::Default, CGAL::Default,
                                                CGAL::SPECTRAL_LINEAR>
    Linear;
typedef CGAL::Spectral_surface_mesh_deformation<Surface_mesh, CGAL::Default, CGAL::Default,
                                                CGAL::SPATIAL_DUAL_LAPLACIAN>
    Spatial;

namespace {

const double pi = 3.14159265358979323846;

template <class Mesh>
Eigen::MatrixXd positions_of(const Mesh& mesh)
{
  auto index = CGAL::get_initialized_vertex_index_map(mesh);
  Eigen::MatrixXd x(num_vertices(mesh), 3);
  for(auto v : vertices(mesh))
  {
    const auto& p = get(CGAL::vertex_point, mesh, v);
    x.row(get(index, v)) << p.x(), p.y(), p.z();
  }
  return x;
}

template <class Mesh>
std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor> vertex_list(const Mesh& mesh)
{
  return std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor>(vertices(mesh).begin(),
                                                                            vertices(mesh).end());
}

// The ends of the cylinder of test_meshes::bar: z below `low`, above `high`.
template <class Mesh>
void select_ends(const Mesh& mesh, double low, double high,
                 std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor>& bottom,
                 std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor>& top)
{
  for(auto v : vertices(mesh))
  {
    const double z = get(CGAL::vertex_point, mesh, v).z();
    if(z < low)
      bottom.push_back(v);
    else if(z > high)
      top.push_back(v);
  }
}

// Exercises every public member of CGAL's Surface_mesh_deformation API: the
// same code must compile and run for both classes.
template <class Deformation, class Mesh>
void exercise_cgal_api(Mesh& mesh)
{
  typedef typename Deformation::vertex_descriptor vertex_descriptor;
  typedef typename Deformation::Point Point;
  Deformation deformation(mesh);
  std::vector<vertex_descriptor> all = vertex_list(mesh), bottom, top;
  select_ends(mesh, 0.3, 4.7, bottom, top);

  deformation.insert_roi_vertices(all.begin(), all.end());
  CHECK(deformation.roi_vertices().size() == all.size());
  CHECK_FALSE(deformation.insert_roi_vertex(all.front()));
  CHECK(deformation.erase_roi_vertex(all.front()));
  CHECK(deformation.insert_roi_vertex(all.front()));
  deformation.insert_control_vertices(bottom.begin(), bottom.end());
  deformation.insert_control_vertices(top.begin(), top.end());
  CHECK(deformation.is_control_vertex(top.front()));
  CHECK(deformation.erase_control_vertex(top.front()));
  CHECK_FALSE(deformation.is_control_vertex(top.front()));
  CHECK(deformation.insert_control_vertex(top.front()));
  CHECK(deformation.is_roi_vertex(top.front()));
  CHECK(deformation.preprocess());

  deformation.set_iterations(8);
  deformation.set_tolerance(1e-6);
  CHECK(deformation.iterations() == 8);
  CHECK(deformation.tolerance() == 1e-6);

  const Eigen::Quaternion<double> quarter(Eigen::AngleAxisd(pi / 4, Eigen::Vector3d::UnitX()));
  deformation.rotate(top.begin(), top.end(), Eigen::Vector3d(0, 0, 4.7), quarter);
  deformation.rotate(top.front(), Eigen::Vector3d(0, 0, 4.7), Eigen::Quaternion<double>::Identity());
  deformation.translate(top.begin(), top.end(), Eigen::Vector3d(0.5, 0, 0));
  deformation.translate(top.front(), Eigen::Vector3d(0, 0, 0));
  const Point target = deformation.target_position(top.front());
  deformation.set_target_position(top.front(), target);
  deformation.deform();
  deformation.deform(3, 0.0);
  const Point moved = get(CGAL::vertex_point, mesh, top.front());
  CHECK(CGAL::squared_distance(moved, target) < 0.25); // near its target

  deformation.overwrite_initial_geometry();
  deformation.reset();
  CHECK(get(CGAL::vertex_point, mesh, top.front()) == moved);
  deformation.clear_control_vertices();
  CHECK_FALSE(deformation.is_control_vertex(bottom.front()));
  deformation.clear_roi_vertices();
  CHECK(deformation.roi_vertices().empty());
  CHECK(&deformation.triangle_mesh() == &mesh);
}

Eigen::RowVector3d row(const Point& p) { return Eigen::RowVector3d(p.x(), p.y(), p.z()); }

struct Run
{
  Eigen::MatrixXd before, after;
  CGAL::Spectral_deformation_report report;
  CGAL::Spectral_preprocess_report preprocess;
  std::vector<std::size_t> controls; // vertex indices
};

// Deforms a copy of `soup` with the ends of the cylinder as control vertices
// and the whole mesh as ROI: the bottom end moved by `bottom_motion`, the top
// end by `top_motion`. `paper`: the iteration of the paper (dual Laplacian
// energy, one rotation per dual vertex, one stage), the spectral
// counterpart of `SPATIAL_DUAL_LAPLACIAN`; otherwise the class's defaults.
template <class Deformation, class Mesh = Surface_mesh>
Run deform_bar(const Soup& soup, const internal::Deformation::Rigid_motion& bottom_motion,
               const internal::Deformation::Rigid_motion& top_motion, unsigned int iterations, double tolerance,
               std::size_t m = 100, CGAL::Spectral_constraint_policy policy = CGAL::EXACT_CONSTRAINTS,
               bool process_wide_tuning = false, bool paper = false)
{
  Mesh mesh = to_mesh<Mesh>(soup);
  Run run;
  run.before = positions_of(mesh);
  Deformation deformation(mesh);
  REQUIRE(!deformation.process_wide_tuning());
  deformation.set_process_wide_tuning(process_wide_tuning);
  REQUIRE(deformation.process_wide_tuning() == process_wide_tuning);
  auto all = vertex_list(mesh);
  std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor> bottom, top;
  select_ends(mesh, 0.3, 4.7, bottom, top);
  deformation.insert_roi_vertices(all.begin(), all.end());
  deformation.insert_control_vertices(bottom.begin(), bottom.end());
  deformation.insert_control_vertices(top.begin(), top.end());
  if constexpr(Deformation::has_basis)
  {
    deformation.set_number_of_frequencies(m);
    deformation.set_constraint_policy(policy);
    if constexpr(Deformation::algorithm == CGAL::SPECTRAL_DUAL_LAPLACIAN)
      if(paper)
      {
        deformation.set_smooth_energy(CGAL::DUAL_LAPLACIAN_ENERGY);
        deformation.set_rotation_patches(0);
        deformation.set_stage_angle(0);
      }
  }
  REQUIRE(deformation.preprocess());
  auto index = CGAL::get_initialized_vertex_index_map(mesh);
  for(auto v : bottom)
  {
    const Eigen::RowVector3d p = bottom_motion.apply(run.before.row(get(index, v)));
    deformation.set_target_position(v, Point(p[0], p[1], p[2]));
    run.controls.push_back(get(index, v));
  }
  for(auto v : top)
  {
    const Eigen::RowVector3d p = top_motion.apply(run.before.row(get(index, v)));
    deformation.set_target_position(v, Point(p[0], p[1], p[2]));
    run.controls.push_back(get(index, v));
  }
  deformation.deform(iterations, tolerance);
  run.report = deformation.deform_report();
  run.preprocess = deformation.preprocess_report();
  INFO(run.report.message);
  REQUIRE(run.report.success);
  run.after = positions_of(mesh);
  return run;
}

internal::Deformation::Rigid_motion motion(double angle, const Eigen::Vector3d& axis,
                              const Eigen::Vector3d& center = Eigen::Vector3d::Zero(),
                              const Eigen::Vector3d& shift = Eigen::Vector3d::Zero())
{
  internal::Deformation::Rigid_motion result;
  result.rotation = Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
  result.translation = center - result.rotation * center + shift;
  return result;
}

Eigen::MatrixXd moved_rigidly(const Eigen::MatrixXd& x, const internal::Deformation::Rigid_motion& m)
{
  return ((x * m.rotation.transpose()).rowwise() + m.translation.transpose()).eval();
}

double diagonal_of(const Eigen::MatrixXd& x)
{
  return (x.colwise().maxCoeff() - x.colwise().minCoeff()).norm();
}

internal::Mesh::Triangle_arrays arrays_of(const Soup& soup)
{
  return internal::Mesh::extract_triangle_arrays(to_mesh<Surface_mesh>(soup),
                                           CGAL::parameters::default_values());
}

} // namespace

TEST_CASE("API parity with CGAL::Surface_mesh_deformation", "[deformation][api]")
{
  const Soup soup = bar(16, 3);
  SECTION("CGAL ARAP")
  {
    Surface_mesh mesh = to_mesh<Surface_mesh>(soup);
    exercise_cgal_api<CGAL::Surface_mesh_deformation<Surface_mesh>>(mesh);
  }
  SECTION("spectral")
  {
    Surface_mesh mesh = to_mesh<Surface_mesh>(soup);
    exercise_cgal_api<Spectral>(mesh);
  }
  SECTION("spectral on Polyhedron_3")
  {
    Polyhedron mesh = to_mesh<Polyhedron>(soup);
    exercise_cgal_api<CGAL::Spectral_surface_mesh_deformation<Polyhedron>>(mesh);
  }
  SECTION("spatial")
  {
    Surface_mesh mesh = to_mesh<Surface_mesh>(soup);
    exercise_cgal_api<Spatial>(mesh);
  }
}

TEST_CASE("a rigid motion of all constraints moves the mesh rigidly", "[deformation]")
{
  const Soup soup = bar(16, 3);
  const internal::Deformation::Rigid_motion rigid = motion(1.0, Eigen::Vector3d(1, 2, 0.5), Eigen::Vector3d(0, 0, 2.5),
                                              Eigen::Vector3d(0.3, -1, 2));
  SECTION("spectral, exact and soft policies")
  {
    for(auto policy : {CGAL::EXACT_CONSTRAINTS, CGAL::SOFT_CONSTRAINTS})
    {
      const Run run = deform_bar<Spectral>(soup, rigid, rigid, 2000, 1e-13, 60, policy);
      const Eigen::MatrixXd expected = moved_rigidly(run.before, rigid);
      INFO("policy " << policy << ", iterations " << run.report.iterations);
      CHECK((run.after - expected).cwiseAbs().maxCoeff() < 1e-8 * diagonal_of(run.before));
    }
  }
  SECTION("spatial")
  {
    const Run run = deform_bar<Spatial>(soup, rigid, rigid, 2000, 1e-13);
    const Eigen::MatrixXd expected = moved_rigidly(run.before, rigid);
    CHECK((run.after - expected).cwiseAbs().maxCoeff() < 1e-8 * diagonal_of(run.before));
  }
  SECTION("linear: translations are reproduced, rotations are not (the reason to iterate)")
  {
    const internal::Deformation::Rigid_motion shift = motion(0.0, Eigen::Vector3d::UnitX(), Eigen::Vector3d::Zero(),
                                                Eigen::Vector3d(0.3, -1, 2));
    const Run run = deform_bar<Linear>(soup, shift, shift, 10, 0.0, 60);
    CHECK((run.after - moved_rigidly(run.before, shift)).cwiseAbs().maxCoeff() <
          1e-10 * diagonal_of(run.before));
    CHECK(run.report.iterations == 1);
    const Run turned = deform_bar<Linear>(soup, rigid, rigid, 10, 0.0, 60);
    CHECK((turned.after - moved_rigidly(turned.before, rigid)).cwiseAbs().maxCoeff() >
          1e-3 * diagonal_of(turned.before));
  }
}

TEST_CASE("exact policy: controls on target, outside the ROI untouched, soft policy reports residuals",
          "[deformation]")
{
  Surface_mesh mesh = to_mesh<Surface_mesh>(bar(24, 3));
  const Eigen::MatrixXd before = positions_of(mesh);
  std::vector<SM_vertex> bottom, top, roi;
  select_ends(mesh, 1.0, 3.9, bottom, top);
  for(auto v : mesh.vertices())
    if(mesh.point(v).z() > 1.0)
      roi.push_back(v); // the lower part is outside the ROI
  std::vector<SM_vertex> handle;
  for(auto v : top)
    if(mesh.point(v).z() > 4.7)
      handle.push_back(v);
  double exact_seam = 0;
  for(auto policy : {CGAL::EXACT_CONSTRAINTS, CGAL::SOFT_CONSTRAINTS})
  {
    Spectral deformation(mesh);
    deformation.insert_roi_vertices(roi.begin(), roi.end());
    deformation.insert_control_vertices(handle.begin(), handle.end());
    deformation.set_number_of_frequencies(80);
    deformation.set_constraint_policy(policy);
    const Eigen::Quaternion<double> q(Eigen::AngleAxisd(pi / 3, Eigen::Vector3d::UnitX()));
    deformation.rotate(handle.begin(), handle.end(), Eigen::Vector3d(0, 0, 3.0), q);
    deformation.deform();
    const CGAL::Spectral_deformation_report& report = deformation.deform_report();
    INFO(report.message);
    REQUIRE(report.success);
    const Eigen::MatrixXd after = positions_of(mesh);
    for(auto v : mesh.vertices())
      if(!deformation.is_roi_vertex(v))
        CHECK(after.row(v.idx()) == before.row(v.idx())); // bit-identical
    double worst = 0;
    for(auto v : handle)
      worst = std::max(worst, (after.row(v.idx()) - row(deformation.target_position(v))).norm());
    INFO("policy " << policy << ": max residual " << worst << ", reported "
                   << report.max_control_residual);
    CHECK(report.max_control_residual * 1.0 >= 0.0);
    if(policy == CGAL::EXACT_CONSTRAINTS)
      CHECK(worst == 0.0);
    else
    {
      CHECK(worst > 0.0);
      CHECK(report.max_control_residual < 2e-2);
    }
    // No seam: edges between the ROI and the fixed vertices keep their length.
    double seam = 0;
    for(auto e : mesh.edges())
    {
      const auto a = mesh.vertex(e, 0), b = mesh.vertex(e, 1);
      if(deformation.is_roi_vertex(a) == deformation.is_roi_vertex(b))
        continue;
      const double rest_length = (before.row(a.idx()) - before.row(b.idx())).norm();
      seam = std::max(seam, std::abs((after.row(a.idx()) - after.row(b.idx())).norm() - rest_length) /
                                rest_length);
    }
    INFO("largest relative length change of an edge across the ROI border: " << seam);
    // The soft policy anchors the fixed vertices like the exact one: the same
    // transition, no seam (it used to stretch these edges by several times).
    if(policy == CGAL::EXACT_CONSTRAINTS)
      exact_seam = seam;
    else
      CHECK(seam < exact_seam + 0.01);
    CHECK(seam < 0.2);
    deformation.reset();
    CHECK(positions_of(mesh) == before);
  }
}

TEST_CASE("iteration lowers the ARAP energy of a twist, the spectral result approaches the spatial one",
          "[deformation]")
{
  const Soup soup = bar(24, 3);
  const internal::Mesh::Triangle_arrays rest = arrays_of(soup);
  const internal::Deformation::Rigid_motion still;
  const internal::Deformation::Rigid_motion twist = motion(2 * pi / 3, Eigen::Vector3d::UnitZ());

  const Run linear = deform_bar<Linear>(soup, still, twist, 1, 0.0, 100);
  const Run iterated = deform_bar<Spectral>(soup, still, twist, 50, 1e-6, 100);
  const double e_linear = internal::Deformation::arap_energy(rest, linear.after);
  const double e_iterated = internal::Deformation::arap_energy(rest, iterated.after);
  INFO("ARAP energy: linear " << e_linear << ", iterated " << e_iterated);
  // The detail transfer removes the stretch of the smooth mesh from both
  // results, which narrows the gap between them: the iteration still takes
  // off close to half of the energy.
  CHECK(e_iterated < 0.6 * e_linear);

  // Bend: the spectral result comes closer to the spatial one as m grows,
  // then levels off (both iterations stop at their own local minimum).
  const internal::Deformation::Rigid_motion bend = motion(pi / 4, Eigen::Vector3d::UnitX(), Eigen::Vector3d(0, 0, 5.0));
  const Run spatial = deform_bar<Spatial>(soup, still, bend, 200, 1e-10);
  std::vector<double> distances;
  for(std::size_t m : {10, 40, 160})
  {
    const Run spectral = deform_bar<Spectral>(soup, still, bend, 200, 1e-10, m, CGAL::EXACT_CONSTRAINTS, false, true);
    distances.push_back((spectral.after - spatial.after).rowwise().norm().maxCoeff() / diagonal_of(spectral.before));
  }
  INFO("largest distance to the spatial result, m = 10, 40, 160: " << distances[0] << ", " << distances[1] << ", "
                                                                   << distances[2]);
  CHECK(distances[1] < 0.8 * distances[0]);
  CHECK(distances[2] < 1.05 * distances[1]);
  CHECK(distances[2] < 0.05);
}

TEST_CASE("process-wide tuning is an opt-in of every algorithm and does not change the result",
          "[deformation]")
{
  const Soup soup = bar(16, 2);
  const internal::Deformation::Rigid_motion still;
  const internal::Deformation::Rigid_motion bend =
      motion(pi / 4, Eigen::Vector3d::UnitX(), Eigen::Vector3d(0, 0, 5.0));
  const auto distance = [](const Run& a, const Run& b) {
    return (a.after - b.after).rowwise().norm().maxCoeff() / diagonal_of(a.before);
  };
  const Run spatial = deform_bar<Spatial>(soup, still, bend, 5, 0.0);
  const Run spatial_tuned = deform_bar<Spatial>(soup, still, bend, 5, 0.0, 100, CGAL::EXACT_CONSTRAINTS, true);
  CHECK(distance(spatial, spatial_tuned) < 1e-12);
  CHECK((spatial.after - spatial.before).cwiseAbs().maxCoeff() > 0.1);
  // With several OpenBLAS threads the basis differs at rounding level.
  const Run spectral = deform_bar<Spectral>(soup, still, bend, 5, 0.0, 40);
  const Run spectral_tuned = deform_bar<Spectral>(soup, still, bend, 5, 0.0, 40, CGAL::EXACT_CONSTRAINTS, true);
  CHECK(distance(spectral, spectral_tuned) < 1e-9);
}

// With two threads, the exact policy's first factorization runs beside the
// basis; on one thread, after it: the same systems, so the same result. The
// bar has more vertices than serial_preparation_vertices, below which the
// region is prepared on one thread whatever the setting.
TEST_CASE("the factorization made during the basis gives the result of the one made after it", "[deformation]")
{
#ifdef _OPENMP
  const Soup soup = bar(160, 8);
  REQUIRE(soup.points.size() >= CGAL::Spectral_deformation::internal::serial_preparation_vertices);
  const internal::Deformation::Rigid_motion still;
  const internal::Deformation::Rigid_motion bend =
      motion(pi / 4, Eigen::Vector3d::UnitX(), Eigen::Vector3d(0, 0, 5.0));
  const int threads = omp_get_max_threads();
  omp_set_num_threads(2);
  const Run overlapped = deform_bar<Spectral>(soup, still, bend, 5, 0.0, 40);
  omp_set_num_threads(1);
  const Run sequential = deform_bar<Spectral>(soup, still, bend, 5, 0.0, 40);
  omp_set_num_threads(threads);
  CHECK((overlapped.after - overlapped.before).cwiseAbs().maxCoeff() > 0.1);
  CHECK((overlapped.after - sequential.after).rowwise().norm().maxCoeff() / diagonal_of(overlapped.before) < 1e-9);
#else
  SUCCEED("without OpenMP the package runs on one thread: nothing overlaps");
#endif
}

// Small regions run on the calling thread alone while a call lasts; the
// caller's OpenMP setting is the same afterwards, whether the call
// succeeded or failed.
TEST_CASE("a small region leaves the caller's OpenMP thread count as it was", "[deformation]")
{
#ifdef _OPENMP
  const int threads = omp_get_max_threads();
  omp_set_num_threads(2);
  const Soup soup = bar(16, 2);
  REQUIRE(soup.points.size() < CGAL::Spectral_deformation::internal::serial_deformation_vertices);
  const internal::Deformation::Rigid_motion still;
  const Run run = deform_bar<Spectral>(soup, still, motion(pi / 4, Eigen::Vector3d::UnitX(),
                                                           Eigen::Vector3d(0, 0, 5.0)), 5, 0.0, 40);
  CHECK((run.after - run.before).cwiseAbs().maxCoeff() > 0.1);
  CHECK(omp_get_max_threads() == 2);
  Surface_mesh mesh = to_mesh<Surface_mesh>(soup);
  Spectral failing(mesh);
  CHECK(!failing.preprocess()); // an empty region of interest
  CHECK(omp_get_max_threads() == 2);
  omp_set_num_threads(threads);
#else
  SUCCEED("without OpenMP the package runs on one thread");
#endif
}

#ifdef CGAL_SSMD_USE_CHOLMOD
namespace {

// The detail transfer's solver with row updates unlimited (`Unlimited`) or
// none, counting the constraint sets it updated instead of factoring.
template <bool Unlimited>
struct Row_update_solver : CGAL::Cholmod_simplicial_sparse_spd_solver_traits
{
  typedef CGAL::Cholmod_simplicial_sparse_spd_solver_traits Base;
  static int updates;
  Row_update_solver() { set_row_update_budget(Unlimited ? std::numeric_limits<double>::infinity() : 0.0); }
  bool refactor_rows(const Matrix& A, const std::vector<int>& rows)
  {
    const bool factored = Base::refactor_rows(A, rows);
    if(factored && rows_updated())
      ++updates;
    return factored;
  }
};
template <bool Unlimited>
int Row_update_solver<Unlimited>::updates = 0;

// The bar bent by its top end, then one top vertex released and a vertex of
// the middle taken and pulled sideways: the positions after both.
template <class Solver>
Eigen::MatrixXd bend_then_change_constraints(const Soup& soup, std::vector<Eigen::RowVector3d>& targets,
                                             std::vector<Eigen::RowVector3d>& reached)
{
  typedef CGAL::Spectral_surface_mesh_deformation<Surface_mesh, CGAL::Default, CGAL::Default,
                                                  CGAL::SPECTRAL_DUAL_LAPLACIAN, CGAL::Default, Solver>
      Deformation;
  Surface_mesh mesh = to_mesh<Surface_mesh>(soup);
  Deformation deformation(mesh);
  std::vector<SM_vertex> all = vertex_list(mesh), bottom, top;
  select_ends(mesh, 0.3, 4.7, bottom, top);
  deformation.insert_roi_vertices(all.begin(), all.end());
  deformation.insert_control_vertices(bottom.begin(), bottom.end());
  deformation.insert_control_vertices(top.begin(), top.end());
  const Eigen::Quaternion<double> quarter(Eigen::AngleAxisd(pi / 4, Eigen::Vector3d::UnitX()));
  deformation.rotate(top.begin(), top.end(), Eigen::Vector3d(0, 0, 4.7), quarter);
  deformation.deform(5, 0.0);
  REQUIRE(deformation.deform_report().success);
  SM_vertex middle = all.front();
  for(SM_vertex v : all)
    if(std::abs(mesh.point(v).z() - 2.5) < std::abs(mesh.point(middle).z() - 2.5))
      middle = v;
  deformation.erase_control_vertex(top.front());
  deformation.insert_control_vertex(middle);
  const Point pulled = mesh.point(middle) + Kernel::Vector_3(0.3, 0, 0);
  deformation.set_target_position(middle, pulled);
  deformation.deform(5, 0.0);
  INFO(deformation.deform_report().message);
  REQUIRE(deformation.deform_report().success);
  targets = {row(pulled), row(deformation.target_position(top.back()))};
  reached = {row(mesh.point(middle)), row(mesh.point(top.back()))};
  return positions_of(mesh);
}

} // namespace

TEST_CASE("a constraint set updated row by row gives the result of a new factorization", "[deformation]")
{
  const Soup soup = bar(16, 2);
  std::vector<Eigen::RowVector3d> targets, reached, refactored_targets, refactored_reached;
  const Eigen::MatrixXd updated = bend_then_change_constraints<Row_update_solver<true>>(soup, targets, reached);
  const Eigen::MatrixXd refactored =
      bend_then_change_constraints<Row_update_solver<false>>(soup, refactored_targets, refactored_reached);
  CHECK(Row_update_solver<true>::updates >= 1);
  CHECK(Row_update_solver<false>::updates == 0);
  CHECK((updated - refactored).rowwise().norm().maxCoeff() < 1e-9 * diagonal_of(updated));
  // The exact policy: the new control vertex and the remaining top ones on their targets.
  for(std::size_t k = 0; k < targets.size(); ++k)
    CHECK((reached[k] - targets[k]).norm() < 1e-12 * diagonal_of(updated));
}
#endif

// Process-wide tuning changes how fast the factorizations and the basis are
// made, not what they are: switched on a prepared region, it keeps the basis,
// and the next constraint set, factored with it, gives the same result.
TEST_CASE("process-wide tuning switched on a prepared region keeps the basis and the results", "[deformation]")
{
  Surface_mesh tuned_mesh = to_mesh<Surface_mesh>(bar(16, 3));
  Surface_mesh plain_mesh = tuned_mesh;
  Spectral tuned(tuned_mesh), plain(plain_mesh);
  std::vector<SM_vertex> bottom, top;
  select_ends(tuned_mesh, 0.3, 4.7, bottom, top);
  const auto all = vertex_list(tuned_mesh);
  const SM_vertex middle = all[all.size() / 2];
  for(Spectral* deformation : {&tuned, &plain})
  {
    deformation->insert_roi_vertices(all.begin(), all.end());
    deformation->insert_control_vertices(bottom.begin(), bottom.end());
    deformation->insert_control_vertices(top.begin(), top.end());
    deformation->set_number_of_frequencies(60);
    deformation->translate(top.begin(), top.end(), Eigen::Vector3d(0.5, 0, 0));
    deformation->deform(3, 0.0);
    REQUIRE(deformation->deform_report().success);
  }
  tuned.set_process_wide_tuning(true);
  CHECK(tuned.process_wide_tuning());
  for(Spectral* deformation : {&tuned, &plain})
  {
    // A new constraint set: the detail transfer is factored again.
    deformation->insert_control_vertex(middle);
    deformation->translate(top.begin(), top.end(), Eigen::Vector3d(0.25, 0, 0));
    deformation->deform(3, 0.0);
    REQUIRE(deformation->deform_report().success);
    CHECK_FALSE(deformation->preprocess_report().basis_computed);
  }
  CHECK(positions_of(tuned_mesh) == positions_of(plain_mesh));
  tuned.set_process_wide_tuning(false);
  CHECK_FALSE(tuned.process_wide_tuning());
}

TEST_CASE("reset, continued iteration and overwrite_initial_geometry", "[deformation]")
{
  Surface_mesh mesh = to_mesh<Surface_mesh>(bar(16, 3));
  const Eigen::MatrixXd before = positions_of(mesh);
  std::vector<SM_vertex> bottom, top;
  select_ends(mesh, 0.3, 4.7, bottom, top);
  Spectral deformation(mesh);
  auto all = vertex_list(mesh);
  deformation.insert_roi_vertices(all.begin(), all.end());
  deformation.insert_control_vertices(bottom.begin(), bottom.end());
  deformation.insert_control_vertices(top.begin(), top.end());
  deformation.set_number_of_frequencies(60);
  deformation.translate(top.begin(), top.end(), Eigen::Vector3d(1.0, 0, 0));
  deformation.deform(2, 0.0);
  CHECK(deformation.preprocess_report().basis_computed);
  const double first_step = deformation.deform_report().last_step;
  deformation.deform(2, 0.0);
  CHECK(deformation.deform_report().last_step < first_step); // it went on
  CHECK_FALSE(deformation.preprocess_report().basis_computed);

  deformation.reset();
  CHECK(positions_of(mesh) == before);
  CHECK(row(deformation.target_position(top.front())) == before.row(top.front().idx()));
  deformation.deform();
  CHECK((positions_of(mesh) - before).cwiseAbs().maxCoeff() < 1e-9); // targets were reset too
  CHECK_FALSE(deformation.preprocess_report().region_rebuilt);         // no new basis

  deformation.translate(top.begin(), top.end(), Eigen::Vector3d(0.0, 0.7, 0));
  deformation.deform();
  const Eigen::MatrixXd deformed = positions_of(mesh);
  deformation.overwrite_initial_geometry();
  deformation.deform();
  CHECK(deformation.preprocess_report().region_rebuilt);
  // The deformed shape is the new rest shape and the targets are met: nothing moves.
  CHECK((positions_of(mesh) - deformed).cwiseAbs().maxCoeff() < 1e-8);
  deformation.reset();
  CHECK(positions_of(mesh) == deformed);
}

TEST_CASE("a basis kept in float: the deformation of the double one, rigid motions exact, saved and loaded",
          "[deformation]")
{
  const Soup soup = bar(16, 3);
  Surface_mesh reference_mesh = to_mesh<Surface_mesh>(soup);
  const Eigen::MatrixXd before = positions_of(reference_mesh);
  const double diagonal = (before.colwise().maxCoeff() - before.colwise().minCoeff()).norm();
  std::vector<SM_vertex> bottom, top;
  select_ends(reference_mesh, 0.3, 4.7, bottom, top);
  // `threshold`: the basis is kept in float from this many region vertices.
  auto set_up = [&](Surface_mesh& mesh, Spectral& deformation, std::size_t threshold) {
    deformation.set_single_precision_basis_threshold(threshold);
    deformation.insert_roi_vertices(vertices(mesh).begin(), vertices(mesh).end());
    deformation.insert_control_vertices(bottom.begin(), bottom.end());
    deformation.insert_control_vertices(top.begin(), top.end());
    deformation.set_number_of_frequencies(60);
  };
  auto bend = [&](Surface_mesh& mesh, Spectral& deformation) {
    deformation.reset();
    deformation.translate(top.begin(), top.end(), Eigen::Vector3d(1.5, 0, 0.5));
    deformation.deform(10, 0.0);
    return positions_of(mesh);
  };

  Spectral reference(reference_mesh);
  CHECK(reference.single_precision_basis_threshold() == 20000);
  set_up(reference_mesh, reference, reference.single_precision_basis_threshold());
  const Eigen::MatrixXd in_double = bend(reference_mesh, reference);
  CHECK_FALSE(reference.preprocess_report().single_precision_basis); // 16 × 3 bar: below the threshold

  Surface_mesh mesh = to_mesh<Surface_mesh>(soup);
  Spectral single(mesh);
  set_up(mesh, single, 0);
  const Eigen::MatrixXd in_float = bend(mesh, single);
  REQUIRE(single.preprocess_report().single_precision_basis);
  // Everything is derived from the stored values: the rounding of the basis
  // barely moves the result (a float copy read by the iteration only, whose
  // reduced matrices come from the double basis, moves it by 1e-4).
  const double deviation = (in_float - in_double).rowwise().norm().maxCoeff() / diagonal;
  CHECK(deviation > 0.0);
  CHECK(deviation < 1e-5);

  // A rigid motion of every control vertex moves the whole bar rigidly.
  const internal::Deformation::Rigid_motion turn = motion(pi / 5, Eigen::Vector3d(0.3, 1, 0.2).normalized(),
                                                          Eigen::Vector3d(0.4, -0.2, 0.7));
  single.reset();
  for(const std::vector<SM_vertex>* end : {&bottom, &top})
    for(SM_vertex v : *end)
    {
      const Eigen::RowVector3d p = turn.apply(before.row(v.idx()));
      single.set_target_position(v, Point(p[0], p[1], p[2]));
    }
  single.deform(2000, 1e-13);
  INFO("iterations " << single.deform_report().iterations);
  CHECK((positions_of(mesh) - moved_rigidly(before, turn)).rowwise().norm().maxCoeff() / diagonal < 1e-6);

  // Saved widened to double and loaded, the basis gives the same deformation,
  // kept in float or in double.
  std::ostringstream out;
  single.save_basis(out);
  for(const std::size_t threshold : {std::size_t(0), std::numeric_limits<std::size_t>::max()})
  {
    Surface_mesh copy = to_mesh<Surface_mesh>(soup);
    Spectral loaded(copy);
    set_up(copy, loaded, threshold);
    std::istringstream in(out.str());
    loaded.load_basis(in);
    const Eigen::MatrixXd result = bend(copy, loaded);
    CHECK_FALSE(loaded.preprocess_report().basis_computed);
    CHECK(loaded.preprocess_report().single_precision_basis == (threshold == 0));
    CHECK((result - in_float).rowwise().norm().maxCoeff() / diagonal < 1e-12);
  }
}

// The default traits under other names: the same numerics, which the
// compiled core does not hold, so that these deformations compile their
// pipelines from the headers.
struct Headers_partition_of_unity_traits : CGAL::Partition_of_unity_eigensolver_traits<>
{
};
struct Headers_block_lanczos_traits : CGAL::Block_lanczos_eigensolver_traits<>
{
};
struct Headers_sparse_solver_traits : CGAL::Default_sparse_spd_solver_traits
{
};

template <CGAL::Spectral_deformation_algorithm_tag TAG, class ET = CGAL::Default, class ST = CGAL::Default>
using Deformation_of = CGAL::Spectral_surface_mesh_deformation<Surface_mesh, CGAL::Default, CGAL::Default, TAG, ET, ST>;
template <CGAL::Spectral_deformation_algorithm_tag TAG, class ET = CGAL::Default, class ST = CGAL::Default>
constexpr bool compiled_pipeline = internal::Deformation::Deformation_class_types<
    Surface_mesh, CGAL::Default, CGAL::Default, TAG, ET, ST, CGAL::Default>::Selector::compiled;

TEST_CASE("the compiled core gives the results of the pipelines compiled from the headers", "[deformation][core]")
{
  // This program links the compiled core of its configuration (the CMake
  // target SSMD::Parallel does), so the default traits run it.
  STATIC_REQUIRE(CGAL_SSMD_USES_COMPILED_CORE);
  typedef Deformation_of<CGAL::SPECTRAL_DUAL_LAPLACIAN> Iterated_core;
  typedef Deformation_of<CGAL::SPECTRAL_DUAL_LAPLACIAN, Headers_partition_of_unity_traits> Iterated_headers;
  typedef Deformation_of<CGAL::SPECTRAL_DUAL_LAPLACIAN, CGAL::Block_lanczos_eigensolver_traits<>> Exact_core;
  typedef Deformation_of<CGAL::SPECTRAL_DUAL_LAPLACIAN, Headers_block_lanczos_traits> Exact_headers;
  typedef Deformation_of<CGAL::SPECTRAL_LINEAR> Linear_core;
  typedef Deformation_of<CGAL::SPECTRAL_LINEAR, Headers_partition_of_unity_traits> Linear_headers;
  typedef Deformation_of<CGAL::SPATIAL_DUAL_LAPLACIAN> Spatial_core;
  typedef Deformation_of<CGAL::SPATIAL_DUAL_LAPLACIAN, CGAL::Default, Headers_sparse_solver_traits> Spatial_headers;
  STATIC_REQUIRE(compiled_pipeline<CGAL::SPECTRAL_DUAL_LAPLACIAN>);
  STATIC_REQUIRE(compiled_pipeline<CGAL::SPECTRAL_DUAL_LAPLACIAN, CGAL::Block_lanczos_eigensolver_traits<>>);
  STATIC_REQUIRE(compiled_pipeline<CGAL::SPECTRAL_LINEAR>);
  STATIC_REQUIRE(compiled_pipeline<CGAL::SPATIAL_DUAL_LAPLACIAN>);
  STATIC_REQUIRE(!compiled_pipeline<CGAL::SPECTRAL_DUAL_LAPLACIAN, Headers_partition_of_unity_traits>);
  STATIC_REQUIRE(!compiled_pipeline<CGAL::SPECTRAL_DUAL_LAPLACIAN, Headers_block_lanczos_traits>);
  STATIC_REQUIRE(!compiled_pipeline<CGAL::SPECTRAL_LINEAR, Headers_partition_of_unity_traits>);
  STATIC_REQUIRE(!compiled_pipeline<CGAL::SPATIAL_DUAL_LAPLACIAN, CGAL::Default, Headers_sparse_solver_traits>);

  const Soup soup = bar(12, 2);
  const internal::Deformation::Rigid_motion still;
  const internal::Deformation::Rigid_motion bend = motion(pi / 2, Eigen::Vector3d::UnitY(), Eigen::Vector3d(0, 0, 5.0));
  for(const CGAL::Spectral_constraint_policy policy : {CGAL::EXACT_CONSTRAINTS, CGAL::SOFT_CONSTRAINTS})
  {
    const Run core = deform_bar<Iterated_core>(soup, still, bend, 10, 0.0, 40, policy);
    const Run headers = deform_bar<Iterated_headers>(soup, still, bend, 10, 0.0, 40, policy);
    CHECK((core.after - core.before).cwiseAbs().maxCoeff() > 0.1);
    CHECK((core.after - headers.after).cwiseAbs().maxCoeff() == 0.0);
  }
  {
    const Run core = deform_bar<Exact_core>(soup, still, bend, 10, 0.0, 40);
    const Run headers = deform_bar<Exact_headers>(soup, still, bend, 10, 0.0, 40);
    CHECK((core.after - headers.after).cwiseAbs().maxCoeff() == 0.0);
  }
  {
    const Run core = deform_bar<Linear_core>(soup, still, bend, 1, 0.0, 40);
    const Run headers = deform_bar<Linear_headers>(soup, still, bend, 1, 0.0, 40);
    CHECK((core.after - headers.after).cwiseAbs().maxCoeff() == 0.0);
  }
  {
    const Run core = deform_bar<Spatial_core>(soup, still, bend, 10, 0.0);
    const Run headers = deform_bar<Spatial_headers>(soup, still, bend, 10, 0.0);
    CHECK((core.after - core.before).cwiseAbs().maxCoeff() > 0.1);
    CHECK((core.after - headers.after).cwiseAbs().maxCoeff() == 0.0);
  }
}

TEST_CASE("Surface_mesh and Polyhedron_3 give the same deformation", "[deformation]")
{
  const Soup soup = bar(12, 2);
  const internal::Deformation::Rigid_motion still;
  const internal::Deformation::Rigid_motion bend = motion(pi / 3, Eigen::Vector3d::UnitY(), Eigen::Vector3d(0, 0, 5.0));
  const Run a = deform_bar<Spectral>(soup, still, bend, 10, 0.0, 40);
  const Run b = deform_bar<CGAL::Spectral_surface_mesh_deformation<Polyhedron>, Polyhedron>(
      soup, still, bend, 10, 0.0, 40);
  CHECK((a.after - b.after).cwiseAbs().maxCoeff() == 0.0);
}

TEST_CASE("basis cache: saved, loaded, handed in, refused when stale", "[deformation][io]")
{
  const Soup soup = bar(12, 2);
  Surface_mesh mesh = to_mesh<Surface_mesh>(soup);
  auto all = vertex_list(mesh);
  std::string bytes;
  {
    Spectral deformation(mesh);
    deformation.insert_roi_vertices(all.begin(), all.end());
    deformation.insert_control_vertex(all.front());
    deformation.set_number_of_frequencies(30);
    REQUIRE(deformation.preprocess());
    CHECK(deformation.preprocess_report().basis_computed);
    std::ostringstream out;
    deformation.save_basis(out);
    bytes = out.str();
  }
  {
    Spectral deformation(mesh);
    deformation.insert_roi_vertices(all.begin(), all.end());
    deformation.insert_control_vertex(all.front());
    std::istringstream in(bytes);
    deformation.load_basis(in);
    REQUIRE(deformation.preprocess());
    CHECK_FALSE(deformation.preprocess_report().basis_computed);
    CHECK(deformation.preprocess_report().number_of_frequencies == 30);
  }
  {
    Spectral deformation(mesh);
    deformation.insert_roi_vertices(all.begin(), all.end());
    deformation.insert_control_vertex(all.front());
    deformation.set_basis(CGAL::Manifold_harmonics_basis<Surface_mesh>(mesh, 25));
    REQUIRE(deformation.preprocess());
    CHECK_FALSE(deformation.preprocess_report().basis_computed);
    CHECK(deformation.preprocess_report().number_of_frequencies == 25);
  }
  {
    // A region that is not the whole mesh: the cached basis does not fit.
    Spectral deformation(mesh);
    deformation.insert_roi_vertices(all.begin(), all.begin() + 40);
    deformation.insert_control_vertex(all.front());
    std::istringstream in(bytes);
    CHECK_THROWS_AS(deformation.load_basis(in), CGAL::Spectral_deformation_error);
    std::string corrupted = bytes;
    corrupted[corrupted.size() / 2] ^= 0x20;
    std::istringstream bad(corrupted);
    CHECK_THROWS_AS(deformation.load_basis(bad), CGAL::Spectral_deformation_error);
    CHECK(deformation.preprocess());
    CHECK(deformation.preprocess_report().basis_computed);
  }
}

TEST_CASE("the region numbers its vertices along the surface, a basis in the mesh's order is reordered",
          "[deformation][io]")
{
  // Loop subdivision appends the new vertices: neighbours get distant indices.
  Surface_mesh mesh = to_mesh<Surface_mesh>(icosphere(2));
  CGAL::Subdivision_method_3::Loop_subdivision(mesh, CGAL::parameters::number_of_iterations(2));
  const auto index_map = get(CGAL::vertex_index, mesh);
  const auto id = [&index_map](SM_vertex v) { return static_cast<std::size_t>(get(index_map, v)); };
  const std::size_t n = num_vertices(mesh);
  std::vector<Point> rest(n);
  for(SM_vertex v : vertices(mesh))
    rest[id(v)] = mesh.point(v);
  const auto region = internal::Mesh::extract_region(mesh, id, std::vector<char>(n, 1), rest);

  // A permutation of the vertices, with their positions.
  REQUIRE(region.vertices.size() == n);
  std::vector<char> seen(n, 0);
  for(std::size_t r = 0; r < n; ++r)
  {
    const std::size_t i = id(region.vertices[r]);
    CHECK(region.local[i] == static_cast<int>(r));
    seen[i] = 1;
    const Point& p = mesh.point(region.vertices[r]);
    CHECK(region.arrays.positions.row(static_cast<Eigen::Index>(r)) ==
          Eigen::RowVector3d(p.x(), p.y(), p.z()));
  }
  CHECK(std::count(seen.begin(), seen.end(), 1) == static_cast<std::ptrdiff_t>(n));

  // The same oriented faces, each as the mesh's vertices from the lowest index on.
  auto canonical = [](std::array<std::size_t, 3> t) {
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    return t;
  };
  std::set<std::array<std::size_t, 3>> mesh_faces, region_faces;
  for(auto f : faces(mesh))
  {
    std::array<std::size_t, 3> t;
    int k = 0;
    for(SM_vertex v : CGAL::vertices_around_face(halfedge(f, mesh), mesh))
      t[static_cast<std::size_t>(k++)] = id(v);
    mesh_faces.insert(canonical(t));
  }
  for(Eigen::Index f = 0; f < region.arrays.triangles.rows(); ++f)
  {
    std::array<std::size_t, 3> t;
    for(int k = 0; k < 3; ++k)
      t[static_cast<std::size_t>(k)] = id(region.vertices[static_cast<std::size_t>(region.arrays.triangles(f, k))]);
    region_faces.insert(canonical(t));
  }
  CHECK(region_faces == mesh_faces);

  // Neighbours are much closer in the region's numbering than in the mesh's.
  double mesh_gap = 0, region_gap = 0;
  for(auto e : edges(mesh))
  {
    const std::size_t a = id(source(e, mesh)), b = id(target(e, mesh));
    mesh_gap += std::abs(double(a) - double(b));
    region_gap += std::abs(double(region.local[a]) - double(region.local[b]));
  }
  CHECK(region_gap < 0.25 * mesh_gap);

  // A basis of the whole mesh is in the mesh's order: recognised, and its
  // rows moved to the region's vertices, where it solves the eigenproblem.
  const CGAL::Manifold_harmonics_basis<Surface_mesh> whole(mesh, 12);
  namespace Basis = internal::Basis;
  const std::uint64_t region_fingerprint = internal::Mesh::fingerprint(region.arrays);
  const Basis::Basis_match match = Basis::basis_match(whole.data(), region, region_fingerprint);
  REQUIRE(match == Basis::Basis_match::MESH_ORDER);
  const Basis::Basis_data reordered = Basis::in_region_order(whole.data(), region, match, region_fingerprint);
  CHECK(Basis::basis_match(reordered, region, region_fingerprint) == Basis::Basis_match::REGION_ORDER);
  const Eigen::SparseMatrix<double> Q = internal::cotangent_stiffness(region.arrays);
  const Eigen::VectorXd mass = internal::lumped_mass(region.arrays);
  auto residual = [&](const Basis::Basis_data& b) {
    const Eigen::MatrixXd QH = Q * b.basis;
    return (QH - mass.asDiagonal() * b.basis * b.eigenvalues.asDiagonal()).norm() / QH.norm();
  };
  CHECK((reordered.mass - mass).cwiseAbs().maxCoeff() < 1e-12 * mass.maxCoeff());
  CHECK(residual(reordered) < 1e-4);
  CHECK(residual(whole.data()) > 1e-2); // the rows in the mesh's order do not fit

  // A basis file in the mesh's order (a whole-mesh basis, or a file written
  // by version 0.1) is accepted by load_basis().
  std::ostringstream out;
  whole.save(out);
  Spectral deformation(mesh);
  auto all = vertex_list(mesh);
  deformation.insert_roi_vertices(all.begin(), all.end());
  deformation.insert_control_vertex(all.front());
  std::istringstream in(out.str());
  deformation.load_basis(in);
  REQUIRE(deformation.preprocess());
  CHECK_FALSE(deformation.preprocess_report().basis_computed);
  CHECK(deformation.preprocess_report().number_of_frequencies == 12);
}

TEST_CASE("clear failures leave the mesh untouched", "[deformation][errors]")
{
  Surface_mesh mesh = to_mesh<Surface_mesh>(bar(10, 2));
  const Eigen::MatrixXd before = positions_of(mesh);
  auto all = vertex_list(mesh);
  SECTION("empty ROI")
  {
    Spectral deformation(mesh);
    CHECK_FALSE(deformation.preprocess());
    CHECK(deformation.preprocess_report().message.find("empty") != std::string::npos);
    deformation.deform();
    CHECK_FALSE(deformation.deform_report().success);
    CHECK_FALSE(deformation.deform_report().message.empty());
  }
  SECTION("whole mesh without a control vertex")
  {
    Spectral deformation(mesh);
    deformation.insert_roi_vertices(all.begin(), all.end());
    CHECK_FALSE(deformation.preprocess());
    CHECK(deformation.preprocess_report().message.find("constraint") != std::string::npos);
  }
  SECTION("non-finite target")
  {
    Spectral deformation(mesh);
    deformation.insert_roi_vertices(all.begin(), all.end());
    deformation.insert_control_vertex(all.front());
    const Point before_target = deformation.target_position(all.front());
    CHECK_THROWS_AS(deformation.set_target_position(all.front(), Point(std::nan(""), 0, 0)),
                    CGAL::Spectral_deformation_error);
    CHECK_THROWS_AS(deformation.translate(all.front(), Eigen::Vector3d(INFINITY, 0, 0)),
                    CGAL::Spectral_deformation_error);
    CHECK(deformation.target_position(all.front()) == before_target);
  }
  SECTION("degenerate face in the region")
  {
    Surface_mesh broken = mesh;
    const auto f = *broken.faces().begin();
    auto h = broken.halfedge(f);
    broken.point(broken.target(h)) = broken.point(broken.source(h));
    const Eigen::MatrixXd broken_before = positions_of(broken);
    Spectral deformation(broken);
    auto vs = vertex_list(broken);
    deformation.insert_roi_vertices(vs.begin(), vs.end());
    deformation.insert_control_vertex(vs.back());
    CHECK_FALSE(deformation.preprocess());
    CHECK(deformation.preprocess_report().message.find("degenerate") != std::string::npos);
    deformation.deform();
    CHECK(positions_of(broken) == broken_before);
  }
  SECTION("a component without constraint")
  {
    Surface_mesh spheres = to_mesh<Surface_mesh>(two_spheres(1));
    Spectral deformation(spheres);
    auto vs = vertex_list(spheres);
    deformation.insert_roi_vertices(vs.begin(), vs.end());
    deformation.insert_control_vertex(vs.front());
    CHECK_FALSE(deformation.preprocess());
    CHECK(deformation.preprocess_report().message.find("connected") != std::string::npos);
  }
  CHECK(positions_of(mesh) == before);
}

TEST_CASE("Botsch-Sorkine cactus and plane: residuals and ROI border of both policies",
          "[deformation][botsch08]")
{
  const std::string dir = SSMD_BOTSCH08_DIR;
  for(const std::string name : {"cactus", "plane"})
  {
    Surface_mesh mesh;
    if(!CGAL::IO::read_polygon_mesh(dir + "/" + name + ".off", mesh))
    {
      WARN("the Botsch-Sorkine benchmark is not available in " << dir << ": case skipped");
      return;
    }
    const auto status = CGAL::IO::read_selection(dir + "/" + name + ".sel", mesh.number_of_vertices());
    const Eigen::Matrix4d handle = CGAL::IO::read_handle_transformation(dir + "/" + name + ".def");
    const Eigen::MatrixXd before = positions_of(mesh);
    double exact_seam = 0;
    for(auto policy : {CGAL::EXACT_CONSTRAINTS, CGAL::SOFT_CONSTRAINTS})
    {
      Surface_mesh copy = mesh;
      Spectral deformation(copy);
      for(auto v : copy.vertices())
        if(status[v.idx()] != CGAL::IO::FIXED_VERTEX)
          deformation.insert_roi_vertex(v);
      for(auto v : copy.vertices())
        if(status[v.idx()] == CGAL::IO::HANDLE_VERTEX)
        {
          deformation.insert_control_vertex(v);
          const Eigen::Vector4d q = handle * Eigen::Vector4d(before(v.idx(), 0), before(v.idx(), 1),
                                                             before(v.idx(), 2), 1.0);
          deformation.set_target_position(v, Point(q[0], q[1], q[2]));
        }
      deformation.set_constraint_policy(policy);
      deformation.deform();
      const CGAL::Spectral_deformation_report& report = deformation.deform_report();
      INFO(name << ", policy " << policy << ": " << report.message);
      REQUIRE(report.success);
      INFO("largest residual " << report.max_control_residual);
      if(policy == CGAL::EXACT_CONSTRAINTS)
        CHECK(report.max_control_residual == 0.0);
      else
      {
        // The handle of the plane is lifted far from its anchored border: the
        // soft constraints of the smooth mesh lag behind more there.
        CHECK(report.max_control_residual > 0.0);
        CHECK(report.max_control_residual < (name == "cactus" ? 2e-3 : 2e-2));
      }
      const Eigen::MatrixXd after = positions_of(copy);
      double seam = 0;
      for(auto e : copy.edges())
      {
        const auto a = copy.vertex(e, 0), b = copy.vertex(e, 1);
        if(deformation.is_roi_vertex(a) == deformation.is_roi_vertex(b))
          continue;
        const double rest_length = (before.row(a.idx()) - before.row(b.idx())).norm();
        seam = std::max(seam, std::abs((after.row(a.idx()) - after.row(b.idx())).norm() - rest_length) /
                                  rest_length);
      }
      INFO("largest relative length change of an edge across the ROI border " << seam);
      if(policy == CGAL::EXACT_CONSTRAINTS)
        exact_seam = seam;
      else
        // Anchored like the exact policy: no seam. The soft constraints leave
        // the smooth mesh freer near the border, whose ring then bends a
        // little more (plane: 11.7 % against 8.7 % with the sum of the
        // energies); a seam tears the ring far beyond that.
        CHECK(seam < 1.5 * exact_seam + 0.01);
      for(auto v : copy.vertices())
        if(status[v.idx()] == CGAL::IO::FIXED_VERTEX)
          CHECK(after.row(v.idx()) == before.row(v.idx()));
      CHECK(internal::Deformation::arap_energy(internal::Mesh::extract_triangle_arrays(mesh, CGAL::parameters::default_values()),
                                  after) < 0.05);
    }
  }
}

// Rotation patches

namespace {

// The bar of test_meshes, ends fixed (z < 0.3) and moved (z > 4.7) by
// `top_motion` (a rotation about `axis` through `center`), deformed with
// `patches` rotation patches (0: the full iteration), or with the patches of
// `patches_before` first, changed to `patches` once the deformation is
// preprocessed.
Eigen::MatrixXd bend_bar_with_patches(std::size_t patches, const Eigen::Matrix3d& top_rotation,
                           const Eigen::Vector3d& center, unsigned int iterations = 10,
                           std::vector<std::size_t> patches_before = {})
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
  if(patches_before.empty())
    deformation.set_rotation_patches(patches);
  else
  {
    deformation.set_rotation_patches(patches_before.front());
    REQUIRE(deformation.preprocess());
    for(std::size_t count : patches_before)
      deformation.set_rotation_patches(count);
    deformation.set_rotation_patches(patches);
  }
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

namespace {

// Two spheres apart, their dual mesh and face centroids: the surface the
// rotation patches are grouped on.
struct Two_spheres_dual
{
  const internal::Mesh::Triangle_arrays arrays = internal::Mesh::extract_triangle_arrays(
      to_mesh<Surface_mesh>(two_spheres(3)), CGAL::parameters::default_values());
  const internal::Mesh::Dual_mesh_operator dual{arrays.triangles, arrays.number_of_vertices()};
  const internal::Mesh::Positions centroids = dual.centroids(arrays.positions);
};

} // namespace

TEST_CASE("rotation patches are connected, cover every dual vertex, one surface each", "[patches]")
{
  const Two_spheres_dual spheres;
  const internal::Mesh::Dual_mesh_operator& dual = spheres.dual;
  const internal::Mesh::Positions& centroids = spheres.centroids;
  const std::vector<int>& row_faces = dual.row_faces();
  for(std::size_t count : {1, 7, 40, 300})
  {
    const std::vector<int> patch = internal::Deformation::cluster_dual_rows(dual, centroids, count);
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

TEST_CASE("the dual rows and the vertices are grouped from one grouping of the faces", "[patches]")
{
  namespace D = internal::Deformation;
  const Two_spheres_dual spheres;
  const internal::Mesh::Triangle_arrays& arrays = spheres.arrays;
  const internal::Mesh::Dual_mesh_operator& dual = spheres.dual;
  const internal::Mesh::Positions& centroids = spheres.centroids;
  const std::vector<int>& row_faces = dual.row_faces();
  const Eigen::Index n = arrays.number_of_vertices();
  for(std::size_t count : {1, 7, 40, 300})
  {
    INFO(count << " patches requested");
    // Either order of the two groupings, and a fresh grouping for each, agree.
    const D::Face_patches rows_first(dual, centroids, count), vertices_first(dual, centroids, count);
    const std::vector<int> row_patch = D::cluster_dual_rows(rows_first);
    const std::vector<int> vertex_patch = D::cluster_vertices(rows_first, n);
    CHECK(D::cluster_vertices(vertices_first, n) == vertex_patch);
    CHECK(D::cluster_dual_rows(vertices_first) == row_patch);
    CHECK(D::cluster_dual_rows(dual, centroids, count) == row_patch);
    CHECK(D::cluster_vertices(dual, centroids, n, count) == vertex_patch);
    // Both are renumberings of the faces' patches: a row takes the patch of
    // its face, a vertex the patch of one of its faces.
    const std::vector<int>& face_patch = rows_first.of_face();
    std::map<int, int> row_id;
    for(std::size_t r = 0; r < row_faces.size(); ++r)
    {
      const auto inserted = row_id.emplace(face_patch[static_cast<std::size_t>(row_faces[r])], row_patch[r]);
      CHECK(inserted.first->second == row_patch[r]);
    }
    std::set<int> row_ids;
    for(const auto& entry : row_id)
      row_ids.insert(entry.second);
    CHECK(row_ids.size() == row_id.size()); // one row patch per patch of faces
    // A vertex takes the patch of the last face that holds it.
    std::vector<int> last_face_patch(static_cast<std::size_t>(n), -1);
    for(Eigen::Index f = 0; f < arrays.triangles.rows(); ++f)
      for(int k = 0; k < 3; ++k)
        last_face_patch[static_cast<std::size_t>(arrays.triangles(f, k))] = face_patch[static_cast<std::size_t>(f)];
    std::map<int, int> vertex_id;
    for(Eigen::Index v = 0; v < n; ++v)
    {
      const auto inserted = vertex_id.emplace(last_face_patch[static_cast<std::size_t>(v)],
                                              vertex_patch[static_cast<std::size_t>(v)]);
      CHECK(inserted.first->second == vertex_patch[static_cast<std::size_t>(v)]);
    }
    std::set<int> vertex_ids;
    for(const auto& entry : vertex_id)
      vertex_ids.insert(entry.second);
    CHECK(vertex_ids.size() == vertex_id.size()); // one vertex patch per patch of faces
  }
}

TEST_CASE("farthest point sampling by cells takes the points of the plain loop over all points", "[patches]")
{
  typedef internal::Deformation::Farthest_point_sampler Sampler;
  // The definition: each point taken is the first of the farthest from
  // those taken so far, until the farthest is at distance 0.
  auto plain = [](const Sampler::Points& points, std::size_t count) {
    std::vector<double> distance(static_cast<std::size_t>(points.rows()), std::numeric_limits<double>::infinity());
    std::vector<int> taken;
    int next = 0;
    while(taken.size() < count && points.rows() > 0)
    {
      taken.push_back(next);
      const Eigen::RowVector3d p = points.row(next);
      double farthest = -1;
      for(Eigen::Index i = 0; i < points.rows(); ++i)
      {
        double& d = distance[static_cast<std::size_t>(i)];
        d = (std::min)(d, (points.row(i) - p).squaredNorm());
        if(d > farthest)
        {
          farthest = d;
          next = static_cast<int>(i);
        }
      }
      if(!(farthest > 0))
        break;
    }
    return taken;
  };
  std::mt19937 random(7);
  std::uniform_real_distribution<double> uniform(-1, 1);
  std::vector<std::pair<std::string, Sampler::Points>> sets;
  auto make = [&](const std::string& name, Eigen::Index n, auto&& point) {
    Sampler::Points points(n, 3);
    for(Eigen::Index i = 0; i < n; ++i)
      points.row(i) = point(i);
    sets.emplace_back(name, points);
  };
  make("a cube of random points", 3000, [&](Eigen::Index) { return Eigen::RowVector3d(uniform(random), uniform(random), uniform(random)); });
  make("a sphere", 4000, [&](Eigen::Index) { return Eigen::RowVector3d(uniform(random), uniform(random), uniform(random)).normalized().eval(); });
  make("a flat grid with ties", 2500, [&](Eigen::Index i) { return Eigen::RowVector3d(double(i % 50), double(i / 50), 0.0); });
  make("a line", 1000, [&](Eigen::Index i) { return Eigen::RowVector3d(1e-3 * double(i), 0.0, 0.0); });
  make("far apart scales", 2000, [&](Eigen::Index i) {
    return Eigen::RowVector3d(i < 1000 ? 1e-6 * uniform(random) : 1e3 + uniform(random), uniform(random), 0.0);
  });
  make("repeated points", 600, [&](Eigen::Index i) { return Eigen::RowVector3d(double(i % 3), 0.0, double(i % 2)); });
  make("one point many times", 50, [&](Eigen::Index) { return Eigen::RowVector3d(0.5, 0.5, 0.5); });
  for(const auto& [name, points] : sets)
    for(std::size_t count : {1, 2, 17, 300, 5000})
    {
      INFO(name << ", " << count << " points asked for");
      CHECK(Sampler(points).sample(count) == plain(points, count));
    }
  CHECK(Sampler(Sampler::Points(0, 3)).sample(10).empty());
}

TEST_CASE("rotation patches grow by distance along the surface, not by the number of faces", "[patches]")
{
  // A strip of one row of cells, square ones on its left half and eight
  // times wider ones on its right half: grown from one face at each end, the
  // two patches meet near half-way along the surface (x = 0.46, the paths
  // between the centroids of the square cells zigzag), not half-way in
  // faces, which would put the border at x = 0.28, deep in the fine half.
  Soup soup;
  std::vector<double> xs;
  for(int i = 0; i < 40; ++i)
    xs.push_back(0.5 * i / 40);
  for(int i = 0; i <= 5; ++i)
    xs.push_back(0.5 + 0.5 * i / 5);
  const int rows = 1, columns = static_cast<int>(xs.size());
  for(int j = 0; j <= rows; ++j)
    for(double x : xs)
      soup.points.emplace_back(x, 0.0125 * j, 0);
  auto id = [&](int i, int j) { return std::size_t(j * columns + i); };
  for(int j = 0; j < rows; ++j)
    for(int i = 0; i + 1 < columns; ++i)
    {
      soup.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      soup.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  const internal::Mesh::Triangle_arrays arrays =
      internal::Mesh::extract_triangle_arrays(to_mesh<Surface_mesh>(soup), CGAL::parameters::default_values());
  const internal::Mesh::Dual_mesh_operator dual(arrays.triangles, arrays.number_of_vertices());
  const internal::Mesh::Positions centroids = dual.centroids(arrays.positions);
  auto nearest_face = [&](double x, double y) {
    Eigen::Index best = 0;
    (centroids.rowwise() - Eigen::RowVector3d(x, y, 0)).rowwise().squaredNorm().minCoeff(&best);
    return static_cast<int>(best);
  };
  const std::vector<int> seeds{nearest_face(0, 0), nearest_face(1, 0)};
  std::vector<int> patch_of_face;
  REQUIRE(internal::Deformation::grow_patches(dual, centroids, seeds, patch_of_face) == 2);
  for(Eigen::Index f = 0; f < centroids.rows(); ++f)
  {
    INFO("face centroid x = " << centroids(f, 0));
    if(centroids(f, 0) < 0.4)
      CHECK(patch_of_face[static_cast<std::size_t>(f)] == 0);
    if(centroids(f, 0) > 0.55)
      CHECK(patch_of_face[static_cast<std::size_t>(f)] == 1);
  }
}

TEST_CASE("more patches approach the full iteration, and under four faces per patch the region is iterated in full",
          "[deformation][patches]")
{
  const Eigen::Matrix3d bend = Eigen::AngleAxisd(pi / 3, Eigen::Vector3d::UnitX()).toRotationMatrix();
  const Eigen::Vector3d center(0, 0, 5.0);
  const Eigen::MatrixXd full = bend_bar_with_patches(0, bend, center);
  const Eigen::MatrixXd rest = bend_bar_with_patches(0, Eigen::Matrix3d::Identity(), center, 1);
  const double diagonal = diagonal_of(rest);

  // The bar has about 600 faces: 128 patches keep more than four faces each.
  double previous = std::numeric_limits<double>::infinity();
  for(std::size_t patches : {8, 32, 128})
  {
    const Eigen::MatrixXd result = bend_bar_with_patches(patches, bend, center);
    const double distance = (result - full).rowwise().norm().maxCoeff() / diagonal;
    INFO(patches << " patches: largest distance to the full iteration " << distance);
    CHECK(distance < previous);
    previous = distance;
  }
  CHECK(previous < 1e-2);
  CHECK(previous > 1e-6);

  for(std::size_t patches : {1000, 1000000})
  {
    const Eigen::MatrixXd result = bend_bar_with_patches(patches, bend, center);
    const double distance = (result - full).rowwise().norm().maxCoeff() / diagonal;
    INFO(patches << " patches on about 600 faces: largest distance to the full iteration " << distance);
    CHECK(distance < 1e-12);
  }
}

TEST_CASE("rotation patches changed after preprocess() give the deformation made with them", "[deformation][patches]")
{
  // The patches release the rest coordinates of the dual Laplacian energy,
  // which the full iteration and new patches make again.
  const Eigen::Matrix3d bend = Eigen::AngleAxisd(1.0, Eigen::Vector3d::UnitX()).toRotationMatrix();
  const Eigen::Vector3d center(0, 0, 5.0);
  const Eigen::MatrixXd full = bend_bar_with_patches(0, bend, center);
  const Eigen::MatrixXd patched = bend_bar_with_patches(30, bend, center);
  REQUIRE((full - patched).cwiseAbs().maxCoeff() > 1e-6); // the two iterations differ
  CHECK((bend_bar_with_patches(0, bend, center, 10, {30}) - full).cwiseAbs().maxCoeff() < 1e-12);
  CHECK((bend_bar_with_patches(30, bend, center, 10, {30, 0}) - patched).cwiseAbs().maxCoeff() < 1e-12);
  CHECK((bend_bar_with_patches(30, bend, center, 10, {0, 20}) - patched).cwiseAbs().maxCoeff() < 1e-12);
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

TEST_CASE("constraint products: rigid parts from per-group moments equal the products with the smooth targets",
          "[deformation][constraints]")
{
  const Eigen::Index n = 60, m = 12;
  std::srand(7);
  const internal::Mesh::Positions rest = internal::Mesh::Positions::Random(n, 3) * 3.0;
  const internal::Mesh::Positions smooth = rest + 0.1 * internal::Mesh::Positions::Random(n, 3);
  internal::Deformation::Constraint_set set;
  set.constrained = {0, 1, 2, 3, 4, 10, 11, 12, 13, 20, 21, 22, 23, 24};
  set.number_of_fixed = 5;
  set.groups = {{0, 1, 2, 3, 4}, {5, 6, 7, 8}, {9, 10, 11, 12, 13}};
  Eigen::MatrixXd rows = Eigen::MatrixXd::Random(static_cast<Eigen::Index>(set.size()), m);
  internal::Deformation::Constraint_products products;
  products.initialize(set, rows, rest, smooth);

  const Eigen::Matrix3d turn = Eigen::AngleAxisd(1.1, Eigen::Vector3d(1, -2, 0.5).normalized()).toRotationMatrix();
  const Eigen::RowVector3d shift(0.3, -2.0, 1.5);
  internal::Mesh::Positions targets(static_cast<Eigen::Index>(set.size()), 3);
  for(std::size_t k = 0; k < set.size(); ++k)
  {
    const Eigen::RowVector3d v = rest.row(set.constrained[k]);
    if(k < 5) // the fixed ring keeps its rest positions
      targets.row(static_cast<Eigen::Index>(k)) = v;
    else if(k < 9) // a handle moved rigidly
      targets.row(static_cast<Eigen::Index>(k)) = v * turn.transpose() + shift;
    else // a handle stretched
      targets.row(static_cast<Eigen::Index>(k)) = v * (1.0 + 0.2 * double(k)) + shift;
  }
  const Eigen::MatrixXd expected =
      rows.transpose() * internal::Deformation::smooth_targets(set, rest, smooth, targets);
  const Eigen::MatrixXd computed = products.product(set, rows, targets);
  INFO("expected\n" << expected << "\ncomputed\n" << computed);
  CHECK((computed - expected).norm() <= 1e-12 * expected.norm());

  // The smooth motion of each group from the same moments equals the rigid
  // fit from its smooth rest positions to its rows times the coefficients.
  const Eigen::MatrixXd coefficients = Eigen::MatrixXd::Random(m, 3);
  for(std::size_t g = 0; g < set.groups.size(); ++g)
  {
    const std::vector<int>& group = set.groups[g];
    internal::Mesh::Positions from(static_cast<Eigen::Index>(group.size()), 3), to(from.rows(), 3);
    for(std::size_t k = 0; k < group.size(); ++k)
    {
      from.row(static_cast<Eigen::Index>(k)) = smooth.row(set.constrained[static_cast<std::size_t>(group[k])]);
      to.row(static_cast<Eigen::Index>(k)) = rows.row(group[k]) * coefficients;
    }
    const internal::Deformation::Rigid_motion fitted = internal::Deformation::fit_rigid_motion(from, to);
    const internal::Deformation::Rigid_motion from_moments = products.smooth_motion(g, coefficients);
    INFO("group " << g);
    CHECK((from_moments.rotation - fitted.rotation).norm() <= 1e-10);
    CHECK((from_moments.translation - fitted.translation).norm() <= 1e-10 * (1 + fitted.translation.norm()));
  }

  // Changing only the stretched handle's targets changes the product as the
  // direct one does.
  targets.row(10) += Eigen::RowVector3d(0.5, 0.25, -1.0);
  const Eigen::MatrixXd expected2 =
      rows.transpose() * internal::Deformation::smooth_targets(set, rest, smooth, targets);
  CHECK((products.product(set, rows, targets) - expected2).norm() <= 1e-12 * expected2.norm());
  CHECK((expected2 - expected).norm() > 1e-3 * expected.norm());
}

// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
// The as-rigid-as-possible refinement (refine()): an energy that never rises,
// its value checked against an independent evaluation, the rigid motion
// found from the rest shape, a converged state kept, the same optimum from
// the spectral and the spatial results and under both constraint policies,
// the volume kept on demand, and failures that leave the mesh unchanged.
#include "test_meshes.h"

#include <CGAL/Spectral_surface_mesh_deformation.h>
#include <CGAL/Spectral_deformation/arap_energy.h>
#include <CGAL/Surface_mesh_deformation.h>

#include <catch2/catch.hpp>

#include <Eigen/Geometry>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

using namespace test_meshes;
namespace internal = CGAL::Spectral_deformation::internal;
typedef boost::graph_traits<Surface_mesh>::vertex_descriptor SM_vertex;

namespace {

const double pi = 3.14159265358979323846;

Eigen::MatrixXd positions_of(const Surface_mesh& mesh)
{
  Eigen::MatrixXd x(mesh.number_of_vertices(), 3);
  for(auto v : mesh.vertices())
    x.row(v.idx()) << mesh.point(v).x(), mesh.point(v).y(), mesh.point(v).z();
  return x;
}

double diagonal_of(const Eigen::MatrixXd& x) { return (x.colwise().maxCoeff() - x.colwise().minCoeff()).norm(); }

double volume_of(const Surface_mesh& mesh)
{
  double volume = 0;
  for(auto f : mesh.faces())
  {
    auto h = mesh.halfedge(f);
    const Point &p = mesh.point(mesh.source(h)), &q = mesh.point(mesh.target(h)),
                &r = mesh.point(mesh.target(mesh.next(h)));
    volume += CGAL::scalar_product(p - CGAL::ORIGIN, CGAL::cross_product(q - CGAL::ORIGIN, r - CGAL::ORIGIN)) / 6;
  }
  return volume;
}

// The bar of test_meshes along z, every vertex in the ROI: the vertices below
// z = 0.3 fixed (control vertices left on their rest positions), those above
// 4.7 turned by `top` about `center`.
template <class Deformation>
std::vector<SM_vertex> set_up_bar(Deformation& deformation, Surface_mesh& mesh, const Eigen::Matrix3d& top,
                                  const Eigen::Vector3d& center)
{
  deformation.insert_roi_vertices(vertices(mesh).begin(), vertices(mesh).end());
  std::vector<SM_vertex> moved;
  for(auto v : vertices(mesh))
  {
    const double z = mesh.point(v).z();
    if(z < 0.3 || z > 4.7)
      deformation.insert_control_vertex(v);
    if(z > 4.7)
      moved.push_back(v);
  }
  for(SM_vertex v : moved)
  {
    const Point& p = mesh.point(v);
    const Eigen::Vector3d q = center + top * (Eigen::Vector3d(p.x(), p.y(), p.z()) - center);
    deformation.set_target_position(v, Point(q[0], q[1], q[2]));
  }
  return moved;
}

const Eigen::Matrix3d bend = Eigen::AngleAxisd(pi / 2, Eigen::Vector3d::UnitX()).toRotationMatrix();
const Eigen::Vector3d bend_center(0, 0, 5.0);

} // namespace

TEST_CASE("Refinement: the energy never rises, matches an independent evaluation, and the handles stay on target",
          "[refine]")
{
  for(CGAL::Spectral_constraint_policy policy : {CGAL::EXACT_CONSTRAINTS, CGAL::SOFT_CONSTRAINTS})
  {
    INFO("policy " << policy);
    Surface_mesh mesh = to_mesh<Surface_mesh>(bar(24, 3));
    const Surface_mesh rest = mesh;
    CGAL::Spectral_surface_mesh_deformation<Surface_mesh> deformation(mesh);
    const std::vector<SM_vertex> moved = set_up_bar(deformation, mesh, bend, bend_center);
    deformation.set_number_of_frequencies(40);
    deformation.set_constraint_policy(policy);
    deformation.deform(10, 0.0);
    REQUIRE(deformation.deform_report().success);

    REQUIRE(deformation.refine(40, 0.0));
    const CGAL::Spectral_refinement_report& report = deformation.refine_report();
    CHECK(report.iterations == 40);
    REQUIRE(report.energies.size() == 41);
    REQUIRE(report.seconds_at_iteration.size() == 41);
    for(std::size_t k = 1; k < report.energies.size(); ++k)
    {
      INFO("iteration " << k << ": " << report.energies[k - 1] << " -> " << report.energies[k]);
      CHECK(report.energies[k] <= report.energies[k - 1] * (1 + 1e-12));
      CHECK(report.seconds_at_iteration[k] >= report.seconds_at_iteration[k - 1]);
    }
    CHECK(report.energy_after < 0.9 * report.energy_before);
    CHECK(report.energy_after == report.energies.back());

    // The energy the report gives is the one arap_energy() measures (which
    // weighs with the absolute cotangent weights: the bar's are all positive).
    const internal::Mesh::Triangle_arrays rest_arrays =
        internal::Mesh::extract_triangle_arrays(rest, CGAL::parameters::default_values());
    CHECK(internal::Deformation::arap_energy(rest_arrays, positions_of(mesh)) ==
          Approx(report.energy_after).epsilon(1e-9));

    const double diagonal = diagonal_of(positions_of(rest));
    for(SM_vertex v : moved)
      CHECK(std::sqrt(CGAL::squared_distance(mesh.point(v), deformation.target_position(v))) < 1e-12 * diagonal);
    for(auto v : vertices(mesh))
      if(rest.point(v).z() < 0.3)
        CHECK(mesh.point(v) == rest.point(v));
  }
}

TEST_CASE("Refinement: from the rest shape, a rigid motion of every constraint gives the rigid image", "[refine]")
{
  Surface_mesh mesh = to_mesh<Surface_mesh>(icosphere(2));
  const Eigen::MatrixXd rest = positions_of(mesh);
  const Eigen::Matrix3d turn = Eigen::AngleAxisd(0.6, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  const Eigen::Vector3d shift(0.3, -0.2, 0.1);
  CGAL::Spectral_surface_mesh_deformation<Surface_mesh> deformation(mesh);
  deformation.insert_roi_vertices(vertices(mesh).begin(), vertices(mesh).end());
  for(auto v : vertices(mesh))
    if(mesh.point(v).z() > 0.7 || mesh.point(v).z() < -0.7)
    {
      deformation.insert_control_vertex(v);
      const Eigen::Vector3d q = turn * rest.row(v.idx()).transpose() + shift;
      deformation.set_target_position(v, Point(q[0], q[1], q[2]));
    }
  // No deform(): the iteration starts from the rest shape, as CGAL's does.
  REQUIRE(deformation.refine(2000, 1e-14));
  const CGAL::Spectral_refinement_report& report = deformation.refine_report();
  INFO(report.iterations << " iterations, energy " << report.energy_before << " -> " << report.energy_after);
  CHECK(report.energy_before > 1e-3);
  CHECK(report.energy_after < 1e-12);
  const Eigen::MatrixXd rigid = (rest * turn.transpose()).rowwise() + shift.transpose();
  CHECK((positions_of(mesh) - rigid).rowwise().norm().maxCoeff() < 1e-5 * diagonal_of(rest));
}

TEST_CASE("Refinement: a converged state does not move, and the spectral and spatial results reach the same optimum",
          "[refine]")
{
  Surface_mesh spectral_mesh = to_mesh<Surface_mesh>(bar(16, 2));
  Surface_mesh spatial_mesh = spectral_mesh;
  CGAL::Spectral_surface_mesh_deformation<Surface_mesh> spectral(spectral_mesh);
  CGAL::Spectral_surface_mesh_deformation<Surface_mesh, CGAL::Default, CGAL::Default, CGAL::SPATIAL_DUAL_LAPLACIAN>
      spatial(spatial_mesh);
  set_up_bar(spectral, spectral_mesh, bend, bend_center);
  set_up_bar(spatial, spatial_mesh, bend, bend_center);
  spectral.set_number_of_frequencies(30);
  spectral.deform(10, 0.0);
  spatial.deform(10, 0.0);
  REQUIRE(spectral.deform_report().success);
  REQUIRE(spatial.deform_report().success);
  const double diagonal = diagonal_of(positions_of(spectral_mesh));
  // The two algorithms give different shapes...
  CHECK((positions_of(spectral_mesh) - positions_of(spatial_mesh)).rowwise().norm().maxCoeff() > 1e-3 * diagonal);

  REQUIRE(spectral.refine(3000, 1e-13));
  REQUIRE(spatial.refine(3000, 1e-13));
  CHECK(spectral.refine_report().converged);
  CHECK(spatial.refine_report().converged);
  // ... that the refinement takes to one optimum.
  CHECK((positions_of(spectral_mesh) - positions_of(spatial_mesh)).rowwise().norm().maxCoeff() < 1e-4 * diagonal);
  CHECK(spectral.refine_report().energy_after == Approx(spatial.refine_report().energy_after).epsilon(1e-6));

  const Eigen::MatrixXd converged = positions_of(spectral_mesh);
  REQUIRE(spectral.refine(100, 0.0));
  CHECK((positions_of(spectral_mesh) - converged).rowwise().norm().maxCoeff() < 1e-6 * diagonal);
  CHECK(spectral.refine_report().energy_after == Approx(spectral.refine_report().energy_before).epsilon(1e-9));
}

TEST_CASE("Refinement: on a mesh with obtuse corners, the optimum of CGAL's ORIGINAL_ARAP", "[refine]")
{
  // A bar whose vertices are moved off their grid: some of its right-angled
  // corners become obtuse, opposite edges whose other corner is acute.
  // Clamping each corner's half of an edge's weight (CGAL) or their sum
  // differs there, and so do the optima.
  Soup soup = bar(16, 3);
  std::mt19937 generator(11);
  std::uniform_real_distribution<double> jitter(-0.05, 0.05);
  for(Point& p : soup.points)
    p = Point(p.x() + jitter(generator), p.y() + jitter(generator), p.z() + jitter(generator));
  Surface_mesh mesh = to_mesh<Surface_mesh>(soup);
  Surface_mesh arap_mesh = mesh;
  const internal::Mesh::Triangle_arrays arrays =
      internal::Mesh::extract_triangle_arrays(mesh, CGAL::parameters::default_values());
  std::size_t obtuse_corners = 0;
  const Eigen::SparseMatrix<double> acute = internal::cotangent_stiffness(arrays, false, &obtuse_corners);
  const Eigen::SparseMatrix<double> full = internal::cotangent_stiffness(arrays);
  std::size_t edges_weighed_differently = 0;
  for(Eigen::Index j = 0; j < full.outerSize(); ++j)
    for(Eigen::SparseMatrix<double>::InnerIterator it(full, j); it; ++it)
      if(it.row() < j && std::abs((std::min)(0.0, it.value()) - acute.coeff(it.row(), j)) > 1e-3 * std::abs(it.value()))
        ++edges_weighed_differently;
  REQUIRE(obtuse_corners > 20);
  REQUIRE(edges_weighed_differently > 20);

  const Eigen::Matrix3d turn = Eigen::AngleAxisd(pi / 3, Eigen::Vector3d::UnitX()).toRotationMatrix();
  CGAL::Surface_mesh_deformation<Surface_mesh, CGAL::Default, CGAL::Default, CGAL::ORIGINAL_ARAP> arap(arap_mesh);
  set_up_bar(arap, arap_mesh, turn, bend_center);
  REQUIRE(arap.preprocess());
  arap.deform(3000, 0.0);

  CGAL::Spectral_surface_mesh_deformation<Surface_mesh> deformation(mesh);
  set_up_bar(deformation, mesh, turn, bend_center);
  deformation.set_number_of_frequencies(30);
  deformation.deform();
  REQUIRE(deformation.deform_report().success);
  const double diagonal = diagonal_of(positions_of(arap_mesh));
  CHECK((positions_of(mesh) - positions_of(arap_mesh)).rowwise().norm().maxCoeff() > 1e-3 * diagonal);
  REQUIRE(deformation.refine(3000, 1e-13));
  CHECK(deformation.refine_report().converged);
  CHECK((positions_of(mesh) - positions_of(arap_mesh)).rowwise().norm().maxCoeff() < 1e-5 * diagonal);
}

TEST_CASE("Refinement: a twisted bar keeps its volume on demand, and loses some without", "[refine][volume]")
{
  const Eigen::Matrix3d twist = Eigen::AngleAxisd(2 * pi / 3, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  std::vector<double> volume_change;
  for(bool keep_volume : {false, true})
  {
    Surface_mesh mesh = to_mesh<Surface_mesh>(bar(30, 3, 0.5, 5.0));
    const double rest_volume = volume_of(mesh);
    CGAL::Spectral_surface_mesh_deformation<Surface_mesh> deformation(mesh);
    set_up_bar(deformation, mesh, twist, Eigen::Vector3d::Zero());
    deformation.set_number_of_frequencies(40);
    deformation.set_volume_preservation(keep_volume);
    deformation.deform(10, 0.0);
    REQUIRE(deformation.deform_report().success);
    REQUIRE(deformation.refine(300, 1e-7));
    CHECK(deformation.refine_report().volume_preserved == keep_volume);
    volume_change.push_back(volume_of(mesh) / rest_volume - 1);
    INFO("volume kept " << keep_volume << ": change " << volume_change.back() << ", energy "
                        << deformation.refine_report().energy_before << " -> "
                        << deformation.refine_report().energy_after);
    CHECK(deformation.refine_report().energy_after < deformation.refine_report().energy_before);
  }
  CHECK(volume_change[0] < -1e-3);
  CHECK(std::abs(volume_change[1]) < 1e-9);
}

TEST_CASE("Refinement: failures leave the mesh unchanged and say why", "[refine][robustness]")
{
  Surface_mesh mesh = to_mesh<Surface_mesh>(bar(12, 2));
  CGAL::Spectral_surface_mesh_deformation<Surface_mesh> deformation(mesh);
  CHECK_FALSE(deformation.refine());
  CHECK(deformation.refine_report().message.find("region of interest is empty") != std::string::npos);

  set_up_bar(deformation, mesh, bend, bend_center);
  deformation.set_number_of_frequencies(20);
  deformation.deform(5, 0.0);
  REQUIRE(deformation.deform_report().success);
  const Eigen::MatrixXd before = positions_of(mesh);
  for(double tolerance : {-1.0, std::numeric_limits<double>::quiet_NaN()})
  {
    CHECK_FALSE(deformation.refine(10, tolerance));
    CHECK(deformation.refine_report().message.find("tolerance") != std::string::npos);
    CHECK(positions_of(mesh) == before);
  }
  // No iteration: the control vertices are put on their targets, nothing else moves.
  REQUIRE(deformation.refine(0, 0.0));
  CHECK(deformation.refine_report().iterations == 0);
  CHECK(positions_of(mesh) == before);
}

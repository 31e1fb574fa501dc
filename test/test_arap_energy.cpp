// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
// The as-rigid-as-possible energy of the reduced iteration (ARAP_ENERGY):
// rest and rigid motions reproduced, one patch per vertex equal to the full
// iteration, the energy decreasing, and a twisted thin tube that keeps its
// section; large turns of the handles reached in stages.
#include "test_meshes.h"

#include <CGAL/Spectral_surface_mesh_deformation.h>
#include <CGAL/Spectral_deformation/internal/Deformation/Face_patches.h>
#include <CGAL/Spectral_deformation/internal/Deformation/Target_stages.h>
#include <CGAL/Spectral_deformation/arap_energy.h>

#include <catch2/catch.hpp>

#include <Eigen/Geometry>

#include <cmath>
#include <limits>
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
  Eigen::MatrixXd x(mesh.number_of_vertices(), 3);
  for(auto v : mesh.vertices())
    x.row(v.idx()) << mesh.point(v).x(), mesh.point(v).y(), mesh.point(v).z();
  return x;
}

double diagonal_of(const Eigen::MatrixXd& x) { return (x.colwise().maxCoeff() - x.colwise().minCoeff()).norm(); }

Eigen::Vector3d position(const Surface_mesh& mesh, SM_vertex v)
{
  const Point& p = mesh.point(v);
  return Eigen::Vector3d(p.x(), p.y(), p.z());
}

// Volume enclosed by a closed, outward-oriented mesh.
double volume_of(const Surface_mesh& mesh)
{
  double volume = 0;
  for(auto f : mesh.faces())
  {
    auto h = mesh.halfedge(f);
    const Eigen::Vector3d p = position(mesh, mesh.source(h)), q = position(mesh, mesh.target(h)),
                          r = position(mesh, mesh.target(mesh.next(h)));
    volume += p.dot(q.cross(r)) / 6.0;
  }
  return volume;
}

// The bar of test_meshes (radius `radius`, length `length`): the vertices
// below `low` fixed, those above `high` moved by `top` (a rotation about
// `axis` through `center`), `patches` rotation patches, `frequencies`.
struct Bar_setup
{
  double radius = 0.5, length = 5.0, low = 0.3, high = 4.7;
  int rings = 24, per_side = 3;
  std::size_t frequencies = 60, patches = 0;
  CGAL::Spectral_smooth_energy energy = CGAL::ARAP_ENERGY;
  CGAL::Spectral_constraint_policy policy = CGAL::EXACT_CONSTRAINTS;
  double stage_angle = 0; // degrees
  bool preserve_volume = false;
};

Surface_mesh deform_bar(const Bar_setup& setup, const Eigen::Matrix3d& top_rotation, const Eigen::Vector3d& center,
                        unsigned int iterations, double tolerance, CGAL::Spectral_deformation_report* report = nullptr,
                        bool move_bottom_too = false)
{
  Surface_mesh mesh = to_mesh<Surface_mesh>(bar(setup.rings, setup.per_side, setup.radius, setup.length));
  Spectral deformation(mesh);
  deformation.insert_roi_vertices(vertices(mesh).begin(), vertices(mesh).end());
  std::vector<SM_vertex> moved;
  for(auto v : vertices(mesh))
  {
    const double z = mesh.point(v).z();
    if(z < setup.low || z > setup.high)
      deformation.insert_control_vertex(v);
    if(z > setup.high || (move_bottom_too && z < setup.low))
      moved.push_back(v);
  }
  deformation.set_number_of_frequencies(setup.frequencies);
  deformation.set_rotation_patches(setup.patches);
  deformation.set_smooth_energy(setup.energy);
  deformation.set_constraint_policy(setup.policy);
  deformation.set_stage_angle(setup.stage_angle);
  deformation.set_volume_preservation(setup.preserve_volume);
  for(SM_vertex v : moved)
  {
    const Point& p = mesh.point(v);
    const Eigen::Vector3d q = center + top_rotation * (Eigen::Vector3d(p.x(), p.y(), p.z()) - center);
    deformation.set_target_position(v, Point(q[0], q[1], q[2]));
  }
  deformation.deform(iterations, tolerance);
  INFO(deformation.deform_report().message);
  REQUIRE(deformation.deform_report().success);
  if(report != nullptr)
    *report = deformation.deform_report();
  return mesh;
}

} // namespace

TEST_CASE("ARAP energy: the smooth energy is a setting with a default and a check", "[arap]")
{
  Surface_mesh mesh = to_mesh<Surface_mesh>(bar(8, 2));
  Spectral deformation(mesh);
  CHECK(deformation.smooth_energy() == CGAL::DUAL_LAPLACIAN_AND_ARAP_ENERGY);
  CHECK(deformation.rotation_patches() == 1000);
  deformation.set_smooth_energy(CGAL::ARAP_ENERGY);
  CHECK(deformation.smooth_energy() == CGAL::ARAP_ENERGY);
  CHECK_THROWS_AS(deformation.set_smooth_energy(static_cast<CGAL::Spectral_smooth_energy>(7)),
                  CGAL::Spectral_deformation_error);
  CHECK(deformation.smooth_energy() == CGAL::ARAP_ENERGY);
}

TEST_CASE("ARAP energy: rest targets give the rest shape, a rigid motion of all constraints its rigid image",
          "[arap]")
{
  for(CGAL::Spectral_smooth_energy energy : {CGAL::ARAP_ENERGY, CGAL::DUAL_LAPLACIAN_AND_ARAP_ENERGY})
  for(std::size_t patches : {std::size_t(0), std::size_t(40)})
    for(CGAL::Spectral_constraint_policy policy : {CGAL::EXACT_CONSTRAINTS, CGAL::SOFT_CONSTRAINTS})
    {
      Bar_setup setup;
      setup.energy = energy;
      setup.patches = patches;
      setup.policy = policy;
      INFO("energy " << energy << ", patches " << patches << ", policy " << policy);
      const Eigen::MatrixXd rest = positions_of(to_mesh<Surface_mesh>(bar(setup.rings, setup.per_side)));
      const double diagonal = diagonal_of(rest);
      const Surface_mesh at_rest = deform_bar(setup, Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero(), 10, 0.0);
      CHECK((positions_of(at_rest) - rest).rowwise().norm().maxCoeff() < 1e-9 * diagonal);

      const Eigen::Matrix3d turn = Eigen::AngleAxisd(2.0, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
      CGAL::Spectral_deformation_report report;
      const Surface_mesh turned = deform_bar(setup, turn, Eigen::Vector3d::Zero(), 2000, 1e-13, &report, true);
      CHECK(report.converged);
      CHECK((positions_of(turned) - rest * turn.transpose()).rowwise().norm().maxCoeff() < 1e-8 * diagonal);
    }
}

TEST_CASE("ARAP energy: more patches approach the full iteration, and under four faces per patch it is the full one",
          "[arap][patches]")
{
  const Eigen::Matrix3d bend = Eigen::AngleAxisd(pi / 3, Eigen::Vector3d::UnitX()).toRotationMatrix();
  const Eigen::Vector3d center(0, 0, 5.0);
  for(CGAL::Spectral_smooth_energy energy : {CGAL::ARAP_ENERGY, CGAL::DUAL_LAPLACIAN_AND_ARAP_ENERGY})
  {
  INFO("energy " << energy);
  Bar_setup setup;
  setup.energy = energy;
  const Eigen::MatrixXd full = positions_of(deform_bar(setup, bend, center, 10, 0.0));
  const double diagonal = diagonal_of(full);

  // The bar has about 600 faces: 128 patches keep more than four faces each.
  double previous = std::numeric_limits<double>::infinity();
  for(std::size_t patches : {8, 32, 128})
  {
    setup.patches = patches;
    const double distance =
        (positions_of(deform_bar(setup, bend, center, 10, 0.0)) - full).rowwise().norm().maxCoeff() / diagonal;
    INFO(patches << " patches: largest distance to the full iteration " << distance);
    CHECK(distance < previous);
    previous = distance;
  }
  CHECK(previous < 1e-2);
  CHECK(previous > 1e-6);

  setup.patches = 1000000;
  const double exact = (positions_of(deform_bar(setup, bend, center, 10, 0.0)) - full).rowwise().norm().maxCoeff();
  INFO("a million patches on about 600 faces: largest distance to the full iteration " << exact / diagonal);
  CHECK(exact < 1e-12 * diagonal);
  }
}

TEST_CASE("ARAP energy: the sum of the energies lies between the two", "[arap]")
{
  // The bar bent by 60 degrees: the ARAP energy of the smooth iteration's
  // result is lowest with ARAP_ENERGY, highest with the dual Laplacian
  // energy, in between with their sum; and the three differ.
  const Eigen::Matrix3d bend = Eigen::AngleAxisd(pi / 3, Eigen::Vector3d::UnitX()).toRotationMatrix();
  const Eigen::Vector3d center(0, 0, 5.0);
  Bar_setup setup;
  const Surface_mesh rest = to_mesh<Surface_mesh>(bar(setup.rings, setup.per_side));
  const internal::Mesh::Triangle_arrays rest_arrays =
      internal::Mesh::extract_triangle_arrays(rest, CGAL::parameters::default_values());
  std::vector<double> energies;
  for(CGAL::Spectral_smooth_energy energy :
      {CGAL::DUAL_LAPLACIAN_ENERGY, CGAL::DUAL_LAPLACIAN_AND_ARAP_ENERGY, CGAL::ARAP_ENERGY})
  {
    setup.energy = energy;
    energies.push_back(internal::Deformation::arap_energy(
        rest_arrays, positions_of(deform_bar(setup, bend, center, 200, 1e-10))));
  }
  INFO("ARAP energies: dual Laplacian " << energies[0] << ", sum " << energies[1] << ", ARAP " << energies[2]);
  CHECK(energies[2] < energies[1]);
  CHECK(energies[1] < energies[0]);
}

TEST_CASE("ARAP energy: vertex patches cover every vertex of a face, numbered without gaps", "[arap][patches]")
{
  const Soup soup = two_spheres(3);
  const internal::Mesh::Triangle_arrays arrays =
      internal::Mesh::extract_triangle_arrays(to_mesh<Surface_mesh>(soup), CGAL::parameters::default_values());
  const internal::Mesh::Dual_mesh_operator dual(arrays.triangles, arrays.number_of_vertices());
  const internal::Mesh::Positions centroids = dual.centroids(arrays.positions);
  for(std::size_t count : {1, 7, 40, 300})
  {
    const std::vector<int> patch =
        internal::Deformation::cluster_vertices(dual, centroids, arrays.number_of_vertices(), count);
    REQUIRE(patch.size() == static_cast<std::size_t>(arrays.number_of_vertices()));
    const int patches = *std::max_element(patch.begin(), patch.end()) + 1;
    INFO(count << " requested, " << patches << " made");
    CHECK(*std::min_element(patch.begin(), patch.end()) == 0);
    CHECK(patches >= 2);
    CHECK(static_cast<std::size_t>(patches) <= (std::max<std::size_t>)(count, 2));
    std::vector<int> sizes(static_cast<std::size_t>(patches), 0);
    for(int p : patch)
      ++sizes[static_cast<std::size_t>(p)];
    CHECK(*std::min_element(sizes.begin(), sizes.end()) > 0);
    // Never across the gap between the spheres.
    std::vector<std::set<bool>> sides(static_cast<std::size_t>(patches));
    for(std::size_t v = 0; v < patch.size(); ++v)
      sides[static_cast<std::size_t>(patch[v])].insert(arrays.positions(static_cast<Eigen::Index>(v), 0) > 1.5);
    for(const std::set<bool>& side : sides)
      CHECK(side.size() == 1);
  }
}

TEST_CASE("ARAP energy: a thin tube twisted by 120 degrees keeps its section and does not fold", "[arap]")
{
  // A tube of radius 0.1 and length 1, bottom 5 % fixed, top 5 % turned
  // about the axis: dual Laplacian editing pinches it (reported below), the
  // ARAP energy turns the edges about the normals too.
  Bar_setup setup;
  setup.radius = 0.1;
  setup.length = 1.0;
  setup.low = 0.05;
  setup.high = 0.95;
  setup.rings = 200;
  setup.per_side = 12;
  setup.frequencies = 100;
  const Surface_mesh rest = to_mesh<Surface_mesh>(bar(setup.rings, setup.per_side, setup.radius, setup.length));
  const double rest_volume = volume_of(rest);
  const Eigen::Matrix3d twist = Eigen::AngleAxisd(2 * pi / 3, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const Eigen::MatrixXd rest_positions = positions_of(rest);

  setup.energy = CGAL::DUAL_LAPLACIAN_ENERGY;
  const Surface_mesh dual = deform_bar(setup, twist, Eigen::Vector3d::Zero(), 10, 0.0);
  for(CGAL::Spectral_smooth_energy energy : {CGAL::ARAP_ENERGY, CGAL::DUAL_LAPLACIAN_AND_ARAP_ENERGY})
  for(std::size_t patches : {std::size_t(0), std::size_t(300)})
  {
    setup.energy = energy;
    setup.patches = patches;
    const Surface_mesh arap = deform_bar(setup, twist, Eigen::Vector3d::Zero(), 10, 0.0);
    const double arap_kept = volume_of(arap) / rest_volume;
    const Eigen::MatrixXd x = positions_of(arap);
    // The section at mid-length: mean distance to the axis.
    double radius = 0;
    int count = 0;
    for(Eigen::Index i = 0; i < x.rows(); ++i)
      if(std::abs(rest_positions(i, 2) - 0.5) < 0.02)
      {
        radius += x.row(i).head<2>().norm();
        ++count;
      }
    radius /= count;
    const internal::Mesh::Triangle_arrays rest_arrays =
        internal::Mesh::extract_triangle_arrays(rest, CGAL::parameters::default_values());
    const double arap_energy = internal::Deformation::arap_energy(rest_arrays, x);
    const double dual_energy = internal::Deformation::arap_energy(rest_arrays, positions_of(dual));
    INFO("energy " << energy << ", patches " << patches << ": volume kept " << arap_kept << " (dual Laplacian editing "
                    << volume_of(dual) / rest_volume << ", " << folded_pairs(rest, dual)
                    << " folded pairs), mid-length radius " << radius << ", ARAP energy " << arap_energy
                    << " (dual Laplacian editing " << dual_energy << ")");
    CHECK(arap_energy < dual_energy);
    CHECK(arap_kept > 0.9);
    CHECK(radius > 0.09);
    CHECK(folded_pairs(rest, arap) == 0);
  }
}

TEST_CASE("ARAP energy: switched on a prepared region, the basis is kept and the result is that of a new object",
          "[arap]")
{
  const Eigen::Matrix3d bend = Eigen::AngleAxisd(pi / 4, Eigen::Vector3d::UnitX()).toRotationMatrix();
  const Eigen::Vector3d center(0, 0, 5.0);
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
  // The settings of Bar_setup, with the dual Laplacian energy first.
  deformation.set_smooth_energy(CGAL::DUAL_LAPLACIAN_ENERGY);
  deformation.set_rotation_patches(0);
  deformation.set_stage_angle(0);
  for(SM_vertex v : top)
  {
    const Point& p = mesh.point(v);
    const Eigen::Vector3d q = center + bend * (Eigen::Vector3d(p.x(), p.y(), p.z()) - center);
    deformation.set_target_position(v, Point(q[0], q[1], q[2]));
  }
  deformation.deform(10, 0.0);
  REQUIRE(deformation.deform_report().success);
  REQUIRE(deformation.preprocess_report().basis_computed);
  const Eigen::MatrixXd with_dual = positions_of(mesh);

  deformation.set_smooth_energy(CGAL::DUAL_LAPLACIAN_AND_ARAP_ENERGY);
  deformation.deform(10, 0.0);
  REQUIRE(deformation.deform_report().success);
  CHECK_FALSE(deformation.preprocess_report().basis_computed);
  CHECK_FALSE(deformation.preprocess_report().region_rebuilt);
  const Eigen::MatrixXd switched = positions_of(mesh);

  Bar_setup setup;
  setup.energy = CGAL::DUAL_LAPLACIAN_AND_ARAP_ENERGY;
  const Eigen::MatrixXd fresh = positions_of(deform_bar(setup, bend, center, 10, 0.0));
  const double diagonal = diagonal_of(fresh);
  CHECK((switched - fresh).rowwise().norm().maxCoeff() < 1e-10 * diagonal);
  CHECK((switched - with_dual).rowwise().norm().maxCoeff() > 1e-5 * diagonal);
}

TEST_CASE("Stages: a group turned far is reached along its rigid path, in stages of at most the stage angle",
          "[stages]")
{
  // Two constrained groups on a bar: the fixed ring (the bottom) and the
  // top, turned by 100 degrees about the bar's axis and moved up.
  Surface_mesh mesh = to_mesh<Surface_mesh>(bar(12, 2));
  const internal::Mesh::Triangle_arrays arrays =
      internal::Mesh::extract_triangle_arrays(mesh, CGAL::parameters::default_values());
  const internal::Mesh::Positions& rest = arrays.positions;
  internal::Deformation::Constraint_set set;
  for(Eigen::Index i = 0; i < rest.rows(); ++i)
    if(rest(i, 2) < 0.1)
      set.constrained.push_back(static_cast<int>(i));
  set.number_of_fixed = set.constrained.size();
  for(Eigen::Index i = 0; i < rest.rows(); ++i)
    if(rest(i, 2) > 4.9)
      set.constrained.push_back(static_cast<int>(i));
  set.groups.resize(2);
  for(std::size_t k = 0; k < set.constrained.size(); ++k)
    set.groups[k < set.number_of_fixed ? 0 : 1].push_back(static_cast<int>(k));
  REQUIRE(set.groups[1].size() > 3);

  // The identity as basis: the coefficients are the positions.
  const Eigen::Index n = rest.rows();
  const Eigen::MatrixXd basis = Eigen::MatrixXd::Identity(n, n);
  Eigen::MatrixXd rows(static_cast<Eigen::Index>(set.size()), n);
  for(std::size_t k = 0; k < set.size(); ++k)
    rows.row(static_cast<Eigen::Index>(k)) = basis.row(set.constrained[k]);
  const Eigen::MatrixXd coefficients = rest;

  auto targets_for = [&](double angle, const Eigen::Vector3d& shift) {
    internal::Mesh::Positions targets(static_cast<Eigen::Index>(set.size()), 3);
    const Eigen::Matrix3d R = Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    for(std::size_t k = 0; k < set.size(); ++k)
    {
      const Eigen::Vector3d p = rest.row(set.constrained[k]).transpose();
      targets.row(static_cast<Eigen::Index>(k)) =
          (k < set.number_of_fixed ? p : Eigen::Vector3d(R * p + shift)).transpose();
    }
    return targets;
  };
  const double stage = pi / 6;
  const Eigen::Vector3d shift(0.2, -0.1, 0.5);
  const internal::Mesh::Positions targets = targets_for(5 * pi / 9, shift);
  const std::vector<internal::Mesh::Positions> stages =
      internal::Deformation::intermediate_targets(set, rows, coefficients, rest, rest, targets, stage);
  // 100 degrees in stages of at most 30: four stages, three before the targets.
  REQUIRE(stages.size() == 3);
  for(std::size_t s = 0; s < stages.size(); ++s)
  {
    const double fraction = double(s + 1) / 4;
    // The group's centroid is turned about itself: the stage is the top
    // turned by a quarter of the angle per stage and moved by as much of
    // the shift, the fixed ring unchanged.
    internal::Mesh::Positions top(static_cast<Eigen::Index>(set.groups[1].size()), 3),
        expected(top.rows(), 3);
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    for(int k : set.groups[1])
      centroid += rest.row(set.constrained[static_cast<std::size_t>(k)]).transpose();
    centroid /= double(set.groups[1].size());
    const Eigen::Matrix3d R = Eigen::AngleAxisd(fraction * 5 * pi / 9, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    const Eigen::Matrix3d full = Eigen::AngleAxisd(5 * pi / 9, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    const Eigen::Vector3d end_centroid = full * centroid + shift;
    for(std::size_t k = 0; k < set.size(); ++k)
    {
      const Eigen::Vector3d p = rest.row(set.constrained[k]).transpose();
      const Eigen::Vector3d want = k < set.number_of_fixed
                                       ? p
                                       : Eigen::Vector3d(R * (p - centroid) + centroid +
                                                         fraction * (end_centroid - centroid));
      CHECK((stages[s].row(static_cast<Eigen::Index>(k)).transpose() - want).norm() < 1e-9);
    }
  }
  // A turn within the stage angle, a translation alone, or no stage angle:
  // reached at once.
  CHECK(internal::Deformation::intermediate_targets(set, rows, coefficients, rest, rest,
                                                    targets_for(pi / 7, shift), stage)
            .empty());
  CHECK(internal::Deformation::intermediate_targets(set, rows, coefficients, rest, rest,
                                                    targets_for(0, 10 * shift), stage)
            .empty());
  CHECK(internal::Deformation::intermediate_targets(set, rows, coefficients, rest, rest, targets, 0.0).empty());
  // A vanishing stage angle: at most 180 stages, not an endless loop.
  CHECK(internal::Deformation::intermediate_targets(set, rows, coefficients, rest, rest, targets, 1e-300).size() ==
        std::size_t(internal::Deformation::max_stages - 1));
  // Measured from where the smooth mesh holds the group now: from a shape
  // already turned by 80 degrees, 100 degrees is one stage away.
  internal::Mesh::Positions turned = rest;
  const Eigen::Matrix3d R80 = Eigen::AngleAxisd(4 * pi / 9, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  for(std::size_t k = set.number_of_fixed; k < set.size(); ++k)
    turned.row(set.constrained[k]) = (R80 * rest.row(set.constrained[k]).transpose()).transpose();
  CHECK(internal::Deformation::intermediate_targets(set, rows, turned, rest, rest, targets, stage).empty());
}

TEST_CASE("Stages: a cylinder bent by 120 degrees in one call does not fold, and the stage angle is checked",
          "[stages]")
{
  Surface_mesh probe = to_mesh<Surface_mesh>(bar(8, 2));
  Spectral settings(probe);
  CHECK(settings.stage_angle() == Approx(30));
  settings.set_stage_angle(45);
  CHECK(settings.stage_angle() == Approx(45));
  CHECK_THROWS_AS(settings.set_stage_angle(-1), CGAL::Spectral_deformation_error);
  CHECK_THROWS_AS(settings.set_stage_angle(std::numeric_limits<double>::quiet_NaN()),
                  CGAL::Spectral_deformation_error);
  CHECK(settings.stage_angle() == Approx(45));

  // The cylinder of Botsch and Sorkine at a quarter of its resolution: the
  // top turned by 120 degrees about an axis across the middle of the bar,
  // which bends it into a C. In one stage the first solve squashes the bar
  // and the iteration settles in a folded shape; in stages it bends.
  Bar_setup setup;
  setup.radius = 0.5;
  setup.length = 6.0;
  setup.low = 0.3;
  setup.high = 5.7;
  setup.rings = 59;
  setup.per_side = 5;
  setup.energy = CGAL::DUAL_LAPLACIAN_AND_ARAP_ENERGY;
  const Surface_mesh rest = to_mesh<Surface_mesh>(bar(setup.rings, setup.per_side, setup.radius, setup.length));
  const Eigen::Matrix3d bend = Eigen::AngleAxisd(2 * pi / 3, Eigen::Vector3d::UnitY()).toRotationMatrix();
  const Eigen::Vector3d center(0, 0, setup.length / 2);
  CGAL::Spectral_deformation_report staged_report, single_report;
  setup.stage_angle = 30;
  const Surface_mesh staged = deform_bar(setup, bend, center, 10, 1e-4, &staged_report);
  setup.stage_angle = 0;
  const Surface_mesh single = deform_bar(setup, bend, center, 10, 1e-4, &single_report);
  const internal::Mesh::Triangle_arrays rest_arrays =
      internal::Mesh::extract_triangle_arrays(rest, CGAL::parameters::default_values());
  const double staged_energy = internal::Deformation::arap_energy(rest_arrays, positions_of(staged));
  const double single_energy = internal::Deformation::arap_energy(rest_arrays, positions_of(single));
  INFO("staged: " << staged_report.stages << " stages, " << staged_report.iterations << " solves, "
                  << folded_pairs(rest, staged) << " folded pairs, ARAP energy " << staged_energy
                  << "; one stage: " << folded_pairs(rest, single) << " folded pairs, ARAP energy "
                  << single_energy);
  CHECK(single_report.stages == 1);
  CHECK(staged_report.stages == 4);
  CHECK(folded_pairs(rest, single) > 0);
  CHECK(folded_pairs(rest, staged) == 0);
  CHECK(staged_energy < 0.7 * single_energy);
}

TEST_CASE("Volume preservation: a twisted tube keeps its volume and section, rigid motions and open sheets are untouched",
          "[volume]")
{
  Surface_mesh probe = to_mesh<Surface_mesh>(bar(8, 2));
  Spectral settings(probe);
  CHECK_FALSE(settings.volume_preservation());
  settings.set_volume_preservation(true);
  CHECK(settings.volume_preservation());

  // The tube of the test above, with the defaults of the iteration, both
  // policies: the volume is the rest volume to round-off, the handles are
  // exact (exact policy), and the mid-length section is kept.
  Bar_setup setup;
  setup.radius = 0.1;
  setup.length = 1.0;
  setup.low = 0.05;
  setup.high = 0.95;
  setup.rings = 100;
  setup.per_side = 8;
  setup.frequencies = 60;
  setup.energy = CGAL::DUAL_LAPLACIAN_AND_ARAP_ENERGY;
  setup.patches = 1000;
  setup.stage_angle = 30;
  const Surface_mesh rest = to_mesh<Surface_mesh>(bar(setup.rings, setup.per_side, setup.radius, setup.length));
  const double rest_volume = volume_of(rest);
  const Eigen::MatrixXd rest_positions = positions_of(rest);
  const Eigen::Matrix3d twist = Eigen::AngleAxisd(2 * pi / 3, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  auto mid_radius = [&](const Eigen::MatrixXd& x) {
    double radius = 0;
    int count = 0;
    for(Eigen::Index i = 0; i < x.rows(); ++i)
      if(std::abs(rest_positions(i, 2) - 0.5) < 0.02)
      {
        radius += x.row(i).head<2>().norm();
        ++count;
      }
    return radius / count;
  };
  for(CGAL::Spectral_constraint_policy policy : {CGAL::EXACT_CONSTRAINTS, CGAL::SOFT_CONSTRAINTS})
  {
    setup.policy = policy;
    setup.preserve_volume = false;
    CGAL::Spectral_deformation_report free_report, kept_report;
    const Eigen::MatrixXd free = positions_of(deform_bar(setup, twist, Eigen::Vector3d::Zero(), 10, 0.0, &free_report));
    setup.preserve_volume = true;
    const Eigen::MatrixXd kept = positions_of(deform_bar(setup, twist, Eigen::Vector3d::Zero(), 10, 0.0, &kept_report));
    const auto volume = [&](const Eigen::MatrixXd& x) {
      Surface_mesh copy = rest;
      for(auto v : copy.vertices())
        copy.point(v) = Point(x(v.idx(), 0), x(v.idx(), 1), x(v.idx(), 2));
      return volume_of(copy);
    };
    INFO("policy " << policy << ": volume kept " << volume(free) / rest_volume << " without, " << volume(kept) / rest_volume
                   << " with; mid-length radius " << mid_radius(free) << " and " << mid_radius(kept));
    CHECK(volume(free) < 0.97 * rest_volume);
    CHECK(std::abs(volume(kept) / rest_volume - 1) < 1e-9);
    CHECK(std::abs(mid_radius(kept) - 0.1) < std::abs(mid_radius(free) - 0.1));
    CHECK(std::abs(mid_radius(kept) - 0.1) < 0.005);
    CHECK_FALSE(free_report.volume_preserved);
    CHECK(kept_report.volume_preserved);
    if(policy == CGAL::EXACT_CONSTRAINTS)
      CHECK(kept_report.max_control_residual == 0.0);
  }

  // A rigid motion of every control vertex keeps the volume: the result is
  // the rigid image, as without the setting.
  setup.policy = CGAL::EXACT_CONSTRAINTS;
  setup.preserve_volume = true;
  const Eigen::Matrix3d turn = Eigen::AngleAxisd(pi / 5, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  const Eigen::MatrixXd moved =
      positions_of(deform_bar(setup, turn, Eigen::Vector3d(0.1, 0, 0.5), 1000, 1e-14, nullptr, true));
  const Eigen::Vector3d center(0.1, 0, 0.5);
  double largest = 0;
  for(Eigen::Index i = 0; i < moved.rows(); ++i)
  {
    const Eigen::Vector3d expected = center + turn * (rest_positions.row(i).transpose() - center);
    largest = std::max(largest, (moved.row(i).transpose() - expected).norm());
  }
  CHECK(largest < 1e-9);

  // An open sheet, its border outside the ROI but one side left free: the
  // volume is not defined and the setting changes nothing.
  auto lift = [](bool preserve) {
    Surface_mesh sheet = to_mesh<Surface_mesh>(bumpy_plane(16));
    Spectral deformation(sheet);
    for(auto v : vertices(sheet))
    {
      const Point& p = sheet.point(v);
      if(p.x() > 0.01)
        deformation.insert_roi_vertex(v);
      if(p.x() > 0.99)
        deformation.insert_control_vertex(v);
    }
    deformation.set_number_of_frequencies(30);
    deformation.set_volume_preservation(preserve);
    for(auto v : vertices(sheet))
      if(sheet.point(v).x() > 0.99)
        deformation.set_target_position(v, Point(sheet.point(v).x(), sheet.point(v).y(), sheet.point(v).z() + 0.3));
    deformation.deform();
    REQUIRE(deformation.deform_report().success);
    CHECK_FALSE(deformation.deform_report().volume_preserved);
    return positions_of(sheet);
  };
  CHECK(lift(true) == lift(false));
}

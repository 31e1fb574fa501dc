// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Detail transfer: the rotations of the smooth mesh, where the smooth mesh is
// well shaped and where it squeezes a thin feature into a near-curve.
#include "test_meshes.h"

#include <CGAL/Spectral_surface_mesh_deformation.h>
#include <CGAL/Spectral_deformation/internal/Deformation/Detail_transfer.h>
#include <CGAL/Spectral_deformation/internal/Deformation/Smooth_rotation_field.h>
#include <CGAL/subdivision_method_3.h>

#include <catch2/catch.hpp>

#include <Eigen/Geometry>
#include <Eigen/SVD>

#include <cmath>
#include <limits>
#include <random>

#ifdef _OPENMP
#include <omp.h>
#endif

using namespace test_meshes;
namespace internal = CGAL::Spectral_deformation::internal;

namespace {

typedef boost::graph_traits<Surface_mesh>::vertex_descriptor Vertex;

Eigen::Matrix3d kabsch(const Eigen::Matrix3d& C)
{
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(C, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d U = svd.matrixU();
  if((U * svd.matrixV().transpose()).determinant() < 0)
    U.col(2) = -U.col(2);
  return U * svd.matrixV().transpose();
}

Eigen::Vector3d position(const Surface_mesh& mesh, Vertex v)
{
  const Point& p = mesh.point(v);
  return Eigen::Vector3d(p.x(), p.y(), p.z());
}

// A unit sphere with a thin spike around the north pole: the vertices within
// the angle `cap` of the pole are pushed out to a cone of height `height`,
// then the mesh is Loop-subdivided `levels` times (the spike keeps its shape
// and gets denser).
Surface_mesh spiky_sphere(int levels, double cap = 0.15, double height = 0.8)
{
  Soup soup = icosphere(3);
  for(Point& p : soup.points)
  {
    const double angle = std::acos(std::max(-1.0, std::min(1.0, p.z())));
    if(angle < cap)
    {
      const double r = 1.0 + height * (1.0 - angle / cap);
      p = Point(r * p.x(), r * p.y(), r * p.z());
    }
  }
  Surface_mesh mesh = to_mesh<Surface_mesh>(soup);
  if(levels > 0)
    CGAL::Subdivision_method_3::Loop_subdivision(mesh, CGAL::parameters::number_of_iterations(levels));
  return mesh;
}

struct Spike_result
{
  std::size_t folded_pairs = 0;
  double max_edge_change = 0;
  Eigen::Vector3d tip_displacement; // of the spike's tip (Loop subdivision moves the rest tip)
  double diagonal = 0;
};

// The sphere below z = -0.8 fixed, a cap on the +x side turned by 30° about
// the y axis through (0, 0, -0.2): the upper body bends and carries the spike
// at the north pole, which is in the region of interest, far from the handle.
Spike_result deform_spiky_sphere(int levels, CGAL::Spectral_constraint_policy policy,
                                 double degrees = 30.0, double handle_x = 0.6)
{
  Surface_mesh mesh = spiky_sphere(levels);
  const Surface_mesh rest = mesh;
  CGAL::Spectral_surface_mesh_deformation<Surface_mesh> deformation(mesh);
  deformation.set_number_of_frequencies(100);
  deformation.set_constraint_policy(policy);
  std::vector<Vertex> handle;
  Vertex tip = *vertices(mesh).begin();
  for(Vertex v : vertices(mesh))
  {
    const Eigen::Vector3d p = position(mesh, v);
    if(p.z() > position(mesh, tip).z())
      tip = v;
    if(p.z() > -0.8)
      deformation.insert_roi_vertex(v);
    if(p.x() > handle_x && p.z() > -0.1)
      handle.push_back(v);
  }
  deformation.insert_control_vertices(handle.begin(), handle.end());
  REQUIRE(deformation.preprocess());
  const Eigen::Quaterniond turn(Eigen::AngleAxisd(degrees * CGAL_PI / 180.0, Eigen::Vector3d::UnitY()));
  deformation.rotate(handle.begin(), handle.end(), Eigen::Vector3d(0, 0, -0.2), turn);
  deformation.deform();
  REQUIRE(deformation.deform_report().success);

  Spike_result result;
  result.tip_displacement = position(mesh, tip) - position(rest, tip);
  Eigen::AlignedBox3d box;
  for(Vertex v : vertices(rest))
    box.extend(position(rest, v));
  result.diagonal = box.diagonal().norm();
  for(auto e : edges(mesh))
  {
    const Vertex a = source(e, mesh), b = target(e, mesh);
    const double before = (position(rest, a) - position(rest, b)).norm();
    const double after = (position(mesh, a) - position(mesh, b)).norm();
    result.max_edge_change = std::max(result.max_edge_change, std::abs(after - before) / before);
  }
  result.folded_pairs = folded_pairs(rest, mesh);
  return result;
}

// The triangles and positions of a soup, as the internal classes take them.
internal::Mesh::Triangle_arrays triangle_arrays_of(const Soup& soup)
{
  return internal::Mesh::extract_triangle_arrays(to_mesh<Surface_mesh>(soup), CGAL::parameters::default_values());
}

} // namespace

TEST_CASE("nearest rotation: the Kabsch solution, reflections and rank two included",
          "[detail_transfer]")
{
  std::mt19937 random(7);
  std::normal_distribution<double> normal;
  for(int trial = 0; trial < 200; ++trial)
  {
    Eigen::Matrix3d C;
    for(int k = 0; k < 9; ++k)
      C.data()[k] = normal(random);
    if(trial % 3 == 1) // rank two: a planar one-ring
    {
      const Eigen::Vector3d a(normal(random), normal(random), normal(random));
      const Eigen::Vector3d b(normal(random), normal(random), normal(random));
      const Eigen::Vector3d c(normal(random), normal(random), normal(random));
      const Eigen::Vector3d d(normal(random), normal(random), normal(random));
      C = a * c.transpose() + b * d.transpose();
    }
    const Eigen::Matrix3d R = internal::Deformation::nearest_rotation(C);
    CHECK((R.transpose() * R - Eigen::Matrix3d::Identity()).norm() < 1e-10);
    CHECK(std::abs(R.determinant() - 1.0) < 1e-10);
    // Optimal: tr(Rᵀ C) as large as for the SVD solution.
    CHECK((R.transpose() * C).trace() >= (kabsch(C).transpose() * C).trace() - 1e-9 * C.norm());
  }
  // A rotated symmetric positive definite matrix gives back the rotation.
  const Eigen::Matrix3d turn = Eigen::AngleAxisd(2.0, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  const Eigen::Matrix3d spd = Eigen::Vector3d(3.0, 1.0, 0.0).asDiagonal();
  CHECK((internal::Deformation::nearest_rotation(turn * spd) - turn).norm() < 1e-12);
}

TEST_CASE("nearest rotation: nearly flat, extreme scales and undetermined inputs", "[detail_transfer]")
{
  std::mt19937 random(11);
  std::normal_distribution<double> normal;
  const auto random_rotation = [&]() {
    return Eigen::AngleAxisd(3.0 * std::abs(normal(random)),
                             Eigen::Vector3d(normal(random), normal(random), normal(random)).normalized())
        .toRotationMatrix();
  };
  // C = U diag(σ) Vᵀ with a known answer U Vᵀ: flat one-rings (σ₃ ≪ σ₂),
  // reflections (σ₃ < 0) and the scales at which CᵀC would over- or underflow.
  for(double flatness : {1.0, 1e-2, 1e-4, 1e-8, 0.0})
    for(double sign : {1.0, -1.0})
      for(double scale : {1.0, 1e-200, 1e200})
        for(int trial = 0; trial < 20; ++trial)
        {
          const Eigen::Matrix3d U = random_rotation(), V = random_rotation();
          const Eigen::Vector3d sigma(1.0 + std::abs(normal(random)), 0.2 + 0.5 * std::abs(normal(random)),
                                      sign * flatness * 0.1);
          const Eigen::Matrix3d C = scale * U * sigma.asDiagonal() * V.transpose();
          const Eigen::Matrix3d R = internal::Deformation::nearest_rotation(C);
          INFO("flatness " << flatness << ", sign " << sign << ", scale " << scale);
          CHECK((R - U * V.transpose()).cwiseAbs().maxCoeff() < 1e-12);
          CHECK((R.transpose() * R - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() < 1e-14);
        }
  // No rotation is determined: rank one, zero, not finite.
  const Eigen::Matrix3d fallback = random_rotation();
  const Eigen::Vector3d a(1, 2, 3), b(-1, 0.5, 2);
  Eigen::Matrix3d not_finite = Eigen::Matrix3d::Identity();
  not_finite(1, 2) = std::numeric_limits<double>::quiet_NaN();
  for(const Eigen::Matrix3d& C : {Eigen::Matrix3d(a * b.transpose()), Eigen::Matrix3d(Eigen::Matrix3d::Zero()),
                                  not_finite, Eigen::Matrix3d(1e300 * a * b.transpose())})
    CHECK(internal::Deformation::nearest_rotation(C, fallback) == fallback);
}

TEST_CASE("smooth rotation field: a one-ring squeezed into a line inherits the rotation around it",
          "[detail_transfer]")
{
  // A flat grid whose right half is squeezed to the line y = 0, z = 0 in the
  // smooth rest shape; the smooth deformed shape is a rigid rotation of it.
  const Soup grid = bumpy_plane(16, 0.0);
  const internal::Mesh::Triangle_arrays detailed = triangle_arrays_of(grid);
  internal::Mesh::Positions rest(static_cast<Eigen::Index>(grid.points.size()), 3);
  for(std::size_t i = 0; i < grid.points.size(); ++i)
  {
    const Point& p = grid.points[i];
    rest.row(static_cast<Eigen::Index>(i)) << p.x(), (p.x() > 0.5 ? 1e-9 * p.y() : p.y()), p.z();
  }
  internal::Deformation::Smooth_rotation_field field;
  field.initialize(internal::cotangent_stiffness(detailed), rest);
  CHECK(field.number_of_undetermined_vertices() > 100);

  const Eigen::Matrix3d turn = Eigen::AngleAxisd(1.2, Eigen::Vector3d(0.3, -1, 0.5).normalized()).toRotationMatrix();
  const internal::Mesh::Positions deformed = (rest * turn.transpose()).rowwise() + Eigen::RowVector3d(1, 2, 3);
  std::vector<Eigen::Matrix3d> rotations;
  field.compute(deformed, rotations);
  double worst = 0;
  for(const Eigen::Matrix3d& R : rotations)
    worst = std::max(worst, (R - turn).norm());
  CHECK(worst < 1e-6);
  // At rest, every rotation is the identity.
  field.compute(rest, rotations);
  worst = 0;
  for(const Eigen::Matrix3d& R : rotations)
    worst = std::max(worst, (R - Eigen::Matrix3d::Identity()).norm());
  CHECK(worst < 1e-6);
}

TEST_CASE("smooth rotation field: the turn about a squeezed feature comes from its base at any resolution",
          "[detail_transfer]")
{
  // The right half of a flat grid squeezed across (y scaled by 0.09, a
  // moment ratio below rank_two_ratio) in the smooth rest shape; the smooth
  // deformed shape is a rigid motion, except that the squeezed half's tiny
  // width is turned by 90° about the feature (what round-off of a band-limited
  // smooth mesh does there). The inherited rotations must stay those of the
  // well-determined left half, on a coarse grid and on one with eight times
  // as many layers of inheriting vertices.
  const double width = 0.09;
  const Eigen::Matrix3d turn = Eigen::AngleAxisd(0.8, Eigen::Vector3d(0.2, 0.4, 1).normalized()).toRotationMatrix();
  double worst_by_resolution[2] = {0, 0};
  const int resolutions[2] = {16, 128};
  for(int r = 0; r < 2; ++r)
  {
    const Soup grid = bumpy_plane(resolutions[r], 0.0);
    const internal::Mesh::Triangle_arrays detailed = triangle_arrays_of(grid);
    const Eigen::Index n = detailed.positions.rows();
    internal::Mesh::Positions rest(n, 3), deformed(n, 3);
    for(Eigen::Index i = 0; i < n; ++i)
    {
      const Point& p = grid.points[static_cast<std::size_t>(i)];
      const bool squeezed = p.x() > 0.5;
      rest.row(i) << p.x(), (squeezed ? width * p.y() : p.y()), p.z();
      // The squeezed width turned about the feature (the x axis).
      const Eigen::Vector3d shape = squeezed ? Eigen::Vector3d(p.x(), 0, width * p.y())
                                             : Eigen::Vector3d(rest.row(i).transpose());
      deformed.row(i) = (turn * shape).transpose() + Eigen::RowVector3d(1, 2, 3);
    }
    internal::Deformation::Smooth_rotation_field field;
    field.initialize(internal::cotangent_stiffness(detailed), rest);
    REQUIRE(field.number_of_undetermined_vertices() > static_cast<std::size_t>(n / 3));
    std::vector<Eigen::Matrix3d> rotations;
    field.compute(deformed, rotations);
    for(Eigen::Index i = 0; i < n; ++i)
      if(rest(i, 0) > 0.6)
        worst_by_resolution[r] = std::max(worst_by_resolution[r],
                                          Eigen::AngleAxisd(rotations[static_cast<std::size_t>(i)] * turn.transpose()).angle());
  }
  INFO("largest angle to the base's rotation: " << worst_by_resolution[0] << " rad (coarse), "
                                                 << worst_by_resolution[1] << " rad (fine)");
  // The one-rings at the border of the two halves see some of the turn
  // (a few degrees); deeper in, nothing is added, at either resolution.
  CHECK(worst_by_resolution[0] < 0.15);
  CHECK(worst_by_resolution[1] < worst_by_resolution[0] + 0.01);
}

TEST_CASE("smooth rotation field: one thread and all threads give the same bits",
          "[detail_transfer]")
{
  // A grid large enough for the parallel loops (over 20,000 vertices, over
  // 2,000 of them inheriting), its right half squeezed to a line, turned by
  // a non-rigid map so that every rotation differs.
  const Soup grid = bumpy_plane(160, 0.02);
  const internal::Mesh::Triangle_arrays detailed = triangle_arrays_of(grid);
  internal::Mesh::Positions rest(detailed.positions.rows(), 3);
  for(std::size_t i = 0; i < grid.points.size(); ++i)
  {
    const Point& p = grid.points[i];
    rest.row(static_cast<Eigen::Index>(i)) << p.x(), (p.x() > 0.5 ? 1e-9 * p.y() : p.y()), p.z();
  }
  REQUIRE(rest.rows() > 20000);
  internal::Deformation::Smooth_rotation_field field;
  field.initialize(internal::cotangent_stiffness(detailed), rest);
  REQUIRE(field.number_of_undetermined_vertices() > 2000);

  internal::Mesh::Positions deformed(rest.rows(), 3);
  for(Eigen::Index i = 0; i < rest.rows(); ++i)
  {
    const double angle = 1.5 * rest(i, 0);
    deformed.row(i) = (Eigen::AngleAxisd(angle, Eigen::Vector3d(0.2, 1, 0.1).normalized()) *
                       rest.row(i).transpose())
                          .transpose();
  }
  std::vector<Eigen::Matrix3d> on_all_threads, on_one_thread;
  field.compute(deformed, on_all_threads);
#ifdef _OPENMP
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
#endif
  field.compute(deformed, on_one_thread);
#ifdef _OPENMP
  omp_set_num_threads(threads);
#endif
  REQUIRE(on_all_threads.size() == on_one_thread.size());
  std::size_t different = 0;
  for(std::size_t i = 0; i < on_one_thread.size(); ++i)
    if(on_all_threads[i] != on_one_thread[i])
      ++different;
  CHECK(different == 0);
  // The inherited rotations are not all alike: the map bends the squeezed half.
  CHECK((on_one_thread.front() - on_one_thread.back()).norm() > 0.1);
}

TEST_CASE("a thin spike far from the handle neither folds nor stretches, at two resolutions",
          "[detail_transfer][deformation]")
{
  for(CGAL::Spectral_constraint_policy policy : {CGAL::EXACT_CONSTRAINTS, CGAL::SOFT_CONSTRAINTS})
  {
    const Spike_result coarse = deform_spiky_sphere(1, policy);
    const Spike_result fine = deform_spiky_sphere(2, policy);
    INFO("policy " << policy << ": max edge change " << coarse.max_edge_change << " / "
                   << fine.max_edge_change << ", folded pairs " << coarse.folded_pairs << " / "
                   << fine.folded_pairs);
    CHECK(coarse.folded_pairs == 0);
    CHECK(fine.folded_pairs == 0);
    CHECK(coarse.max_edge_change < 1.0);
    CHECK(fine.max_edge_change < 1.5 * coarse.max_edge_change + 0.1);
    // The same shape at both resolutions: the tip lands at the same place.
    CHECK((coarse.tip_displacement - fine.tip_displacement).norm() < 0.02 * coarse.diagonal);
  }
}

TEST_CASE("detail transfer: a thin feature squeezed into a curve by the smooth mesh follows a rigid motion",
          "[detail_transfer]")
{
  // The detailed mesh is the spiky sphere; its smooth version squeezes the
  // spike onto the z axis (a band-limited smooth mesh does the same to thin
  // features) and carries round-off noise. A rigid motion of the smooth mesh
  // must move the details rigidly, the spike included.
  const Surface_mesh mesh = spiky_sphere(2);
  internal::Mesh::Triangle_arrays detailed;
  detailed.positions.resize(static_cast<Eigen::Index>(num_vertices(mesh)), 3);
  detailed.triangles.resize(static_cast<Eigen::Index>(num_faces(mesh)), 3);
  for(Vertex v : vertices(mesh))
    detailed.positions.row(static_cast<Eigen::Index>(v.idx())) = position(mesh, v).transpose();
  Eigen::Index f_index = 0;
  for(auto f : faces(mesh))
  {
    int k = 0;
    for(Vertex v : vertices_around_face(halfedge(f, mesh), mesh))
      detailed.triangles(f_index, k++) = static_cast<int>(v.idx());
    ++f_index;
  }
  std::mt19937 random(3);
  std::uniform_real_distribution<double> noise(-1e-10, 1e-10);
  internal::Mesh::Positions smooth_rest = detailed.positions;
  std::size_t squeezed = 0;
  for(Eigen::Index i = 0; i < smooth_rest.rows(); ++i)
  {
    if(smooth_rest(i, 2) > 1.05)
    {
      smooth_rest(i, 0) *= 1e-9;
      smooth_rest(i, 1) *= 1e-9;
      ++squeezed;
    }
    for(int c = 0; c < 3; ++c)
      smooth_rest(i, c) += noise(random);
  }
  REQUIRE(squeezed > 20);

  const Eigen::Matrix3d turn = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, -0.4, 0.2).normalized()).toRotationMatrix();
  const Eigen::RowVector3d shift(0.3, -0.2, 0.5);
  internal::Mesh::Positions smooth_deformed = (smooth_rest * turn.transpose()).rowwise() + shift;
  for(Eigen::Index i = 0; i < smooth_deformed.rows(); ++i)
    for(int c = 0; c < 3; ++c)
      smooth_deformed(i, c) += noise(random);
  const internal::Mesh::Positions expected = (detailed.positions * turn.transpose()).rowwise() + shift;

  std::vector<char> prescribed(static_cast<std::size_t>(detailed.positions.rows()), 0);
  for(Eigen::Index i = 0; i < detailed.positions.rows(); ++i)
    prescribed[static_cast<std::size_t>(i)] = detailed.positions(i, 2) < -0.8;
  internal::Deformation::Detail_transfer<> transfer;
  transfer.initialize(detailed, smooth_rest);
  REQUIRE(transfer.prepare_dirichlet(prescribed));
  internal::Mesh::Positions result;
  REQUIRE(transfer.transfer_exact(smooth_deformed, expected, result));
  CHECK((result - expected).rowwise().norm().maxCoeff() < 1e-6);
}

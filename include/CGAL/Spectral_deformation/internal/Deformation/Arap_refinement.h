// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_ARAP_REFINEMENT_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_ARAP_REFINEMENT_H

#include <CGAL/Spectral_deformation/internal/available_threads.h>
#include <CGAL/Spectral_deformation/Deformation_reports.h>
#include <CGAL/Spectral_deformation/Spectral_deformation_error.h>
#include <CGAL/Spectral_deformation/cotangent_operators.h>
#include <CGAL/Spectral_deformation/internal/Deformation/Constraint_set.h>
#include <CGAL/Spectral_deformation/internal/Deformation/Detail_transfer.h>
#include <CGAL/Spectral_deformation/internal/Deformation/Iteration_report.h>
#include <CGAL/Spectral_deformation/internal/Deformation/Smooth_rotation_field.h>
#include <CGAL/Spectral_deformation/internal/Deformation/rigid_fit.h>
#include <CGAL/Spectral_deformation/internal/Mesh/Region.h>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <chrono>
#include <cmath>
#include <cstddef>
#include <memory>
#include <vector>

namespace CGAL {
namespace Spectral_deformation {
namespace internal {
namespace Deformation {

using Mesh::Positions;
using Mesh::Region_geometry;

/// The stiffness of the refinement's weights: the cotangent weights of the
/// region at rest with the cotangent of every obtuse corner taken as 0, as
/// CGAL's `ORIGINAL_ARAP` weighs (each half of an edge's weight clamped, not
/// their sum), so that the refinement converges to the optimum of CGAL's
/// energy. With a negative weight the energy below is no sum of squares:
/// its local step would favour rotations that stretch the edges of obtuse
/// triangles, and on the meshes of scanned shapes (the armadillo) it goes
/// below 0. `clamped` tells whether a corner was obtuse.
inline Eigen::SparseMatrix<double> acute_cotangent_stiffness(const Mesh::Triangle_arrays& rest, bool& clamped)
{
  std::size_t obtuse_corners = 0;
  Eigen::SparseMatrix<double> result = cotangent_stiffness(rest, false, &obtuse_corners);
  clamped = obtuse_corners > 0;
  if(clamped)
    result.prune(0.0);
  return result;
}

/// The local step of as-rigid-as-possible deformation (Sorkine and Alexa
/// 2007) on the detailed mesh, and the energy it minimizes:
///
///   E(x) = min over R of Σ_i Σ_j w_ij ‖(x_i − x_j) − R_i (v_i − v_j)‖²,
///
/// over the one-ring edges ij of every vertex, w_ij the weights of the
/// stiffness Q that the global step solves with (`acute_cotangent_stiffness()`:
/// the cotangent weights without the obtuse corners, as CGAL's
/// `ORIGINAL_ARAP` weighs) and v the rest positions, divided by
/// Σ_i Σ_j w_ij ‖v_i − v_j‖² so that it does not depend on the scale. The rotations that reach the
/// minimum give the right-hand side of the global step,
/// b_i = Σ_j w_ij ½(R_i + R_j)(v_i − v_j): both steps lower the same energy,
/// so that the iteration of `refine_as_rigid_as_possible()` never raises it.
///
/// Unlike the rotations of the detail transfer (`Smooth_rotation_field`),
/// fitted on a smooth mesh whose thin features are squeezed into curves,
/// the one-rings of the detailed mesh determine their rotations, and none is
/// inherited.
class Arap_local_step
{
public:
  /// `stiffness` the stiffness of the weights (`acute_cotangent_stiffness()`), `rest`
  /// the rest positions.
  void initialize(const Eigen::SparseMatrix<double>& stiffness, const Positions& rest)
  {
    m_adjacency.initialize(stiffness);
    m_rest = rest.transpose();
    const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(m_adjacency.number_of_vertices());
    double normalization = 0;
    for(std::ptrdiff_t i = 0; i < n; ++i)
      for(int s = m_adjacency.start[static_cast<std::size_t>(i)]; s < m_adjacency.start[static_cast<std::size_t>(i) + 1];
          ++s)
        normalization += m_adjacency.weights[static_cast<std::size_t>(s)] *
                         (m_rest.col(i) - m_rest.col(m_adjacency.neighbours[static_cast<std::size_t>(s)])).squaredNorm();
    m_normalization = normalization > 0 ? normalization : 1.0;
    m_initialized = true;
  }

  bool initialized() const { return m_initialized; }

  /// Fits the rotations to `deformed` (n×3), forms the right-hand side of the
  /// global step for them, and returns E(deformed).
  double fit(const Positions& deformed)
  {
    const Cotangent_adjacency& a = m_adjacency;
    const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(a.number_of_vertices());
    m_deformed = deformed.transpose();
    m_rotations.resize(static_cast<std::size_t>(n));
    double energy = 0;
#ifdef _OPENMP
#pragma omp parallel for schedule(static) reduction(+ : energy) if(n > parallel_loop_items)
#endif
    for(std::ptrdiff_t i = 0; i < n; ++i)
    {
      Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
      double squared_lengths = 0; // Σ_j w_ij (‖x_i − x_j‖² + ‖v_i − v_j‖²)
      for(int s = a.start[static_cast<std::size_t>(i)]; s < a.start[static_cast<std::size_t>(i) + 1]; ++s)
      {
        const int j = a.neighbours[static_cast<std::size_t>(s)];
        const double w = a.weights[static_cast<std::size_t>(s)];
        const Eigen::Vector3d d = m_deformed.col(i) - m_deformed.col(j);
        const Eigen::Vector3d e = m_rest.col(i) - m_rest.col(j);
        covariance.noalias() += (w * d) * e.transpose();
        squared_lengths += w * (d.squaredNorm() + e.squaredNorm());
      }
      const Eigen::Matrix3d R = nearest_rotation(covariance);
      m_rotations[static_cast<std::size_t>(i)] = R;
      // Σ_j w ‖d − R e‖² = Σ_j w (‖d‖² + ‖e‖²) − 2 ⟨R, Σ_j w d eᵀ⟩.
      energy += squared_lengths - 2 * R.cwiseProduct(covariance).sum();
    }
    form_right_hand_side();
    return energy / m_normalization;
  }

  /// The right-hand side of the global step for the rotations of the last
  /// `fit()` (n×3).
  const Eigen::MatrixXd& right_hand_side() const { return m_right_hand_side; }

  /// Regions from this many vertices fit their rotations on all threads.

private:
  void form_right_hand_side()
  {
    const Cotangent_adjacency& a = m_adjacency;
    const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(a.number_of_vertices());
    m_right_hand_side.resize(n, 3);
#ifdef _OPENMP
#pragma omp parallel for schedule(static) if(n > parallel_loop_items)
#endif
    for(std::ptrdiff_t i = 0; i < n; ++i)
    {
      Eigen::Vector3d sum = Eigen::Vector3d::Zero();
      for(int s = a.start[static_cast<std::size_t>(i)]; s < a.start[static_cast<std::size_t>(i) + 1]; ++s)
      {
        const int j = a.neighbours[static_cast<std::size_t>(s)];
        const Eigen::Vector3d e = m_rest.col(i) - m_rest.col(j);
        sum.noalias() += (0.5 * a.weights[static_cast<std::size_t>(s)]) *
                         ((m_rotations[static_cast<std::size_t>(i)] + m_rotations[static_cast<std::size_t>(j)]) * e);
      }
      m_right_hand_side.row(i) = sum.transpose();
    }
  }

  Cotangent_adjacency m_adjacency;
  Eigen::Matrix3Xd m_rest, m_deformed; // one column per vertex
  std::vector<Eigen::Matrix3d> m_rotations;
  Eigen::MatrixXd m_right_hand_side;
  double m_normalization = 1.0;
  bool m_initialized = false;
};

/// Sets the rows of the constrained vertices of `set` to their `targets`
/// (one row each, in the order of `set`) in `prescribed` (resized to the
/// rows of `positions`) and in `positions`.
inline void place_constrained(const Constraint_set& set, const Positions& targets, Positions& prescribed, Positions& positions)
{
  prescribed.resize(positions.rows(), 3);
  for(std::size_t k = 0; k < set.constrained.size(); ++k)
  {
    prescribed.row(set.constrained[k]) = targets.row(static_cast<Eigen::Index>(k));
    positions.row(set.constrained[k]) = targets.row(static_cast<Eigen::Index>(k));
  }
}

/// Iterates as-rigid-as-possible deformation from `positions` (n×3, the
/// prescribed vertices already at their places): each iteration fits the
/// rotations (`local`) and solves the global step with `solve(rhs, out)`,
/// which keeps the prescribed vertices where they are. Stops after
/// `max_iterations` or when an iteration lowers the energy by less than
/// `tolerance` times its value. Fills the iterations, energies, times and
/// convergence of `report`; throws `Spectral_deformation_error` when a solve
/// fails or gives non-finite positions (`positions` is then unspecified).
template <class GlobalSolve>
void refine_as_rigid_as_possible(Arap_local_step& local, const GlobalSolve& solve, Positions& positions,
                                 unsigned int max_iterations, double tolerance, Spectral_refinement_report& report)
{
  typedef Spectral_deformation_error Error;
  const auto start = std::chrono::steady_clock::now();
  double energy = local.fit(positions);
  report.energy_before = energy;
  report.energies.assign(1, energy);
  report.seconds_at_iteration.assign(1, seconds_since(start));
  report.iterations = 0;
  report.converged = !(energy > 0); // a rigid motion of the rest shape stays where it is
  Positions next;
  while(!report.converged && report.iterations < max_iterations)
  {
    if(!solve(local.right_hand_side(), next) || !next.allFinite())
      throw Error(Error::SOLVER_FAILURE, "the refinement's solve produced non-finite positions");
    positions.swap(next);
    const double previous = energy;
    energy = local.fit(positions);
    ++report.iterations;
    report.energies.push_back(energy);
    report.seconds_at_iteration.push_back(seconds_since(start));
    report.converged = std::abs(previous - energy) <= tolerance * previous;
  }
  report.energy_after = energy;
}

/// The refinement of a region's deformation towards the optimum of the
/// as-rigid-as-possible energy (`refine_as_rigid_as_possible()`), with the
/// control vertices on their targets and the fixed ring at rest. Its global
/// step is a Dirichlet problem of the stiffness without obtuse corners
/// (`acute_cotangent_stiffness()`): when no corner of the region is obtuse
/// that is the stiffness of the detail transfer, whose exact policy's
/// factorization is reused; otherwise the refinement factors its own, once
/// per constraint set.
template <class SparseSPDSolverTraits>
class Arap_refinement
{
public:
  typedef Detail_transfer<SparseSPDSolverTraits> System;

  /// For the region `region`; `shared`, when not null, a detail transfer set
  /// on the region's cotangent stiffness whose factorization may be reused
  /// (it must outlive this object).
  void initialize(const Region_geometry& region, System* shared)
  {
    bool clamped = false;
    Eigen::SparseMatrix<double> weights = acute_cotangent_stiffness(region.arrays, clamped);
    m_local_step.initialize(weights, region.arrays.positions);
    m_own.reset();
    m_shared = nullptr;
    if(clamped || shared == nullptr)
    {
      m_own.reset(new System());
      m_own->set_mesh(region.arrays, std::move(weights));
    }
    else
      m_shared = shared;
  }

  bool initialized() const { return m_own != nullptr || m_shared != nullptr; }

  /// Refines `positions` (one row per vertex of the region) for the
  /// constraint set `set` and the `targets` of its constrained vertices; the
  /// volume kept when `preserve_volume` and defined. Throws
  /// `Spectral_deformation_error` when a factorization or a solve fails.
  void refine(const Region_geometry& region, const Constraint_set& set, const Positions& targets,
              bool preserve_volume, unsigned int max_iterations, double tolerance, Positions& positions,
              Spectral_refinement_report& report)
  {
    typedef Spectral_deformation_error Error;
    const auto start = std::chrono::steady_clock::now();
    System& system = m_own ? *m_own : *m_shared;
    if(m_own)
      m_own->set_volume_preservation(preserve_volume, region.is_fixed);
    if(!system.prepare_dirichlet(prescribed_flags(region, set)))
      throw Error(Error::SOLVER_FAILURE, "the factorization of the refinement's system failed");
    report.factorization_seconds = seconds_since(start);
    place_constrained(set, targets, m_prescribed, positions);
    refine_as_rigid_as_possible(
        m_local_step,
        [this, &system](const Eigen::MatrixXd& rhs, Positions& out) {
          return system.solve_dirichlet(rhs, m_prescribed, out);
        },
        positions, max_iterations, tolerance, report);
    report.volume_preserved = system.preserves_volume();
  }

private:
  Arap_local_step m_local_step;
  std::unique_ptr<System> m_own;
  System* m_shared = nullptr;
  Positions m_prescribed;
};

} // namespace Deformation
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_ARAP_REFINEMENT_H

// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_SPATIAL_PIPELINE_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_SPATIAL_PIPELINE_H

#include <CGAL/Spectral_deformation/Deformation_reports.h>
#include <CGAL/Spectral_deformation/cotangent_operators.h>
#include <CGAL/Spectral_deformation/internal/Deformation/Arap_refinement.h>
#include <CGAL/Spectral_deformation/internal/Deformation/Constraint_set.h>
#include <CGAL/Spectral_deformation/internal/Deformation/Spatial_dual_laplacian_solver.h>
#include <CGAL/Spectral_deformation/internal/Mesh/Region.h>

#include <CGAL/assertions.h>

#include <chrono>
#include <memory>

namespace CGAL {
namespace Spectral_deformation {
namespace internal {
namespace Deformation {

using Mesh::Positions;
using Mesh::Region_geometry;

/// The steps of `SPATIAL_DUAL_LAPLACIAN` for one region: the dual Laplacian
/// system of the detailed region, factored per constraint set with the
/// constrained vertices eliminated, iterated per target change. There is no
/// basis and no detail transfer. Every step throws
/// `Spectral_deformation_error` when it fails.
template <class SparseSPDSolverTraits>
class Spatial_pipeline
{
public:
  /// `process_wide_tuning`: see `Spatial_dual_laplacian_solver::set_process_wide_tuning()`.
  void build(const Region_geometry& region, bool process_wide_tuning)
  {
    m_solver.reset(new Spatial_dual_laplacian_solver<SparseSPDSolverTraits>(region.arrays));
    m_solver->set_process_wide_tuning(process_wide_tuning);
    m_refinement.reset();
    m_has_solution = false;
  }

  /// See `Spatial_dual_laplacian_solver::set_process_wide_tuning()`.
  void set_process_wide_tuning(bool enabled)
  {
    if(m_solver)
      m_solver->set_process_wide_tuning(enabled);
  }

  void prepare(const Region_geometry&, const Constraint_set& set) { m_solver->preprocess_exact(set.constrained); }

  /// The positions of the region for the `targets` of the constrained
  /// vertices, continuing from the last accepted result. The targets are
  /// reached in one stage: the stage angle of the spectral pipeline is not
  /// used.
  void deform(const Region_geometry& region, const Constraint_set&, const Positions& targets,
              unsigned int iterations, double tolerance, double /* stage_angle */, Positions& result,
              Spectral_deformation_report& report)
  {
    CGAL_precondition(m_solver != nullptr);
    const auto start = std::chrono::steady_clock::now();
    const Positions& from = m_has_solution ? m_solution : region.arrays.positions;
    const Iteration_report iteration =
        m_solver->solve(targets, from, result, static_cast<int>(iterations) - 1, tolerance);
    report.iterations = static_cast<unsigned int>(iteration.iterations + 1);
    report.last_step = iteration.last_step;
    report.converged = iteration.converged;
    report.solve_seconds = seconds_since(start);
    m_pending = result;
  }

  /// Refines `positions` (the region's, one row per vertex) towards the
  /// optimum of the as-rigid-as-possible energy, with the constrained
  /// vertices of `set` on their `targets` (`Arap_refinement`, which factors
  /// the cotangent stiffness of the region: the dual Laplacian system has
  /// no use for it).
  void refine(const Region_geometry& region, const Constraint_set& set, const Positions& targets,
              unsigned int max_iterations, double tolerance, Positions& positions,
              Spectral_refinement_report& report)
  {
    if(!m_refinement)
    {
      m_refinement.reset(new Arap_refinement<SparseSPDSolverTraits>());
      m_refinement->initialize(region, nullptr);
    }
    m_refinement->refine(region, set, targets, false, max_iterations, tolerance, positions, report);
  }

  void accept()
  {
    m_solution.swap(m_pending);
    m_has_solution = true;
  }

  void restart() { m_has_solution = false; }

private:
  std::unique_ptr<Spatial_dual_laplacian_solver<SparseSPDSolverTraits>> m_solver;
  Positions m_solution, m_pending;
  bool m_has_solution = false;
  std::unique_ptr<Arap_refinement<SparseSPDSolverTraits>> m_refinement; // made by the first refine()
};

} // namespace Deformation
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_SPATIAL_PIPELINE_H

// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_SPECTRAL_PIPELINE_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_SPECTRAL_PIPELINE_H

#include <CGAL/Manifold_harmonics_basis.h>
#include <CGAL/Spectral_deformation/Deformation_options.h>
#include <CGAL/Spectral_deformation/Deformation_reports.h>
#include <CGAL/Spectral_deformation/Spectral_deformation_error.h>
#include <CGAL/Spectral_deformation/internal/Basis/basis_in_region_order.h>
#include <CGAL/Spectral_deformation/internal/Basis/basis_io.h>
#include <CGAL/Spectral_deformation/internal/Deformation/Arap_refinement.h>
#include <CGAL/Spectral_deformation/internal/Deformation/Constraint_products.h>
#include <CGAL/Spectral_deformation/internal/Deformation/Constraint_set.h>
#include <CGAL/Spectral_deformation/internal/Deformation/Detail_transfer.h>
#include <CGAL/Spectral_deformation/internal/Deformation/Spectral_dual_laplacian_solver.h>
#include <CGAL/Spectral_deformation/internal/Deformation/Spectral_settings.h>
#include <CGAL/Spectral_deformation/internal/Deformation/Target_stages.h>
#include <CGAL/Spectral_deformation/internal/Linear_algebra/Stored_basis.h>
#include <CGAL/Spectral_deformation/internal/Memory/Process_wide_tuning.h>
#include <CGAL/Spectral_deformation/internal/Mesh/Region.h>
#include <CGAL/Spectral_deformation/internal/available_threads.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <exception>
#include <ostream>
#include <system_error>
#include <thread>
#include <utility>
#include <vector>

namespace CGAL {
namespace Spectral_deformation {
namespace internal {
namespace Deformation {

using Basis::Basis_data;
using Memory::process_wide_tuning_of;
using Mesh::Positions;
using Mesh::Region_geometry;
using Mesh::fingerprint;
typedef Smooth_rotation_field::Vertex_major_positions Vertex_major_positions;

/// The steps of the spectral algorithms for one region: the basis, the
/// reduced dual Laplacian solve of the smooth mesh (iterated, or once with
/// the rest coordinates when `Iterated` is false) and the detail transfer
/// under the chosen constraint policy. Every step throws
/// `Spectral_deformation_error` when it fails.
template <class SparseSPDSolverTraits, bool Iterated>
class Spectral_pipeline
{
public:
  /// Per region: uses `supplied` when it was computed on this region (in its
  /// order or in the mesh's, `Basis::basis_match()`), else
  /// computes the basis with `eigensolver`; then the reduced matrices and
  /// the detail transfer.
  ///
  /// With `first_set`, the constraint set that `prepare()` will be called
  /// with next, the exact policy's factorization for it runs on a second
  /// thread while the basis is computed (see `overlapped()`).
  template <class EigensolverTraits>
  void build(const Region_geometry& region, const Basis_data& supplied, const Spectral_settings& settings,
             const EigensolverTraits& eigensolver, Spectral_preprocess_report& report,
             const Constraint_set* first_set = nullptr)
  {
    const std::uint64_t region_fingerprint = fingerprint(region.arrays);
    const bool tuning = process_wide_tuning_of(eigensolver);
    // The stiffness of the region: for the basis, the ARAP energy and the detail transfer.
    m_detail.set_process_wide_tuning(tuning);
    m_detail.set_mesh(region.arrays, cotangent_stiffness(region.arrays, tuning));
    m_detail.set_volume_preservation(settings.preserve_volume, region.is_fixed);
    const Eigen::SparseMatrix<double>& stiffness = m_detail.stiffness();
    const Basis::Basis_match match = Basis::basis_match(supplied, region, region_fingerprint);
    const bool single_precision = static_cast<std::size_t>(region.arrays.number_of_vertices()) >=
                                  settings.single_precision_basis_threshold;
    if(match != Basis::Basis_match::NONE)
    {
      m_basis = Basis::in_region_order(supplied, region, match, region_fingerprint);
      m_stored_basis.assign(std::move(m_basis.basis), single_precision);
    }
    else
    {
      const auto start = std::chrono::steady_clock::now();
      const Eigen::Index m = std::min<Eigen::Index>(static_cast<Eigen::Index>(settings.frequencies),
                                                    region.arrays.number_of_vertices());
      EigensolverTraits solver = eigensolver;
      const bool overlap = first_set != nullptr && settings.policy == EXACT_CONSTRAINTS && !tuning;
      // A basis kept in float is computed in float, when the eigensolver
      // can: on large regions the double one would be the largest
      // allocation of the deformation.
      overlapped(overlap ? prescribed_flags(region, *first_set) : std::vector<char>(), [&] {
        if(single_precision)
        {
          Eigen::MatrixXf basis;
          compute_manifold_harmonics(region.arrays, stiffness, m, solver, m_basis.eigenvalues, basis,
                                     m_basis.mass);
          m_stored_basis.assign(std::move(basis));
        }
        else
        {
          compute_manifold_harmonics(region.arrays, stiffness, m, solver, m_basis.eigenvalues, m_basis.basis,
                                     m_basis.mass);
          m_stored_basis.assign(std::move(m_basis.basis), false);
        }
      });
      m_basis.number_of_faces = static_cast<std::uint64_t>(region.arrays.number_of_faces());
      m_basis.fingerprint = region_fingerprint;
      report.basis_computed = true;
      report.basis_seconds = seconds_since(start);
    }
    m_solver.set_rotation_patches(settings.rotation_patches);
    // Without iterations there are no rotations to fit: the linear
    // algorithm keeps the paper's system.
    m_solver.set_smooth_energy(Iterated ? settings.smooth_energy : DUAL_LAPLACIAN_ENERGY);
    m_solver.initialize(m_stored_basis, m_basis.mass, region.arrays, stiffness);
    m_detail.set_smooth_rest(m_solver.smooth_rest(), m_solver.shared_rotation_field());
    m_has_solution = false;
  }

  /// Per constraint set: the reduced factorization, and the detail transfer
  /// system of the policy.
  void prepare(const Region_geometry& region, const Constraint_set& set, const Spectral_settings& settings)
  {
    typedef Spectral_deformation_error Error;
    if(!m_solver.preprocess(set.constrained, settings.weight))
      throw Error(Error::SOLVER_FAILURE, "the reduced system is not positive definite");
    m_constraint_products.initialize(set, m_solver.constrained_rows(), region.arrays.positions,
                                     m_solver.smooth_rest());
    m_policy = settings.policy;
    bool factored = false;
    if(m_policy == EXACT_CONSTRAINTS)
      factored = m_detail.prepare_dirichlet(prescribed_flags(region, set));
    else
      factored = m_detail.prepare_soft(region.is_fixed);
    if(!factored)
      throw Error(Error::SOLVER_FAILURE, "the factorization of the detail transfer failed");
  }

  /// Per target change: the positions of the region for the `targets` of the
  /// constrained vertices (one row each, in the order of `set`), continuing
  /// the iteration from the last accepted result. `accept()` makes it the
  /// start of the next call. A group of control vertices turned by more
  /// than `stage_angle` (radians, 0: never) from where the smooth mesh
  /// holds it is reached in stages (`intermediate_targets()`), each but the
  /// last iterated `stage_iterations` times.
  void deform(const Region_geometry& region, const Constraint_set& set, const Positions& targets,
              unsigned int iterations, double tolerance, double stage_angle, Positions& result,
              Spectral_deformation_report& report)
  {
    CGAL_precondition(targets.rows() == static_cast<Eigen::Index>(set.size()));
    const auto start = std::chrono::steady_clock::now();
    m_pending = (m_has_solution && Iterated) ? m_coefficients : m_solver.rest_coefficients();
    unsigned int solves = 0;
    report.stages = 1;
    if(Iterated)
    {
      const std::vector<Positions> stages = intermediate_targets(
          set, [this](std::size_t g) { return m_constraint_products.smooth_motion(g, m_pending); },
          region.arrays.positions, targets, stage_angle);
      for(const Positions& stage : stages)
      {
        const Iteration_report step = m_solver.solve_with_constraint_products(
            m_constraint_products.product(set, m_solver.constrained_rows(), stage), m_pending,
            static_cast<int>(stage_iterations) - 1, tolerance);
        solves += static_cast<unsigned int>(step.iterations + 1);
      }
      report.stages = static_cast<unsigned int>(stages.size() + 1);
    }
    const Eigen::MatrixXd products = m_constraint_products.product(set, m_solver.constrained_rows(), targets);
    const Iteration_report iteration = m_solver.solve_with_constraint_products(
        products, m_pending, Iterated ? static_cast<int>(iterations) - 1 : 0, tolerance);
    report.iterations = solves + static_cast<unsigned int>(iteration.iterations + 1);
    report.last_step = iteration.last_step;
    report.converged = iteration.converged;
    report.solve_seconds = seconds_since(start);

    const auto transfer_start = std::chrono::steady_clock::now();
    // One column per vertex, as the rotation fit of the detail transfer reads it.
    Vertex_major_positions& smooth_deformed = m_smooth_deformed;
    m_solver.shape(m_pending, smooth_deformed);
    const bool transferred = (m_policy == EXACT_CONSTRAINTS)
                                 ? transfer_exact(region, set, targets, smooth_deformed, result)
                                 : transfer_soft(region, set, targets, smooth_deformed, result);
    if(!transferred)
      throw Spectral_deformation_error(Spectral_deformation_error::SOLVER_FAILURE, "the detail transfer failed (a face of the smooth "
                                         "deformed mesh is degenerate)");
    report.detail_transfer_seconds = seconds_since(transfer_start);
    report.volume_preserved = m_detail.preserves_volume();
  }

  /// Refines `positions` (the region's, one row per vertex) towards the
  /// optimum of the as-rigid-as-possible energy of the detailed region, with
  /// the constrained vertices of `set` on their `targets` (`Arap_refinement`,
  /// which reuses the exact policy's factorization when it can). The volume
  /// is kept when the detail transfer keeps it.
  void refine(const Region_geometry& region, const Constraint_set& set, const Positions& targets,
              unsigned int max_iterations, double tolerance, Positions& positions,
              Spectral_refinement_report& report)
  {
    if(!m_refinement.initialized())
      m_refinement.initialize(region, &m_detail);
    m_refinement.refine(region, set, targets, m_detail.preserves_volume(), max_iterations, tolerance, positions,
                        report);
  }

  /// The solves of each stage before the last in `deform()`.
  static constexpr unsigned int stage_iterations = 3;

  /// The result of the last `deform()` was written: the iteration goes on from it.
  void accept()
  {
    m_coefficients.swap(m_pending);
    m_has_solution = true;
  }

  /// The next `deform()` starts from the rest shape.
  void restart() { m_has_solution = false; }

  /// See `Detail_transfer::set_process_wide_tuning()`.
  void set_process_wide_tuning(bool enabled) { m_detail.set_process_wide_tuning(enabled); }
  void set_rotation_patches(std::size_t count) { m_solver.set_rotation_patches(count); }
  /// See `Detail_transfer::set_volume_preservation()`; takes effect at the next `deform()`.
  void set_volume_preservation(bool preserve, const Region_geometry& region)
  {
    m_detail.set_volume_preservation(preserve, region.is_fixed);
  }
  bool preserves_volume() const { return m_detail.preserves_volume(); }
  /// Sets the energy of the iteration: the reduced matrices are computed
  /// again (the basis and the detail transfer are kept) and the next
  /// `deform()` starts from the rest shape; the constraint set must be
  /// prepared again.
  void set_smooth_energy(Spectral_smooth_energy energy, const Region_geometry& region)
  {
    if(!Iterated || energy == m_solver.smooth_energy())
      return;
    m_solver.set_smooth_energy(energy);
    m_solver.initialize(m_stored_basis, m_basis.mass, region.arrays, m_detail.stiffness());
    if(m_solver.shared_rotation_field() != nullptr)
      m_detail.set_smooth_rest(m_solver.smooth_rest(), m_solver.shared_rotation_field());
    m_has_solution = false;
  }
  bool has_basis() const { return !m_stored_basis.empty(); }
  std::uint64_t basis_fingerprint() const { return m_basis.fingerprint; }
  /// Whether the basis is kept in float (`Stored_basis`).
  bool single_precision_basis() const { return m_stored_basis.single_precision(); }
  /// Writes the basis (`Basis::write_basis()`); a float basis is written
  /// widened to double.
  void write_basis(std::ostream& os) const
  {
    m_stored_basis.visit([this, &os](const auto& H) { Basis::write_basis(os, m_basis, H); });
  }
  std::size_t number_of_frequencies() const { return static_cast<std::size_t>(m_stored_basis.cols()); }
  Eigen::RowVector3d smooth_rest(Eigen::Index i) const { return m_solver.smooth_rest().row(i); }
  /// The smooth deformed position of local vertex `i` (the smooth rest one
  /// before the first accepted result).
  Eigen::RowVector3d smooth_deformed(Eigen::Index i) const
  {
    if(!m_has_solution)
      return smooth_rest(i);
    return m_stored_basis.visit([this, i](const auto& H) {
      return Eigen::RowVector3d(H.row(i).template cast<double>() * m_coefficients);
    });
  }

private:
  // Runs `basis_step` and, with `prescribed` not empty and two threads
  // available, the exact
  // policy's factorization of the detail transfer for these prescribed
  // vertices on a second thread at the same time: neither needs the other,
  // the factorization runs mostly on one thread, and the basis has long
  // sequential stages (its reduced eigenproblem). Without a second thread
  // the factorization is left to `prepare()`, which also retries it when it
  // failed here and reports why.
  template <class Step>
  void overlapped(const std::vector<char>& prescribed, const Step& basis_step)
  {
    if(prescribed.empty() || available_threads() < 2)
    {
      basis_step();
      return;
    }
    std::exception_ptr error;
    std::thread worker;
    try
    {
      worker = std::thread([this, &prescribed, &error] {
        try
        {
          m_detail.prepare_dirichlet(prescribed);
        }
        catch(...)
        {
          error = std::current_exception();
        }
      });
    }
    catch(const std::system_error&)
    {
      basis_step(); // no thread to be had: one after the other
      return;
    }
    try
    {
      basis_step();
    }
    catch(...)
    {
      worker.join();
      throw;
    }
    worker.join();
    if(error)
      std::rethrow_exception(error);
  }

  bool transfer_exact(const Region_geometry& region, const Constraint_set& set, const Positions& targets,
                      const Vertex_major_positions& smooth_deformed, Positions& result)
  {
    Positions& prescribed = m_prescribed;
    prescribed.resize(region.arrays.positions.rows(), 3);
    for(std::size_t k = 0; k < set.size(); ++k)
      prescribed.row(set.constrained[k]) = targets.row(static_cast<Eigen::Index>(k));
    return m_detail.transfer_exact(smooth_deformed, prescribed, result);
  }

  // The fixed vertices around the ROI are anchored: only the control
  // vertices are soft.
  bool transfer_soft(const Region_geometry& region, const Constraint_set& set, const Positions& targets,
                     const Vertex_major_positions& smooth_deformed, Positions& result)
  {
    const Positions& rest = region.arrays.positions;
    Positions& anchored = m_prescribed;
    anchored.resize(rest.rows(), 3);
    for(std::size_t i = 0; i < region.is_fixed.size(); ++i)
      if(region.is_fixed[i])
        anchored.row(static_cast<Eigen::Index>(i)) = rest.row(static_cast<Eigen::Index>(i));
    if(!m_detail.transfer_soft(smooth_deformed, anchored, set.constrained, targets, result))
      return false;
    meet_soft_constraints(region, set, targets, result);
    return m_detail.keep_volume_soft(result);
  }

  // The detail transfer carries the rotations of the smooth mesh, not its
  // stretch, so the control vertices end farther from their targets than
  // the smooth mesh did. The residuals are met as the reduced system meets
  // its targets, by a smooth field of the basis added to the region (not to
  // the fixed vertices, which stay where they are).
  void meet_soft_constraints(const Region_geometry& region, const Constraint_set& set, const Positions& targets,
                             Positions& result) const
  {
    typedef Spectral_deformation_error Error;
    Positions residuals(targets.rows(), 3);
    for(std::size_t k = 0; k < set.size(); ++k)
      residuals.row(static_cast<Eigen::Index>(k)) =
          targets.row(static_cast<Eigen::Index>(k)) - result.row(set.constrained[k]);
    const Positions correction = m_solver.shape(m_solver.fit_constraints(residuals));
    if(!correction.allFinite())
      throw Error(Error::SOLVER_FAILURE, "the iteration produced non-finite values");
    for(std::size_t i = 0; i < region.is_fixed.size(); ++i)
      if(!region.is_fixed[i])
        result.row(static_cast<Eigen::Index>(i)) += correction.row(static_cast<Eigen::Index>(i));
  }

  Basis_data m_basis; // all but the basis itself, which is in m_stored_basis
  Linear_algebra::Stored_basis m_stored_basis;
  Spectral_dual_laplacian_solver m_solver;
  Constraint_products m_constraint_products;
  Detail_transfer<SparseSPDSolverTraits> m_detail;
  Arap_refinement<SparseSPDSolverTraits> m_refinement; // made by the first refine()
  Spectral_constraint_policy m_policy = EXACT_CONSTRAINTS;
  Eigen::MatrixXd m_coefficients, m_pending;
  // Buffers of a drag, kept between drags: on large meshes, fresh pages for
  // them cost more than the arithmetic.
  Vertex_major_positions m_smooth_deformed;
  Positions m_prescribed;
  bool m_has_solution = false;
};

} // namespace Deformation
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_SPECTRAL_PIPELINE_H

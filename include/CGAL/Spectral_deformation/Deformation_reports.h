// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_DEFORMATION_REPORTS_H
#define CGAL_SPECTRAL_DEFORMATION_DEFORMATION_REPORTS_H

#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {

/// \ingroup PkgSpectralSurfaceMeshDeformationRef
/// What the last `preprocess()` of a `Spectral_surface_mesh_deformation` did.
///
/// When `preprocess()` finds nothing to do (neither the region nor the
/// constraint set changed since its last success), the report is kept, with
/// `region_rebuilt` and `basis_computed` set to `false` and the times to 0.
/// Times are wall-clock seconds.
struct Spectral_preprocess_report
{
  bool success = false;                     ///< whether the deformation can run
  std::string message;                      ///< why not, when `success` is `false`
  bool region_rebuilt = false;              ///< the region (and its basis) had to be built
  bool basis_computed = false;              ///< the eigensolver ran (not reused, handed in or loaded)
  std::size_t number_of_region_vertices = 0;///< vertices of the region of interest and their fixed ring
  std::size_t number_of_frequencies = 0;    ///< basis functions in use (spectral algorithms; 0 with `SPATIAL_DUAL_LAPLACIAN`)
  bool single_precision_basis = false;      ///< the basis is kept in float (see `Spectral_parameters::set_single_precision_basis_threshold()`)
  std::size_t number_of_constrained_vertices = 0; ///< control vertices and fixed ring vertices
  double region_seconds = 0;                ///< region extraction, validation, basis, per-region matrices and factorizations
  double basis_seconds = 0;                 ///< of which the eigensolve (with the exact policy's first sparse factorization, which runs on a second thread meanwhile when two threads are available)
  double factorization_seconds = 0;         ///< per constraint set: the reduced factorization, plus the sparse one of the exact policy (unless done during the eigensolve) or of `SPATIAL_DUAL_LAPLACIAN`
};

/// \ingroup PkgSpectralSurfaceMeshDeformationRef
/// What the last `deform()` of a `Spectral_surface_mesh_deformation` did.
///
/// The residuals are measured on the positions written to the mesh: they are
/// 0 up to round-off with `EXACT_CONSTRAINTS` and with
/// `SPATIAL_DUAL_LAPLACIAN`. Times are wall-clock seconds.
struct Spectral_deformation_report
{
  bool success = false;             ///< whether the mesh was updated
  std::string message;              ///< why not, when `success` is `false`
  unsigned int iterations = 0;      ///< solves of the (reduced or spatial) system, in all stages
  unsigned int stages = 1;          ///< stages the targets were reached in (see `Spectral_parameters::set_stage_angle()`)
  /// whether the detail transfer kept the enclosed volume: volume preservation
  /// is on and the region is cut out of a closed surface (see
  /// `Spectral_parameters::set_volume_preservation()`)
  bool volume_preserved = false;
  double last_step = 0;             ///< last relative step (see `set_tolerance()`)
  bool converged = false;           ///< the last step fell below the tolerance
  double max_control_residual = 0;  ///< largest distance of a control vertex to its target, relative to the bounding-box diagonal of the region
  double rms_control_residual = 0;  ///< root mean square of the same distances, relative likewise
  double solve_seconds = 0;         ///< rigid fits and iterations
  double detail_transfer_seconds = 0; ///< deformation transfer (spectral algorithms; 0 with `SPATIAL_DUAL_LAPLACIAN`)
  double total_seconds = 0;         ///< the whole `deform()` call, preprocessing excluded
};

/// \ingroup PkgSpectralSurfaceMeshDeformationRef
/// What the last `refine()` of a `Spectral_surface_mesh_deformation` did.
///
/// The energy is the as-rigid-as-possible energy of Sorkine and Alexa (2007)
/// of the region against its initial geometry, with the best rotation per
/// vertex one-ring and the cotangent weights clamped at 0 (as CGAL's
/// `ORIGINAL_ARAP` weighs), divided by the weighted sum of the squared rest
/// edge lengths: 0 for a rigid motion, about the mean squared relative edge
/// distortion otherwise. Times are wall-clock seconds.
struct Spectral_refinement_report
{
  bool success = false;             ///< whether the mesh was updated
  std::string message;              ///< why not, when `success` is `false`
  unsigned int iterations = 0;      ///< as-rigid-as-possible iterations run
  double energy_before = 0;         ///< energy of the positions refined from (control vertices on their targets)
  double energy_after = 0;          ///< energy of the positions written to the mesh
  /// the last iteration lowered the energy by less than the tolerance times
  /// its value (or the energy is 0)
  bool converged = false;
  /// whether each iteration kept the enclosed volume (see
  /// `Spectral_parameters::set_volume_preservation()`)
  bool volume_preserved = false;
  std::vector<double> energies;     ///< the energy before the first iteration and after each
  std::vector<double> seconds_at_iteration; ///< the time since the iterations started, at each entry of `energies`
  double factorization_seconds = 0; ///< the sparse factorization of the constraint set, when it had none yet (none when `EXACT_CONSTRAINTS` made one for `deform()` and the region has no negative cotangent weight)
  double total_seconds = 0;         ///< the whole `refine()` call, preprocessing excluded
};

} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_DEFORMATION_REPORTS_H

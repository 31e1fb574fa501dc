// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_DEFORMATION_OPTIONS_H
#define CGAL_SPECTRAL_DEFORMATION_DEFORMATION_OPTIONS_H

namespace CGAL {

/// \ingroup PkgSpectralSurfaceMeshDeformationRef
/// The algorithms of `Spectral_surface_mesh_deformation`, its template
/// parameter `TAG`.
enum Spectral_deformation_algorithm_tag {
  /// The paper's algorithm (the default): dual Laplacian editing in the space
  /// of the first `m` manifold harmonics, iterated so that the dual Laplacian
  /// coordinates follow the local rotations, then detail transfer. The
  /// energy of the iteration, its stages and its rotation patches are
  /// settings (`Spectral_parameters`); by default the iteration minimizes
  /// the sum of the dual Laplacian and ARAP energies.
  SPECTRAL_DUAL_LAPLACIAN,
  /// The same reduced system solved once with the dual Laplacian coordinates
  /// of the rest shape, then detail transfer: the linear spectral solution
  /// the paper compares against, which cannot follow large rotations.
  /// Every `deform()` starts again from the rest shape, and the number of
  /// iterations is not used.
  SPECTRAL_LINEAR,
  /// Dual Laplacian editing of Au et al.\ 2006 on the detailed region, the
  /// paper's spatial baseline: a sparse system of the size of the region,
  /// factored once per constraint set, with the constrained vertices
  /// eliminated (they land exactly on their targets). There is no basis and
  /// no detail transfer; the constraint weight and the constraint policy are
  /// not used.
  SPATIAL_DUAL_LAPLACIAN
};

/// \ingroup PkgSpectralSurfaceMeshDeformationRef
/// How the spectral algorithms of `Spectral_surface_mesh_deformation` meet
/// the constraints (`SPATIAL_DUAL_LAPLACIAN` always meets them exactly).
///
/// In both policies the reduced solve meets the constraints of the smooth
/// mesh in the least-squares sense, and the vertices outside the region of
/// interest are never moved; the policies differ in the detail transfer.
enum Spectral_constraint_policy {
  /// CGAL's semantics (the default): control vertices land exactly on their
  /// targets and the region of interest joins the fixed vertices around it.
  /// The detail transfer is a Poisson problem in which the control vertices
  /// and the fixed vertices are prescribed; `preprocess()` factors it once
  /// per constraint set, a sparse factorization of the size of the region.
  EXACT_CONSTRAINTS,
  /// The paper's formulation: the control vertices are met in the least
  /// squares sense only. The detail transfer prescribes the fixed vertices
  /// around the region of interest, which only change with the region, so it
  /// is factored once per region and a new constraint set costs no sparse
  /// factorization at all (only the `m × m` one); in a connected part of the
  /// region without fixed vertices, the translation that best matches the
  /// control vertices is fitted. Control vertices land near their targets
  /// (the residuals are in `Spectral_deformation_report`); the region joins
  /// the fixed vertices as with the exact policy.
  SOFT_CONSTRAINTS
};

/// \ingroup PkgSpectralSurfaceMeshDeformationRef
/// The energy of the smooth mesh that the iteration of the spectral
/// algorithm minimizes in the space of the basis, with the constraints
/// (`Spectral_parameters::set_smooth_energy()`).
enum Spectral_smooth_energy {
  /// The paper's: dual Laplacian editing. Each iteration turns
  /// the dual Laplacian coordinates of the smooth rest mesh to the normals
  /// of the current smooth mesh and solves the reduced least squares system.
  /// Open sheets bend with the least stretch; thin tubes pinch when twisted
  /// and fold when bent far.
  DUAL_LAPLACIAN_ENERGY,
  /// The as-rigid-as-possible energy of the smooth mesh (Sorkine and Alexa
  /// 2007) minimized in the space of the basis: each iteration fits a
  /// rotation to every one-ring of the current smooth mesh (or to every
  /// rotation patch) and solves the reduced system whose matrix is
  /// \f$ H^T Q H \f$, \f$ Q \f$ the cotangent stiffness. Unlike dual Laplacian
  /// editing, the rotations turn the edges about the surface's normal too, so
  /// twisted tubes keep their section; bends of open sheets spread less
  /// evenly within ten iterations.
  ARAP_ENERGY,
  /// The default: the sum of the two, the ARAP energy scaled so that the
  /// matrices of the two reduced systems have the same trace: twisted tubes keep their
  /// section as with `ARAP_ENERGY`, and twists and bends spread along the
  /// shape almost as with `DUAL_LAPLACIAN_ENERGY`; with stages
  /// (`Spectral_parameters::set_stage_angle()`), large bends do not fold.
  /// Each iteration does the work of both.
  DUAL_LAPLACIAN_AND_ARAP_ENERGY
};

} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_DEFORMATION_OPTIONS_H

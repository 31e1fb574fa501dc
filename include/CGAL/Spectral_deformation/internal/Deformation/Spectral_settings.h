// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_SPECTRAL_SETTINGS_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_SPECTRAL_SETTINGS_H

#include <CGAL/Spectral_deformation/Deformation_options.h>

#include <cstddef>

namespace CGAL {
namespace Spectral_deformation {
namespace internal {
namespace Deformation {

/// The settings of a spectral deformation that its pipeline reads.
struct Spectral_settings
{
  std::size_t frequencies = 100;
  double weight = 1.0;
  Spectral_constraint_policy policy = EXACT_CONSTRAINTS;
  // Regions of at least this many vertices keep their basis in float.
  std::size_t single_precision_basis_threshold = default_single_precision_basis_threshold;
  // The defaults are those of the quality sweep of the manual: no folded
  // faces on large bends and twists, ARAP energies within a few per cent of
  // the full iteration's, and an iteration whose cost does not grow with n.
  std::size_t rotation_patches = default_rotation_patches;
  Spectral_smooth_energy smooth_energy = DUAL_LAPLACIAN_AND_ARAP_ENERGY;
  double stage_angle = default_stage_angle; // radians; 0: the targets reached in one stage
  bool preserve_volume = false;             // the detail transfer keeps the enclosed volume

  static constexpr std::size_t default_rotation_patches = 1000;
  static constexpr std::size_t default_single_precision_basis_threshold = 20000;
  static constexpr double default_stage_angle = 3.14159265358979323846 / 6;
};

} // namespace Deformation
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_SPECTRAL_SETTINGS_H

// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_PIPELINE_SELECTOR_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_PIPELINE_SELECTOR_H

#include <CGAL/Spectral_deformation/Deformation_options.h>
#include <CGAL/Spectral_deformation/internal/Deformation/Spatial_pipeline.h>
#include <CGAL/Spectral_deformation/internal/Deformation/Spectral_pipeline.h>

namespace CGAL {
namespace Spectral_deformation {
namespace internal {
namespace Deformation {

/// The pipeline type of an algorithm tag, chosen at compile time: only the
/// chosen one is instantiated. `DetailSolverTraits` factors the detail
/// transfer of the spectral algorithms, `SpatialSolverTraits` the system of
/// the spatial one.
template <Spectral_deformation_algorithm_tag TAG, class DetailSolverTraits, class SpatialSolverTraits>
struct Pipeline_selector
{
  typedef Spectral_pipeline<DetailSolverTraits, TAG == SPECTRAL_DUAL_LAPLACIAN> type;
  static constexpr bool is_spectral = true;
};

template <class DetailSolverTraits, class SpatialSolverTraits>
struct Pipeline_selector<SPATIAL_DUAL_LAPLACIAN, DetailSolverTraits, SpatialSolverTraits>
{
  typedef Spatial_pipeline<SpatialSolverTraits> type;
  static constexpr bool is_spectral = false;
};

} // namespace Deformation
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_PIPELINE_SELECTOR_H

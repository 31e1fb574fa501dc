// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_PIPELINE_SELECTOR_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_PIPELINE_SELECTOR_H

#include <CGAL/Spectral_deformation/Deformation_options.h>
#include <CGAL/Spectral_deformation/Sparse_spd_solver_traits.h>
#include <CGAL/Spectral_deformation/internal/Deformation/Compiled_spectral_pipeline.h>
#include <CGAL/Spectral_deformation/internal/compiled_core.h>

#include <type_traits>

namespace CGAL {
namespace Spectral_deformation {
namespace internal {
namespace Deformation {

template <class SparseSPDSolverTraits, bool Iterated>
class Spectral_pipeline;
template <class SparseSPDSolverTraits>
class Spatial_pipeline;

/// The pipeline of the algorithm `TAG` with these traits: the one of the
/// compiled core when the program links it and it holds these traits
/// (`compiled_core.h`), else the class template, whose definition is in
/// `Spectral_pipeline.h` and `Spatial_pipeline.h`. `compiled` says which.
template <Spectral_deformation_algorithm_tag TAG, class DetailSolverTraits, class SpatialSolverTraits,
          class EigensolverTraits>
struct Pipeline_selector
{
  static constexpr bool compiled =
      CGAL_SSMD_USES_COMPILED_CORE &&
      std::is_same_v<DetailSolverTraits, Default_deformation_sparse_spd_solver_traits> &&
      (std::is_same_v<EigensolverTraits, Compiled_spectral_pipeline<true>::Approximate_eigensolver> ||
       std::is_same_v<EigensolverTraits, Compiled_spectral_pipeline<true>::Exact_eigensolver>);
  typedef std::conditional_t<compiled, Compiled_spectral_pipeline<TAG == SPECTRAL_DUAL_LAPLACIAN>,
                             Spectral_pipeline<DetailSolverTraits, TAG == SPECTRAL_DUAL_LAPLACIAN>>
      type;
  static constexpr bool is_spectral = true;
};

template <class DetailSolverTraits, class SpatialSolverTraits, class EigensolverTraits>
struct Pipeline_selector<SPATIAL_DUAL_LAPLACIAN, DetailSolverTraits, SpatialSolverTraits, EigensolverTraits>
{
  static constexpr bool compiled =
      CGAL_SSMD_USES_COMPILED_CORE && std::is_same_v<SpatialSolverTraits, Default_sparse_spd_solver_traits>;
  typedef std::conditional_t<compiled, Compiled_spatial_pipeline, Spatial_pipeline<SpatialSolverTraits>> type;
  static constexpr bool is_spectral = false;
};

} // namespace Deformation
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

// Without the compiled core, every deformation compiles its pipeline from the
// headers; with it, only those with other traits do, after
// <CGAL/Spectral_deformation/Pipelines_from_headers.h>.
#if !CGAL_SSMD_USES_COMPILED_CORE
#include <CGAL/Spectral_deformation/internal/Deformation/Spatial_pipeline.h>
#include <CGAL/Spectral_deformation/internal/Deformation/Spectral_pipeline.h>
#endif

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_PIPELINE_SELECTOR_H

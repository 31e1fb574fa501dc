// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_DEFORMATION_CLASS_TYPES_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_DEFORMATION_CLASS_TYPES_H

#include <CGAL/Spectral_deformation/Partition_of_unity_eigensolver_traits.h>
#include <CGAL/Spectral_deformation/Sparse_spd_solver_traits.h>
#include <CGAL/Spectral_deformation/internal/Deformation/Pipeline_selector.h>
#include <CGAL/Spectral_deformation/internal/Deformation/Region_deformation.h>
#include <CGAL/Spectral_deformation/internal/Deformation/Template_arguments.h>
#include <CGAL/Spectral_deformation/internal/Deformation/Vertex_selection.h>

#include <CGAL/Default.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/boost/graph/properties.h>

namespace CGAL {
namespace Spectral_deformation {
namespace internal {
namespace Deformation {

/// The types of `Spectral_surface_mesh_deformation<TM, VIM, HIM, TAG, ET, ST,
/// Reserved, VPM>`, resolved from its template arguments (`Default`, CGAL's
/// tags, weight calculators and solver traits); a template argument of none
/// of the accepted kinds fails a `static_assert` that names it.
template <class TM, class VIM, class HIM, auto TAG, class ET, class ST, class VPM>
struct Deformation_class_types
{
  typedef Algorithm_of<TAG> Algorithm;
  typedef Eigensolver_argument<ET, TM, Partition_of_unity_eigensolver_traits<>> Eigensolver;
  typedef Sparse_solver_argument<ST> Sparse_solver;

  static_assert(Algorithm::valid,
                "Spectral_surface_mesh_deformation: the 4th template argument (TAG) must be a "
                "Spectral_deformation_algorithm_tag (CGAL::SPECTRAL_DUAL_LAPLACIAN, the default; "
                "CGAL::SPECTRAL_LINEAR; CGAL::SPATIAL_DUAL_LAPLACIAN) or one of CGAL's "
                "Deformation_algorithm_tag values (CGAL::ORIGINAL_ARAP, CGAL::SPOKES_AND_RIMS, "
                "CGAL::SRE_ARAP), which select CGAL::SPECTRAL_DUAL_LAPLACIAN");
  static_assert(Eigensolver::valid,
                "Spectral_surface_mesh_deformation: the 5th template argument (ET) must be "
                "CGAL::Default, a model of ManifoldHarmonicsEigensolverTraits (such as "
                "CGAL::Partition_of_unity_eigensolver_traits<>, CGAL::Block_lanczos_eigensolver_traits<> "
                "or CGAL::Spectra_eigensolver_traits<>), "
                "or a weight calculator of CGAL::Surface_mesh_deformation, which is not used; "
                "write CGAL::Default");
  static_assert(Sparse_solver::valid,
                "Spectral_surface_mesh_deformation: the 6th template argument (ST) must be "
                "CGAL::Default, a model of SparseSPDSolverTraits (such as "
                "CGAL::Eigen_sparse_spd_solver_traits), or a sparse solver traits of "
                "CGAL::Surface_mesh_deformation, which is not used; write CGAL::Default");
  static_assert(Requirements_unless<Eigensolver::is_default || Eigensolver::is_weight_calculator, ET,
                                    Eigensolver_requirements>::met);
  static_assert(Requirements_unless<Sparse_solver::is_default || Sparse_solver::is_cgal_solver_traits, ST,
                                    Sparse_spd_solver_requirements>::met);

  typedef typename Default::Get<VIM, typename GetInitializedVertexIndexMap<TM>::type>::type Vertex_index_map;
  typedef typename Default::Get<HIM, typename GetInitializedHalfedgeIndexMap<TM>::type>::type Hedge_index_map;
  typedef typename Default::Get<VPM, typename boost::property_map<TM, vertex_point_t>::type>::type Vertex_point_map;
  typedef typename Eigensolver::type Eigensolver_traits;
  typedef typename Default::Get<typename Sparse_solver::type, Default_deformation_sparse_spd_solver_traits>::type
      Sparse_solver_traits;
  // The spatial solver's system couples two rings of neighbours, dense
  // enough for a supernodal factor to pay (see benchmark/NOTES.md).
  typedef typename Default::Get<typename Sparse_solver::type, Default_sparse_spd_solver_traits>::type
      Spatial_solver_traits;

  typedef Pipeline_selector<Algorithm::value, Sparse_solver_traits, Spatial_solver_traits, Eigensolver_traits>
      Selector;
#if CGAL_SSMD_USES_COMPILED_CORE && !defined(CGAL_SPECTRAL_DEFORMATION_PIPELINES_FROM_HEADERS_H)
  static_assert(Selector::compiled,
                "Spectral_surface_mesh_deformation: the compiled core holds the pipelines of the default "
                "sparse solver traits and of the eigensolver traits Partition_of_unity_eigensolver_traits<> "
                "and Block_lanczos_eigensolver_traits<>; for other traits, include "
                "<CGAL/Spectral_deformation/Pipelines_from_headers.h> first");
#endif
  typedef Vertex_selection<TM, Vertex_index_map, Vertex_point_map> Selection;
  typedef Region_deformation<Selection, typename Selector::type, Eigensolver_traits, Selector::is_spectral>
      Computation;
};

} // namespace Deformation
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_DEFORMATION_CLASS_TYPES_H

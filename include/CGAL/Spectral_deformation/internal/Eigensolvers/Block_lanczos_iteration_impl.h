// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_BLOCK_LANCZOS_ITERATION_IMPL_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_BLOCK_LANCZOS_ITERATION_IMPL_H

// The definitions of the functions declared in Block_lanczos_iteration.h (see
// internal/compiled_core.h: the compiled core holds them).

#include <CGAL/Spectral_deformation/internal/Eigensolvers/Block_lanczos_iteration.h>

namespace CGAL {
namespace Spectral_deformation {
namespace internal {
namespace Eigensolvers {

CGAL_SSMD_CORE_FUNCTION bool accept_ritz_pairs(Block_lanczos_state& state, const Ritz_pairs& ritz, Eigen::Index k,
                                               const Block_lanczos_sizes& sizes, double sigma,
                                               const Eigen::SparseMatrix<double>& stiffness, double tolerance,
                                               Eigen::VectorXd& eigenvalues, Eigen::MatrixXd& eigenvectors,
                                               Block_lanczos_failure& failure)
{
  Eigen::MatrixXd selected;
  Eigen::VectorXd values = ritz_eigenvalues(ritz, sizes.known, sigma, k, selected);
  if(!ritz_vectors_in_place(state.V, k, selected, state.mass,
                            state.null_space.basis().leftCols(sizes.known)))
    return failure.set("the Ritz vectors are not independent");
  // The leading columns are kept without a copy (a realloc that shrinks a
  // block mapped apart moves no data).
  state.V.conservativeResize(state.n, sizes.m);
  if(state.breakdown && !verify_eigenpairs(stiffness, state.mass, values, state.V, tolerance))
    return failure.set("the eigenpairs found after a deflation of the Krylov subspace do not "
                       "satisfy the tolerance");
  eigenvalues.swap(values);
  eigenvectors.swap(state.V);
  return true;
}

} // namespace Eigensolvers
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_BLOCK_LANCZOS_ITERATION_IMPL_H

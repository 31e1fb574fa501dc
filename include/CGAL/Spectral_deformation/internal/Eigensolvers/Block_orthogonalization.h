// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_BLOCK_ORTHOGONALIZATION_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_BLOCK_ORTHOGONALIZATION_H

#include <CGAL/Spectral_deformation/internal/compiled_core.h>
#include <CGAL/Spectral_deformation/internal/Eigensolvers/Block_lanczos_state.h>
#include <CGAL/Spectral_deformation/internal/Linear_algebra/Dense_products.h>

#include <Eigen/Dense>

#include <cmath>
#include <stdexcept>

namespace CGAL {
namespace Spectral_deformation {
namespace internal {
namespace Eigensolvers {

using Linear_algebra::threaded_dense_product;

// The M-orthogonalization of the block being built (`state.block`) against
// the subspace V, and its M-orthonormalization.

// One pass of classical Gram-Schmidt: makes `state.block` M-orthogonal to
// the columns [first, k) of V and adds the coefficients to the rows
// [first, k) of `added` (when given).
void project_out(Block_lanczos_state& state, Eigen::Index first, Eigen::Index k,
                 Eigen::MatrixXd* added);

// Makes the block M-orthogonal to the known constants and to all k leading
// columns of V, with two passes: for a block with no relation to V.
void orthogonalize_against_subspace(Block_lanczos_state& state, Eigen::Index k);

// block = Q_new R with Q_new M-orthonormal (Cholesky QR, twice if needed).
// Returns false when the block is too ill-conditioned for it.
bool cholesky_qr(Block_lanczos_state& state, Eigen::MatrixXd& R);

// block = Q_new R for a block M-orthogonal to the k leading columns of V,
// whatever its rank: a pivoted Householder QR finds the directions the
// block lacks (the Krylov subspace contains an invariant subspace, e.g.
// converged eigenvectors of a repeated eigenvalue); they are replaced by
// random directions with a zero coupling, which keeps T exact (deflation).
// Returns true when the block had full rank.
bool normalize_block(Block_lanczos_state& state, Eigen::Index k, Eigen::MatrixXd& R);

} // namespace Eigensolvers
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#if CGAL_SSMD_CORE_DEFINITIONS
#include <CGAL/Spectral_deformation/internal/Eigensolvers/Block_orthogonalization_impl.h>
#endif

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_BLOCK_ORTHOGONALIZATION_H

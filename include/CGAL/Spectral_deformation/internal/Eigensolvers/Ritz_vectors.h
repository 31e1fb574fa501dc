// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_RITZ_VECTORS_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_RITZ_VECTORS_H

#include <CGAL/Spectral_deformation/internal/compiled_core.h>
#include <CGAL/Spectral_deformation/internal/Linear_algebra/Dense_products.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cstddef>
#include <vector>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace CGAL {
namespace Spectral_deformation {
namespace internal {
namespace Eigensolvers {

using Linear_algebra::dense_product;

// The eigenvectors of the block Lanczos method, computed in place in the
// memory of the subspace V, by panels of rows split between the threads.
//
// The Ritz vectors of a subspace orthogonal only to sqrt(eps) are
// M-orthonormal to the same level: the Gram matrix Yᵀ M Y, summed panel by
// panel while the panel is in cache, gives Y U^{-1} (Cholesky QR)
// M-orthonormal to rounding, a change of the vectors of the order of
// sqrt(eps) that leaves their span and residuals as they were (the
// eigenvalues come from the Lanczos recurrence, exact to rounding). A
// Rayleigh-Ritz step with Q on their span did the same at a higher cost: it
// reads the vectors again and multiplies them by Q.

// Rows of a panel, and the threads the panels are split between. Panels of
// 128 rows keep the work arrays of a panel (128 × m doubles) below the size
// from which the allocator maps fresh pages for each of them (128 KiB by
// default for glibc): a page fault costs more than the products of a
// panel on the virtual machines measured (Ritz vectors of 550 to 999
// vertices, m = 100: 6.5-9 ms with panels of 512 rows, 5-8 ms with 128).
Eigen::Index ritz_panel_rows();

int ritz_vector_threads();

// Overwrites the leading columns of V with the known eigenvectors, then the
// Ritz vectors Y = V(:, 0 .. k) S (rows are independent in that product),
// and returns Yᵀ M Y.
Eigen::MatrixXd ritz_vectors_with_gram(Eigen::MatrixXd& V, Eigen::Index k,
                                       const Eigen::MatrixXd& S, const Eigen::VectorXd& mass,
                                       const Eigen::MatrixXd& known_vectors);

// V(:, known .. known + wanted) U^{-1}, in place, with gram = Uᵀ U
// (Cholesky), unless gram is the identity to rounding. Returns false when
// the columns are not independent.
bool orthonormalize_in_place(Eigen::MatrixXd& V, Eigen::Index known,
                             const Eigen::MatrixXd& gram);

// Overwrites the leading columns of V with the eigenvectors: the known
// ones, then the Ritz vectors V(:, 0 .. k) S, M-orthonormal. Returns false
// when the Ritz vectors are not independent.
bool ritz_vectors_in_place(Eigen::MatrixXd& V, Eigen::Index k, const Eigen::MatrixXd& S,
                           const Eigen::VectorXd& mass, const Eigen::MatrixXd& known_vectors);

} // namespace Eigensolvers
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#if CGAL_SSMD_CORE_DEFINITIONS
#include <CGAL/Spectral_deformation/internal/Eigensolvers/Ritz_vectors_impl.h>
#endif

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_RITZ_VECTORS_H

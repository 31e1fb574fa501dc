// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_PARTIAL_REORTHOGONALIZATION_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_PARTIAL_REORTHOGONALIZATION_H

#include <CGAL/Spectral_deformation/internal/compiled_core.h>
#include <CGAL/Spectral_deformation/internal/Eigensolvers/Block_lanczos_state.h>
#include <CGAL/Spectral_deformation/internal/Eigensolvers/Block_orthogonalization.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace CGAL {
namespace Spectral_deformation {
namespace internal {
namespace Eigensolvers {

// Partial reorthogonalization (Simon 1984, in block form): the new block is
// orthogonalized against the last two blocks only, which the block
// three-term recurrence makes sufficient in exact arithmetic, while a
// recurrence driven by T estimates how far rounding has carried it from the
// older blocks. When that estimate passes sqrt(eps), the new block and the
// next are orthogonalized against the whole subspace. Keeping V orthogonal
// to sqrt(eps) is enough for T to be, up to rounding, the projection of the
// operator on the subspace (no spurious copies of the converged
// eigenvalues); the Ritz vectors are made orthonormal at the end. Each
// reorthogonalization reads the whole subspace twice, the most expensive
// step of a full reorthogonalization at every block.

// The level of orthogonality kept: sqrt(eps).
double semi_orthogonality();

// Estimates the blocks (i, J + 1) of Vᵀ M V for i < J from those of the
// columns J and J - 1 and the blocks of T; the new block J + 1 has been
// orthogonalized against J - 1 and J, and normalized with the coupling R.
// Returns the largest estimate.
double estimate_orthogonality(Block_lanczos_state& state, Eigen::Index J,
                              const Eigen::MatrixXd& R);

// After a reorthogonalization of the block J + 1 against the whole
// subspace: its estimated orthogonality is that of rounding.
void reset_orthogonality(Block_lanczos_state& state, Eigen::Index J);

// Orthogonalizes the normalized new block (coupling R) against the whole
// subspace of k columns and normalizes it again: block = V h + Q' R', the
// coupling of the new block becomes R' R, and the coefficients h, of the
// order of sqrt(eps), are left out of T as in the Lanczos recurrence.
void reorthogonalize_block(Block_lanczos_state& state, Eigen::Index k, Eigen::MatrixXd& R);

} // namespace Eigensolvers
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#if CGAL_SSMD_CORE_DEFINITIONS
#include <CGAL/Spectral_deformation/internal/Eigensolvers/Partial_reorthogonalization_impl.h>
#endif

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_PARTIAL_REORTHOGONALIZATION_H

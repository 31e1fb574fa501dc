// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_BLOCK_LANCZOS_STEPS_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_BLOCK_LANCZOS_STEPS_H

#include <CGAL/Spectral_deformation/internal/compiled_core.h>
#include <CGAL/Spectral_deformation/internal/Eigensolvers/Block_lanczos_state.h>
#include <CGAL/Spectral_deformation/internal/Eigensolvers/Block_orthogonalization.h>
#include <CGAL/Spectral_deformation/internal/Eigensolvers/Partial_reorthogonalization.h>

#include <Eigen/Dense>

#include <algorithm>

namespace CGAL {
namespace Spectral_deformation {
namespace internal {
namespace Eigensolvers {

// The three-term recurrence of the block Lanczos method, one block at a
// time: with V_J the J-th block of b columns of V,
//   (Q - sigma M)^{-1} M V_J = V_{J-1} B_Jᵀ + V_J A_J + V_{J+1} B_{J+1},
// A_J and B_J the diagonal and lower blocks of T.

// The first block: random, M-orthogonal to the known constants,
// M-orthonormal. `R` receives its coupling to the random block.
void start_lanczos(Block_lanczos_state& state, Eigen::MatrixXd& R);

// The shift-invert step: state.block = (Q - sigma M)^{-1} M V(:, k - b .. k),
// the image of the last block, with `solver` holding the factor of
// Q - sigma M. Returns false when the solve fails.
template <class SparseSPDSolverTraits>
bool shift_invert_block(Block_lanczos_state& state, const SparseSPDSolverTraits& solver,
                        Eigen::Index k)
{
  state.weighted = state.mass.asDiagonal() * state.V.middleCols(k - state.b, state.b);
  return solver.solve(state.weighted, state.block);
}

// Makes the image of the last block the next block V(:, k .. k + b): it is
// orthogonalized against the last two blocks, twice (the coefficients are
// the column block of T), normalized, and, when the estimated loss of
// orthogonality asks for it, reorthogonalized against the whole subspace
// (Partial_reorthogonalization.h). `R`, its coupling, is the lower block of
// T. A block that lacked directions is completed against the whole
// subspace: T stays exact, and the residuals are verified on the result.
void extend_lanczos_basis(Block_lanczos_state& state, Eigen::Index k, Eigen::MatrixXd& R);

} // namespace Eigensolvers
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#if CGAL_SSMD_CORE_DEFINITIONS
#include <CGAL/Spectral_deformation/internal/Eigensolvers/Block_lanczos_steps_impl.h>
#endif

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_BLOCK_LANCZOS_STEPS_H

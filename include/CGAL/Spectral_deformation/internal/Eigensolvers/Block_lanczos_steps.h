// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_BLOCK_LANCZOS_STEPS_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_BLOCK_LANCZOS_STEPS_H

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
inline void start_lanczos(Block_lanczos_state& state, Eigen::MatrixXd& R)
{
  state.randomize_columns(state.block, 0);
  orthogonalize_against_subspace(state, 0);
  normalize_block(state, 0, R);
  state.V.leftCols(state.b) = state.block;
  state.W_block(0, 0).setIdentity();
}

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
inline void extend_lanczos_basis(Block_lanczos_state& state, Eigen::Index k, Eigen::MatrixXd& R)
{
  const Eigen::Index b = state.b;
  const Eigen::Index J = k / b - 1;
  state.grow_projection(k);
  state.null_space.project_out(state.block);
  Eigen::MatrixXd column_block = Eigen::MatrixXd::Zero(k, b);
  const Eigen::Index local = (std::max)(Eigen::Index(0), k - 2 * b);
  project_out(state, local, k, &column_block);
  project_out(state, local, k, &column_block);
  state.T.block(0, k - b, k, b) = column_block;
  if(!normalize_block(state, k, R))
  {
    state.breakdown = true;
    state.reorthogonalize_next = true;
    reset_orthogonality(state, J);
  }
  else if(estimate_orthogonality(state, J, R) > semi_orthogonality() || state.reorthogonalize_next)
  {
    reorthogonalize_block(state, k, R);
    state.reorthogonalize_next = !state.reorthogonalize_next;
    reset_orthogonality(state, J);
    ++state.reorthogonalizations;
  }
  state.V.middleCols(k, b) = state.block;
  state.T.block(k, k - b, b, b) = R;
}

} // namespace Eigensolvers
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_BLOCK_LANCZOS_STEPS_H

// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_BLOCK_LANCZOS_STEPS_IMPL_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_BLOCK_LANCZOS_STEPS_IMPL_H

// The definitions of the functions declared in Block_lanczos_steps.h (see
// internal/compiled_core.h: the compiled core holds them).

#include <CGAL/Spectral_deformation/internal/Eigensolvers/Block_lanczos_steps.h>

namespace CGAL {
namespace Spectral_deformation {
namespace internal {
namespace Eigensolvers {

CGAL_SSMD_CORE_FUNCTION void start_lanczos(Block_lanczos_state& state, Eigen::MatrixXd& R)
{
  state.randomize_columns(state.block, 0);
  orthogonalize_against_subspace(state, 0);
  normalize_block(state, 0, R);
  state.V.leftCols(state.b) = state.block;
  state.W_block(0, 0).setIdentity();
}

CGAL_SSMD_CORE_FUNCTION void extend_lanczos_basis(Block_lanczos_state& state, Eigen::Index k, Eigen::MatrixXd& R)
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

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_BLOCK_LANCZOS_STEPS_IMPL_H

// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_PARTIAL_REORTHOGONALIZATION_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_PARTIAL_REORTHOGONALIZATION_H

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
inline double semi_orthogonality()
{
  return std::sqrt(std::numeric_limits<double>::epsilon());
}

// Estimates the blocks (i, J + 1) of Vᵀ M V for i < J from those of the
// columns J and J - 1 and the blocks of T; the new block J + 1 has been
// orthogonalized against J - 1 and J, and normalized with the coupling R.
// Returns the largest estimate.
inline double estimate_orthogonality(Block_lanczos_state& state, Eigen::Index J,
                                     const Eigen::MatrixXd& R)
{
  typedef Eigen::MatrixXd Matrix;
  const double eps = std::numeric_limits<double>::epsilon();
  const Eigen::Index b = state.b;
  const Matrix identity = Matrix::Identity(b, b);
  const Matrix A_J = 0.5 * (state.T_block(J, J) + state.T_block(J, J).transpose());
  state.operator_norm = (std::max)(state.operator_norm, A_J.norm() + R.norm());
  const auto inverse_R = R.template triangularView<Eigen::Upper>();
  double largest = 0;
  for(Eigen::Index i = 0; i < J; ++i)
  {
    const Matrix A_i = 0.5 * (state.T_block(i, i) + state.T_block(i, i).transpose());
    Matrix estimate = A_i * state.W_block(i, J) - state.W_block(i, J) * A_J;
    if(i > 0)
      estimate += state.T_block(i, i - 1) * state.W_block(i - 1, J);
    estimate += state.T_block(i + 1, i).transpose() *
                (i + 1 == J ? identity : Matrix(state.W_block(i + 1, J)));
    if(J > 0)
      estimate -= (i == J - 1 ? identity : Matrix(state.W_block(i, J - 1))) *
                  state.T_block(J, J - 1).transpose();
    // The rounding of one step, with the sign that makes it grow.
    const double norm = state.operator_norm;
    estimate = estimate.unaryExpr([&](double x) { return x + (x < 0 ? -eps : eps) * norm; });
    estimate = inverse_R.template solve<Eigen::OnTheRight>(estimate);
    state.W_block(i, J + 1) = estimate;
    largest = (std::max)(largest, estimate.cwiseAbs().maxCoeff());
  }
  state.W_block(J, J + 1).setConstant(eps);
  state.W_block(J + 1, J + 1).setIdentity();
  return largest;
}

// After a reorthogonalization of the block J + 1 against the whole
// subspace: its estimated orthogonality is that of rounding.
inline void reset_orthogonality(Block_lanczos_state& state, Eigen::Index J)
{
  const double eps = std::numeric_limits<double>::epsilon();
  state.W_block(J + 1, J + 1).setIdentity();
  for(Eigen::Index i = 0; i <= J; ++i)
    state.W_block(i, J + 1).setConstant(eps);
}

// Orthogonalizes the normalized new block (coupling R) against the whole
// subspace of k columns and normalizes it again: block = V h + Q' R', the
// coupling of the new block becomes R' R, and the coefficients h, of the
// order of sqrt(eps), are left out of T as in the Lanczos recurrence.
inline void reorthogonalize_block(Block_lanczos_state& state, Eigen::Index k, Eigen::MatrixXd& R)
{
  project_out(state, 0, k, nullptr);
  state.null_space.project_out(state.block);
  Eigen::MatrixXd correction;
  if(!cholesky_qr(state, correction))
    throw std::runtime_error("the reorthogonalized Lanczos block is rank deficient");
  R = correction * R;
}

} // namespace Eigensolvers
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_PARTIAL_REORTHOGONALIZATION_H

// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_PARTIAL_REORTHOGONALIZATION_IMPL_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_PARTIAL_REORTHOGONALIZATION_IMPL_H

// The definitions of the functions declared in Partial_reorthogonalization.h (see
// internal/compiled_core.h: the compiled core holds them).

#include <CGAL/Spectral_deformation/internal/Eigensolvers/Partial_reorthogonalization.h>

namespace CGAL {
namespace Spectral_deformation {
namespace internal {
namespace Eigensolvers {

CGAL_SSMD_CORE_FUNCTION double semi_orthogonality()
{
  return std::sqrt(std::numeric_limits<double>::epsilon());
}

CGAL_SSMD_CORE_FUNCTION double estimate_orthogonality(Block_lanczos_state& state, Eigen::Index J,
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

CGAL_SSMD_CORE_FUNCTION void reset_orthogonality(Block_lanczos_state& state, Eigen::Index J)
{
  const double eps = std::numeric_limits<double>::epsilon();
  state.W_block(J + 1, J + 1).setIdentity();
  for(Eigen::Index i = 0; i <= J; ++i)
    state.W_block(i, J + 1).setConstant(eps);
}

CGAL_SSMD_CORE_FUNCTION void reorthogonalize_block(Block_lanczos_state& state, Eigen::Index k, Eigen::MatrixXd& R)
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

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_PARTIAL_REORTHOGONALIZATION_IMPL_H

// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_BLOCK_ORTHOGONALIZATION_IMPL_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_BLOCK_ORTHOGONALIZATION_IMPL_H

// The definitions of the functions declared in Block_orthogonalization.h (see
// internal/compiled_core.h: the compiled core holds them).

#include <CGAL/Spectral_deformation/internal/Eigensolvers/Block_orthogonalization.h>

namespace CGAL {
namespace Spectral_deformation {
namespace internal {
namespace Eigensolvers {

CGAL_SSMD_CORE_FUNCTION void project_out(Block_lanczos_state& state, Eigen::Index first, Eigen::Index k,
                                         Eigen::MatrixXd* added)
{
  const Eigen::Index count = k - first;
  if(count <= 0)
    return;
  state.weighted = state.mass.asDiagonal() * state.block;
  auto h = state.coefficients.topRows(count);
  threaded_dense_product(true, state.V.middleCols(first, count), false, state.weighted, 1.0, 0.0, h);
  threaded_dense_product(false, state.V.middleCols(first, count), false, h, -1.0, 1.0, state.block);
  if(added != nullptr)
    added->middleRows(first, count) += h;
}

CGAL_SSMD_CORE_FUNCTION void orthogonalize_against_subspace(Block_lanczos_state& state, Eigen::Index k)
{
  state.null_space.project_out(state.block);
  project_out(state, 0, k, nullptr);
  project_out(state, 0, k, nullptr);
}

CGAL_SSMD_CORE_FUNCTION bool cholesky_qr(Block_lanczos_state& state, Eigen::MatrixXd& R)
{
  typedef Eigen::MatrixXd Matrix;
  const Eigen::Index b = state.b;
  R = Matrix::Identity(b, b);
  for(int pass = 0; pass < 2; ++pass)
  {
    state.weighted = state.mass.asDiagonal() * state.block;
    Matrix gram(b, b);
    threaded_dense_product(true, state.block, false, state.weighted, 1.0, 0.0, gram);
    Eigen::LLT<Matrix> cholesky(gram);
    if(cholesky.info() != Eigen::Success)
      return false;
    const Matrix upper = cholesky.matrixU();
    const double smallest = upper.diagonal().minCoeff(), largest = upper.diagonal().maxCoeff();
    // Cholesky QR twice is accurate up to cond(block) ≈ 1/sqrt(eps).
    if(!(smallest > 1e-6 * largest))
      return false;
    const Matrix inverse = upper.template triangularView<Eigen::Upper>().solve(Matrix::Identity(b, b));
    threaded_dense_product(false, state.block, false, inverse, 1.0, 0.0, state.scratch);
    state.block.swap(state.scratch);
    R = upper * R;
    // It loses orthogonality like cond(block)² eps: a second pass is
    // needed only for an ill-conditioned block.
    if(pass == 0 && largest < 10 * smallest)
      break;
  }
  return true;
}

CGAL_SSMD_CORE_FUNCTION bool normalize_block(Block_lanczos_state& state, Eigen::Index k, Eigen::MatrixXd& R)
{
  typedef Eigen::MatrixXd Matrix;
  if(cholesky_qr(state, R))
    return true;
  const Eigen::Index n = state.n, b = state.b;
  state.scratch = state.sqrt_mass.asDiagonal() * state.block;
  Eigen::ColPivHouseholderQR<Matrix> qr(state.scratch);
  const Matrix triangular = qr.matrixR().topRows(b).template triangularView<Eigen::Upper>();
  Matrix coupling = triangular * qr.colsPermutation().transpose();
  state.block = state.inverse_sqrt_mass.asDiagonal() * (qr.householderQ() * Matrix::Identity(n, b));
  const double largest = std::abs(triangular(0, 0));
  Eigen::Index rank = 0;
  while(rank < b && std::abs(triangular(rank, rank)) > 1e-10 * largest)
    ++rank;
  state.randomize_columns(state.block, rank);
  for(Eigen::Index j = rank; j < b; ++j)
    coupling.row(j).setZero();
  orthogonalize_against_subspace(state, k);
  Matrix correction;
  if(!cholesky_qr(state, correction))
    throw std::runtime_error("could not extend the Krylov subspace with new directions");
  R = correction * coupling;
  return rank == b;
}

} // namespace Eigensolvers
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_BLOCK_ORTHOGONALIZATION_IMPL_H

// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_BLOCK_ORTHOGONALIZATION_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_BLOCK_ORTHOGONALIZATION_H

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
inline void project_out(Block_lanczos_state& state, Eigen::Index first, Eigen::Index k,
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

// Makes the block M-orthogonal to the known constants and to all k leading
// columns of V, with two passes: for a block with no relation to V.
inline void orthogonalize_against_subspace(Block_lanczos_state& state, Eigen::Index k)
{
  state.null_space.project_out(state.block);
  project_out(state, 0, k, nullptr);
  project_out(state, 0, k, nullptr);
}

// block = Q_new R with Q_new M-orthonormal (Cholesky QR, twice if needed).
// Returns false when the block is too ill-conditioned for it.
inline bool cholesky_qr(Block_lanczos_state& state, Eigen::MatrixXd& R)
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

// block = Q_new R for a block M-orthogonal to the k leading columns of V,
// whatever its rank: a pivoted Householder QR finds the directions the
// block lacks (the Krylov subspace contains an invariant subspace, e.g.
// converged eigenvectors of a repeated eigenvalue); they are replaced by
// random directions with a zero coupling, which keeps T exact (deflation).
// Returns true when the block had full rank.
inline bool normalize_block(Block_lanczos_state& state, Eigen::Index k, Eigen::MatrixXd& R)
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

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_BLOCK_ORTHOGONALIZATION_H

// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_LINEAR_ALGEBRA_SPARSE_TIMES_DENSE_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_LINEAR_ALGEBRA_SPARSE_TIMES_DENSE_H

#include <CGAL/Spectral_deformation/internal/available_threads.h>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <algorithm>

namespace CGAL {
namespace Spectral_deformation {
namespace internal {
namespace Linear_algebra {

/// Calls `consume(first, width, buffer)` with A times each block of
/// `width` (at most eight) columns of H starting at column `first`, for a
/// column-major sparse A and a dense H with many columns (a basis, n × m),
/// `buffer` a row-major A.rows() × 8 matrix of which the first `width`
/// columns hold the product. Eigen's product makes one pass over A for each
/// column of H; here each pass serves a block, accumulated in a row-major
/// buffer so that a nonzero of A updates one cache line whatever the
/// ordering of the vertices, and the blocks are shared by the OpenMP threads
/// (`consume` is called from them). Every entry sums the same terms in the
/// same order as Eigen's product (the columns of A in ascending order), so
/// the products do not depend on the number of threads.
template <class Matrix, class Consume>
void for_each_column_block_product(const Eigen::SparseMatrix<double>& A, const Matrix& H, const Consume& consume)
{
  constexpr Eigen::Index block_columns = 8;
  typedef Eigen::Matrix<double, Eigen::Dynamic, block_columns, Eigen::RowMajor> Row_block;
  eigen_assert(A.cols() == H.rows());
  const long long blocks = (H.cols() + block_columns - 1) / block_columns;
#ifdef _OPENMP
#pragma omp parallel if(A.nonZeros() * H.cols() > parallel_sparse_products)
#endif
  {
    Row_block buffer(A.rows(), block_columns);
#ifdef _OPENMP
#pragma omp for schedule(dynamic)
#endif
    for(long long b = 0; b < blocks; ++b)
    {
      const Eigen::Index first = static_cast<Eigen::Index>(b) * block_columns;
      const Eigen::Index width = (std::min)(block_columns, H.cols() - first);
      buffer.setZero();
      Eigen::Matrix<double, 1, block_columns> h = Eigen::Matrix<double, 1, block_columns>::Zero();
      for(Eigen::Index k = 0; k < A.outerSize(); ++k)
      {
        for(Eigen::Index c = 0; c < width; ++c)
          h[c] = static_cast<double>(H(k, first + c));
        for(Eigen::SparseMatrix<double>::InnerIterator it(A, k); it; ++it)
          buffer.row(it.index()) += it.value() * h;
      }
      consume(first, width, static_cast<const Row_block&>(buffer));
    }
  }
}

/// `result` = A H (see `for_each_column_block_product()`).
inline void sparse_times_dense(const Eigen::SparseMatrix<double>& A, const Eigen::MatrixXd& H,
                               Eigen::MatrixXd& result)
{
  result.resize(A.rows(), H.cols());
  for_each_column_block_product(A, H, [&result](Eigen::Index first, Eigen::Index width, const auto& buffer) {
    result.middleCols(first, width) = buffer.leftCols(width);
  });
}

} // namespace Linear_algebra
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_LINEAR_ALGEBRA_SPARSE_TIMES_DENSE_H

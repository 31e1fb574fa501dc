// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_LINEAR_ALGEBRA_OPERATORS_IN_BASIS_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_LINEAR_ALGEBRA_OPERATORS_IN_BASIS_H

#include <CGAL/Spectral_deformation/internal/available_threads.h>
#include <CGAL/Spectral_deformation/internal/Linear_algebra/Dense_products.h>
#include <CGAL/Spectral_deformation/internal/Linear_algebra/Sparse_times_dense.h>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <algorithm>
#include <array>
#include <type_traits>

namespace CGAL {
namespace Spectral_deformation {
namespace internal {
namespace Linear_algebra {

// The reduced matrices of the iteration, m × m, from an n × m basis H,
// computed without any n × m or n × n intermediate: on large regions those
// intermediates were the largest transient memory of the region's
// preparation, and every one of their pages was touched for the first time.

/// `result` = (A H)ᵀ (A H), the m × m Gram matrix of the operator A (rows ×
/// n) in the basis H (n × m), with A given by `row_value(r, h)`, row `r` of A
/// applied to one column `h` of H (a pointer to its n values, double or
/// float as H stores them). The rows of
/// A H are computed by blocks into a small buffer, each block added to a
/// partial sum as a rank update; the rows are split into a fixed number of
/// ranges, each summed by one thread and the ranges added in order, so that
/// the result does not depend on the number of threads.
template <class RowValue, typename Scalar>
void gram_in_basis(Eigen::Index rows, const RowValue& row_value,
                   const Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>& H, Eigen::MatrixXd& result)
{
  constexpr int ranges = 8;
  constexpr Eigen::Index block_rows = 256;
  const Eigen::Index m = H.cols();
  const Eigen::Index range_rows = (rows + ranges - 1) / ranges;
  std::array<Eigen::MatrixXd, ranges> partial;
#ifdef _OPENMP
#pragma omp parallel for schedule(dynamic) if(rows * m > parallel_operator_entries)
#endif
  for(int range = 0; range < ranges; ++range)
  {
    Eigen::MatrixXd& sum = partial[static_cast<std::size_t>(range)];
    sum.setZero(m, m);
    Eigen::MatrixXd block(block_rows, m);
    const Eigen::Index end = (std::min)(rows, (range + 1) * range_rows);
    for(Eigen::Index first = range * range_rows; first < end; first += block_rows)
    {
      const Eigen::Index count = (std::min)(block_rows, end - first);
      for(Eigen::Index j = 0; j < m; ++j)
      {
        const Scalar* h = H.col(j).data();
        for(Eigen::Index r = 0; r < count; ++r)
          block(r, j) = row_value(first + r, h);
      }
      sum.selfadjointView<Eigen::Lower>().rankUpdate(block.topRows(count).transpose());
    }
  }
  result.setZero(m, m);
  for(const Eigen::MatrixXd& sum : partial)
    result += sum;
  result = result.selfadjointView<Eigen::Lower>();
}

/// `result` = Hᵀ A H for a symmetric sparse n × n matrix A and a basis H
/// (n × m): A times blocks of columns of H (`for_each_column_block_product()`),
/// each block multiplied by the transpose of the columns of H from the
/// block's first one on, so that A H is never stored and only the lower
/// triangle is summed (the result is symmetric to the last bit; for an A
/// that is not symmetric it would be the mirror of the lower half). A float H is widened by blocks of rows: Eigen
/// would widen all of it for the product.
template <typename Scalar>
void sparse_in_basis(const Eigen::SparseMatrix<double>& A,
                     const Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>& H, Eigen::MatrixXd& result)
{
  eigen_assert(A.rows() == H.rows());
  eigen_assert((A - Eigen::SparseMatrix<double>(A.transpose())).norm() <= 1e-12 * A.norm());
  const Eigen::Index m = H.cols();
  result.setZero(m, m);
  for_each_column_block_product(A, H, [&result, &H, m](Eigen::Index first, Eigen::Index width, const auto& buffer) {
    auto lower = result.block(first, first, m - first, width);
    if constexpr(std::is_same<Scalar, double>::value)
    {
#ifdef CGAL_SSMD_USE_BLAS
      // The row-major n × 8 buffer is the column-major 8 × n matrix of its
      // transpose.
      const Eigen::Map<const Eigen::MatrixXd, 0, Eigen::OuterStride<>> transposed(
          buffer.data(), buffer.cols(), buffer.rows(), Eigen::OuterStride<>(buffer.cols()));
      dense_product(true, H.rightCols(m - first), true, transposed.topRows(width), 1.0, 0.0, lower);
#else
      lower.noalias() = H.rightCols(m - first).transpose() * buffer.leftCols(width);
#endif
    }
    else
    {
      constexpr Eigen::Index block_rows = 4096;
      Eigen::MatrixXd widened;
      for(Eigen::Index start = 0; start < H.rows(); start += block_rows)
      {
        const Eigen::Index count = (std::min)(block_rows, H.rows() - start);
        if(count != widened.rows())
          widened.resize(0, 0); // see Sequential_basis_rows: no dangling buffer after a failed allocation
        widened = H.block(start, first, count, m - first).template cast<double>();
        lower.noalias() += widened.transpose() * buffer.block(start, 0, count, width);
      }
    }
  });
  result = result.selfadjointView<Eigen::Lower>();
}

} // namespace Linear_algebra
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_LINEAR_ALGEBRA_OPERATORS_IN_BASIS_H

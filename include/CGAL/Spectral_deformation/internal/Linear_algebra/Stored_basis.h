// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_LINEAR_ALGEBRA_STORED_BASIS_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_LINEAR_ALGEBRA_STORED_BASIS_H

#include <CGAL/Spectral_deformation/internal/available_threads.h>

#include <Eigen/Core>

#ifdef _OPENMP
#include <omp.h>
#endif

#include <algorithm>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Spectral_deformation {
namespace internal {
namespace Linear_algebra {

// The two products of every iteration with a basis H (n×m), S = H C and
// Hᵀ X, both with three columns, by blocks of rows: a block of S or X stays
// in the first-level cache while the block of H streams through once.
// Eigen's general products pack H into blocks first, which costs about as
// much as the product itself when the other factor has three columns.
// `block_of(start, rows)` gives the rows [start, start + rows) of H; the
// blocks are shared by the threads of an OpenMP team when the code is
// compiled with OpenMP. A float block is widened to double: the arithmetic
// is in double whatever the storage, since the right-hand sides of the
// iteration are sums with heavy cancellation (L̂F annihilates the
// constants), which float accumulation would spoil.
namespace row_blocks {

typedef Eigen::Matrix<double, Eigen::Dynamic, 3> Columns3;
// The same n×3 values one column per vertex (3×n), as the rotation fit of
// the detail transfer reads them.
typedef Eigen::Matrix<double, 3, Eigen::Dynamic> Rows3;

inline void resize(Columns3& shape, Eigen::Index n) { shape.resize(n, 3); }
inline void resize(Rows3& shape, Eigen::Index n) { shape.resize(3, n); }

template <typename Block>
void store(const Block& block, Eigen::Index start, Columns3& shape)
{
  shape.middleRows(start, block.rows()) = block;
}
template <typename Block>
void store(const Block& block, Eigen::Index start, Rows3& shape)
{
  shape.middleCols(start, block.rows()) = block.transpose();
}

// A float column is widened once into `buffer` rather than inside every
// expression that reads it: Eigen re-evaluates a lazy cast at each use.
template <typename Column, typename Buffer>
auto in_double(const Column& column, Buffer& buffer)
{
  if constexpr(std::is_same<typename Column::Scalar, double>::value)
  {
    (void)buffer;
    return column;
  }
  else
  {
    buffer.head(column.rows()) = column.template cast<double>();
    return buffer.head(column.rows());
  }
}

template <Eigen::Index BlockRows, typename BlockOf, typename Coefficients, typename Shape>
void multiply(Eigen::Index n, Eigen::Index m, const BlockOf& block_of, const Coefficients& coefficients,
              Shape& shape)
{
  resize(shape, n);
  const Eigen::Matrix<double, Eigen::Dynamic, 3> c = coefficients;
  const long long blocks = (n + BlockRows - 1) / BlockRows;
#ifdef _OPENMP
#pragma omp parallel for schedule(static) if(n * m > parallel_basis_entries)
#endif
  for(long long b = 0; b < blocks; ++b)
  {
    const Eigen::Index start = static_cast<Eigen::Index>(b) * BlockRows;
    const auto h = block_of(start, (std::min)(BlockRows, n - start));
    Eigen::Matrix<double, BlockRows, 3> block;
    auto s = block.topRows(h.rows());
    s.setZero();
    // Column updates (axpy) rather than row dot products: no horizontal
    // reduction per row, and each column of the block is read in order.
    Eigen::Matrix<double, BlockRows, 1> widened;
    for(Eigen::Index k = 0; k < m; ++k)
    {
      const auto column = in_double(h.col(k), widened);
      s.col(0) += c(k, 0) * column;
      s.col(1) += c(k, 1) * column;
      s.col(2) += c(k, 2) * column;
    }
    store(s, start, shape);
  }
}

// Each thread sums its own contiguous range of blocks and the partial sums
// are added in thread order, so that a given number of threads always gives
// the same result.
template <Eigen::Index BlockRows, typename BlockOf, typename Values>
void multiply_transpose(Eigen::Index n, Eigen::Index m, const BlockOf& block_of, const Values& values,
                        Eigen::MatrixXd& result)
{
  const long long blocks = (n + BlockRows - 1) / BlockRows;
  std::vector<Eigen::MatrixXd> partial(1);
#ifdef _OPENMP
#pragma omp parallel if(n * m > parallel_basis_entries)
#endif
  {
    int thread = 0;
#ifdef _OPENMP
#pragma omp single
    partial.resize(static_cast<std::size_t>(omp_get_num_threads()));
    thread = omp_get_thread_num();
#endif
    Eigen::MatrixXd sum = Eigen::MatrixXd::Zero(m, 3);
    Eigen::Matrix<double, Eigen::Dynamic, 3> block_sum(m, 3);
    Eigen::Matrix<double, BlockRows, 3> block;
    Eigen::Matrix<double, BlockRows, 1> widened;
#ifdef _OPENMP
#pragma omp for schedule(static)
#endif
    for(long long b = 0; b < blocks; ++b)
    {
      const Eigen::Index start = static_cast<Eigen::Index>(b) * BlockRows;
      const auto h = block_of(start, (std::min)(BlockRows, n - start));
      auto x = block.topRows(h.rows());
      x = values.middleRows(start, h.rows());
      if constexpr(std::is_same<typename std::decay_t<decltype(h)>::Scalar, double>::value)
        block_sum.noalias() = h.transpose().lazyProduct(x);
      else
        for(Eigen::Index k = 0; k < m; ++k)
          block_sum.row(k).noalias() = in_double(h.col(k), widened).transpose().lazyProduct(x);
      sum += block_sum;
    }
    partial[static_cast<std::size_t>(thread)].swap(sum);
  }
  result.setZero(m, 3);
  for(const Eigen::MatrixXd& sum : partial)
    if(sum.size() != 0)
      result += sum;
}

} // namespace row_blocks

/// The basis H (n×m) of a deformation, kept by columns in double or, to
/// halve its memory on large regions, in float, and the two products of the
/// iteration, read straight from it. Blocks of a few hundred rows make each
/// of the m column pieces of a block long enough for the hardware
/// prefetcher, so that this layout streams about as fast as a copy stored
/// by panels of contiguous rows (measured), without the copy's bytes.
///
/// A float basis is not a rounded copy of a double one: everything the
/// deformation derives from H (the reduced matrices, the smooth rest shape,
/// the constrained rows) is computed from the stored values, widened to
/// double, so the reduced system stays consistent at rest and the rounding
/// only perturbs the subspace, by about 10⁻⁷ of each function.
class Stored_basis
{
public:
  typedef row_blocks::Columns3 Columns3;

  Stored_basis() = default;

  /// Takes `basis`, kept in float when `single_precision`; `basis` is left
  /// empty.
  void assign(Eigen::MatrixXd&& basis, bool single_precision)
  {
    if(single_precision)
    {
      m_float = basis.cast<float>();
      m_double = Eigen::MatrixXd();
    }
    else
    {
      m_double.swap(basis);
      m_float = Eigen::MatrixXf();
    }
    basis = Eigen::MatrixXd();
    m_single = single_precision;
  }

  /// Takes `basis`, kept in float; `basis` is left empty.
  void assign(Eigen::MatrixXf&& basis)
  {
    m_float.swap(basis);
    m_double = Eigen::MatrixXd();
    basis = Eigen::MatrixXf();
    m_single = true;
  }

  bool empty() const { return rows() == 0; }
  bool single_precision() const { return m_single; }
  Eigen::Index rows() const { return m_single ? m_float.rows() : m_double.rows(); }
  Eigen::Index cols() const { return m_single ? m_float.cols() : m_double.cols(); }
  std::size_t bytes() const
  {
    return static_cast<std::size_t>(m_double.size()) * sizeof(double) +
           static_cast<std::size_t>(m_float.size()) * sizeof(float);
  }

  /// Calls `visitor` with the stored matrix (`Eigen::MatrixXd` or
  /// `Eigen::MatrixXf`) and returns what it returns.
  template <class Visitor>
  decltype(auto) visit(Visitor&& visitor) const
  {
    if(m_single)
      return visitor(m_float);
    return visitor(m_double);
  }

  /// Row `i` of H, in double.
  Eigen::RowVectorXd row(Eigen::Index i) const
  {
    return visit([i](const auto& H) { return Eigen::RowVectorXd(H.row(i).template cast<double>()); });
  }

  /// `shape` = H `coefficients` (n×3, or its transpose when `Shape` is
  /// `row_blocks::Rows3`), `coefficients` m×3; `shape` must not alias
  /// `coefficients`.
  template <typename Coefficients, typename Shape>
  void multiply(const Coefficients& coefficients, Shape& shape) const
  {
    visit([&](const auto& H) {
      row_blocks::multiply<512>(H.rows(), H.cols(), block_of(H), coefficients, shape);
    });
  }

  /// `result` = Hᵀ `values` (m×3), `values` n×3.
  template <typename Values>
  void multiply_transpose(const Values& values, Eigen::MatrixXd& result) const
  {
    visit([&](const auto& H) {
      row_blocks::multiply_transpose<128>(H.rows(), H.cols(), block_of(H), values, result);
    });
  }

private:
  template <typename Matrix>
  static auto block_of(const Matrix& H)
  {
    return [&H](Eigen::Index start, Eigen::Index count) { return H.middleRows(start, count); };
  }

  Eigen::MatrixXd m_double;
  Eigen::MatrixXf m_float;
  bool m_single = false;
};

} // namespace Linear_algebra
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_LINEAR_ALGEBRA_STORED_BASIS_H

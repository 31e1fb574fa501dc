// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_LINEAR_ALGEBRA_BASIS_PANELS_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_LINEAR_ALGEBRA_BASIS_PANELS_H

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

/// A copy of a basis H (n×m) laid out for the two products of every
/// iteration, S = H C and Hᵀ X with three columns: the rows are cut into
/// panels of `panel_rows` rows, each panel stored by columns in one
/// contiguous block. Both products then stream through H once, in memory
/// order, with a panel of S or X in the first-level cache. Eigen's general
/// products pack H into blocks first, which costs about as much as the
/// product itself when the other factor has three columns. The panels are
/// shared by the threads of an OpenMP team when the code is compiled with
/// OpenMP.
///
/// `Scalar` is the storage type (`double`, or `float` to halve the memory
/// traffic). The arithmetic is in double whatever the storage: the
/// right-hand sides of the iteration are sums with heavy cancellation (L̂F
/// annihilates the constants), which float accumulation would spoil.
template <typename Scalar>
class Basis_panels
{
public:
  typedef Eigen::Matrix<double, Eigen::Dynamic, 3> Columns3;
  static constexpr Eigen::Index panel_rows = 128;

  Basis_panels() = default;

  explicit Basis_panels(const Eigen::MatrixXd& basis) { assign(basis); }

  void assign(const Eigen::MatrixXd& basis)
  {
    m_rows = basis.rows();
    m_cols = basis.cols();
    m_data.assign(static_cast<std::size_t>(m_rows * m_cols), Scalar(0));
    for(Eigen::Index start = 0; start < m_rows; start += panel_rows)
      panel(start) = basis.middleRows(start, panel_height(start)).template cast<Scalar>();
  }

  Eigen::Index rows() const { return m_rows; }
  Eigen::Index cols() const { return m_cols; }
  std::size_t bytes() const { return m_data.size() * sizeof(Scalar); }

  /// `shape` = H `coefficients` (n×3), `coefficients` m×3; `shape` must not
  /// alias `coefficients`.
  template <typename Coefficients>
  void multiply(const Coefficients& coefficients, Columns3& shape) const
  {
    shape.resize(m_rows, 3);
    const Eigen::Matrix<double, Eigen::Dynamic, 3> c = coefficients;
    const long long panels = number_of_panels();
#ifdef _OPENMP
#pragma omp parallel for schedule(static) if(m_rows * m_cols > 100000)
#endif
    for(long long p = 0; p < panels; ++p)
    {
      const Eigen::Index start = static_cast<Eigen::Index>(p) * panel_rows;
      const auto h = panel(start);
      Eigen::Matrix<double, panel_rows, 3> block;
      auto s = block.topRows(h.rows());
      s.setZero();
      // Column updates (axpy) rather than row dot products: no horizontal
      // reduction per row, and the panel is read once in memory order.
      Eigen::Matrix<double, panel_rows, 1> widened;
      for(Eigen::Index k = 0; k < m_cols; ++k)
      {
        const auto column = in_double(h.col(k), widened);
        s.col(0) += c(k, 0) * column;
        s.col(1) += c(k, 1) * column;
        s.col(2) += c(k, 2) * column;
      }
      shape.middleRows(start, h.rows()) = s;
    }
  }

  /// `result` = Hᵀ `values` (m×3), `values` n×3. Each thread sums its own
  /// contiguous range of panels and the partial sums are added in thread
  /// order, so that a given number of threads always gives the same result.
  template <typename Values>
  void multiply_transpose(const Values& values, Eigen::MatrixXd& result) const
  {
    const long long panels = number_of_panels();
    std::vector<Eigen::MatrixXd> partial(1);
#ifdef _OPENMP
#pragma omp parallel if(m_rows * m_cols > 100000)
#endif
    {
      int thread = 0;
#ifdef _OPENMP
#pragma omp single
      partial.resize(static_cast<std::size_t>(omp_get_num_threads()));
      thread = omp_get_thread_num();
#endif
      Eigen::MatrixXd sum = Eigen::MatrixXd::Zero(m_cols, 3);
      Eigen::Matrix<double, Eigen::Dynamic, 3> panel_sum(m_cols, 3);
      Eigen::Matrix<double, panel_rows, 3> block;
      Eigen::Matrix<double, panel_rows, 1> widened;
#ifdef _OPENMP
#pragma omp for schedule(static)
#endif
      for(long long p = 0; p < panels; ++p)
      {
        const Eigen::Index start = static_cast<Eigen::Index>(p) * panel_rows;
        const auto h = panel(start);
        auto x = block.topRows(h.rows());
        x = values.middleRows(start, h.rows());
        if constexpr(std::is_same<Scalar, double>::value)
          panel_sum.noalias() = h.transpose().lazyProduct(x);
        else
          for(Eigen::Index k = 0; k < m_cols; ++k)
            panel_sum.row(k).noalias() = in_double(h.col(k), widened).transpose().lazyProduct(x);
        sum += panel_sum;
      }
      partial[static_cast<std::size_t>(thread)].swap(sum);
    }
    result.setZero(m_cols, 3);
    for(const Eigen::MatrixXd& sum : partial)
      if(sum.size() != 0)
        result += sum;
  }

private:
  // A float column is widened once into `buffer` rather than inside every
  // expression that reads it: Eigen re-evaluates a lazy cast at each use.
  template <typename Column>
  static auto in_double(const Column& column, Eigen::Matrix<double, panel_rows, 1>& buffer)
  {
    if constexpr(std::is_same<Scalar, double>::value)
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

  long long number_of_panels() const { return (m_rows + panel_rows - 1) / panel_rows; }
  Eigen::Index panel_height(Eigen::Index start) const { return (std::min)(panel_rows, m_rows - start); }

  Eigen::Map<Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>> panel(Eigen::Index start)
  {
    return {m_data.data() + start * m_cols, panel_height(start), m_cols};
  }
  Eigen::Map<const Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>> panel(Eigen::Index start) const
  {
    return {m_data.data() + start * m_cols, panel_height(start), m_cols};
  }

  Eigen::Index m_rows = 0;
  Eigen::Index m_cols = 0;
  std::vector<Scalar> m_data;
};

} // namespace Linear_algebra
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_LINEAR_ALGEBRA_BASIS_PANELS_H

// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_LINEAR_ALGEBRA_DIRICHLET_SYSTEM_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_LINEAR_ALGEBRA_DIRICHLET_SYSTEM_H

#include <CGAL/Spectral_deformation/internal/Memory/Process_wide_tuning.h>

#include <Eigen/Dense>

#include <Eigen/Sparse>

#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Spectral_deformation {
namespace internal {
namespace Linear_algebra {

using Memory::set_process_wide_tuning_if_supported;

/// Whether a sparse solver can report a fill-reducing ordering of a matrix
/// and take one for its next factorization (`Cholmod_llt_solver_traits`).
template <class Solver, class = void>
struct Takes_fill_reducing_ordering : std::false_type
{
};
template <class Solver>
struct Takes_fill_reducing_ordering<
    Solver, std::void_t<decltype(std::declval<Solver&>().fill_reducing_ordering(
                            std::declval<const Eigen::SparseMatrix<double>&>())),
                        decltype(std::declval<Solver&>().set_fill_reducing_ordering(std::vector<int>()))>>
  : std::true_type
{
};

/// A symmetric positive semi-definite system A X = B in which some unknowns
/// are prescribed: A is restricted to the free unknowns and factored once,
/// the prescribed values enter the right-hand side.
///
/// When the solver takes a fill-reducing ordering, every factorization of
/// the same matrix (until `forget_matrix()`) uses one ordering of the whole
/// matrix (`fill_reducing_ordering()`), restricted to the free unknowns,
/// instead of choosing a new one for each free block: on a large mesh,
/// choosing the ordering costs several times the numeric factorization, and
/// the solver's choice for the whole matrix weighs nested dissection, which
/// its default choice for a block skips on these systems.
template <class SparseSPDSolverTraits>
class Dirichlet_system
{
public:
  /// Factors the free block of `A`; `prescribed[i]` flags unknown i. Later
  /// calls must pass the same `A` until `forget_matrix()`.
  bool factor(const Eigen::SparseMatrix<double>& A, const std::vector<char>& prescribed)
  {
    const Eigen::Index n = A.rows();
    m_free.clear();
    m_free_index.assign(static_cast<std::size_t>(n), -1);
    for(Eigen::Index i = 0; i < n; ++i)
      if(!prescribed[static_cast<std::size_t>(i)])
      {
        m_free_index[static_cast<std::size_t>(i)] = static_cast<int>(m_free.size());
        m_free.push_back(static_cast<int>(i));
      }
    std::vector<Eigen::Triplet<double>> inner, outer;
    for(int k = 0; k < A.outerSize(); ++k)
      for(Eigen::SparseMatrix<double>::InnerIterator it(A, k); it; ++it)
      {
        const int r = m_free_index[static_cast<std::size_t>(it.row())];
        if(r < 0)
          continue;
        const int c = m_free_index[static_cast<std::size_t>(it.col())];
        if(c >= 0)
          inner.emplace_back(r, c, it.value());
        else
          outer.emplace_back(r, static_cast<int>(it.col()), it.value());
      }
    const Eigen::Index m = static_cast<Eigen::Index>(m_free.size());
    Eigen::SparseMatrix<double> free_block(m, m);
    free_block.setFromTriplets(inner.begin(), inner.end());
    m_coupling.resize(m, n);
    m_coupling.setFromTriplets(outer.begin(), outer.end());
    if(m == 0)
      return true;
    if constexpr(Takes_fill_reducing_ordering<SparseSPDSolverTraits>::value)
    {
      if(!m_ordered)
      {
        m_whole_ordering = m_solver.fill_reducing_ordering(A);
        m_ordered = true;
      }
      if(static_cast<Eigen::Index>(m_whole_ordering.size()) == n)
      {
        std::vector<int> restricted;
        restricted.reserve(static_cast<std::size_t>(m));
        for(int i : m_whole_ordering)
          if(m_free_index[static_cast<std::size_t>(i)] >= 0)
            restricted.push_back(m_free_index[static_cast<std::size_t>(i)]);
        m_solver.set_fill_reducing_ordering(std::move(restricted));
      }
    }
    return m_solver.factor(free_block);
  }

  /// The next `factor()` may pass another matrix.
  void forget_matrix()
  {
    m_whole_ordering.clear();
    m_ordered = false;
  }

  /// Solves with the right-hand side `rhs` (n×d) and the values of the
  /// prescribed unknowns taken from `prescribed_values` (n×d, other rows
  /// ignored); `out` is n×d with the prescribed rows copied. `out` may be
  /// `prescribed_values` itself.
  template <class Values, class Out>
  bool solve(const Eigen::MatrixXd& rhs, const Values& prescribed_values, Out& out) const
  {
    const Eigen::Index m = static_cast<Eigen::Index>(m_free.size());
    // The buffers are kept between calls: on large meshes, fresh pages for
    // them cost more than the arithmetic.
    Eigen::MatrixXd& b = m_free_rhs;
    Eigen::MatrixXd& x = m_free_solution;
    if(m > 0)
    {
      // The coupling block has prescribed columns only: free rows are not read.
      m_coupled.noalias() = m_coupling * prescribed_values;
      b.resize(m, rhs.cols());
      for(Eigen::Index r = 0; r < m; ++r)
        b.row(r) = rhs.row(m_free[static_cast<std::size_t>(r)]) - m_coupled.row(r);
    }
    if(static_cast<const void*>(&out) != static_cast<const void*>(&prescribed_values))
      out = prescribed_values;
    if(m == 0)
      return true;
    if(!m_solver.solve(b, x))
      return false;
    for(Eigen::Index r = 0; r < m; ++r)
      out.row(m_free[static_cast<std::size_t>(r)]) = x.row(r);
    return true;
  }

  /// Hands the permission to change process-wide state to the solver
  /// (`SparseSPDSolverTraits::set_process_wide_tuning()`, when it has it).
  void set_process_wide_tuning(bool enabled) { set_process_wide_tuning_if_supported(m_solver, enabled); }

private:
  SparseSPDSolverTraits m_solver;
  // One ordering of the whole matrix (empty when the solver found none), and
  // whether it was sought.
  std::vector<int> m_whole_ordering;
  bool m_ordered = false;
  std::vector<int> m_free;
  std::vector<int> m_free_index;
  Eigen::SparseMatrix<double> m_coupling;
  mutable Eigen::MatrixXd m_coupled, m_free_rhs, m_free_solution;
};

} // namespace Linear_algebra
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_LINEAR_ALGEBRA_DIRICHLET_SYSTEM_H

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

/// A symmetric positive semi-definite system A X = B in which some unknowns
/// are prescribed. The matrix factored is A with the rows and columns of the
/// prescribed unknowns replaced by those of the identity, whose right-hand
/// side is the prescribed values; their coupling to the free unknowns moves
/// to the right-hand side.
///
/// Keeping every unknown in the factored matrix lets a new set of prescribed
/// unknowns that differs from the last one in a few of them update the
/// factor (when the solver can, see the tag `Supports_row_updates` of
/// SparseSPDSolverTraits) instead of factoring
/// anew. When the solver takes a fill-reducing ordering, every factorization
/// of the same matrix (until `forget_matrix()`) uses one ordering of the
/// whole matrix (`fill_reducing_ordering()`) instead of choosing a new one
/// for each set: on a large mesh, choosing the ordering costs several times
/// the numeric factorization, and the solver's choice for the whole matrix
/// weighs nested dissection, which its default choice for a block skips on
/// these systems.
template <class SparseSPDSolverTraits>
class Dirichlet_system
{
public:
  /// Factors for the unknowns flagged in `prescribed`. Later calls must
  /// pass the same `A` until `forget_matrix()`.
  bool factor(const Eigen::SparseMatrix<double>& A, const std::vector<char>& prescribed)
  {
    const Eigen::Index n = A.rows();
    std::vector<int> changed;
    const bool same_size = m_factored && m_prescribed.size() == prescribed.size();
    if(same_size)
      for(std::size_t i = 0; i < prescribed.size(); ++i)
        if((prescribed[i] != 0) != (m_prescribed[i] != 0))
          changed.push_back(static_cast<int>(i));
    m_factored = false;
    m_prescribed.assign(prescribed.begin(), prescribed.end());
    m_prescribed_list.clear();
    for(Eigen::Index i = 0; i < n; ++i)
      if(prescribed[static_cast<std::size_t>(i)])
        m_prescribed_list.push_back(static_cast<int>(i));
    Eigen::SparseMatrix<double> system;
    split(A, prescribed, system, m_coupling);
    if(n == 0)
      return m_factored = true;
    if constexpr(Declares_Supports_fill_reducing_ordering<SparseSPDSolverTraits>::value)
    {
      if(!m_ordered)
      {
        m_whole_ordering = m_solver.fill_reducing_ordering(A);
        m_ordered = true;
      }
      if(static_cast<Eigen::Index>(m_whole_ordering.size()) == n)
        m_solver.set_fill_reducing_ordering(m_whole_ordering);
    }
    if constexpr(Declares_Supports_row_updates<SparseSPDSolverTraits>::value)
    {
      if(same_size)
        return m_factored = m_solver.refactor_rows(system, changed);
    }
    return m_factored = m_solver.factor(system);
  }

  /// The next `factor()` may pass another matrix.
  void forget_matrix()
  {
    m_whole_ordering.clear();
    m_ordered = false;
    m_factored = false;
    m_prescribed.clear();
  }

  /// Solves with the right-hand side `rhs` (n×d) and the values of the
  /// prescribed unknowns taken from `prescribed_values` (n×d, other rows
  /// ignored); `out` is n×d with the prescribed rows copied. `out` may be
  /// `prescribed_values` itself.
  template <class Values, class Out>
  bool solve(const Eigen::MatrixXd& rhs, const Values& prescribed_values, Out& out) const
  {
    if(!m_factored || rhs.rows() != static_cast<Eigen::Index>(m_prescribed.size()))
      return false;
    // The buffer is kept between calls: on large meshes, fresh pages for it
    // cost more than the arithmetic.
    Eigen::MatrixXd& b = m_right_hand_side;
    b = rhs;
    // The coupling has prescribed columns only: free rows of the values are not read.
    b.noalias() -= m_coupling * prescribed_values;
    for(int i : m_prescribed_list)
      b.row(i) = prescribed_values.row(i);
    if(rhs.rows() == 0)
    {
      out = b;
      return true;
    }
    if constexpr(std::is_same<Out, Eigen::MatrixXd>::value)
    {
      if(!m_solver.solve(b, out))
        return false;
    }
    else
    {
      if(!m_solver.solve(b, m_solution))
        return false;
      out = m_solution;
    }
    // The identity's rows return their values up to the factor's rounding:
    // the prescribed unknowns get theirs bit for bit.
    if(static_cast<const void*>(&out) != static_cast<const void*>(&prescribed_values))
      for(int i : m_prescribed_list)
        out.row(i) = prescribed_values.row(i);
    return true;
  }

  /// Hands the permission to change process-wide state to the solver
  /// (`SparseSPDSolverTraits::set_process_wide_tuning()`, when it has it).
  void set_process_wide_tuning(bool enabled) { set_process_wide_tuning_if_supported(m_solver, enabled); }

  /// The solver, for its settings.
  SparseSPDSolverTraits& solver() { return m_solver; }

private:
  // The system (the identity's rows and columns for the prescribed unknowns,
  // A's entries between free ones) and the coupling (A's entries of free
  // rows in prescribed columns), written straight into compressed storage in
  // two passes over A: a new constraint set whose factor is updated, not made
  // anew, does little else of order n.
  static void split(const Eigen::SparseMatrix<double>& A, const std::vector<char>& prescribed,
                    Eigen::SparseMatrix<double>& system, Eigen::SparseMatrix<double>& coupling)
  {
    typedef Eigen::SparseMatrix<double>::StorageIndex Index;
    const Eigen::Index n = A.rows();
    const auto free_row = [&prescribed](Index i) { return prescribed[static_cast<std::size_t>(i)] == 0; };
    system.resize(n, n);
    coupling.resize(n, n);
    system.makeCompressed();
    coupling.makeCompressed();
    Index* system_start = system.outerIndexPtr();
    Index* coupling_start = coupling.outerIndexPtr();
    // Entries per column, then their offsets.
    system_start[0] = coupling_start[0] = 0;
    for(Eigen::Index j = 0; j < n; ++j)
    {
      Index free_entries = 0;
      for(Eigen::SparseMatrix<double>::InnerIterator it(A, j); it; ++it)
        free_entries += free_row(static_cast<Index>(it.row())) ? 1 : 0;
      const bool fixed = !free_row(static_cast<Index>(j));
      system_start[j + 1] = system_start[j] + (fixed ? 1 : free_entries);
      coupling_start[j + 1] = coupling_start[j] + (fixed ? free_entries : 0);
    }
    system.resizeNonZeros(system_start[n]);
    coupling.resizeNonZeros(coupling_start[n]);
    Index* system_rows = system.innerIndexPtr();
    double* system_values = system.valuePtr();
    Index* coupling_rows = coupling.innerIndexPtr();
    double* coupling_values = coupling.valuePtr();
    for(Eigen::Index j = 0; j < n; ++j)
    {
      const bool fixed = !free_row(static_cast<Index>(j));
      Index k = fixed ? coupling_start[j] : system_start[j];
      Index* rows = fixed ? coupling_rows : system_rows;
      double* values = fixed ? coupling_values : system_values;
      for(Eigen::SparseMatrix<double>::InnerIterator it(A, j); it; ++it)
        if(free_row(static_cast<Index>(it.row())))
        {
          rows[k] = static_cast<Index>(it.row());
          values[k] = it.value();
          ++k;
        }
      if(fixed)
      {
        system_rows[system_start[j]] = static_cast<Index>(j);
        system_values[system_start[j]] = 1.0;
      }
    }
  }

  SparseSPDSolverTraits m_solver;
  // One ordering of the whole matrix (empty when the solver found none), and
  // whether it was sought.
  std::vector<int> m_whole_ordering;
  bool m_ordered = false;
  bool m_factored = false;
  std::vector<char> m_prescribed;     // the flags of the last factor()
  std::vector<int> m_prescribed_list; // their indices
  Eigen::SparseMatrix<double> m_coupling; // free rows, prescribed columns
  mutable Eigen::MatrixXd m_right_hand_side, m_solution;
};

} // namespace Linear_algebra
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_LINEAR_ALGEBRA_DIRICHLET_SYSTEM_H

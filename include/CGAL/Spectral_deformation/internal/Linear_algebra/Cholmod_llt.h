// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_LINEAR_ALGEBRA_CHOLMOD_LLT_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_LINEAR_ALGEBRA_CHOLMOD_LLT_H

#include <CGAL/Spectral_deformation/internal/Linear_algebra/Cholmod_factorization.h>
#include <CGAL/Spectral_deformation/internal/Linear_algebra/Two_subtree_triangular_solve.h>
#include <CGAL/Spectral_deformation/internal/Memory/Cholmod_huge_page_allocator.h>
#include <CGAL/Spectral_deformation/internal/available_threads.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <cholmod.h>

#include <cstddef>
#include <exception>
#include <utility>
#include <vector>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace CGAL {
namespace Spectral_deformation {
namespace internal {
namespace Linear_algebra {

// The implementation of `Cholmod_llt_solver_traits` (see there for what each
// member does and why): a CHOLMOD factor in supernodal or simplicial form,
// the work arrays of its solves kept between calls, the solves split
// between two threads, and the row updates of a simplicial factor.
template <bool Supernodal>
class Cholmod_llt
{
public:
  typedef Eigen::SparseMatrix<double> Matrix;
  typedef Eigen::MatrixXd Dense_matrix;

  Cholmod_llt() : m_solver(Supernodal) { cholmod_start(&m_second_common); }
  // A CHOLMOD factor has a single owner.
  Cholmod_llt(const Cholmod_llt&) = delete;
  Cholmod_llt& operator=(const Cholmod_llt&) = delete;
  ~Cholmod_llt()
  {
    release_work_arrays();
    cholmod_finish(&m_second_common);
  }

  double supernodal_factorization_switch() const { return m_supernodal_switch; }

  void set_supernodal_factorization_switch(double flops_per_entry)
  {
    m_supernodal_switch = flops_per_entry;
  }

  bool solves_in_subtrees() const { return m_subtree_solve.usable(); }

  bool process_wide_tuning() const { return m_process_wide_tuning; }

  void set_process_wide_tuning(bool enabled) { m_process_wide_tuning = enabled; }

  std::vector<int> fill_reducing_ordering(const Matrix& A)
  {
    if(A.rows() == 0 || A.nonZeros() == 0)
      return {};
    const Memory::Cholmod_huge_page_allocator huge_pages(
        m_process_wide_tuning);
    return m_solver.ordering_of(A);
  }

  void set_fill_reducing_ordering(std::vector<int> permutation) { m_given_ordering = std::move(permutation); }

  double factor_nonzeros() const { return m_factor_nonzeros; }

  bool factor(const Matrix& A)
  {
    release_work_arrays();
    m_empty = (A.rows() == 0);
    if(A.nonZeros() == 0)
    {
      // CHOLMOD's analysis refuses a matrix without values (see
      // Eigen_sparse_spd_solver_traits::factor()).
      m_factored = m_empty;
      return m_factored;
    }
    const Memory::Cholmod_huge_page_allocator huge_pages(
        m_process_wide_tuning);
    bool computed = false;
    if(!Supernodal)
      m_solver.common().supernodal_switch = m_supernodal_switch;
    std::vector<int> given;
    given.swap(m_given_ordering);
    std::vector<int>* ordering = is_permutation_of_rows(given, A.rows()) ? &given : nullptr;
    if(m_solver.analyze(A, ordering))
    {
#ifdef _OPENMP
      // CHOLMOD's supernodal factorization runs some of its loops on
      // CHOLMOD_OMP_NUM_THREADS (4) threads whatever the machine. Where that
      // is more than the processors, they run on one thread instead, nested
      // in a team of two whose second thread waits (see the class
      // description). A simplicial factorization has no such loops and gets
      // no team: the waiting thread competed with the BLAS threads still
      // spinning after the basis, and the factorization of a 550-vertex
      // region took 3.2-11.7 ms with it, 2.4-2.7 ms without.
      if(m_solver.factor()->is_super && !omp_in_parallel() &&
         omp_get_num_procs() < CHOLMOD_OMP_NUM_THREADS && omp_get_max_active_levels() <= 1)
        run_beside_a_second_thread([&] { computed = m_solver.factorize(A); },
                                   [](const std::atomic<bool>&) {});
      else
#endif
        computed = m_solver.factorize(A);
    }
    m_factored = computed;
    m_rows_updated = false;
    m_factor_nonzeros = computed ? m_solver.common().lnz : 0.0;
    m_factorization_flops = computed ? m_solver.common().fl : 0.0;
    m_update_entries = 0;
    analyze_solves();
    return m_factored;
  }

  double row_update_budget() const { return m_row_update_budget; }

  void set_row_update_budget(double share) { m_row_update_budget = share; }

  bool rows_updated() const { return m_rows_updated; }

  bool refactor_rows(const Matrix& A, const std::vector<int>& rows)
  {
    cholmod_factor* L = m_factored && !m_empty ? m_solver.factor() : nullptr;
    // analyze_solves() found the factor's position of every row exactly
    // when the factor has the simplicial LLᵀ form the updates start from.
    if(Supernodal || L == nullptr || A.cols() != A.rows() ||
       m_factor_position.size() != L->n || A.rows() != static_cast<Eigen::Index>(L->n))
      return factor(A);
    if(rows.empty())
      return true;
    const int n = static_cast<int>(L->n);
    for(int k : rows)
      if(k < 0 || k >= n)
        return factor(A);
    const std::vector<int>& position = m_factor_position;
    // The factor is made anew when this set's updates would cost too much,
    // and after updates worth several budgets, so that the rounding errors
    // of the updates do not pile up without end.
    const double estimate = row_update_entries(*L, A, rows, position);
    if(estimate > m_row_update_budget * m_factorization_flops ||
       m_update_entries + estimate > 10 * m_row_update_budget * m_factorization_flops)
      return factor(A);
    m_update_entries += estimate;
    release_work_arrays();
    const Memory::Cholmod_huge_page_allocator huge_pages(
        m_process_wide_tuning);
    if(!update_rows(A, rows, position))
      return factor(A);
    m_given_ordering.clear(); // meant for a factor() that did not happen
    m_rows_updated = true;
    analyze_solves();
    m_factor_nonzeros = 0;
    const int* counts = static_cast<const int*>(m_solver.factor()->nz);
    for(int j = 0; j < n; ++j)
      m_factor_nonzeros += counts[j];
    return true;
  }

  bool solve(const Dense_matrix& B, Dense_matrix& X) const
  {
    if(!m_factored)
      return false;
    if(m_empty)
    {
      X.resize(0, B.cols());
      return B.rows() == 0;
    }
    if(B.rows() != static_cast<Eigen::Index>(m_solver.factor()->n))
      return false;
    X.resize(B.rows(), B.cols());
    // The work arrays of the first solve are allocated then.
    const Memory::Cholmod_huge_page_allocator huge_pages(
        m_process_wide_tuning);
    // A factor split by subtrees is always solved that way, on one thread
    // when no second is available: the result is then the same whatever the
    // number of threads.
    if(m_subtree_solve.usable())
      return solve_in_subtrees(B, X, available_threads() >= Two_subtree_triangular_solve::number_of_subtrees) &&
             X.allFinite();
    // Otherwise a simplicial factor is solved column by column without the
    // BLAS: two threads each solve half of the right-hand sides against the
    // shared, read-only factor, with their own CHOLMOD workspace (the
    // supernodal solve, which calls the BLAS, was slower that way).
    const Eigen::Index halves =
        (!Supernodal && B.cols() >= 2 &&
         available_threads() >= 2)
            ? 2
            : 1;
    bool success[2] = {true, true};
#ifdef _OPENMP
#pragma omp parallel for num_threads(static_cast<int>(halves)) if(halves > 1)
#endif
    for(int half = 0; half < static_cast<int>(halves); ++half)
    {
      const Eigen::Index first = B.cols() * half / halves;
      const Eigen::Index count = B.cols() * (half + 1) / halves - first;
      success[half] = solve_columns(B, first, count, X, m_work[half],
                                    half == 0 ? &m_solver.common() : &m_second_common);
    }
    return success[0] && success[1] && X.allFinite();
  }

private:
  static bool is_permutation_of_rows(const std::vector<int>& ordering, Eigen::Index rows)
  {
    if(static_cast<Eigen::Index>(ordering.size()) != rows)
      return false;
    std::vector<char> seen(ordering.size(), 0);
    for(int i : ordering)
    {
      if(i < 0 || i >= rows || seen[static_cast<std::size_t>(i)])
        return false;
      seen[static_cast<std::size_t>(i)] = 1;
    }
    return true;
  }

  // The split of the solves by subtrees and the factor's position of every
  // row, for the last factor when it is a simplicial LLᵀ one.
  void analyze_solves()
  {
    m_subtree_solve = Two_subtree_triangular_solve();
    m_factor_position.clear();
    const cholmod_factor* L = m_factored ? m_solver.factor() : nullptr;
    if(!Supernodal && L != nullptr && !L->is_super && L->is_ll &&
       L->itype == CHOLMOD_INT && L->xtype == CHOLMOD_REAL && L->dtype == CHOLMOD_DOUBLE)
    {
      m_subtree_solve.analyze(static_cast<int>(L->n), static_cast<const int*>(L->p),
                              static_cast<const int*>(L->nz),
                              static_cast<const int*>(L->i));
      const int* permutation = static_cast<const int*>(L->Perm);
      m_factor_position.resize(L->n);
      for(int k = 0; k < static_cast<int>(L->n); ++k)
        m_factor_position[permutation != nullptr ? permutation[k] : k] = k;
    }
  }

  // An estimate of the entries of L that refactor_rows() reads: for every
  // row, the columns on the paths of the elimination tree from its column,
  // and from the columns of its neighbours in A, to the root (the solve for
  // the new row and the two rank-one updates follow them).
  static double row_update_entries(const cholmod_factor& L, const Matrix& A,
                                   const std::vector<int>& rows, const std::vector<int>& position)
  {
    const int* starts = static_cast<const int*>(L.p);
    const int* indices = static_cast<const int*>(L.i);
    const int* counts = static_cast<const int*>(L.nz); // a simplicial factor has them
    const int n = static_cast<int>(L.n);
    std::vector<int> mark(static_cast<std::size_t>(n), -1);
    double entries = 0;
    int stamp = 0;
    for(int k : rows)
    {
      auto walk = [&](int j) {
        while(j >= 0 && mark[static_cast<std::size_t>(j)] != stamp)
        {
          mark[static_cast<std::size_t>(j)] = stamp;
          const int count = counts[j];
          entries += count;
          j = count > 1 ? indices[starts[j] + 1] : -1;
        }
      };
      walk(position[static_cast<std::size_t>(k)]);
      for(Matrix::InnerIterator it(A, k); it; ++it)
        walk(position[static_cast<std::size_t>(it.row())]);
      ++stamp;
    }
    return 2 * entries;
  }

  // The updates of refactor_rows(): every listed row of the factored matrix
  // set to the identity's, then, one after the other, to those of A, each
  // coupled only to the rows already in their final state (the others get
  // their coupling when their turn comes); then the factor back to the LLᵀ
  // form the solves read. It stays unpacked (columns moved to the end of
  // its arrays when they grew), since packing it would copy the whole
  // factor.
  bool update_rows(const Matrix& A, const std::vector<int>& rows, const std::vector<int>& position)
  {
    cholmod_common& common = m_solver.common();
    cholmod_factor* L = m_solver.factor();
    common.status = CHOLMOD_OK;
    for(int k : rows)
      if(!cholmod_rowdel(static_cast<std::size_t>(position[static_cast<std::size_t>(k)]), nullptr, L,
                         &common))
        return false;
    std::vector<char> pending(static_cast<std::size_t>(A.rows()), 0);
    for(int k : rows)
      pending[static_cast<std::size_t>(k)] = 1;
    std::vector<int> column_rows;
    std::vector<double> column_values;
    for(int k : rows)
    {
      pending[static_cast<std::size_t>(k)] = 0;
      column_rows.clear();
      column_values.clear();
      bool identity = true;
      for(Matrix::InnerIterator it(A, k); it; ++it)
      {
        const int i = static_cast<int>(it.row());
        if(i != k && it.value() != 0)
          identity = false;
        else if(i == k && it.value() != 1)
          identity = false;
        if(pending[static_cast<std::size_t>(i)] || it.value() == 0)
          continue;
        column_rows.push_back(position[static_cast<std::size_t>(i)]);
        column_values.push_back(it.value());
      }
      if(identity)
        continue; // rowdel left it so
      int column_starts[2] = {0, static_cast<int>(column_rows.size())};
      cholmod_sparse column;
      column.nrow = L->n;
      column.ncol = 1;
      column.nzmax = column_rows.size();
      column.p = column_starts;
      column.i = column_rows.data();
      column.nz = nullptr;
      column.x = column_values.data();
      column.z = nullptr;
      column.stype = 0;
      column.itype = CHOLMOD_INT;
      column.xtype = CHOLMOD_REAL;
      column.dtype = CHOLMOD_DOUBLE;
      column.sorted = 0;
      column.packed = 1;
      if(!cholmod_rowadd(static_cast<std::size_t>(position[static_cast<std::size_t>(k)]), &column, L,
                         &common))
        return false;
    }
    // LDLᵀ to LLᵀ needs a positive D: a matrix that is not positive
    // definite stops there.
    if(!cholmod_change_factor(CHOLMOD_REAL, 1, 0, 0, 0, L, &common) || common.status != CHOLMOD_OK ||
       L->minor < L->n || !L->is_ll)
      return false;
    return true;
  }

  // The solution and the work arrays of cholmod_solve2(), kept between
  // calls.
  struct Work_arrays
  {
    cholmod_dense* solution = nullptr;
    cholmod_dense* y = nullptr;
    cholmod_dense* e = nullptr;
    void release(cholmod_common* common)
    {
      cholmod_free_dense(&solution, common);
      cholmod_free_dense(&y, common);
      cholmod_free_dense(&e, common);
    }
  };

  // X(:, first .. first + count) = A^{-1} B(:, first .. first + count).
  bool solve_columns(const Dense_matrix& B, Eigen::Index first, Eigen::Index count,
                     Dense_matrix& X, Work_arrays& work, cholmod_common* common) const
  {
    cholmod_dense right_hand_side;
    right_hand_side.nrow = static_cast<std::size_t>(B.rows());
    right_hand_side.ncol = static_cast<std::size_t>(count);
    right_hand_side.nzmax = static_cast<std::size_t>(B.rows() * count);
    right_hand_side.d = static_cast<std::size_t>(B.rows());
    // read only by cholmod_solve2
    right_hand_side.x = const_cast<double*>(B.data() + B.rows() * first);
    right_hand_side.z = nullptr;
    right_hand_side.xtype = CHOLMOD_REAL;
    right_hand_side.dtype = CHOLMOD_DOUBLE;
    common->status = CHOLMOD_OK;
    cholmod_factor* L = m_solver.factor();
    if(L->is_super)
    {
      // The supernodal solve makes two work arrays, Y then E, and checks
      // for a failed allocation only after both, while making E resets the
      // status: a failure to make Y goes unseen and the solve dereferences
      // it. They are made here, each checked, with the sizes the solve
      // reuses.
      const std::size_t columns = static_cast<std::size_t>(count);
      cholmod_ensure_dense(&work.y, L->n, columns, L->n, L->xtype, common);
      if(common->status >= CHOLMOD_OK)
        cholmod_ensure_dense(&work.e, columns, L->maxesize, columns, L->xtype, common);
      if(common->status < CHOLMOD_OK)
      {
        work.release(common);
        return false;
      }
    }
    if(!cholmod_solve2(CHOLMOD_A, L, &right_hand_side, nullptr, &work.solution,
                       nullptr, &work.y, &work.e, common) ||
       work.solution == nullptr || common->status < CHOLMOD_OK)
    {
      // Out of memory: the work arrays may be half made; the next solve
      // makes them anew.
      work.release(common);
      return false;
    }
    X.middleCols(first, count) =
        Eigen::Map<const Dense_matrix>(static_cast<const double*>(work.solution->x), B.rows(), count);
    return true;
  }

  // Solves with the factor split by subtrees of its elimination tree, on
  // two threads with `parallel` (see
  // Two_subtree_triangular_solve::solve_permuted()).
  bool solve_in_subtrees(const Dense_matrix& B, Dense_matrix& X, bool parallel) const
  {
    const cholmod_factor* L = m_solver.factor();
    m_subtree_solve.solve_permuted(static_cast<const int*>(L->p), static_cast<const int*>(L->i),
                                   static_cast<const double*>(L->x), m_factor_position.data(), B,
                                   X, m_rows, parallel);
    return true;
  }

  void release_work_arrays()
  {
    m_work[0].release(&m_solver.common());
    m_work[1].release(&m_second_common);
  }

  Cholmod_factorization m_solver;
  // The workspace of the second thread of a simplicial solve.
  mutable cholmod_common m_second_common;
  mutable Work_arrays m_work[2];
  double m_supernodal_switch = 200.0;
  Two_subtree_triangular_solve m_subtree_solve;
  // The right-hand sides of solve_in_subtrees(), row after row.
  mutable std::vector<double> m_rows;
  // Row k of the system is row m_factor_position[k] of the factor.
  std::vector<int> m_factor_position;
  // The ordering of the next factor(), when one was given.
  std::vector<int> m_given_ordering;
  double m_factor_nonzeros = 0;
  // The flops of the last factor() and the entries estimated for the row
  // updates since (refactor_rows()).
  double m_factorization_flops = 0;
  double m_update_entries = 0;
  double m_row_update_budget = 0.1;
  bool m_rows_updated = false;
  bool m_factored = false;
  bool m_empty = false;
  bool m_process_wide_tuning = false;
};

} // namespace Linear_algebra
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_LINEAR_ALGEBRA_CHOLMOD_LLT_H

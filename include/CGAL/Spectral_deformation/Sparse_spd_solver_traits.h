// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_SPARSE_SPD_SOLVER_TRAITS_H
#define CGAL_SPECTRAL_DEFORMATION_SPARSE_SPD_SOLVER_TRAITS_H

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <cstddef>
#include <exception>
#include <mutex>
#include <utility>
#include <vector>

#ifdef _OPENMP
#include <omp.h>
#endif

#ifdef CGAL_SSMD_USE_CHOLMOD
#include <Eigen/CholmodSupport>

#include <CGAL/Spectral_deformation/internal/Memory/Cholmod_huge_page_allocator.h>
#include <CGAL/Spectral_deformation/internal/Linear_algebra/Two_subtree_triangular_solve.h>
#include <CGAL/Spectral_deformation/internal/available_threads.h>
#endif

namespace CGAL {
#ifdef CGAL_SSMD_USE_CHOLMOD
namespace Spectral_deformation {
namespace internal {

// The lock of CHOLMOD's analyses (`Cholmod_llt_solver_traits`): one for the
// whole process, whichever form of the factor, since METIS's random
// generator is shared by all of them.
inline std::mutex& cholmod_analysis_mutex()
{
  static std::mutex mutex;
  return mutex;
}

} // namespace internal
} // namespace Spectral_deformation
#endif

/// \ingroup PkgSpectralSurfaceMeshDeformationTraits
/// A model of `SparseSPDSolverTraits` built on an Eigen sparse Cholesky-type
/// solver.
///
/// Symmetric positive definite systems are factored with a Cholesky or LDLᵀ
/// decomposition, never with a general LU: on the cotangent systems of this
/// package an LU with partial pivoting was measured far slower.
///
/// \tparam EigenSolver an Eigen sparse solver with the interface of
///         `Eigen::SimplicialLDLT` (`compute()`, `info()`, `solve()`), for
///         instance `Eigen::SimplicialLDLT`, `Eigen::SimplicialLLT` or
///         `Eigen::CholmodSupernodalLLT` over `Eigen::SparseMatrix<double>`.
template <class EigenSolver>
class Eigen_sparse_spd_solver_traits
{
public:
  /// The sparse matrix type accepted by `factor()`.
  typedef Eigen::SparseMatrix<double> Matrix;
  /// The dense matrix type of right-hand sides and solutions.
  typedef Eigen::MatrixXd Dense_matrix;

  /// Factors the symmetric positive definite matrix `A` (both triangles
  /// stored). Returns `false` when the factorization fails, for instance when
  /// `A` is not positive definite.
  bool factor(const Matrix& A)
  {
    m_empty = (A.rows() == 0);
    if(A.nonZeros() == 0)
    {
      // A zero matrix is not positive definite, and an empty one needs no
      // factorization. (CHOLMOD's analysis refuses a matrix without values,
      // and Eigen's wrapper then dereferences the missing factor.)
      m_factored = m_empty;
      return m_factored;
    }
    m_solver.compute(A);
    m_factored = (m_solver.info() == Eigen::Success);
    return m_factored;
  }

  /// Solves `A X = B` for the last factored `A`. Returns `false` when nothing
  /// is factored, when the solve fails, or when `X` is not finite.
  bool solve(const Dense_matrix& B, Dense_matrix& X) const
  {
    if(!m_factored)
      return false;
    if(m_empty)
    {
      X.resize(0, B.cols());
      return B.rows() == 0;
    }
    X = m_solver.solve(B);
    return m_solver.info() == Eigen::Success && X.allFinite();
  }

private:
  EigenSolver m_solver;
  bool m_factored = false;
  bool m_empty = false;
};

#if defined(CGAL_SSMD_USE_CHOLMOD) || defined(DOXYGEN_RUNNING)
/// \ingroup PkgSpectralSurfaceMeshDeformationTraits
/// The two forms of CHOLMOD's Cholesky factor.
enum Cholmod_factor_form
{
  /// Supernodal: columns with the same pattern are factored and solved as
  /// dense blocks through the BLAS. The faster form for solves with many
  /// right-hand sides (the block eigensolver solves eight at a time).
  CHOLMOD_SUPERNODAL_FACTOR,
  /// Simplicial: column by column. On the cotangent systems of meshes up to
  /// some 10⁵ vertices both its factorization and its solves with a few
  /// right-hand sides were measured faster.
  ///
  /// Larger systems, whose factorization costs more than
  /// `Cholmod_llt_solver_traits::supernodal_factorization_switch()` flops
  /// per entry of the factor, are factored in supernodal form and the factor
  /// then converted to the simplicial one, without the zeros the supernodes
  /// carried (CHOLMOD's `final_resymbol`): faster than a simplicial
  /// factorization there (416k vertices, 275 flops per entry), for the same
  /// factor.
  CHOLMOD_SIMPLICIAL_FACTOR
};

/// \ingroup PkgSpectralSurfaceMeshDeformationTraits
/// A model of `SparseSPDSolverTraits` on CHOLMOD's Cholesky factorization,
/// in the form `Form`, that keeps the work arrays of its solves from one
/// call to the next (`cholmod_solve2()`).
///
/// Eigen's `CholmodSupernodalLLT` allocates the solution and CHOLMOD's work
/// arrays anew in every `solve()`. With many solves against the same factor
/// (block eigensolvers, iterations), touching that fresh memory costs more
/// than the triangular solves themselves on some machines.
///
/// After `set_process_wide_tuning(true)`, SuiteSparse allocates its large
/// blocks in transparent huge pages while the object factors or solves (see
/// `set_process_wide_tuning()`); by default it changes no state of the
/// process.
///
/// CHOLMOD's supernodal factorization runs some of its loops on a fixed
/// number of OpenMP threads (`CHOLMOD_OMP_NUM_THREADS`, 4). When that is
/// more than the processors, `factor()` runs them on one thread, nested in
/// an OpenMP team of two whose second thread waits (unless it is called in
/// a parallel region, or nested parallelism is enabled): on two cores the
/// four threads competed for them and the factorization was slower. The
/// team is local to the call: no OpenMP setting of the process changes.
///
/// Available when the package is configured with CHOLMOD (the macro
/// `CGAL_SSMD_USE_CHOLMOD` is defined). Like every model, an object may be
/// used by one thread at a time; the work arrays make even `solve()`, which
/// is `const`, unsafe to call concurrently on one object.
///
/// \tparam Form the form of the factor, see `Cholmod_factor_form`.
template <Cholmod_factor_form Form>
class Cholmod_llt_solver_traits
{
public:
  /// The sparse matrix type accepted by `factor()`.
  typedef Eigen::SparseMatrix<double> Matrix;
  /// The dense matrix type of right-hand sides and solutions.
  typedef Eigen::MatrixXd Dense_matrix;

  Cholmod_llt_solver_traits()
  {
    m_solver.setMode(Form == CHOLMOD_SUPERNODAL_FACTOR ? Eigen::CholmodSupernodalLLt
                                                       : Eigen::CholmodSimplicialLLt);
    if(Form == CHOLMOD_SIMPLICIAL_FACTOR)
    {
      // CHOLMOD chooses the form of the factorization from the analysis and
      // converts the factor to the simplicial LLᵀ the solves are split on.
      cholmod_common& common = m_solver.cholmod();
      common.supernodal = CHOLMOD_AUTO;
      common.final_asis = 0;
      common.final_super = 0;
      common.final_ll = 1;
      common.final_pack = 1;
      common.final_monotonic = 1;
      common.final_resymbol = 1;
    }
    cholmod_start(&m_second_common);
  }
  // A CHOLMOD factor has a single owner, as in Eigen's wrapper.
  Cholmod_llt_solver_traits(const Cholmod_llt_solver_traits&) = delete;
  Cholmod_llt_solver_traits& operator=(const Cholmod_llt_solver_traits&) = delete;
  ~Cholmod_llt_solver_traits()
  {
    release_work_arrays();
    cholmod_finish(&m_second_common);
  }

  /// With the simplicial form, the flops per entry of the factor from which
  /// the factorization runs in supernodal form (see
  /// `CHOLMOD_SIMPLICIAL_FACTOR`). The default, 200, lies between the
  /// cotangent systems of the 104k-vertex armadillo (144 flops per entry,
  /// where the simplicial factorization was the faster) and of the
  /// 416k-vertex one (275).
  double supernodal_factorization_switch() const { return m_supernodal_switch; }

  /// Sets `supernodal_factorization_switch()`, used from the next
  /// `factor()`: 0 always factors in supernodal form, infinity never.
  void set_supernodal_factorization_switch(double flops_per_entry)
  {
    m_supernodal_switch = flops_per_entry;
  }

  /// Whether `solve()` splits the last factor between two threads by
  /// subtrees of its elimination tree (simplicial form, OpenMP with two
  /// threads or more at the call): each thread reads its part of the factor
  /// once for eight right-hand sides, instead of CHOLMOD's own solve reading
  /// it once for four. Otherwise the right-hand sides are split between two
  /// threads, each solving with CHOLMOD.
  bool solves_in_subtrees() const { return m_subtree_solve.usable(); }

  /// Whether `factor()` and `solve()` may change state of the whole process
  /// to run faster (default `false`); see `set_process_wide_tuning()`.
  bool process_wide_tuning() const { return m_process_wide_tuning; }

  /// Sets `process_wide_tuning()`. With `true` (Linux), while `factor()` or
  /// `solve()` runs, SuiteSparse allocates its blocks of 4 MiB and more with
  /// transparent huge pages requested: a factor of hundreds of MiB, first
  /// written by the factorization, then faults once per 2 MiB instead of
  /// once per 4 KiB page, a large part of the cost of a big factorization on
  /// the virtual machines this package was measured on. SuiteSparse's
  /// allocator is global to the process: it is replaced for that time, if
  /// it is SuiteSparse's default one, and restored afterwards, so that other
  /// threads calling SuiteSparse meanwhile allocate through it too; and the
  /// huge-page advice stays on the memory after it is freed. The result
  /// does not depend on it. The eigensolver traits hand their own setting to
  /// the solver they create (see
  /// `Block_lanczos_eigensolver_traits::set_process_wide_tuning()`).
  void set_process_wide_tuning(bool enabled) { m_process_wide_tuning = enabled; }

  /// A fill-reducing ordering of the pattern of `A` (both triangles stored):
  /// entry k is the row eliminated k-th. Of the orderings by minimum degree
  /// (AMD) and by nested dissection (METIS, when CHOLMOD was built with it),
  /// the one CHOLMOD's analysis finds sparser: on the cotangent systems of
  /// meshes of 10⁵ vertices and more, nested dissection gave the sparser
  /// factor, which every back-substitution reads, where CHOLMOD's default
  /// strategy keeps minimum degree. Empty when the analysis fails. The last
  /// factor is kept.
  std::vector<int> fill_reducing_ordering(const Matrix& A)
  {
    if(A.rows() == 0 || A.nonZeros() == 0)
      return {};
    const Spectral_deformation::internal::Memory::Cholmod_huge_page_allocator huge_pages(
        m_process_wide_tuning);
    return m_solver.ordering_of(A);
  }

  /// Makes the next `factor()` analyze its matrix with `permutation` as the
  /// fill-reducing ordering (entry k: the row eliminated k-th) instead of
  /// choosing one: CHOLMOD's choice of an ordering is most of the cost of a
  /// factorization of a large mesh's system, and one ordering of a whole
  /// system serves all its principal submatrices. Ignored when it is not a
  /// permutation of the rows of the next matrix; if the analysis with it
  /// fails, CHOLMOD chooses its own.
  void set_fill_reducing_ordering(std::vector<int> permutation) { m_given_ordering = std::move(permutation); }

  /// The entries of the last factor, as its analysis counted them (0 before
  /// the first `factor()`).
  double factor_nonzeros() const { return m_factor_nonzeros; }

  /// Factors the symmetric positive definite matrix `A` (both triangles
  /// stored). Returns `false` when the factorization fails.
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
    const Spectral_deformation::internal::Memory::Cholmod_huge_page_allocator huge_pages(
        m_process_wide_tuning);
    bool computed = false;
    if(Form == CHOLMOD_SIMPLICIAL_FACTOR)
      m_solver.cholmod().supernodal_switch = m_supernodal_switch;
    std::vector<int> given;
    given.swap(m_given_ordering);
    std::vector<int>* ordering = is_permutation_of_rows(given, A.rows()) ? &given : nullptr;
#ifdef _OPENMP
    // CHOLMOD's supernodal factorization runs some of its loops on
    // CHOLMOD_OMP_NUM_THREADS (4) threads whatever the machine. Where that
    // is more than the processors, they run on one thread instead, nested
    // in a team of two whose second thread waits (see the class
    // description).
    if(!omp_in_parallel() && omp_get_num_procs() < CHOLMOD_OMP_NUM_THREADS &&
       omp_get_max_active_levels() <= 1)
    {
      // A team of one thread would not be active, and CHOLMOD's loops
      // would then form the active level; two is the smallest active team.
      constexpr int smallest_active_team = 2;
      std::exception_ptr error;
#pragma omp parallel num_threads(smallest_active_team)
      {
        if(omp_get_thread_num() == 0)
        {
          try
          {
            computed = m_solver.compute_checked(A, ordering);
          }
          catch(...)
          {
            error = std::current_exception();
          }
        }
      }
      if(error)
        std::rethrow_exception(error);
    }
    else
#endif
      computed = m_solver.compute_checked(A, ordering);
    m_factored = computed;
    m_rows_updated = false;
    m_factor_nonzeros = computed ? m_solver.cholmod().lnz : 0.0;
    m_factorization_flops = computed ? m_solver.cholmod().fl : 0.0;
    m_update_entries = 0;
    analyze_solves();
    return m_factored;
  }

  /// The share of a factorization's cost that the row updates of one call
  /// of `refactor_rows()` may take before it factors anew instead (see
  /// there), counted as entries of the factor read against the
  /// factorization's floating-point operations. Default 0.1: an update reads
  /// an entry several times slower than a supernodal factorization makes a
  /// floating-point operation, so that updates within the default cost
  /// well under a factorization.
  double row_update_budget() const { return m_row_update_budget; }

  /// Sets `row_update_budget()`: 0 always factors anew.
  void set_row_update_budget(double share) { m_row_update_budget = share; }

  /// Whether the current factor was made by `refactor_rows()`'s updates
  /// rather than by a factorization.
  bool rows_updated() const { return m_rows_updated; }

  /// Factors `A` (both triangles stored), which differs from the last
  /// factored matrix only in the rows and columns listed in `rows` (and is
  /// of the same size).
  ///
  /// With the simplicial form, the factor is updated in place, row by row
  /// (CHOLMOD's `cholmod_rowdel()` and `cholmod_rowadd()`, which set a row
  /// and column of the factored matrix to those of the identity, then to
  /// the new ones), when the entries of the factor those updates are
  /// estimated to read stay within `row_update_budget()` times the
  /// floating-point operations of the last `factor()`, and those of all the
  /// updates since that factorization within ten times as many. A new set
  /// of prescribed vertices that differs from the last one in a few
  /// vertices then costs a small fraction of a factorization. Otherwise, and
  /// whenever an update fails, this is `factor(A)`. The factor keeps its fill-reducing ordering: the rows
  /// updated should be rows that the ordering was made for (the Dirichlet
  /// systems of the package order the whole matrix, see
  /// `fill_reducing_ordering()`).
  bool refactor_rows(const Matrix& A, const std::vector<int>& rows)
  {
    cholmod_factor* L = m_factored && !m_empty ? m_solver.factor() : nullptr;
    // analyze_solves() found the factor's position of every row exactly
    // when the factor has the simplicial LLᵀ form the updates start from.
    if(Form != CHOLMOD_SIMPLICIAL_FACTOR || L == nullptr || A.cols() != A.rows() ||
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
    const Spectral_deformation::internal::Memory::Cholmod_huge_page_allocator huge_pages(
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

  /// Solves `A X = B` for the last factored `A`. Returns `false` when nothing
  /// is factored, when the solve fails, or when `X` is not finite.
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
    const Spectral_deformation::internal::Memory::Cholmod_huge_page_allocator huge_pages(
        m_process_wide_tuning);
    if(m_subtree_solve.usable() &&
       Spectral_deformation::internal::available_threads() >=
           Spectral_deformation::internal::Linear_algebra::Two_subtree_triangular_solve::number_of_subtrees)
      return solve_in_subtrees(B, X) && X.allFinite();
    // Otherwise a simplicial factor is solved column by column without the
    // BLAS: two threads each solve half of the right-hand sides against the
    // shared, read-only factor, with their own CHOLMOD workspace (the
    // supernodal solve, which calls the BLAS, was slower that way).
    const Eigen::Index halves =
        (Form == CHOLMOD_SIMPLICIAL_FACTOR && B.cols() >= 2 &&
         Spectral_deformation::internal::available_threads() >= 2)
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
                                    half == 0 ? &m_solver.cholmod() : &m_second_common);
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
    m_subtree_solve = Spectral_deformation::internal::Linear_algebra::Two_subtree_triangular_solve();
    m_factor_position.clear();
    const cholmod_factor* L = m_factored ? m_solver.factor() : nullptr;
    if(Form == CHOLMOD_SIMPLICIAL_FACTOR && L != nullptr && !L->is_super && L->is_ll &&
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
    cholmod_common& common = m_solver.cholmod();
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

  // Eigen keeps the factor protected; CHOLMOD's own solve needs it.
  struct Factorization : Eigen::CholmodDecomposition<Matrix, Eigen::Lower>
  {
    cholmod_factor* factor() const { return this->m_cholmodFactor; }

    // Eigen's analyzePattern() with a given ordering (cholmod_analyze_p).
    void analyze_with_ordering(const Matrix& A, std::vector<int>& ordering)
    {
      if(this->m_cholmodFactor != nullptr)
      {
        cholmod_free_factor(&this->m_cholmodFactor, &this->cholmod());
        this->m_cholmodFactor = nullptr;
      }
      cholmod_sparse a = Eigen::viewAsCholmod(A.template selfadjointView<Eigen::Lower>());
      cholmod_common& common = this->cholmod();
      const int methods = common.nmethods, first_method = common.method[0].ordering;
      const int postorder = common.postorder;
      common.nmethods = 1;
      common.method[0].ordering = CHOLMOD_GIVEN;
      common.postorder = 1;
      this->m_cholmodFactor = cholmod_analyze_p(&a, ordering.data(), nullptr, 0, &common);
      common.nmethods = methods;
      common.method[0].ordering = first_method;
      common.postorder = postorder;
      this->m_isInitialized = true;
      this->m_info = Eigen::Success;
      this->m_analysisIsOk = true;
      this->m_factorizationIsOk = false;
    }

    // The sparser of the orderings of the pattern of A by minimum degree
    // (AMD) and by nested dissection (METIS, when CHOLMOD has it), the
    // current factor left as it is.
    std::vector<int> ordering_of(const Matrix& A)
    {
      cholmod_sparse a = Eigen::viewAsCholmod(A.template selfadjointView<Eigen::Lower>());
      cholmod_common& common = this->cholmod();
      const int methods = common.nmethods, first_method = common.method[0].ordering,
                second_method = common.method[1].ordering;
      common.nmethods = 2;
      common.method[0].ordering = CHOLMOD_AMD;
      common.method[1].ordering = CHOLMOD_METIS;
      common.status = CHOLMOD_OK;
      cholmod_factor* analysis = analyze_serialized(a, common);
      if(analysis == nullptr && common.status != CHOLMOD_OUT_OF_MEMORY)
      {
        // A CHOLMOD built without METIS refuses that method: AMD alone.
        common.nmethods = 1;
        common.status = CHOLMOD_OK;
        analysis = analyze_serialized(a, common);
      }
      common.nmethods = methods;
      common.method[0].ordering = first_method;
      common.method[1].ordering = second_method;
      std::vector<int> ordering;
      if(analysis != nullptr && common.status >= CHOLMOD_OK && analysis->Perm != nullptr)
      {
        const int* permutation = static_cast<const int*>(analysis->Perm);
        ordering.assign(permutation, permutation + analysis->n);
      }
      if(analysis != nullptr)
        cholmod_free_factor(&analysis, &common);
      common.status = CHOLMOD_OK;
      return ordering;
    }

    // CHOLMOD's analysis of `a`, one at a time in the process. METIS, which
    // the analysis may call, draws from a random generator that all its
    // callers share: two analyses at once could get different orderings
    // than one after the other, and so factors and results that differ in
    // their last bits.
    static cholmod_factor* analyze_serialized(cholmod_sparse& a, cholmod_common& common)
    {
      std::lock_guard<std::mutex> lock(Spectral_deformation::internal::cholmod_analysis_mutex());
      return cholmod_analyze(&a, &common);
    }

    // Eigen's compute() when every allocation succeeds. When CHOLMOD runs
    // out of memory, its analysis returns no factor, which Eigen's
    // factorize() then dereferences, and an interrupted factorization keeps
    // the "success" of its analysis: both are checked here.
    // With `ordering`, the analysis takes it as the fill-reducing ordering
    // and falls back to CHOLMOD's own choice if that fails.
    bool compute_checked(const Matrix& A, std::vector<int>* ordering = nullptr)
    {
      this->cholmod().status = CHOLMOD_OK;
      if(ordering != nullptr)
        analyze_with_ordering(A, *ordering);
      if(ordering == nullptr || factor() == nullptr || this->cholmod().status < CHOLMOD_OK)
      {
        this->cholmod().status = CHOLMOD_OK;
        std::lock_guard<std::mutex> lock(Spectral_deformation::internal::cholmod_analysis_mutex());
        this->analyzePattern(A);
      }
      if(factor() == nullptr || this->cholmod().status < CHOLMOD_OK)
        return false;
      this->factorize(A);
      return this->info() == Eigen::Success && this->cholmod().status >= CHOLMOD_OK;
    }
  };

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

  // Solves with the factor split between two threads by subtrees of its
  // elimination tree (see Two_subtree_triangular_solve::solve_permuted()).
  bool solve_in_subtrees(const Dense_matrix& B, Dense_matrix& X) const
  {
    const cholmod_factor* L = m_solver.factor();
    m_subtree_solve.solve_permuted(static_cast<const int*>(L->p), static_cast<const int*>(L->i),
                                   static_cast<const double*>(L->x), m_factor_position.data(), B,
                                   X, m_rows);
    return true;
  }

  void release_work_arrays()
  {
    m_work[0].release(&m_solver.cholmod());
    m_work[1].release(&m_second_common);
  }

  mutable Factorization m_solver;
  // The workspace of the second thread of a simplicial solve.
  mutable cholmod_common m_second_common;
  mutable Work_arrays m_work[2];
  double m_supernodal_switch = 200.0;
  Spectral_deformation::internal::Linear_algebra::Two_subtree_triangular_solve m_subtree_solve;
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

/// \ingroup PkgSpectralSurfaceMeshDeformationTraits
/// CHOLMOD's supernodal Cholesky factorization (the sparse solver of the
/// eigensolvers by default).
typedef Cholmod_llt_solver_traits<CHOLMOD_SUPERNODAL_FACTOR> Cholmod_sparse_spd_solver_traits;

/// \ingroup PkgSpectralSurfaceMeshDeformationTraits
/// CHOLMOD's simplicial Cholesky factorization (the sparse solver of the
/// detail transfer by default).
typedef Cholmod_llt_solver_traits<CHOLMOD_SIMPLICIAL_FACTOR> Cholmod_simplicial_sparse_spd_solver_traits;
#endif

/// \ingroup PkgSpectralSurfaceMeshDeformationTraits
/// The default model of `SparseSPDSolverTraits`:
/// `Cholmod_sparse_spd_solver_traits` when the package was configured with
/// CHOLMOD (the macro `CGAL_SSMD_USE_CHOLMOD` is defined), Eigen's
/// `SimplicialLDLT` otherwise.
#ifdef CGAL_SSMD_USE_CHOLMOD
typedef Cholmod_sparse_spd_solver_traits Default_sparse_spd_solver_traits;
#else
typedef Eigen_sparse_spd_solver_traits<Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>>
    Default_sparse_spd_solver_traits;
#endif

/// \ingroup PkgSpectralSurfaceMeshDeformationTraits
/// The default model of `SparseSPDSolverTraits` of
/// `Spectral_surface_mesh_deformation` for its detail transfer (one
/// factorization per constraint set or per mesh, then solves with three
/// right-hand sides): `Cholmod_simplicial_sparse_spd_solver_traits`
/// when the package was configured with CHOLMOD, Eigen's `SimplicialLDLT`
/// otherwise. Against the supernodal factor, the simplicial one was measured
/// (armadillo Loop-subdivided, cotangent matrix) faster to factor up to
/// 104k vertices and a little slower beyond, and faster to solve with three
/// right-hand sides at every size.
#ifdef CGAL_SSMD_USE_CHOLMOD
typedef Cholmod_simplicial_sparse_spd_solver_traits Default_deformation_sparse_spd_solver_traits;
#else
typedef Eigen_sparse_spd_solver_traits<Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>>
    Default_deformation_sparse_spd_solver_traits;
#endif

/// \ingroup PkgSpectralSurfaceMeshDeformationTraits
/// The default model of `SparseSPDSolverTraits` of
/// `Block_lanczos_eigensolver_traits` (one factorization, then solves with
/// eight right-hand sides): the same as
/// `Default_deformation_sparse_spd_solver_traits`. With eight right-hand
/// sides split over two threads, the simplicial factor was measured faster
/// than the supernodal one on the 104k-vertex armadillo, to factor and to
/// solve.
typedef Default_deformation_sparse_spd_solver_traits Default_eigensolver_sparse_spd_solver_traits;

} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_SPARSE_SPD_SOLVER_TRAITS_H

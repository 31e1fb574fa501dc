// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_SPARSE_SPD_SOLVER_TRAITS_H
#define CGAL_SPECTRAL_DEFORMATION_SPARSE_SPD_SOLVER_TRAITS_H

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <utility>
#include <vector>

#ifdef CGAL_SSMD_USE_CHOLMOD
#include <CGAL/Spectral_deformation/internal/Linear_algebra/Cholmod_llt.h>
#endif

#include <CGAL/tags.h>

namespace CGAL {
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
  /// Declares the optional members `process_wide_tuning()` and
  /// `set_process_wide_tuning()` (see `SparseSPDSolverTraits`).
  typedef CGAL::Tag_true Supports_process_wide_tuning;
  /// Declares the optional members `fill_reducing_ordering()` and
  /// `set_fill_reducing_ordering()`.
  typedef CGAL::Tag_true Supports_fill_reducing_ordering;
  /// Declares the optional member `refactor_rows()`.
  typedef CGAL::Tag_true Supports_row_updates;

  /// With the simplicial form, the flops per entry of the factor from which
  /// the factorization runs in supernodal form (see
  /// `CHOLMOD_SIMPLICIAL_FACTOR`). The default, 200, lies between the
  /// cotangent systems of the 104k-vertex armadillo (144 flops per entry,
  /// where the simplicial factorization was the faster) and of the
  /// 416k-vertex one (275).
  double supernodal_factorization_switch() const { return m_llt.supernodal_factorization_switch(); }

  /// Sets `supernodal_factorization_switch()`, used from the next
  /// `factor()`: 0 always factors in supernodal form, infinity never.
  void set_supernodal_factorization_switch(double flops_per_entry)
  {
    m_llt.set_supernodal_factorization_switch(flops_per_entry);
  }

  /// Whether `solve()` splits the last factor between two threads by
  /// subtrees of its elimination tree (simplicial form, OpenMP with two
  /// threads or more at the call): each thread reads its part of the factor
  /// once for eight right-hand sides, instead of CHOLMOD's own solve reading
  /// it once for four. Otherwise the right-hand sides are split between two
  /// threads, each solving with CHOLMOD.
  bool solves_in_subtrees() const { return m_llt.solves_in_subtrees(); }

  /// Whether `factor()` and `solve()` may change state of the whole process
  /// to run faster (default `false`); see `set_process_wide_tuning()`.
  bool process_wide_tuning() const { return m_llt.process_wide_tuning(); }

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
  void set_process_wide_tuning(bool enabled) { m_llt.set_process_wide_tuning(enabled); }

  /// A fill-reducing ordering of the pattern of `A` (both triangles stored):
  /// entry k is the row eliminated k-th. Of the orderings by minimum degree
  /// (AMD) and by nested dissection (METIS, when CHOLMOD was built with it),
  /// the one CHOLMOD's analysis finds sparser: on the cotangent systems of
  /// meshes of 10⁵ vertices and more, nested dissection gave the sparser
  /// factor, which every back-substitution reads, where CHOLMOD's default
  /// strategy keeps minimum degree. Empty when the analysis fails. The last
  /// factor is kept.
  std::vector<int> fill_reducing_ordering(const Matrix& A) { return m_llt.fill_reducing_ordering(A); }

  /// Makes the next `factor()` analyze its matrix with `permutation` as the
  /// fill-reducing ordering (entry k: the row eliminated k-th) instead of
  /// choosing one: CHOLMOD's choice of an ordering is most of the cost of a
  /// factorization of a large mesh's system, and one ordering of a whole
  /// system serves all its principal submatrices. Ignored when it is not a
  /// permutation of the rows of the next matrix; if the analysis with it
  /// fails, CHOLMOD chooses its own.
  void set_fill_reducing_ordering(std::vector<int> permutation)
  {
    m_llt.set_fill_reducing_ordering(std::move(permutation));
  }

  /// The entries of the last factor, as its analysis counted them (0 before
  /// the first `factor()`).
  double factor_nonzeros() const { return m_llt.factor_nonzeros(); }

  /// Factors the symmetric positive definite matrix `A` (both triangles
  /// stored). Returns `false` when the factorization fails.
  bool factor(const Matrix& A) { return m_llt.factor(A); }

  /// The share of a factorization's cost that the row updates of one call
  /// of `refactor_rows()` may take before it factors anew instead (see
  /// there), counted as entries of the factor read against the
  /// factorization's floating-point operations. Default 0.1: an update reads
  /// an entry several times slower than a supernodal factorization makes a
  /// floating-point operation, so that updates within the default cost
  /// well under a factorization.
  double row_update_budget() const { return m_llt.row_update_budget(); }

  /// Sets `row_update_budget()`: 0 always factors anew.
  void set_row_update_budget(double share) { m_llt.set_row_update_budget(share); }

  /// Whether the current factor was made by `refactor_rows()`'s updates
  /// rather than by a factorization.
  bool rows_updated() const { return m_llt.rows_updated(); }

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
  bool refactor_rows(const Matrix& A, const std::vector<int>& rows) { return m_llt.refactor_rows(A, rows); }

  /// Solves `A X = B` for the last factored `A`. Returns `false` when nothing
  /// is factored, when the solve fails, or when `X` is not finite.
  bool solve(const Dense_matrix& B, Dense_matrix& X) const { return m_llt.solve(B, X); }

private:
  Spectral_deformation::internal::Linear_algebra::Cholmod_llt<Form == CHOLMOD_SUPERNODAL_FACTOR> m_llt;
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

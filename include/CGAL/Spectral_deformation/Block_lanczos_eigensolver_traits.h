// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_BLOCK_LANCZOS_EIGENSOLVER_TRAITS_H
#define CGAL_SPECTRAL_DEFORMATION_BLOCK_LANCZOS_EIGENSOLVER_TRAITS_H

#include <CGAL/Spectral_deformation/Sparse_spd_solver_traits.h>
#include <CGAL/Spectral_deformation/internal/Eigensolvers/Block_lanczos_iteration.h>
#include <CGAL/Spectral_deformation/internal/Eigensolvers/Block_lanczos_state.h>
#include <CGAL/Spectral_deformation/internal/Eigensolvers/Eigenvalue_count.h>
#include <CGAL/Spectral_deformation/internal/Eigensolvers/Spectra_lanczos.h>
#include <CGAL/Spectral_deformation/internal/Eigensolvers/Single_vector_lanczos.h>
#include <CGAL/Spectral_deformation/internal/Eigensolvers/dense_eigenpairs.h>
#include <CGAL/Spectral_deformation/internal/Traits_requirements.h>

#include <CGAL/tags.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <algorithm>
#include <cstddef>
#include <exception>
#include <functional>
#include <string>

namespace CGAL {

/// \ingroup PkgSpectralSurfaceMeshDeformationTraits
/// The default model of `ManifoldHarmonicsEigensolverTraits`: a block
/// shift-invert Lanczos method, with the shifted matrix `Q - sigma M` factored
/// once by a sparse Cholesky factorization.
///
/// The method builds a Krylov subspace of the operator
/// `(Q - sigma M)^{-1} M`, which is self-adjoint in the M inner product and
/// whose largest eigenvalues `1 / (lambda - sigma)` belong to the wanted
/// smallest `lambda`. It advances `block_size()` vectors at a time: one
/// sparse solve with that many right-hand sides per block, and an
/// orthogonalization written as products of tall dense matrices. The
/// Rayleigh-Ritz values of the subspace are checked as it grows, and the
/// method stops when the `m` wanted pairs have a residual
/// `‖(Q - sigma M)^{-1} M h - theta h‖_M ≤ tolerance * theta` (the
/// criterion of `Spectra_eigensolver_traits`).
///
/// The default tolerance, `1e-6`, is looser than the reference's `1e-10`
/// because a deformation does not need more: the Ritz values converge with
/// the square of the residual (relative errors below `1e-11` against the
/// reference on the armadillo meshes), the final orthonormalization makes
/// the basis M-orthonormal to rounding whatever the tolerance, and the
/// armadillo arm deformed with the basis moved from the same deformation
/// with the reference basis by `2.3e-7` of the bounding-box diagonal at 104k
/// vertices, m = 100 (`3.1e-7` at `1e-10`, `1.2e-4` at `1e-4`), and by
/// `7.7e-6` at 26k vertices, m = 50 (`6e-9` at `1e-10`): far below the
/// relative step, `1e-4` by default, at which the deformation iteration
/// itself stops. It saves a seventh of the subspace (320 columns instead
/// of 368 at 104k, m = 100).
///
/// Three things keep the orthogonalization, otherwise the largest cost, small:
/// - *partial reorthogonalization* (Simon 1984, in block form): each new
///   block is orthogonalized against the last two blocks, which suffices in
///   exact arithmetic, while a recurrence on the small block tridiagonal
///   matrix estimates how much orthogonality rounding has cost against the
///   older blocks; only when that estimate exceeds `sqrt(eps)` are the block
///   and the next one orthogonalized against the whole subspace (18 times in
///   40 blocks for m = 100 on the 104k-vertex armadillo, 30 in 66 for
///   m = 200). Orthogonality to `sqrt(eps)` keeps the Rayleigh-Ritz values
///   exact to rounding, and a final Cholesky QR of the Ritz vectors (their
///   M-Gram matrix is summed while they are computed, in place of the
///   subspace) makes them M-orthonormal to rounding;
/// - *deflation of the constants*: when `Q` is a Laplacian (its rows sum to
///   zero), the functions constant on each connected component are known
///   eigenvectors of 0. They are returned as such and kept out of the Krylov
///   subspace, where their huge shift-inverted eigenvalue `1 / |sigma|`
///   would drive the loss of orthogonality;
/// - *two threads*: the tall products are split between the OpenMP
///   threads; with the default CHOLMOD simplicial factor, each solve is
///   split between two threads too, by subtrees of the elimination tree
///   (see `Cholmod_llt_solver_traits::solves_in_subtrees()`).
///   `OMP_NUM_THREADS=1` makes the whole method sequential. With the
///   default solver traits the result does not depend on the number of
///   OpenMP threads, to the last bit: the partial sums come in pieces fixed
///   by the sizes, added in order, and on one thread the solves by subtrees
///   run one subtree after the other. The dense products call the BLAS in pieces of at most 2¹⁸
///   multiply-adds, which OpenBLAS computes on the calling thread: they
///   never wake the threads of an OpenBLAS that runs threads of its own
///   (its pthreads build, Debian's default), whose idle threads spin
///   between calls and took the cores from the OpenMP teams.
///
/// Some of its speed comes from settings of the whole process, which
/// `compute()` changes only after `set_process_wide_tuning(true)`: by
/// default, including this header and calling `compute()` change no state
/// of the process (see `set_process_wide_tuning()`).
///
/// Compared with Spectra's single-vector Lanczos (`Spectra_eigensolver_traits`,
/// kept as the reference), which reorthogonalizes every vector against all
/// the previous ones, this reads the subspace a few times instead of once per
/// vector, and a solve with many right-hand sides reads the Cholesky factor
/// once. The subspace is not restarted: it grows until convergence, up to
/// `maximum_subspace_dimension()` columns of `n` doubles.
///
/// The price of advancing several vectors at a time is a slower convergence
/// where eigenvalues are clustered or repeated more often than the block size
/// (meshes with symmetries such as spheres). When the wanted pairs have not
/// converged at `maximum_subspace_dimension()`, `compute()` runs the
/// reference solver `Spectra_eigensolver_traits` instead (unless
/// `set_reference_fallback(false)` was called), so that the result never
/// depends on the block method converging.
///
/// On small meshes (a few thousand vertices) a single-vector method is
/// faster, but it can miss copies of a repeated eigenvalue, which
/// the block method finds up to the block size: on two unit spheres (1284
/// vertices, m = 10) Spectra's solver returned five of the six copies of
/// the eigenvalue 2, and on an icosphere of 642 vertices (m = 100) three
/// copies of its clusters of `2l + 1`. The single-vector method is therefore
/// used only where its result is checked (`uses_checked_single_vector()`,
/// small problems): the number of eigenvalues below the largest one it
/// found, counted by Sylvester's law of inertia on a sparse `L D Lᵀ`
/// factorization of the shifted matrix (about 1 ms on 1,000 vertices), must
/// be the number it found; copies of the largest eigenvalue may be any of
/// them, as with a dense solver. When a copy is missing, `compute()` solves
/// again with the block or the dense method. The single-vector method is
/// this class's iteration with blocks of one vector, written apart: the
/// subspace grows without restarts, with the same partial
/// reorthogonalization and deflation of the constants, and its
/// Rayleigh-Ritz checks solve a tridiagonal eigenproblem (LAPACK's
/// `dstemr`), at least k² / n steps apart (a check costs about that many
/// steps). Spectra's restarted solver, used there before, reorthogonalized
/// every new vector against the whole subspace: on the reference harness's
/// regions (one thread, as the deformation prepares regions of fewer than
/// 5,000 vertices, `m` = 100), the basis of 999 vertices takes 33-37 ms
/// instead of 58-70 ms, that of 3,433 vertices 89-130 ms instead of
/// 193-228 ms. `set_reference_threshold()` hands larger meshes to the
/// reference solver unchecked.
///
/// Small problems (at most `dense_threshold()` vertices, 300 by default, or
/// fewer than `5 m`), and problems whose subspace would not be much smaller
/// than `n` (`8 m > n`) when the checked single-vector method does not
/// apply or finds a copy missing, are solved with a dense solver instead,
/// which is exact and faster there. From 400 vertices on, wherever the block
/// method can run, it was measured faster than the dense solver (one thread,
/// `m` = 10 to 100): 900 vertices and `m` = 100 in 55 ms instead of 92 ms,
/// `m` = 10 in 10 ms instead of 64 ms.
///
/// \tparam SparseSPDSolverTraits a model of `SparseSPDSolverTraits`, used to
///         factor `Q - sigma M`; its `solve()` receives `block_size()`
///         right-hand sides at a time.
template <class SparseSPDSolverTraits = Default_eigensolver_sparse_spd_solver_traits>
class Block_lanczos_eigensolver_traits
{
  static_assert(Spectral_deformation::internal::Sparse_spd_solver_requirements<SparseSPDSolverTraits>::met);

public:
  /// Declares the optional members `process_wide_tuning()` and
  /// `set_process_wide_tuning()` (see `ManifoldHarmonicsEigensolverTraits`).
  typedef CGAL::Tag_true Supports_process_wide_tuning;

  /// The state of a running `compute()`, passed to the progress callback.
  struct Progress
  {
    /// The stages of `compute()`, in this order.
    enum Stage {
      FACTORIZATION, ///< the shifted matrix `Q - sigma M` is being factored
      ITERATION,     ///< the subspace grows; reported after every block solve (after every solve in the checked single-vector method of small problems, see `uses_checked_single_vector()`)
      REFERENCE_SOLVE, ///< the reference solver runs: when the mesh is below `reference_threshold()`, or when the subspace reached its maximum dimension unconverged; reported after every solve of the reference solver
      DENSE_SOLVE,   ///< a small problem is solved with the dense solver (no intermediate report)
      APPROXIMATION, ///< `Partition_of_unity_eigensolver_traits` builds its space of sampled functions and solves the reduced problem (no intermediate report)
      FINISHED       ///< `compute()` is about to return, successfully or not
    };
    Stage stage = FACTORIZATION;                   ///< the current stage
    std::size_t solves = 0;                        ///< right-hand sides solved so far
    std::size_t subspace_dimension = 0;            ///< columns of the subspace so far
    std::size_t maximum_subspace_dimension = 0;    ///< the cap on `subspace_dimension`
    std::size_t converged_eigenpairs = 0;          ///< wanted pairs converged at the last check
    std::size_t number_of_eigenpairs = 0;          ///< the `m` of the call
    std::size_t number_of_vertices = 0;            ///< the `n` of the call
  };

  /// The type of the progress callback.
  typedef std::function<void(const Progress&)> Progress_callback;

  /// Creates a solver with the relative residual tolerance, the block size
  /// (`0`: chosen from `m`, see `block_size()`), the cap on the subspace
  /// dimension (`0`: chosen from `m`, see `maximum_subspace_dimension()`),
  /// and the size at or below which the dense solver is used.
  explicit Block_lanczos_eigensolver_traits(double tolerance = 1e-6, Eigen::Index block_size = 0,
                                            Eigen::Index maximum_subspace_dimension = 0,
                                            Eigen::Index dense_threshold = 300)
    : m_tolerance(tolerance), m_block_size(block_size),
      m_maximum_subspace_dimension(maximum_subspace_dimension), m_dense_threshold(dense_threshold)
  {}

  /// The size at or below which the dense solver is used.
  Eigen::Index dense_threshold() const { return m_dense_threshold; }

  /// The relative residual tolerance.
  double tolerance() const { return m_tolerance; }

  /// The number of vectors of a block for `m` eigenpairs: the value given at
  /// construction, or `clamp(m / 32, 8, 32)`. Larger blocks make the dense
  /// products and the solves more efficient but need a larger subspace for
  /// the same accuracy; 8 was the fastest of 4, 6, 8, 12 and 16 for
  /// m = 100 and m = 200 on meshes of 26k and 104k vertices, and still
  /// faster than 12 and 16 with partial reorthogonalization.
  Eigen::Index block_size(Eigen::Index m) const
  {
    if(m_block_size > 0)
      return m_block_size;
    return (std::min)(Eigen::Index(32), (std::max)(Eigen::Index(8), m / 32));
  }

  /// The largest subspace for `m` eigenpairs: the value given at
  /// construction, or `max(8 m, m + 16 block_size(m))`. The memory of the
  /// subspace is reserved at that size but only touched as it grows: on the
  /// armadillo meshes it converged at 3 to 4 m, while clusters of repeated
  /// eigenvalues larger than the block (symmetric meshes) need more.
  Eigen::Index maximum_subspace_dimension(Eigen::Index m) const
  {
    if(m_maximum_subspace_dimension > 0)
      return m_maximum_subspace_dimension;
    return (std::max)(8 * m, m + 16 * block_size(m));
  }

  /// The number of vertices below which `compute()` hands the problem to
  /// `Spectra_eigensolver_traits` (see the class description).
  Eigen::Index reference_threshold() const { return m_reference_threshold; }

  /// Sets `reference_threshold()`; 0 (the default) always runs the block
  /// method.
  void set_reference_threshold(Eigen::Index vertices) { m_reference_threshold = vertices; }

  /// Whether `compute()` first runs the reference solver on `m` eigenpairs
  /// of `n` vertices and checks its result by an eigenvalue count (see the
  /// class description): when enabled (the default), above
  /// `dense_threshold()`, for `5 m <= n <= 5000` and `n m² <= 4·10⁷` (up to
  /// 4,000 vertices for m = 100, 1,000 for m = 200), where it was measured
  /// faster than both the block and the dense method.
  bool uses_checked_single_vector(Eigen::Index n, Eigen::Index m) const
  {
    const double work = static_cast<double>(n) * static_cast<double>(m) * static_cast<double>(m);
    return m_checked_single_vector && n > m_dense_threshold && 5 * m <= n && n <= 5000 && work <= 4e7;
  }

  /// Enables or disables the checked single-vector method of small problems.
  void set_checked_single_vector(bool enabled) { m_checked_single_vector = enabled; }

  /// The memory the subspace may take, in bytes (default 4 GiB). The cap on
  /// the subspace dimension is lowered to fit in it, and when even a typical
  /// subspace (4 m columns of n doubles) would not fit, `compute()` runs
  /// `Spectra_eigensolver_traits` directly, whose subspace has 2 m + 1
  /// columns: for m = 100 on 1.6 million vertices the block method's subspace
  /// would take about 5 GiB.
  std::size_t memory_limit() const { return m_memory_limit; }

  /// Sets `memory_limit()`.
  void set_memory_limit(std::size_t bytes) { m_memory_limit = bytes; }

  /// Whether `compute()` runs `Spectra_eigensolver_traits` when the block
  /// method does not converge within `maximum_subspace_dimension()` (default
  /// `true`); with `false` it fails instead.
  void set_reference_fallback(bool enabled) { m_reference_fallback = enabled; }

  /// Sets a function that `compute()` calls at the start of every stage
  /// (see `Progress`), after every block solve and once before it returns.
  /// An empty function (the default) disables the reports. The callback
  /// must not throw; it is copied with the traits.
  void set_progress_callback(const Progress_callback& callback) { m_progress_callback = callback; }

  /// Whether `compute()` may change state of the whole process to run
  /// faster (default `false`); see `set_process_wide_tuning()`.
  bool process_wide_tuning() const { return m_process_wide_tuning; }

  /// Sets `process_wide_tuning()`. With `true`, the block method
  /// (not the dense solver) changes, for the time of `compute()`:
  /// - the number of OpenBLAS threads, set to one and restored when
  ///   `compute()` returns (when the package uses OpenBLAS, the macro
  ///   `CGAL_SSMD_USE_OPENBLAS`): OpenBLAS's idle threads keep a core busy
  ///   between calls, which slowed the two-thread products and solves of
  ///   the method down. Other threads of the program calling OpenBLAS
  ///   meanwhile run single-threaded too;
  /// - the mapping of the subspace: transparent huge pages are requested on
  ///   it (Linux `madvise`), and its pages are mapped ahead, on a second
  ///   thread, while the factorization runs, because the first write of
  ///   a subspace of hundreds of MiB costs about as much as the
  ///   factorization. The advice stays on the address range after the
  ///   memory is freed, where the allocator may place other data of the
  ///   program;
  /// - the sparse solver, handed the same choice when its traits class has
  ///   a `set_process_wide_tuning()` member (`Cholmod_llt_solver_traits`
  ///   then replaces SuiteSparse's global allocator while it factors and
  ///   solves), and the reference solver of the fallback likewise.
  ///
  /// `Manifold_harmonics_basis` (and `Spectral_surface_mesh_deformation`,
  /// which computes its basis with it) also assembles the cotangent matrix in
  /// huge pages when its eigensolver traits have this option set.
  ///
  /// A program that owns its process (a command-line tool, a benchmark)
  /// should enable it; a library that shares its process with code it does
  /// not know should leave it off. Without it, OpenBLAS runs on the threads
  /// the process gives it: where that is more than one, the method runs its
  /// own parts on one thread (see the class description), and its results
  /// differ from those with the option by rounding
  /// (a multi-threaded OpenBLAS splits its products, and sums them in
  /// another order). Setting `OPENBLAS_NUM_THREADS=1` in the environment
  /// gives the results of the option without it.
  void set_process_wide_tuning(bool enabled) { m_process_wide_tuning = enabled; }

  /// Computes the `m` smallest eigenpairs of `Q h = lambda M h` with
  /// `M = diag(mass)`: `eigenvalues` ascending, `eigenvectors` (n×m)
  /// M-orthonormal. Returns `false`, with `error_message()` set, when the
  /// factorization fails or the eigenpairs do not converge within
  /// `maximum_subspace_dimension(m)`.
  bool compute(const Eigen::SparseMatrix<double>& stiffness, const Eigen::VectorXd& mass,
               Eigen::Index m, Eigen::VectorXd& eigenvalues, Eigen::MatrixXd& eigenvectors)
  {
    m_error_message.clear();
    const Eigen::Index n = stiffness.rows();
    if(m < 1 || m > n)
      return fail("the number of eigenpairs must be between 1 and the number of vertices");
    const Eigen::Index b = block_size(m);
    // The subspace and one more block must fit in n dimensions and in the
    // memory limit.
    const Eigen::Index columns_in_memory =
        static_cast<Eigen::Index>(m_memory_limit / (sizeof(double) * static_cast<std::size_t>(n)));
    const Eigen::Index dimension_in_memory = (columns_in_memory / b - 1) * b;
    const Eigen::Index dimension_in_n = ((n - b) / b - 1) * b;
    const Eigen::Index max_dimension = (std::min)(
        {round_up(maximum_subspace_dimension(m), b), dimension_in_n, dimension_in_memory});
    Progress progress;
    progress.number_of_eigenpairs = static_cast<std::size_t>(m);
    progress.number_of_vertices = static_cast<std::size_t>(n);
    progress.maximum_subspace_dimension = static_cast<std::size_t>(max_dimension);
    bool success = false;
    if(uses_checked_single_vector(n, m) && solve_checked(stiffness, mass, m, progress, eigenvalues, eigenvectors))
      success = true;
    // A typical subspace (4 m) would not be much smaller than n: the dense
    // solver is then both exact and cheaper.
    else if(n <= m_dense_threshold || 8 * m > n || dimension_in_n < m + b)
      success = solve_densely(stiffness, mass, m, progress, eigenvalues, eigenvectors);
    else if(n < m_reference_threshold || dimension_in_memory < round_up(4 * m, b))
    {
      std::string message;
      success = run_reference(stiffness, mass, m, progress, eigenvalues, eigenvectors, message) ||
                fail(message);
    }
    else
      success = solve_by_blocks(stiffness, mass, m, b, max_dimension, progress, eigenvalues,
                                eigenvectors);
    report(progress, Progress::FINISHED);
    return success;
  }

  /// The reason of the last failure of `compute()`.
  const std::string& error_message() const { return m_error_message; }

private:
  static Eigen::Index round_up(Eigen::Index value, Eigen::Index multiple)
  {
    return Spectral_deformation::internal::Eigensolvers::round_up(value, multiple);
  }

  // Reports the block iteration as `Progress`.
  struct Progress_listener
  {
    const Block_lanczos_eigensolver_traits& traits;
    Progress& progress;

    void factorization_started() { traits.report(progress, Progress::FACTORIZATION); }
    void block_solved(Eigen::Index b, Eigen::Index subspace_dimension)
    {
      progress.solves += static_cast<std::size_t>(b);
      progress.subspace_dimension = static_cast<std::size_t>(subspace_dimension);
      traits.report(progress, Progress::ITERATION);
    }
    void checked(Eigen::Index converged_eigenpairs)
    {
      progress.converged_eigenpairs = static_cast<std::size_t>(converged_eigenpairs);
    }
  };

  bool solve_densely(const Eigen::SparseMatrix<double>& stiffness, const Eigen::VectorXd& mass,
                     Eigen::Index m, Progress& progress, Eigen::VectorXd& eigenvalues,
                     Eigen::MatrixXd& eigenvectors)
  {
    report(progress, Progress::DENSE_SOLVE);
    std::string message;
    return Spectral_deformation::internal::Eigensolvers::dense_generalized_eigenpairs(
               stiffness, mass, m, eigenvalues, eigenvectors, message) ||
           fail(message);
  }

  // The reference solver, its result kept only when no eigenvalue below the
  // largest one it found is missing. A failure of the reference solver only
  // leaves the problem to the other methods, which report their own.
  bool solve_checked(const Eigen::SparseMatrix<double>& stiffness, const Eigen::VectorXd& mass, Eigen::Index m,
                     Progress& progress, Eigen::VectorXd& eigenvalues, Eigen::MatrixXd& eigenvectors) const
  {
    namespace SD = Spectral_deformation::internal;
    std::string message;
    Eigen::VectorXd values;
    Eigen::MatrixXd vectors;
    SD::Eigensolvers::Single_vector_lanczos_settings settings;
    settings.max_dimension = maximum_subspace_dimension(m);
    settings.tolerance = m_tolerance;
    report(progress, Progress::FACTORIZATION);
    const std::size_t solves_before = progress.solves;
    auto after_solve = [this, &progress, solves_before](Eigen::Index k) {
      progress.solves = solves_before + static_cast<std::size_t>(k);
      progress.subspace_dimension = static_cast<std::size_t>(k);
      report(progress, Progress::ITERATION);
    };
    auto after_check = [&progress](Eigen::Index converged) {
      progress.converged_eigenpairs = static_cast<std::size_t>(converged);
    };
    if(!SD::Eigensolvers::single_vector_lanczos_eigenpairs<SparseSPDSolverTraits>(
           stiffness, mass, m, settings, after_solve, after_check, values, vectors, message) ||
       !SD::Eigensolvers::smallest_eigenvalues_complete(stiffness, mass, values))
      return false;
    eigenvalues.swap(values);
    eigenvectors.swap(vectors);
    return true;
  }

  // The block method; when it does not converge within `max_dimension`,
  // the reference solver, unless disabled.
  bool solve_by_blocks(const Eigen::SparseMatrix<double>& stiffness, const Eigen::VectorXd& mass,
                       Eigen::Index m, Eigen::Index b, Eigen::Index max_dimension,
                       Progress& progress, Eigen::VectorXd& eigenvalues,
                       Eigen::MatrixXd& eigenvectors)
  {
    Spectral_deformation::internal::Eigensolvers::Block_lanczos_settings settings;
    settings.block_size = b;
    settings.max_dimension = max_dimension;
    settings.tolerance = m_tolerance;
    settings.process_wide_tuning = m_process_wide_tuning;
    Progress_listener listener{*this, progress};
    Spectral_deformation::internal::Eigensolvers::Block_lanczos_failure failure;
    bool success = false;
    try
    {
      success = Spectral_deformation::internal::Eigensolvers::block_lanczos_eigenpairs<SparseSPDSolverTraits>(
                    stiffness, mass, m, settings, listener, eigenvalues, eigenvectors, failure) ||
                fail(failure.message);
    }
    catch(const std::exception& e)
    {
      success = fail(e.what());
    }
    if(!success && failure.unconverged && m_reference_fallback)
    {
      std::string message;
      success = run_reference(stiffness, mass, m, progress, eigenvalues, eigenvectors, message);
      m_error_message =
          success ? std::string() : m_error_message + "; the reference solver failed too: " + message;
    }
    return success;
  }

  // The reference solver (Spectra's shift-invert Lanczos, as
  // `Spectra_eigensolver_traits` with the same tolerance, no dense
  // threshold and the same process-wide tuning); its solves are reported as
  // REFERENCE_SOLVE progress (added to the block solves so far).
  bool run_reference(const Eigen::SparseMatrix<double>& stiffness, const Eigen::VectorXd& mass,
                     Eigen::Index m, Progress& progress, Eigen::VectorXd& eigenvalues,
                     Eigen::MatrixXd& eigenvectors, std::string& message) const
  {
    namespace SD = Spectral_deformation::internal;
    report(progress, Progress::REFERENCE_SOLVE);
    const Eigen::Index ncv = SD::Eigensolvers::spectra_subspace_dimension(stiffness.rows(), m);
    if(ncv >= stiffness.rows())
      return SD::Eigensolvers::dense_generalized_eigenpairs(stiffness, mass, m, eigenvalues, eigenvectors,
                                              message);
    std::function<void()> after_solve;
    if(m_progress_callback)
      after_solve = [this, &progress]() {
        ++progress.solves;
        report(progress, Progress::REFERENCE_SOLVE);
      };
    SD::Eigensolvers::Spectra_lanczos_settings settings;
    settings.subspace_dimension = ncv;
    settings.max_iterations = 1000;
    settings.tolerance = m_tolerance;
    settings.process_wide_tuning = m_process_wide_tuning;
    return SD::Eigensolvers::spectra_shift_invert_eigenpairs<SparseSPDSolverTraits>(
        stiffness, mass, m, settings, m_progress_callback ? &after_solve : nullptr, eigenvalues,
        eigenvectors, message);
  }

  bool fail(const std::string& message)
  {
    m_error_message = message;
    return false;
  }

  void report(Progress& progress, typename Progress::Stage stage) const
  {
    progress.stage = stage;
    if(m_progress_callback)
      m_progress_callback(progress);
  }

  double m_tolerance;
  Eigen::Index m_block_size;
  Eigen::Index m_maximum_subspace_dimension;
  Eigen::Index m_dense_threshold;
  Eigen::Index m_reference_threshold = 0;
  std::size_t m_memory_limit = std::size_t(4) << 30;
  bool m_reference_fallback = true;
  bool m_checked_single_vector = true;
  bool m_process_wide_tuning = false;
  std::string m_error_message;
  Progress_callback m_progress_callback;
};

} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_BLOCK_LANCZOS_EIGENSOLVER_TRAITS_H

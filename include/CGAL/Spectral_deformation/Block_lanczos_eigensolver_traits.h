// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_BLOCK_LANCZOS_EIGENSOLVER_TRAITS_H
#define CGAL_SPECTRAL_DEFORMATION_BLOCK_LANCZOS_EIGENSOLVER_TRAITS_H

#include <CGAL/Spectral_deformation/Sparse_spd_solver_traits.h>
#include <CGAL/Spectral_deformation/Spectra_eigensolver_traits.h>
#include <CGAL/Spectral_deformation/internal/Linear_algebra/Dense_products.h>
#include <CGAL/Spectral_deformation/internal/Eigensolvers/dense_eigenpairs.h>
#include <CGAL/Spectral_deformation/internal/Eigensolvers/Laplacian_null_space.h>
#include <CGAL/Spectral_deformation/internal/Eigensolvers/Largest_eigenpairs.h>
#include <CGAL/Spectral_deformation/internal/Memory/Large_array.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <exception>
#include <functional>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#ifdef _OPENMP
#include <omp.h>
#endif

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
/// - *two threads*: OpenBLAS runs on one thread during `compute()` (its idle
///   threads keep a core busy between calls) and the tall products are split
///   between the OpenMP threads; with the default CHOLMOD simplicial factor,
///   each solve is split between two threads too, by subtrees of the
///   elimination tree (see `Cholmod_llt_solver_traits::solves_in_subtrees()`).
///   The OpenBLAS thread count is a setting of the whole process, restored
///   when `compute()` returns: other threads calling OpenBLAS meanwhile run
///   single-threaded. `OMP_NUM_THREADS=1` makes the whole method sequential.
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
/// On small meshes the single-vector method is faster (0.27 s against
/// 0.52 s for the block method with m = 100 on 2281 vertices; 2.4 s against
/// 1.2 s on 26002), but it can miss copies of a repeated eigenvalue, which
/// the block method finds up to the block size: on two unit spheres (1284
/// vertices, m = 10) Spectra's solver returned five of the six copies of
/// the eigenvalue 2. The block method is therefore used at every size by
/// default; `set_reference_threshold()` hands meshes below a size to the
/// reference solver instead.
///
/// Small problems (at most `dense_threshold()` vertices) and problems whose
/// subspace would not be much smaller than `n` are solved with a dense
/// solver instead, which is exact and faster at that size.
///
/// \tparam SparseSPDSolverTraits a model of `SparseSPDSolverTraits`, used to
///         factor `Q - sigma M`; its `solve()` receives `block_size()`
///         right-hand sides at a time.
template <class SparseSPDSolverTraits = Default_eigensolver_sparse_spd_solver_traits>
class Block_lanczos_eigensolver_traits
{
public:
  /// The state of a running `compute()`, passed to the progress callback.
  struct Progress
  {
    /// The stages of `compute()`, in this order.
    enum Stage {
      FACTORIZATION, ///< the shifted matrix `Q - sigma M` is being factored
      ITERATION,     ///< the subspace grows; reported after every block solve
      REFERENCE_SOLVE, ///< the reference solver runs: the mesh is below `reference_threshold()`, or the subspace reached its maximum dimension unconverged; reported after every solve of the reference solver
      DENSE_SOLVE,   ///< a small problem is solved with the dense solver (no intermediate report)
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
                                            Eigen::Index dense_threshold = 1000)
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
  /// faster than 12 and 16 with partial reorthogonalization (3.6 s against
  /// 4.2 s and 4.5 s for m = 100 on 104k vertices).
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
    // A typical subspace (4 m) would not be much smaller than n: the dense
    // solver is then both exact and cheaper.
    if(n <= m_dense_threshold || 8 * m > n || dimension_in_n < m + b)
    {
      report(progress, Progress::DENSE_SOLVE);
      std::string message;
      const bool success =
          Spectral_deformation::internal::dense_generalized_eigenpairs(stiffness, mass, m, eigenvalues,
                                                                      eigenvectors, message) ||
          fail(message);
      report(progress, Progress::FINISHED);
      return success;
    }
    if(n < m_reference_threshold || dimension_in_memory < round_up(4 * m, b))
    {
      std::string message;
      const bool success =
          run_reference(stiffness, mass, m, progress, eigenvalues, eigenvectors, message) ||
          fail(message);
      report(progress, Progress::FINISHED);
      return success;
    }
    bool success = false;
    bool converged = true;
    try
    {
      success = iterate(stiffness, mass, m, b, max_dimension, progress, converged, eigenvalues,
                        eigenvectors);
    }
    catch(const std::exception& e)
    {
      success = fail(e.what());
    }
    if(!success && !converged && m_reference_fallback)
    {
      std::string message;
      success = run_reference(stiffness, mass, m, progress, eigenvalues, eigenvectors, message);
      m_error_message =
          success ? std::string() : m_error_message + "; the reference solver failed too: " + message;
    }
    report(progress, Progress::FINISHED);
    return success;
  }

  /// The reason of the last failure of `compute()`.
  const std::string& error_message() const { return m_error_message; }

private:
  typedef Eigen::MatrixXd Matrix;

  static Eigen::Index round_up(Eigen::Index value, Eigen::Index multiple)
  {
    return ((value + multiple - 1) / multiple) * multiple;
  }

  bool iterate(const Eigen::SparseMatrix<double>& stiffness, const Eigen::VectorXd& mass,
               Eigen::Index m, Eigen::Index b, Eigen::Index max_dimension, Progress& progress,
               bool& converged_in_time, Eigen::VectorXd& eigenvalues, Eigen::MatrixXd& eigenvectors)
  {
    using Spectral_deformation::internal::threaded_dense_product;
    using Spectral_deformation::internal::prefault;
    const Spectral_deformation::internal::Single_threaded_blas single_threaded_blas;
    const Eigen::Index n = stiffness.rows();
    const double sigma = Spectral_deformation::internal::shift_invert_shift(mass);

    // The constants of each component are eigenvectors of the eigenvalue 0,
    // known in closed form. Kept out of the Krylov subspace, they no longer
    // dominate it: their shift-inverted eigenvalue 1 / |sigma| is thousands
    // of times the wanted ones, and its rounding errors would be what
    // destroys the orthogonality of the Lanczos vectors first.
    const Spectral_deformation::internal::Laplacian_null_space null_space(stiffness, mass);
    const Eigen::Index known = (std::min)(null_space.dimension(), m);
    const Eigen::Index wanted = m - known;
    if(wanted == 0)
    {
      eigenvalues = Eigen::VectorXd::Zero(m);
      eigenvectors = null_space.basis().leftCols(m);
      return true;
    }

    // V holds the M-orthonormal subspace, one block more than the
    // Rayleigh-Ritz dimension; T = Vᵀ M (Q - sigma M)^{-1} M V is block
    // tridiagonal: its diagonal and upper blocks come from the
    // orthogonalization against the last two blocks, its lower blocks from
    // the normalization of each new block.
    // The eigenvectors are computed in the leading columns of V at the end
    // (see ritz_vectors_in_place()), so that V's memory is returned: memory
    // new to the process costs more to map than the products done on it.
    // V is only touched as it grows.
    Matrix V(n, max_dimension + b);
    Spectral_deformation::internal::advise_huge_pages(
        V.data(), sizeof(double) * static_cast<std::size_t>(V.size()));
    const Eigen::Index typical_columns = (std::min)(max_dimension + b, round_up(3 * m, b) + b);
    report(progress, Progress::FACTORIZATION);
    SparseSPDSolverTraits solver;
    if(!factor_while_mapping(
           solver, Spectral_deformation::internal::shifted_stiffness(stiffness, mass, sigma), V.data(),
           sizeof(double) * static_cast<std::size_t>(n) * static_cast<std::size_t>(typical_columns)))
      return fail("the factorization of the shifted stiffness matrix failed");
    progress.stage = Progress::ITERATION;
    // T and the estimates of Vᵀ M V (`orthogonality`, upper blocks only)
    // grow with the subspace (they would be 8 m squared at full size).
    const Eigen::Index initial_size = (std::min)(max_dimension + b, round_up(4 * m, b) + b);
    Matrix T = Matrix::Zero(initial_size, initial_size);
    Matrix orthogonality = Matrix::Zero(initial_size, initial_size);
    Matrix block(n, b), weighted(n, b), coefficients(max_dimension + b, b), scratch(n, b);
    for(Matrix* work : {&block, &weighted, &scratch})
      prefault(work->data(), sizeof(double) * static_cast<std::size_t>(work->size()));

    std::mt19937 generator(20080806u);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    auto randomize = [&](Matrix& target) {
      for(Eigen::Index j = 0; j < target.cols(); ++j)
        for(Eigen::Index i = 0; i < n; ++i)
          target(i, j) = uniform(generator);
    };

    // One pass of classical Gram-Schmidt: makes `block` M-orthogonal to the
    // columns [first, k) of V and adds the coefficients to the rows
    // [first, k) of `added` (when given).
    auto project_out = [&](Eigen::Index first, Eigen::Index k, Matrix* added) {
      const Eigen::Index count = k - first;
      if(count <= 0)
        return;
      weighted = mass.asDiagonal() * block;
      auto h = coefficients.topRows(count);
      threaded_dense_product(true, V.middleCols(first, count), false, weighted, 1.0, 0.0, h);
      threaded_dense_product(false, V.middleCols(first, count), false, h, -1.0, 1.0, block);
      if(added != nullptr)
        added->middleRows(first, count) += h;
    };
    // Twice against all k columns: for a block with no relation to V.
    auto orthogonalize = [&](Eigen::Index k) {
      null_space.project_out(block);
      project_out(0, k, nullptr);
      project_out(0, k, nullptr);
    };
    const Eigen::VectorXd sqrt_mass = mass.cwiseSqrt();
    const Eigen::VectorXd inverse_sqrt_mass = sqrt_mass.cwiseInverse();
    // block = Q_new R with Q_new M-orthonormal (Cholesky QR, twice). Returns
    // false when the block is too ill-conditioned for it.
    auto cholesky_qr = [&](Matrix& R) -> bool {
      R = Matrix::Identity(b, b);
      for(int pass = 0; pass < 2; ++pass)
      {
        weighted = mass.asDiagonal() * block;
        Matrix gram(b, b);
        threaded_dense_product(true, block, false, weighted, 1.0, 0.0, gram);
        Eigen::LLT<Matrix> cholesky(gram);
        if(cholesky.info() != Eigen::Success)
          return false;
        const Matrix upper = cholesky.matrixU();
        const double smallest = upper.diagonal().minCoeff(), largest = upper.diagonal().maxCoeff();
        // Cholesky QR twice is accurate up to cond(block) ≈ 1/sqrt(eps).
        if(!(smallest > 1e-6 * largest))
          return false;
        const Matrix inverse = upper.template triangularView<Eigen::Upper>().solve(
            Matrix::Identity(b, b));
        threaded_dense_product(false, block, false, inverse, 1.0, 0.0, scratch);
        block.swap(scratch);
        R = upper * R;
        // It loses orthogonality like cond(block)² eps: a second pass is
        // needed only for an ill-conditioned block.
        if(pass == 0 && largest < 10 * smallest)
          break;
      }
      return true;
    };
    // block = Q_new R for a block M-orthogonal to the k leading columns of V,
    // whatever its rank: a pivoted Householder QR finds the directions the
    // block lacks (the Krylov subspace contains an invariant subspace, e.g.
    // converged eigenvectors of a repeated eigenvalue); they are replaced by
    // random directions with a zero coupling, which keeps T exact (deflation).
    // Returns true when the block had full rank.
    auto normalize = [&](Eigen::Index k, Matrix& R) -> bool {
      if(cholesky_qr(R))
        return true;
      scratch = sqrt_mass.asDiagonal() * block;
      Eigen::ColPivHouseholderQR<Matrix> qr(scratch);
      const Matrix triangular = qr.matrixR().topRows(b).template triangularView<Eigen::Upper>();
      Matrix coupling = triangular * qr.colsPermutation().transpose();
      block = inverse_sqrt_mass.asDiagonal() * (qr.householderQ() * Matrix::Identity(n, b));
      const double largest = std::abs(triangular(0, 0));
      Eigen::Index rank = 0;
      while(rank < b && std::abs(triangular(rank, rank)) > 1e-10 * largest)
        ++rank;
      for(Eigen::Index j = rank; j < b; ++j)
      {
        for(Eigen::Index i = 0; i < n; ++i)
          block(i, j) = uniform(generator);
        coupling.row(j).setZero();
      }
      orthogonalize(k);
      Matrix correction;
      if(!cholesky_qr(correction))
        throw std::runtime_error("could not extend the Krylov subspace with new directions");
      R = correction * coupling;
      return rank == b;
    };

    // Partial reorthogonalization (Simon 1984, in block form): the new block
    // is orthogonalized against the last two blocks only, which the block
    // three-term recurrence makes sufficient in exact arithmetic, while a
    // recurrence driven by T estimates how far rounding has carried it from
    // the older blocks. When that estimate passes sqrt(eps), the new block
    // and the next are orthogonalized against the whole subspace. Keeping
    // V orthogonal to sqrt(eps) is enough for T to be, up to rounding, the
    // projection of the operator on the subspace (no spurious copies of the
    // converged eigenvalues); the Ritz vectors are made orthonormal at the
    // end. Each reorthogonalization reads the whole subspace twice, the
    // most expensive step of a full reorthogonalization at every block.
    const double eps = std::numeric_limits<double>::epsilon();
    const double semi_orthogonality = std::sqrt(eps);
    double operator_norm = 0;
    auto T_block = [&](Eigen::Index i, Eigen::Index j) { return T.block(i * b, j * b, b, b); };
    auto W_block = [&](Eigen::Index i, Eigen::Index j) {
      return orthogonality.block(i * b, j * b, b, b);
    };
    // Estimates the blocks (i, J + 1) of Vᵀ M V for i < J from those of the
    // columns J and J - 1 and the blocks of T; the new block J + 1 has been
    // orthogonalized against J - 1 and J. Returns the largest estimate.
    auto estimate_orthogonality = [&](Eigen::Index J, const Matrix& R) -> double {
      const Matrix identity = Matrix::Identity(b, b);
      const Matrix A_J = 0.5 * (T_block(J, J) + T_block(J, J).transpose());
      operator_norm = (std::max)(operator_norm, A_J.norm() + R.norm());
      const auto inverse_R = R.template triangularView<Eigen::Upper>();
      double largest = 0;
      for(Eigen::Index i = 0; i < J; ++i)
      {
        const Matrix A_i = 0.5 * (T_block(i, i) + T_block(i, i).transpose());
        Matrix estimate = A_i * W_block(i, J) - W_block(i, J) * A_J;
        if(i > 0)
          estimate += T_block(i, i - 1) * W_block(i - 1, J);
        estimate += T_block(i + 1, i).transpose() * (i + 1 == J ? identity : Matrix(W_block(i + 1, J)));
        if(J > 0)
          estimate -= (i == J - 1 ? identity : Matrix(W_block(i, J - 1))) * T_block(J, J - 1).transpose();
        // The rounding of one step, with the sign that makes it grow.
        estimate = estimate.unaryExpr([&](double x) { return x + (x < 0 ? -eps : eps) * operator_norm; });
        estimate = inverse_R.template solve<Eigen::OnTheRight>(estimate);
        W_block(i, J + 1) = estimate;
        largest = (std::max)(largest, estimate.cwiseAbs().maxCoeff());
      }
      W_block(J, J + 1).setConstant(eps);
      W_block(J + 1, J + 1).setIdentity();
      return largest;
    };
    auto reset_orthogonality = [&](Eigen::Index J) {
      W_block(J + 1, J + 1).setIdentity();
      for(Eigen::Index i = 0; i <= J; ++i)
        W_block(i, J + 1).setConstant(eps);
    };

    Matrix R;
    randomize(block);
    orthogonalize(0);
    normalize(0, R);
    V.leftCols(b) = block;
    W_block(0, 0).setIdentity();
    bool breakdown = false;
    bool reorthogonalize_next = false;
    std::size_t reorthogonalizations = 0;

    // Each Rayleigh-Ritz check costs a dense k × k eigendecomposition: the
    // checks start where convergence is plausible.
    Eigen::Index next_check = (std::max)(m + b, round_up((3 * m) / 2, b));
    for(Eigen::Index k = b;; k += b)
    {
      const Eigen::Index J = k / b - 1;
      // The block V(:, k - b .. k) enters the operator; its image is
      // orthogonalized against the last two blocks, twice.
      weighted = mass.asDiagonal() * V.middleCols(k - b, b);
      if(!solver.solve(weighted, block))
        return fail("a solve with the factored shifted stiffness matrix failed");
      progress.solves += static_cast<std::size_t>(b);
      progress.subspace_dimension = static_cast<std::size_t>(k);
      report(progress, Progress::ITERATION);

      if(k + b > T.rows())
      {
        const Eigen::Index size = (std::min)(max_dimension + b, 2 * T.rows());
        T.conservativeResizeLike(Matrix::Zero(size, size));
        orthogonality.conservativeResizeLike(Matrix::Zero(size, size));
      }
      null_space.project_out(block);
      Matrix column_block = Matrix::Zero(k, b);
      const Eigen::Index local = (std::max)(Eigen::Index(0), k - 2 * b);
      project_out(local, k, &column_block);
      project_out(local, k, &column_block);
      T.block(0, k - b, k, b) = column_block;
      // A block that lacked directions was completed against the whole
      // subspace: T stays exact, and the residuals are verified on the
      // result.
      if(!normalize(k, R))
      {
        breakdown = true;
        reorthogonalize_next = true;
        reset_orthogonality(J);
      }
      else if(estimate_orthogonality(J, R) > semi_orthogonality || reorthogonalize_next)
      {
        // block = V h + Q' R': the coupling of the new block becomes R' R,
        // and the coefficients h, of the order of sqrt(eps), are left out of
        // T as in the Lanczos recurrence.
        project_out(0, k, nullptr);
        null_space.project_out(block);
        Matrix correction;
        if(!cholesky_qr(correction))
          throw std::runtime_error("the reorthogonalized Lanczos block is rank deficient");
        R = correction * R;
        reorthogonalize_next = !reorthogonalize_next;
        reset_orthogonality(J);
        ++reorthogonalizations;
      }
      V.middleCols(k, b) = block;
      T.block(k, k - b, b, b) = R;

      if(k < next_check && k < max_dimension)
        continue;
      // Rayleigh-Ritz on the k columns.
      const Matrix projected = 0.5 * (T.topLeftCorner(k, k) + T.topLeftCorner(k, k).transpose());
      Eigen::VectorXd ritz_values;
      Matrix ritz_coordinates;
      if(!Spectral_deformation::internal::largest_symmetric_eigenpairs(projected, wanted, ritz_values,
                                                                       ritz_coordinates))
        return fail("the Rayleigh-Ritz eigensolver did not converge");
      // Largest theta first: the smallest lambda.
      std::size_t converged = 0;
      for(Eigen::Index i = 0; i < wanted; ++i)
      {
        const Eigen::Index column = wanted - 1 - i;
        const double theta = ritz_values[column];
        const double residual = (R * ritz_coordinates.col(column).tail(b)).norm();
        if(residual <= m_tolerance * std::abs(theta))
          ++converged;
      }
      progress.converged_eigenpairs = converged + static_cast<std::size_t>(known);
      // A block brought about b / 3 eigenpairs to convergence on the
      // armadillo meshes: the next check is spaced by about 1/16 of the
      // dimension, and comes at every block when fewer than 2 b pairs are
      // missing (the last checks decide how far the subspace overshoots).
      const Eigen::Index missing = wanted - static_cast<Eigen::Index>(converged);
      next_check = k + (std::min)(round_up((std::max)(b, k / 16), b),
                                  b * (std::max)(Eigen::Index(1), missing / b));
      if(converged == static_cast<std::size_t>(wanted))
      {
        Matrix selected(k, wanted);
        for(Eigen::Index i = 0; i < wanted; ++i)
          selected.col(i) = ritz_coordinates.col(wanted - 1 - i);
        Eigen::VectorXd values(m);
        values.head(known).setZero();
        for(Eigen::Index i = 0; i < wanted; ++i)
          values[known + i] = sigma + 1.0 / ritz_values[wanted - 1 - i];
        if(!ritz_vectors_in_place(V, k, selected, mass, null_space.basis().leftCols(known)))
          return fail("the Ritz vectors are not independent");
        // The leading columns are kept without a copy (a realloc that
        // shrinks a block mapped apart moves no data).
        V.conservativeResize(n, m);
        if(breakdown && !verify(stiffness, mass, values, V))
          return fail("the eigenpairs found after a deflation of the Krylov subspace do not "
                      "satisfy the tolerance");
        eigenvalues.swap(values);
        eigenvectors.swap(V);
        return true;
      }
      if(k + b > max_dimension)
      {
        converged_in_time = false;
        return fail(std::to_string(converged + static_cast<std::size_t>(known)) + " of the " +
                    std::to_string(m) +
                    " eigenpairs converged within the maximum subspace dimension " +
                    std::to_string(max_dimension));
      }
    }
  }

  // Factors `shifted` with `solver` on one core while the other maps the
  // first `bytes` of `subspace`, the columns the iteration typically reaches
  // (3 to 4 m on the armadillo meshes), until the factorization ends: on the
  // machines measured, the first write of the subspace cost as much as the
  // factorization. With OpenMP both run in a team of two threads, so that
  // OpenMP loops inside the factorization (CHOLMOD's supernodal one has
  // some) run nested, on one thread, instead of competing with the mapping.
  static bool factor_while_mapping(SparseSPDSolverTraits& solver,
                                   const Eigen::SparseMatrix<double>& shifted, void* subspace,
                                   std::size_t bytes)
  {
#ifdef _OPENMP
    if(!omp_in_parallel() && omp_get_max_threads() >= 2)
    {
      std::atomic<bool> factored{false};
      bool success = false;
      std::exception_ptr error;
#pragma omp parallel num_threads(2)
      {
        if(omp_get_thread_num() == 0)
        {
          try
          {
            success = solver.factor(shifted);
          }
          catch(...)
          {
            error = std::current_exception();
          }
          factored.store(true, std::memory_order_relaxed);
        }
        else
          Spectral_deformation::internal::prefault_until(subspace, bytes, factored);
      }
      if(error)
        std::rethrow_exception(error);
      return success;
    }
#endif
    Spectral_deformation::internal::Background_prefault mapping(subspace, bytes);
    return solver.factor(shifted);
  }

  // Overwrites the leading columns of V with the eigenvectors: the known
  // ones, then the Ritz vectors V(:, 0 .. k) S. Rows are independent in that
  // product, so it runs in place by panels of rows, split between the
  // threads. The Ritz vectors of a subspace orthogonal only to sqrt(eps)
  // are M-orthonormal to the same level: the Gram matrix Yᵀ M Y, summed
  // panel by panel while the panel is in cache, gives Y U^{-1} (Cholesky QR)
  // M-orthonormal to rounding, a change of the vectors of the order of
  // sqrt(eps) that leaves their span and residuals as they were (the
  // eigenvalues come from the Lanczos recurrence, exact to rounding). A
  // Rayleigh-Ritz step with Q on their span did the same at three times the
  // cost (0.7 to 0.85 s against about 0.25 s at 416k vertices, m = 100).
  // Returns false when the Ritz vectors are not independent.
  static bool ritz_vectors_in_place(Matrix& V, Eigen::Index k, const Matrix& S,
                                    const Eigen::VectorXd& mass, const Matrix& known_vectors)
  {
    using Spectral_deformation::internal::dense_product;
    const Eigen::Index n = V.rows(), known = known_vectors.cols(), wanted = S.cols();
    const Eigen::Index panel = 512;
    const Eigen::Index panels = (n + panel - 1) / panel;
    int threads = 1;
#ifdef _OPENMP
    threads = omp_in_parallel() ? 1 : (std::min)(omp_get_max_threads(), 8);
#endif
    std::vector<Matrix> grams(static_cast<std::size_t>(threads), Matrix::Zero(wanted, wanted));
#ifdef _OPENMP
#pragma omp parallel num_threads(threads)
#endif
    {
      int thread = 0;
#ifdef _OPENMP
      thread = omp_get_thread_num();
#endif
      Matrix ritz(panel, wanted), weighted(panel, wanted);
      Matrix& gram = grams[static_cast<std::size_t>(thread)];
#ifdef _OPENMP
#pragma omp for schedule(static)
#endif
      for(Eigen::Index p = 0; p < panels; ++p)
      {
        const Eigen::Index first = p * panel, rows = (std::min)(panel, n - first);
        auto ritz_rows = ritz.topRows(rows);
        auto weighted_rows = weighted.topRows(rows);
        dense_product(false, V.block(first, 0, rows, k), false, S, 1.0, 0.0, ritz_rows);
        weighted_rows = mass.segment(first, rows).asDiagonal() * ritz_rows;
        dense_product(true, ritz_rows, false, weighted_rows, 1.0, 1.0, gram);
        V.block(first, 0, rows, known) = known_vectors.middleRows(first, rows);
        V.block(first, known, rows, wanted) = ritz_rows;
      }
    }
    for(std::size_t t = 1; t < grams.size(); ++t)
      grams[0] += grams[t];
    const Matrix gram = 0.5 * (grams[0] + grams[0].transpose());
    if((gram - Matrix::Identity(wanted, wanted)).cwiseAbs().maxCoeff() <= 1e-13)
      return true;
    Eigen::LLT<Matrix> cholesky(gram);
    if(cholesky.info() != Eigen::Success)
      return false;
    const Matrix inverse_upper = cholesky.matrixU().solve(Matrix::Identity(wanted, wanted));
#ifdef _OPENMP
#pragma omp parallel num_threads(threads)
#endif
    {
      Matrix rotated(panel, wanted);
#ifdef _OPENMP
#pragma omp for schedule(static)
#endif
      for(Eigen::Index p = 0; p < panels; ++p)
      {
        const Eigen::Index first = p * panel, rows = (std::min)(panel, n - first);
        auto rotated_rows = rotated.topRows(rows);
        dense_product(false, V.block(first, known, rows, wanted), false, inverse_upper, 1.0, 0.0,
                      rotated_rows);
        V.block(first, known, rows, wanted) = rotated_rows;
      }
    }
    return true;
  }

  // Spectra_eigensolver_traits with the same tolerance; its solves are
  // reported as REFERENCE_SOLVE progress (added to the block solves so far).
  bool run_reference(const Eigen::SparseMatrix<double>& stiffness, const Eigen::VectorXd& mass,
                     Eigen::Index m, Progress& progress, Eigen::VectorXd& eigenvalues,
                     Eigen::MatrixXd& eigenvectors, std::string& message) const
  {
    typedef Spectra_eigensolver_traits<SparseSPDSolverTraits> Reference;
    Reference reference(1000, m_tolerance, 0);
    const std::size_t solves_before = progress.solves;
    report(progress, Progress::REFERENCE_SOLVE);
    if(m_progress_callback)
      reference.set_progress_callback([&](const typename Reference::Progress& step) {
        progress.solves = solves_before + step.solves;
        report(progress, Progress::REFERENCE_SOLVE);
      });
    const bool success = reference.compute(stiffness, mass, m, eigenvalues, eigenvectors);
    message = reference.error_message();
    return success;
  }

  // Checks ‖Q h - lambda M h‖ against the tolerance directly.
  bool verify(const Eigen::SparseMatrix<double>& stiffness, const Eigen::VectorXd& mass,
              const Eigen::VectorXd& eigenvalues, const Eigen::MatrixXd& eigenvectors) const
  {
    // Relative to the spread of the computed spectrum and the shift, as the
    // residuals reported by the benchmarks.
    const Eigen::VectorXd inverse_sqrt_mass = mass.cwiseSqrt().cwiseInverse();
    const double sigma = Spectral_deformation::internal::shift_invert_shift(mass);
    const double scale = (std::max)(1e-6, 1e3 * m_tolerance) * (eigenvalues.maxCoeff() - sigma);
    for(Eigen::Index i = 0; i < eigenvalues.size(); ++i)
    {
      const Eigen::VectorXd residual =
          stiffness * eigenvectors.col(i) - eigenvalues[i] * mass.cwiseProduct(eigenvectors.col(i));
      if(!(inverse_sqrt_mass.cwiseProduct(residual).norm() <= scale))
        return false;
    }
    return true;
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
  std::string m_error_message;
  Progress_callback m_progress_callback;
};

} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_BLOCK_LANCZOS_EIGENSOLVER_TRAITS_H

// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_SPECTRA_EIGENSOLVER_TRAITS_H
#define CGAL_SPECTRAL_DEFORMATION_SPECTRA_EIGENSOLVER_TRAITS_H

#include <CGAL/Spectral_deformation/Sparse_spd_solver_traits.h>
#include <CGAL/Spectral_deformation/internal/Eigensolvers/Spectra_lanczos.h>
#include <CGAL/Spectral_deformation/internal/Eigensolvers/dense_eigenpairs.h>
#include <CGAL/Spectral_deformation/internal/Traits_requirements.h>

#include <CGAL/tags.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <cstddef>
#include <functional>
#include <string>

namespace CGAL {

/// \ingroup PkgSpectralSurfaceMeshDeformationTraits
/// The reference model of `ManifoldHarmonicsEigensolverTraits`: Spectra's
/// shift-invert generalized symmetric Lanczos solver, with the shifted system
/// `Q - sigma M` factored once by a sparse Cholesky/LDLᵀ.
///
/// The shift `sigma` is negative and small against the low end of the
/// spectrum (`sigma = -0.01 * 4 pi / area`, while the first non-zero
/// eigenvalue of a sphere of the same area is `8 pi / area`), so that
/// `Q - sigma M` is positive definite even though `Q` is singular, and the
/// wanted eigenvalues are the largest of the inverted operator.
///
/// Small problems (at most `dense_threshold()` vertices) and problems that ask
/// for nearly all eigenpairs are solved with a dense solver instead, which is
/// exact and faster at that size.
///
/// An optional progress callback (`set_progress_callback()`) lets a program
/// show the progress of a long eigensolve; it does not change the result.
///
/// By default `compute()` changes no state of the process;
/// `set_process_wide_tuning(true)` hands the sparse solver the permission to
/// do so (see `Cholmod_llt_solver_traits::set_process_wide_tuning()`).
///
/// \tparam SparseSPDSolverTraits a model of `SparseSPDSolverTraits`, used to
///         factor `Q - sigma M`.
template <class SparseSPDSolverTraits = Default_sparse_spd_solver_traits>
class Spectra_eigensolver_traits
{
  static_assert(Spectral_deformation::internal::Sparse_spd_solver_requirements<SparseSPDSolverTraits>::met);

public:
  /// Declares the optional members `process_wide_tuning()` and
  /// `set_process_wide_tuning()` (see `ManifoldHarmonicsEigensolverTraits`).
  typedef CGAL::Tag_true Supports_process_wide_tuning;

  /// The state of a running `compute()`, passed to the progress callback.
  ///
  /// The number of solves needed by the Lanczos iteration is not known in
  /// advance: it is `subspace_dimension` for the first Lanczos factorization,
  /// then at most `subspace_dimension - number_of_eigenpairs` per restart
  /// until the eigenpairs converge. A caller can estimate the remaining time
  /// from `solves` and the time per solve.
  struct Progress
  {
    /// The stages of `compute()`, in this order.
    enum Stage {
      FACTORIZATION, ///< the shifted matrix `Q - sigma M` is being factored
      ITERATION,     ///< the Lanczos iteration runs; reported after every solve
      DENSE_SOLVE,   ///< a small problem is solved with the dense solver (no intermediate report)
      FINISHED       ///< `compute()` is about to return, successfully or not
    };
    Stage stage = FACTORIZATION;           ///< the current stage
    std::size_t solves = 0;                ///< solves with the factored shifted matrix so far
    std::size_t subspace_dimension = 0;    ///< dimension of the Lanczos subspace (0 for the dense solver)
    std::size_t number_of_eigenpairs = 0;  ///< the `m` of the call
    std::size_t number_of_vertices = 0;    ///< the `n` of the call
  };

  /// The type of the progress callback.
  typedef std::function<void(const Progress&)> Progress_callback;

  /// Creates a solver with a cap on Lanczos restarts, a relative tolerance on
  /// the Ritz values, and the size at or below which the dense solver is used.
  explicit Spectra_eigensolver_traits(int max_iterations = 1000, double tolerance = 1e-10,
                                      Eigen::Index dense_threshold = 1000)
    : m_max_iterations(max_iterations), m_tolerance(tolerance), m_dense_threshold(dense_threshold)
  {}

  /// The size at or below which the dense solver is used.
  Eigen::Index dense_threshold() const { return m_dense_threshold; }

  /// Sets a function that `compute()` calls at the start of every stage
  /// (see `Progress`), after every solve of the Lanczos iteration and once
  /// before it returns. An empty function (the default) disables the
  /// reports. The callback must not throw; it is copied with the traits.
  void set_progress_callback(const Progress_callback& callback) { m_progress_callback = callback; }

  /// Whether `compute()` may change state of the whole process to run
  /// faster (default `false`); see `set_process_wide_tuning()`.
  bool process_wide_tuning() const { return m_process_wide_tuning; }

  /// Sets `process_wide_tuning()`. The choice is handed to the sparse solver
  /// that factors `Q - sigma M`, when its traits class has a
  /// `set_process_wide_tuning()` member (`Cholmod_llt_solver_traits`: it
  /// then replaces SuiteSparse's global allocator while it factors and
  /// solves). The result does not depend on it.
  void set_process_wide_tuning(bool enabled) { m_process_wide_tuning = enabled; }

  /// Computes the `m` smallest eigenpairs of `Q h = lambda M h` with
  /// `M = diag(mass)`: `eigenvalues` ascending, `eigenvectors` (n×m)
  /// M-orthonormal. Returns `false`, with `error_message()` set, when the
  /// factorization fails or the iteration does not converge.
  bool compute(const Eigen::SparseMatrix<double>& stiffness, const Eigen::VectorXd& mass,
               Eigen::Index m, Eigen::VectorXd& eigenvalues, Eigen::MatrixXd& eigenvectors)
  {
    m_error_message.clear();
    const Eigen::Index n = stiffness.rows();
    if(m < 1 || m > n)
      return fail("the number of eigenpairs must be between 1 and the number of vertices");
    const Eigen::Index ncv = Spectral_deformation::internal::Eigensolvers::spectra_subspace_dimension(n, m);
    Progress progress;
    progress.number_of_eigenpairs = static_cast<std::size_t>(m);
    progress.number_of_vertices = static_cast<std::size_t>(n);
    std::string message;
    bool success = false;
    if(n <= m_dense_threshold || ncv >= n)
    {
      report(progress, Progress::DENSE_SOLVE);
      success = Spectral_deformation::internal::Eigensolvers::dense_generalized_eigenpairs(
          stiffness, mass, m, eigenvalues, eigenvectors, message);
    }
    else
    {
      progress.subspace_dimension = static_cast<std::size_t>(ncv);
      // Without a callback the operator gets no hook at all. The first
      // solve follows the factorization.
      std::function<void()> after_solve;
      if(m_progress_callback)
        after_solve = [this, &progress]() {
          ++progress.solves;
          report(progress, Progress::ITERATION);
        };
      report(progress, Progress::FACTORIZATION);
      Spectral_deformation::internal::Eigensolvers::Spectra_lanczos_settings settings;
      settings.subspace_dimension = ncv;
      settings.max_iterations = m_max_iterations;
      settings.tolerance = m_tolerance;
      settings.process_wide_tuning = m_process_wide_tuning;
      success = Spectral_deformation::internal::Eigensolvers::spectra_shift_invert_eigenpairs<
          SparseSPDSolverTraits>(stiffness, mass, m, settings,
                                 m_progress_callback ? &after_solve : nullptr, eigenvalues,
                                 eigenvectors, message);
    }
    if(!success)
      fail(message);
    report(progress, Progress::FINISHED);
    return success;
  }

  /// The reason of the last failure of `compute()`.
  const std::string& error_message() const { return m_error_message; }

private:
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

  int m_max_iterations;
  double m_tolerance;
  Eigen::Index m_dense_threshold;
  bool m_process_wide_tuning = false;
  std::string m_error_message;
  Progress_callback m_progress_callback;
};

} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_SPECTRA_EIGENSOLVER_TRAITS_H

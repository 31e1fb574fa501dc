// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_SPECTRA_EIGENSOLVER_TRAITS_H
#define CGAL_SPECTRAL_DEFORMATION_SPECTRA_EIGENSOLVER_TRAITS_H

#include <CGAL/Spectral_deformation/Sparse_spd_solver_traits.h>
#include <CGAL/Spectral_deformation/internal/Eigensolvers/dense_eigenpairs.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <Spectra/SymGEigsShiftSolver.h>

#include <algorithm>
#include <cstddef>
#include <exception>
#include <functional>
#include <string>

namespace CGAL {
namespace Spectral_deformation {
namespace internal {

// The shift of both eigensolvers: negative and small against the low end of
// the spectrum (the first non-zero eigenvalue of a sphere of the same area is
// 8 pi / area), so that Q - sigma M is positive definite although Q is
// singular.
inline double shift_invert_shift(const Eigen::VectorXd& mass)
{
  return -1e-2 * 4.0 * 3.14159265358979323846 / mass.sum();
}

// Q - sigma M for the diagonal (lumped) mass matrix M.
inline Eigen::SparseMatrix<double> shifted_stiffness(const Eigen::SparseMatrix<double>& stiffness,
                                                     const Eigen::VectorXd& mass, double sigma)
{
  Eigen::SparseMatrix<double> shifted = stiffness;
  for(Eigen::Index i = 0; i < mass.size(); ++i)
    shifted.coeffRef(i, i) -= sigma * mass[i];
  return shifted;
}

// y = (Q - sigma M)^{-1} x, with the factorization done by a sparse SPD
// solver traits. Spectra's own SymShiftInvert uses a sparse LU, which is
// far slower on these systems. `after_solve`, when set, is called after
// every solve (the Lanczos iteration cannot be observed otherwise).
template <class SparseSPDSolverTraits>
class Shift_invert_operator
{
public:
  typedef double Scalar;

  Shift_invert_operator(const Eigen::SparseMatrix<double>& stiffness, const Eigen::VectorXd& mass,
                        const std::function<void()>* after_solve = nullptr)
    : m_stiffness(stiffness), m_mass(mass), m_after_solve(after_solve)
  {}

  Eigen::Index rows() const { return m_stiffness.rows(); }
  Eigen::Index cols() const { return m_stiffness.cols(); }

  void set_shift(double sigma)
  {
    if(!m_solver.factor(shifted_stiffness(m_stiffness, m_mass, sigma)))
      throw std::runtime_error("the factorization of the shifted stiffness matrix failed");
  }

  void perform_op(const double* x_in, double* y_out) const
  {
    m_rhs = Eigen::Map<const Eigen::VectorXd>(x_in, rows());
    if(!m_solver.solve(m_rhs, m_solution))
      throw std::runtime_error("a shift-invert solve failed");
    Eigen::Map<Eigen::VectorXd>(y_out, rows()) = m_solution.col(0);
    if(m_after_solve != nullptr)
      (*m_after_solve)();
  }

private:
  const Eigen::SparseMatrix<double>& m_stiffness;
  const Eigen::VectorXd& m_mass;
  const std::function<void()>* m_after_solve;
  SparseSPDSolverTraits m_solver;
  mutable Eigen::MatrixXd m_rhs, m_solution;
};

// y = M x for the diagonal (lumped) mass matrix.
class Diagonal_mass_operator
{
public:
  typedef double Scalar;
  explicit Diagonal_mass_operator(const Eigen::VectorXd& mass) : m_mass(mass) {}
  Eigen::Index rows() const { return m_mass.size(); }
  Eigen::Index cols() const { return m_mass.size(); }
  void perform_op(const double* x_in, double* y_out) const
  {
    Eigen::Map<Eigen::VectorXd>(y_out, rows()) =
        m_mass.cwiseProduct(Eigen::Map<const Eigen::VectorXd>(x_in, rows()));
  }

private:
  const Eigen::VectorXd& m_mass;
};

} // namespace internal
} // namespace Spectral_deformation

/// \ingroup PkgSpectralSurfaceMeshDeformationTraits
/// The default model of `ManifoldHarmonicsEigensolverTraits`: Spectra's
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
/// \tparam SparseSPDSolverTraits a model of `SparseSPDSolverTraits`, used to
///         factor `Q - sigma M`.
template <class SparseSPDSolverTraits = Default_sparse_spd_solver_traits>
class Spectra_eigensolver_traits
{
public:
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
    const Eigen::Index ncv = (std::min)(n, (std::max)(2 * m + 1, m + 20));
    Progress progress;
    progress.number_of_eigenpairs = static_cast<std::size_t>(m);
    progress.number_of_vertices = static_cast<std::size_t>(n);
    if(n <= m_dense_threshold || ncv >= n)
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

    typedef Spectral_deformation::internal::Shift_invert_operator<SparseSPDSolverTraits> Op;
    typedef Spectral_deformation::internal::Diagonal_mass_operator Mass_op;
    progress.subspace_dimension = static_cast<std::size_t>(ncv);
    // Without a callback the operator gets no hook at all.
    std::function<void()> after_solve;
    if(m_progress_callback)
      after_solve = [this, &progress]() {
        ++progress.solves;
        m_progress_callback(progress);
      };
    report(progress, Progress::FACTORIZATION);
    bool success = true;
    try
    {
      Op op(stiffness, mass, m_progress_callback ? &after_solve : nullptr);
      Mass_op mass_op(mass);
      const double sigma = Spectral_deformation::internal::shift_invert_shift(mass);
      Spectra::SymGEigsShiftSolver<Op, Mass_op, Spectra::GEigsMode::ShiftInvert> solver(
          op, mass_op, m, ncv, sigma);
      // The factorization happens in the constructor of the solver; the
      // first solve is the one of init().
      progress.stage = Progress::ITERATION;
      solver.init();
      solver.compute(Spectra::SortRule::LargestMagn, m_max_iterations, m_tolerance,
                     Spectra::SortRule::SmallestAlge);
      if(solver.info() != Spectra::CompInfo::Successful)
        success = fail("the Lanczos iteration did not converge within " +
                       std::to_string(m_max_iterations) + " restarts");
      else
      {
        eigenvalues = solver.eigenvalues();
        eigenvectors = solver.eigenvectors();
      }
    }
    catch(const std::exception& e)
    {
      success = fail(e.what());
    }
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
  std::string m_error_message;
  Progress_callback m_progress_callback;
};

} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_SPECTRA_EIGENSOLVER_TRAITS_H

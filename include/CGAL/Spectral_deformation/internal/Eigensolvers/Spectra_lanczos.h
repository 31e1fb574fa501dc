// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_SPECTRA_LANCZOS_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_SPECTRA_LANCZOS_H

#include <CGAL/Spectral_deformation/internal/compiled_core.h>
#include <CGAL/Spectral_deformation/internal/Eigensolvers/Shift_invert.h>
#include <CGAL/Spectral_deformation/internal/Memory/Process_wide_tuning.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <Spectra/SymGEigsShiftSolver.h>

#include <algorithm>
#include <exception>
#include <functional>
#include <stdexcept>
#include <string>

namespace CGAL {
namespace Spectral_deformation {
namespace internal {
namespace Eigensolvers {

using Memory::set_process_wide_tuning_if_supported;

// Spectra's shift-invert Lanczos on the generalized problem Q h = lambda M h:
// the solver of `Spectra_eigensolver_traits`, and the fallback of
// `Block_lanczos_eigensolver_traits`, which runs it without including the
// public header of the reference traits.

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
                        const std::function<void()>* after_solve = nullptr,
                        bool process_wide_tuning = false)
    : m_stiffness(stiffness), m_mass(mass), m_after_solve(after_solve)
  {
    set_process_wide_tuning_if_supported(m_solver, process_wide_tuning);
  }

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

// The dimension of the Lanczos subspace for m eigenpairs of an n × n
// problem: 2 m + 1, at least m + 20, at most n.
Eigen::Index spectra_subspace_dimension(Eigen::Index n, Eigen::Index m);

// Settings of one run of spectra_shift_invert_eigenpairs().
struct Spectra_lanczos_settings
{
  Eigen::Index subspace_dimension = 0; // ncv, see spectra_subspace_dimension()
  int max_iterations = 1000;           // restarts
  double tolerance = 1e-10;            // relative, on the Ritz values
  bool process_wide_tuning = false;    // handed to the sparse solver
};

// The m smallest eigenpairs of Q h = lambda M h by Spectra's shift-invert
// Lanczos, with Q - sigma M factored by `SparseSPDSolverTraits`.
// `after_solve`, when not null, is called after every solve. Returns false
// with `message` set when the factorization, a solve or the iteration fails.
template <class SparseSPDSolverTraits>
bool spectra_shift_invert_eigenpairs(const Eigen::SparseMatrix<double>& stiffness,
                                     const Eigen::VectorXd& mass, Eigen::Index m,
                                     const Spectra_lanczos_settings& settings,
                                     const std::function<void()>* after_solve,
                                     Eigen::VectorXd& eigenvalues, Eigen::MatrixXd& eigenvectors,
                                     std::string& message)
{
  typedef Shift_invert_operator<SparseSPDSolverTraits> Op;
  try
  {
    Op op(stiffness, mass, after_solve, settings.process_wide_tuning);
    Diagonal_mass_operator mass_op(mass);
    const double sigma = shift_invert_shift(mass);
    // The factorization happens in the constructor of the solver; the
    // first solve is the one of init().
    Spectra::SymGEigsShiftSolver<Op, Diagonal_mass_operator, Spectra::GEigsMode::ShiftInvert>
        solver(op, mass_op, m, settings.subspace_dimension, sigma);
    solver.init();
    solver.compute(Spectra::SortRule::LargestMagn, settings.max_iterations, settings.tolerance,
                   Spectra::SortRule::SmallestAlge);
    if(solver.info() != Spectra::CompInfo::Successful)
    {
      message = "the Lanczos iteration did not converge within " +
                std::to_string(settings.max_iterations) + " restarts";
      return false;
    }
    eigenvalues = solver.eigenvalues();
    eigenvectors = solver.eigenvectors();
    return true;
  }
  catch(const std::exception& e)
  {
    message = e.what();
    return false;
  }
}

} // namespace Eigensolvers
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#if CGAL_SSMD_CORE_DEFINITIONS
#include <CGAL/Spectral_deformation/internal/Eigensolvers/Spectra_lanczos_impl.h>
#endif

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_SPECTRA_LANCZOS_H

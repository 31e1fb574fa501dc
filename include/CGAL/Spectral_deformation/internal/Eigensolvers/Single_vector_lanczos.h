// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_SINGLE_VECTOR_LANCZOS_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_SINGLE_VECTOR_LANCZOS_H

#include <CGAL/assertions.h>
#include <CGAL/Spectral_deformation/internal/compiled_core.h>
#include <CGAL/Spectral_deformation/internal/Eigensolvers/Laplacian_null_space.h>
#include <CGAL/Spectral_deformation/internal/Eigensolvers/Rayleigh_ritz.h>
#include <CGAL/Spectral_deformation/internal/Eigensolvers/Ritz_vectors.h>
#include <CGAL/Spectral_deformation/internal/Eigensolvers/Shift_invert.h>
#include <CGAL/Spectral_deformation/internal/Eigensolvers/Symmetric_eigenpairs.h>
#include <CGAL/Spectral_deformation/internal/Linear_algebra/Dense_products.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>

namespace CGAL {
namespace Spectral_deformation {
namespace internal {
namespace Eigensolvers {

// A single-vector shift-invert Lanczos method for the small problems that
// `Block_lanczos_eigensolver_traits` checks by an eigenvalue count
// (`uses_checked_single_vector()`). Spectra's restarted Lanczos, used there
// before, reorthogonalizes every new vector against all the previous ones,
// two or three products with the n × ncv subspace per step, which were
// three quarters of its time on 1,000 to 4,000 vertices. Here the subspace
// grows without restarts and is reorthogonalized only when Simon's
// recurrence (1984) estimates that its orthogonality has dropped to
// sqrt(eps), as in the block method (which it is with blocks of one vector,
// but without the block method's small dense matrices per step); its
// Rayleigh–Ritz checks solve a tridiagonal eigenproblem. Like any
// single-vector method it may miss copies of a repeated eigenvalue: its
// result is only used once an eigenvalue count has confirmed it.

// The recurrence of the iteration: A v_j = beta_j v_{j-1} + alpha_j v_j +
// beta_{j+1} v_{j+1}, and the estimates omega_{j,i} of v_jᵀ M v_i, i < j.
class Lanczos_recurrence
{
public:
  explicit Lanczos_recurrence(Eigen::Index capacity);

  // Records alpha_j and beta_{j+1} of step j and returns the largest
  // estimate |omega_{j+1,i}|, i ≤ j.
  double step(Eigen::Index j, double alpha, double beta);

  // After v_{j+1} was orthogonalized against v_0 .. v_j: its estimates are
  // the rounding of that orthogonalization, and beta_{j+1} its new norm.
  void reorthogonalized(Eigen::Index j, double beta);

  // The Rayleigh–Ritz pairs of the k × k tridiagonal matrix for the
  // `wanted` largest eigenvalues, and how many of them have a residual
  // |beta_k s_k| at most `tolerance` times their eigenvalue.
  bool rayleigh_ritz(Eigen::Index k, Eigen::Index wanted, double tolerance, Ritz_pairs& ritz) const;

private:
  Eigen::VectorXd m_alpha, m_beta; // m_beta[j] couples v_{j-1} and v_j; m_beta[0] = 0
  Eigen::VectorXd m_previous, m_current, m_next; // omega_{j-1,.}, omega_{j,.}, omega_{j+1,.}
  double m_norm = 0;                             // an estimate of the operator's norm
};

// The settings of `single_vector_lanczos_eigenpairs()`.
struct Single_vector_lanczos_settings
{
  Eigen::Index max_dimension = 0; // the largest subspace, in vectors
  double tolerance = 1e-6;        // relative, on the Ritz values (see Block_lanczos_eigensolver_traits)
};

// The step after `k` at which the Ritz pairs of a subspace of `n` rows
// are checked again: the forecast of the block method, at most a sixteenth
// of k later, but not before about k² / n steps, at most k / 4. A check
// (all eigenpairs of the k × k tridiagonal matrix, O(k²)) costs as much as
// k² / n steps (a solve and a few vector operations of n entries): 2.6-3.5
// ms against 36-65 µs per step at k ≈ 200 on 550 and 999 vertices, where
// the forecast, which counts only steps, asked for checks one step apart
// near convergence and the checks took half of the iteration's time. A few
// steps beyond convergence cost less than a check that finds it not reached.
Eigen::Index next_single_vector_check(Convergence_forecast& forecast, Eigen::Index k, Eigen::Index n,
                                      Eigen::Index wanted, const Ritz_pairs& ritz);

// The mass matrix M of the single-vector method as the iteration uses it:
// y = M x, the shifted matrix Q - sigma M, and the Ritz vectors made
// M-orthonormal. `Diagonal_mass` is the lumped mass of a mesh,
// `Sparse_mass` the Gram matrix of a space of functions (the reduced
// problem of the partition-of-unity basis).
class Diagonal_mass
{
public:
  explicit Diagonal_mass(const Eigen::VectorXd& diagonal) : m_diagonal(diagonal) {}

  template <class In, class Out>
  void apply(const In& x, Out& y) const
  {
    y.noalias() = m_diagonal.asDiagonal() * x;
  }

  Eigen::SparseMatrix<double> shifted(const Eigen::SparseMatrix<double>& stiffness, double sigma) const
  {
    return shifted_stiffness(stiffness, m_diagonal, sigma);
  }

  // Whether the iteration keeps M V beside V for `ritz_vectors()`.
  static constexpr bool keeps_weighted_subspace = false;

  // The known vectors, then V(:, 0 .. k) S, M-orthonormal, in the leading
  // columns of V.
  bool ritz_vectors(Eigen::MatrixXd& V, const Eigen::MatrixXd& /* weighted_subspace */, Eigen::Index k,
                    const Eigen::MatrixXd& S, const Eigen::MatrixXd& known_vectors) const
  {
    return ritz_vectors_in_place(V, k, S, m_diagonal, known_vectors);
  }

private:
  const Eigen::VectorXd& m_diagonal;
};

class Sparse_mass
{
public:
  explicit Sparse_mass(const Eigen::SparseMatrix<double>& matrix) : m_matrix(matrix) {}

  template <class In, class Out>
  void apply(const In& x, Out& y) const
  {
    y.noalias() = m_matrix * x;
  }

  Eigen::SparseMatrix<double> shifted(const Eigen::SparseMatrix<double>& stiffness, double sigma) const
  {
    return stiffness - sigma * m_matrix;
  }

  // M V, kept by the iteration: M Y = (M V) S is a dense product, where a
  // product with the sparse M took as long as the rest of `ritz_vectors()`.
  static constexpr bool keeps_weighted_subspace = true;

  // Y = V(:, 0 .. k) S, M-orthonormal, in the leading columns of V (no
  // vector is known in closed form), with `weighted_subspace` = M V.
  bool ritz_vectors(Eigen::MatrixXd& V, const Eigen::MatrixXd& weighted_subspace, Eigen::Index k,
                    const Eigen::MatrixXd& S, const Eigen::MatrixXd& known_vectors) const
  {
    CGAL_precondition(known_vectors.cols() == 0);
    (void)known_vectors;
    const Eigen::MatrixXd ritz = V.leftCols(k) * S;
    const Eigen::MatrixXd weighted = weighted_subspace.leftCols(k) * S;
    const Eigen::MatrixXd gram = ritz.transpose() * weighted;
    V.leftCols(S.cols()) = ritz;
    return orthonormalize_in_place(V, 0, 0.5 * (gram + gram.transpose()));
  }

private:
  const Eigen::SparseMatrix<double>& m_matrix;
};

// The m smallest eigenpairs of Q h = lambda M h, with Q - sigma M factored
// by `SparseSPDSolverTraits`: `eigenvalues` ascending, `eigenvectors`
// M-orthonormal. The vectors of `null_space` (when given: the constants of
// each component of a Laplacian Q) are returned as eigenvectors of 0 and
// kept out of the Krylov subspace. `after_solve(k)` is called after each
// solve with the subspace's dimension, `after_check(converged)` after each
// Rayleigh–Ritz check. Returns false with `message` set when the
// factorization or a solve fails, when the subspace breaks down or when
// the pairs have not converged within `settings.max_dimension` vectors.
//
// M v_j, the right-hand side of step j, is kept from the step before
// (M v_j = M w / beta_j, with M w made for the norm of w), and the inner
// products with v_j read it: one product with M per step, and one more per
// orthogonalization pass, which matters when M is not diagonal.
template <class SparseSPDSolverTraits, class Mass, class AfterSolve, class AfterCheck>
bool single_vector_lanczos_iteration(const Eigen::SparseMatrix<double>& stiffness, const Mass& mass,
                                     const Laplacian_null_space* null_space, double sigma, Eigen::Index m,
                                     const Single_vector_lanczos_settings& settings,
                                     const AfterSolve& after_solve, const AfterCheck& after_check,
                                     Eigen::VectorXd& eigenvalues, Eigen::MatrixXd& eigenvectors,
                                     std::string& message)
{
  typedef Eigen::MatrixXd Matrix;
  const Eigen::Index n = stiffness.rows();
  const Eigen::Index known = null_space != nullptr ? (std::min)(null_space->dimension(), m) : 0;
  const Eigen::Index wanted = m - known;
  const Matrix known_vectors = null_space != nullptr ? Matrix(null_space->basis().leftCols(known)) : Matrix(n, 0);
  if(wanted == 0)
  {
    eigenvalues = Eigen::VectorXd::Zero(m);
    eigenvectors = known_vectors;
    return true;
  }
  const Eigen::Index capacity = (std::min)(settings.max_dimension, n - known - 1);
  if(capacity < wanted + 1)
  {
    message = "the subspace cannot hold the wanted eigenpairs";
    return false;
  }
  SparseSPDSolverTraits solver;
  if(!solver.factor(mass.shifted(stiffness, sigma)))
  {
    message = "the factorization of the shifted stiffness matrix failed";
    return false;
  }

  auto project_out = [null_space](Matrix& x) {
    if(null_space != nullptr)
      null_space->project_out(x);
  };
  Matrix V(n, capacity + 1);
  Matrix weighted_subspace(Mass::keeps_weighted_subspace ? n : 0, capacity + 1);
  // w, M w and M v_j.
  Matrix w(n, 1), weighted(n, 1), weighted_current(n, 1), coefficients(capacity + 1, 1);
  auto weigh = [&]() {
    mass.apply(w, weighted);
    return std::sqrt(w.col(0).dot(weighted.col(0)));
  };
  // v_k = w / norm, and M v_k from M w.
  auto append = [&](Eigen::Index k, double norm) {
    V.col(k) = w.col(0) / norm;
    weighted_current = weighted / norm;
    if(Mass::keeps_weighted_subspace)
      weighted_subspace.col(k) = weighted_current.col(0);
  };
  // A fixed start: the result does not depend on the run.
  std::mt19937 generator(20080806u);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  for(Eigen::Index i = 0; i < n; ++i)
    w(i, 0) = uniform(generator);
  project_out(w);
  append(0, weigh());

  // w -= V_k (V_kᵀ M w) by classical Gram–Schmidt, through Eigen's
  // matrix-vector products (a BLAS's dgemm packs its operands even for one
  // column), a second time only when the first removed more than half of
  // w's norm (Daniel, Gragg, Kaufman and Stewart's criterion): w has lost
  // orthogonality to sqrt(eps) only, from which one pass recovers it.
  // Returns w's norm, with M w in `weighted`.
  auto orthogonalize = [&](Eigen::Index k, double norm) {
    for(int pass = 0; pass < 2; ++pass)
    {
      auto h = coefficients.topRows(k);
      h.noalias() = V.leftCols(k).transpose() * weighted;
      w.noalias() -= V.leftCols(k) * h;
      project_out(w);
      const double reduced = weigh();
      if(reduced > 0.7071 * norm)
        return reduced;
      norm = reduced;
    }
    return norm;
  };

  Lanczos_recurrence recurrence(capacity);
  Convergence_forecast forecast;
  // Spectra's restarted method converged in 2 m + 1 to 2.5 m solves on
  // these problems; this one in about 2.2 m.
  Eigen::Index next_check = 2 * wanted;
  bool reorthogonalize_next = false;
  double beta = 0;
  for(Eigen::Index j = 0; j < capacity; ++j)
  {
    if(!solver.solve(weighted_current, w))
    {
      message = "a solve with the factored shifted stiffness matrix failed";
      return false;
    }
    project_out(w);
    if(j > 0)
      w.col(0) -= beta * V.col(j - 1);
    double alpha = 0;
    // Twice against the last vector: the local orthogonality that the
    // recurrence assumes.
    for(int pass = 0; pass < 2; ++pass)
    {
      const double c = weighted_current.col(0).dot(w.col(0));
      w.col(0) -= c * V.col(j);
      alpha += c;
    }
    beta = weigh();
    const Eigen::Index k = j + 1;
    after_solve(k);
    const double lost = recurrence.step(j, alpha, beta);
    if(lost > std::sqrt(std::numeric_limits<double>::epsilon()) || reorthogonalize_next)
    {
      beta = orthogonalize(k, beta);
      recurrence.reorthogonalized(j, beta);
      reorthogonalize_next = !reorthogonalize_next;
    }
    if(!(beta > 1e-12 * std::abs(alpha)))
    {
      message = "the Krylov subspace broke down";
      return false;
    }
    append(k, beta);
    if(k < next_check && k < capacity)
      continue;
    Ritz_pairs ritz;
    if(!recurrence.rayleigh_ritz(k, wanted, settings.tolerance, ritz))
    {
      message = "the Rayleigh-Ritz eigensolver did not converge";
      return false;
    }
    after_check(ritz.converged + known);
    if(ritz.converged == wanted)
    {
      Matrix selected;
      Eigen::VectorXd values = ritz_eigenvalues(ritz, known, sigma, k, selected);
      if(!mass.ritz_vectors(V, weighted_subspace, k, selected, known_vectors))
      {
        message = "the Ritz vectors are not independent";
        return false;
      }
      V.conservativeResize(n, m);
      eigenvalues.swap(values);
      eigenvectors.swap(V);
      return true;
    }
    next_check = next_single_vector_check(forecast, k, n, wanted, ritz);
  }
  message = "the eigenpairs did not converge within a subspace of " + std::to_string(capacity) + " vectors";
  return false;
}

// The m smallest eigenpairs of Q h = lambda M h (M = diag(mass)) by
// `single_vector_lanczos_iteration()`, the constants of each component of a
// Laplacian Q known, with the shift of `shift_invert_shift()`.
template <class SparseSPDSolverTraits, class AfterSolve, class AfterCheck>
bool single_vector_lanczos_eigenpairs(const Eigen::SparseMatrix<double>& stiffness, const Eigen::VectorXd& mass,
                                      Eigen::Index m, const Single_vector_lanczos_settings& settings,
                                      const AfterSolve& after_solve, const AfterCheck& after_check,
                                      Eigen::VectorXd& eigenvalues, Eigen::MatrixXd& eigenvectors,
                                      std::string& message)
{
  const Laplacian_null_space null_space(stiffness, mass);
  return single_vector_lanczos_iteration<SparseSPDSolverTraits>(stiffness, Diagonal_mass(mass), &null_space,
                                                                shift_invert_shift(mass), m, settings, after_solve,
                                                                after_check, eigenvalues, eigenvectors, message);
}

} // namespace Eigensolvers
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#if CGAL_SSMD_CORE_DEFINITIONS
#include <CGAL/Spectral_deformation/internal/Eigensolvers/Single_vector_lanczos_impl.h>
#endif

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_SINGLE_VECTOR_LANCZOS_H

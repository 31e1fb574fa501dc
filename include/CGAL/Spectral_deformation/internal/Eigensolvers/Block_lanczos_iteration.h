// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_BLOCK_LANCZOS_ITERATION_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_BLOCK_LANCZOS_ITERATION_H

#include <CGAL/Spectral_deformation/internal/compiled_core.h>
#include <CGAL/Spectral_deformation/internal/Eigensolvers/Block_lanczos_state.h>
#include <CGAL/Spectral_deformation/internal/Eigensolvers/Block_lanczos_steps.h>
#include <CGAL/Spectral_deformation/internal/Eigensolvers/Laplacian_null_space.h>
#include <CGAL/Spectral_deformation/internal/Eigensolvers/Rayleigh_ritz.h>
#include <CGAL/Spectral_deformation/internal/Eigensolvers/Ritz_vectors.h>
#include <CGAL/Spectral_deformation/internal/Eigensolvers/Shift_invert.h>
#include <CGAL/Spectral_deformation/internal/Linear_algebra/Dense_products.h>
#include <CGAL/Spectral_deformation/internal/Memory/Page_mapping.h>
#include <CGAL/Spectral_deformation/internal/Memory/Process_wide_tuning.h>
#include <CGAL/Spectral_deformation/internal/available_threads.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <string>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace CGAL {
namespace Spectral_deformation {
namespace internal {
namespace Eigensolvers {

using Linear_algebra::Single_threaded_blas_scope;
using Memory::Background_prefault;
using Memory::prefault_until;
using Memory::set_process_wide_tuning_if_supported;

// The block shift-invert Lanczos iteration of
// `Block_lanczos_eigensolver_traits`, from the factorization of
// Q - sigma M to the eigenpairs: the steps of the recurrence are in
// Block_lanczos_steps.h, the checks in Rayleigh_ritz.h.
//
// The caller observes the iteration through a `Listener` with the members
//   void factorization_started();
//   void block_solved(Eigen::Index b, Eigen::Index subspace_dimension);
//   void checked(Eigen::Index converged_eigenpairs);

// Settings of one run.
struct Block_lanczos_settings
{
  Eigen::Index block_size = 8;
  Eigen::Index max_dimension = 0; // a multiple of block_size
  double tolerance = 1e-6;
  bool process_wide_tuning = false;
};

// Why a run failed: `message`, and whether the cause was the subspace
// reaching its maximum dimension (the reference solver may then succeed).
struct Block_lanczos_failure
{
  std::string message;
  bool unconverged = false;

  bool set(const std::string& text)
  {
    message = text;
    return false;
  }
};

// Factors `shifted` with `solver` on one core while the other maps the
// first `bytes` of `subspace`, the columns the iteration typically reaches
// (3 to 4 m on the armadillo meshes), until the factorization ends: on the
// machines measured, the first write of the subspace cost as much as the
// factorization. With OpenMP both run in a team of two threads, so that
// OpenMP loops inside the factorization (CHOLMOD's supernodal one has some)
// run nested, on one thread, instead of competing with the mapping.
template <class SparseSPDSolverTraits>
bool factor_while_mapping(SparseSPDSolverTraits& solver, const Eigen::SparseMatrix<double>& shifted,
                          void* subspace, std::size_t bytes)
{
#ifdef _OPENMP
  if(!omp_in_parallel() && omp_get_max_threads() >= 2)
  {
    bool success = false;
    run_beside_a_second_thread([&] { success = solver.factor(shifted); },
                               [&](const std::atomic<bool>& factored) {
                                 prefault_until(subspace, bytes, factored);
                               });
    return success;
  }
#endif
  Background_prefault mapping(subspace, bytes);
  return solver.factor(shifted);
}

// Factors Q - sigma M; with process-wide tuning, maps the typical part of
// the subspace meanwhile.
template <class SparseSPDSolverTraits>
bool factor_shifted_stiffness(SparseSPDSolverTraits& solver,
                              const Eigen::SparseMatrix<double>& stiffness, double sigma,
                              Block_lanczos_state& state, Eigen::Index m)
{
  const Eigen::SparseMatrix<double> shifted = shifted_stiffness(stiffness, state.mass, sigma);
  if(!state.process_wide_tuning)
    return solver.factor(shifted);
  const Eigen::Index typical_columns =
      (std::min)(state.max_dimension + state.b, round_up(3 * m, state.b) + state.b);
  return factor_while_mapping(
      solver, shifted, state.V.data(),
      sizeof(double) * static_cast<std::size_t>(state.n) * static_cast<std::size_t>(typical_columns));
}

// The eigenpairs of converged Ritz pairs, computed in the memory of V and
// handed to `eigenvalues` and `eigenvectors` (V is left empty). After a
// deflation of the Krylov subspace (`state.breakdown`), the residuals are
// verified.
bool accept_ritz_pairs(Block_lanczos_state& state, const Ritz_pairs& ritz, Eigen::Index k,
                       const Block_lanczos_sizes& sizes, double sigma,
                       const Eigen::SparseMatrix<double>& stiffness, double tolerance,
                       Eigen::VectorXd& eigenvalues, Eigen::MatrixXd& eigenvectors,
                       Block_lanczos_failure& failure);

// Grows the subspace block by block from a random start until the wanted
// Ritz pairs converge (then computes the eigenpairs) or the subspace
// reaches its maximum dimension (then fails with `failure.unconverged`).
template <class SparseSPDSolverTraits, class Listener>
bool grow_until_converged(Block_lanczos_state& state, const SparseSPDSolverTraits& solver,
                          const Block_lanczos_sizes& sizes, double sigma, double tolerance,
                          const Eigen::SparseMatrix<double>& stiffness, Listener& listener,
                          Eigen::VectorXd& eigenvalues, Eigen::MatrixXd& eigenvectors,
                          Block_lanczos_failure& failure)
{
  const Eigen::Index b = sizes.b;
  Eigen::MatrixXd R;
  start_lanczos(state, R);
  Eigen::Index next_check = first_check_dimension(sizes.m, b);
  Convergence_forecast forecast;
  for(Eigen::Index k = b;; k += b)
  {
    if(!shift_invert_block(state, solver, k))
      return failure.set("a solve with the factored shifted stiffness matrix failed");
    listener.block_solved(b, k);
    extend_lanczos_basis(state, k, R);
    if(k < next_check && k < sizes.max_dimension)
      continue;
    Ritz_pairs ritz;
    if(!rayleigh_ritz(state, k, sizes.wanted, tolerance, R, ritz))
      return failure.set("the Rayleigh-Ritz eigensolver did not converge");
    listener.checked(ritz.converged + sizes.known);
    next_check = forecast.next_check(k, b, sizes.wanted, ritz);
    if(ritz.converged == sizes.wanted)
      return accept_ritz_pairs(state, ritz, k, sizes, sigma, stiffness, tolerance, eigenvalues,
                               eigenvectors, failure);
    if(k + b > sizes.max_dimension)
    {
      failure.unconverged = true;
      return failure.set(std::to_string(ritz.converged + sizes.known) + " of the " +
                         std::to_string(sizes.m) +
                         " eigenpairs converged within the maximum subspace dimension " +
                         std::to_string(sizes.max_dimension));
    }
  }
}

// The m smallest eigenpairs of Q h = lambda M h by the block shift-invert
// Lanczos method. The constants of each component are eigenvectors of the
// eigenvalue 0, known in closed form: kept out of the Krylov subspace, they
// no longer dominate it (their shift-inverted eigenvalue 1 / |sigma| is
// thousands of times the wanted ones, and its rounding errors would be what
// destroys the orthogonality of the Lanczos vectors first). Returns false
// with `failure` set; may throw std::runtime_error on a breakdown it cannot
// recover from.
template <class SparseSPDSolverTraits, class Listener>
bool block_lanczos_eigenpairs(const Eigen::SparseMatrix<double>& stiffness,
                              const Eigen::VectorXd& mass, Eigen::Index m,
                              const Block_lanczos_settings& settings, Listener& listener,
                              Eigen::VectorXd& eigenvalues, Eigen::MatrixXd& eigenvectors,
                              Block_lanczos_failure& failure)
{
  const Single_threaded_blas_scope threads(settings.process_wide_tuning);
  const double sigma = shift_invert_shift(mass);
  const Laplacian_null_space null_space(stiffness, mass);
  Block_lanczos_sizes sizes;
  sizes.m = m;
  sizes.known = (std::min)(null_space.dimension(), m);
  sizes.wanted = m - sizes.known;
  sizes.b = settings.block_size;
  sizes.max_dimension = settings.max_dimension;
  if(sizes.wanted == 0)
  {
    eigenvalues = Eigen::VectorXd::Zero(m);
    eigenvectors = null_space.basis().leftCols(m);
    return true;
  }
  Block_lanczos_state state(mass, null_space, sizes, settings.process_wide_tuning);
  listener.factorization_started();
  SparseSPDSolverTraits solver;
  set_process_wide_tuning_if_supported(solver, settings.process_wide_tuning);
  if(!factor_shifted_stiffness(solver, stiffness, sigma, state, m))
    return failure.set("the factorization of the shifted stiffness matrix failed");
  state.allocate_work(m);
  return grow_until_converged(state, solver, sizes, sigma, settings.tolerance, stiffness,
                              listener, eigenvalues, eigenvectors, failure);
}

} // namespace Eigensolvers
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#if CGAL_SSMD_CORE_DEFINITIONS
#include <CGAL/Spectral_deformation/internal/Eigensolvers/Block_lanczos_iteration_impl.h>
#endif

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_BLOCK_LANCZOS_ITERATION_H

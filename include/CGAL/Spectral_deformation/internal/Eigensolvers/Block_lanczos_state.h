// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_BLOCK_LANCZOS_STATE_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_BLOCK_LANCZOS_STATE_H

#include <CGAL/Spectral_deformation/internal/compiled_core.h>
#include <CGAL/Spectral_deformation/internal/Eigensolvers/Laplacian_null_space.h>
#include <CGAL/Spectral_deformation/internal/Memory/Page_mapping.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cstddef>
#include <random>

namespace CGAL {
namespace Spectral_deformation {
namespace internal {
namespace Eigensolvers {

using Memory::advise_huge_pages;
using Memory::prefault;

Eigen::Index round_up(Eigen::Index value, Eigen::Index multiple);

// The sizes of one run of the block Lanczos method.
struct Block_lanczos_sizes
{
  Eigen::Index m = 0;             // eigenpairs asked for
  Eigen::Index known = 0;         // of which known in closed form (the constants)
  Eigen::Index wanted = 0;        // of which computed by the iteration: m - known
  Eigen::Index b = 0;             // vectors of a block
  Eigen::Index max_dimension = 0; // cap on the Rayleigh-Ritz dimension, a multiple of b
};

// The data of a block Lanczos run, shared by its steps
// (Block_orthogonalization.h, Partial_reorthogonalization.h,
// Block_lanczos_steps.h, Rayleigh_ritz.h). The operator is
// (Q - sigma M)^{-1} M, self-adjoint in the M inner product.
//
// - V holds the M-orthonormal subspace, one block more than the
//   Rayleigh-Ritz dimension. The eigenvectors are computed in its leading
//   columns at the end (see ritz_vectors_in_place()), so that V's memory is
//   returned: memory new to the process costs more to map than the products
//   done on it. V is only touched as it grows.
// - T = Vᵀ M (Q - sigma M)^{-1} M V is block tridiagonal: its diagonal and
//   upper blocks come from the orthogonalization of each new block against
//   the last two, its lower blocks from the normalization of the new block.
// - `orthogonality` (W) holds the estimates of Vᵀ M V used by the partial
//   reorthogonalization (upper blocks only).
// T and W grow with the subspace (they would be 8 m squared at full size).
// - `block` is the block being built; `weighted`, `scratch` and
//   `coefficients` are work arrays of the steps.
struct Block_lanczos_state
{
  typedef Eigen::MatrixXd Matrix;

  // Reserves V (untouched); with `process_wide_tuning`, asks for huge pages
  // on it (see Page_mapping.h).
  Block_lanczos_state(const Eigen::VectorXd& mass, const Laplacian_null_space& null_space,
                      const Block_lanczos_sizes& sizes, bool process_wide_tuning)
    : mass(mass), null_space(null_space), n(mass.size()), b(sizes.b),
      max_dimension(sizes.max_dimension), process_wide_tuning(process_wide_tuning),
      V(n, sizes.max_dimension + sizes.b), generator(20080806u), uniform(-1.0, 1.0)
  {
    if(process_wide_tuning)
      advise_huge_pages(V.data(), sizeof(double) * static_cast<std::size_t>(V.size()));
  }

  // Allocates T, W and the work arrays, sized for the typical subspace of m
  // eigenpairs (4 m columns); with `process_wide_tuning`, maps the work
  // arrays at once.
  void allocate_work(Eigen::Index m)
  {
    const Eigen::Index initial_size = (std::min)(max_dimension + b, round_up(4 * m, b) + b);
    T = Matrix::Zero(initial_size, initial_size);
    orthogonality = Matrix::Zero(initial_size, initial_size);
    block.resize(n, b);
    weighted.resize(n, b);
    coefficients.resize(max_dimension + b, b);
    scratch.resize(n, b);
    if(process_wide_tuning)
      for(Matrix* work : {&block, &weighted, &scratch})
        prefault(work->data(), sizeof(double) * static_cast<std::size_t>(work->size()));
    sqrt_mass = mass.cwiseSqrt();
    inverse_sqrt_mass = sqrt_mass.cwiseInverse();
  }

  // Makes room in T and W for the column block of the block k / b.
  void grow_projection(Eigen::Index k)
  {
    if(k + b <= T.rows())
      return;
    const Eigen::Index size = (std::min)(max_dimension + b, 2 * T.rows());
    T.conservativeResizeLike(Matrix::Zero(size, size));
    orthogonality.conservativeResizeLike(Matrix::Zero(size, size));
  }

  // The b × b blocks (i, j) of T and W.
  Eigen::Block<Matrix> T_block(Eigen::Index i, Eigen::Index j) { return T.block(i * b, j * b, b, b); }
  Eigen::Block<Matrix> W_block(Eigen::Index i, Eigen::Index j)
  {
    return orthogonality.block(i * b, j * b, b, b);
  }

  // Fills the columns [first, cols) of `target` (n rows) with uniform random
  // values in [-1, 1], column after column.
  void randomize_columns(Matrix& target, Eigen::Index first)
  {
    for(Eigen::Index j = first; j < target.cols(); ++j)
      for(Eigen::Index i = 0; i < n; ++i)
        target(i, j) = uniform(generator);
  }

  const Eigen::VectorXd& mass;
  Eigen::VectorXd sqrt_mass, inverse_sqrt_mass;
  // The constants of each component, kept out of the subspace.
  const Laplacian_null_space& null_space;
  const Eigen::Index n, b, max_dimension;
  const bool process_wide_tuning;

  Matrix V, T, orthogonality;
  Matrix block, weighted, coefficients, scratch;
  std::mt19937 generator;
  std::uniform_real_distribution<double> uniform;

  // The partial reorthogonalization: the estimate of the norm of the
  // operator, whether the next block is reorthogonalized against the whole
  // subspace, whether a block lacked directions (its eigenpairs are then
  // verified), and how many blocks were reorthogonalized.
  double operator_norm = 0;
  bool reorthogonalize_next = false;
  bool breakdown = false;
  std::size_t reorthogonalizations = 0;
};

} // namespace Eigensolvers
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#if CGAL_SSMD_CORE_DEFINITIONS
#include <CGAL/Spectral_deformation/internal/Eigensolvers/Block_lanczos_state_impl.h>
#endif

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_BLOCK_LANCZOS_STATE_H

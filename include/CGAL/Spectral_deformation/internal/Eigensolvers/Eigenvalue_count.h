// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_EIGENVALUE_COUNT_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_EIGENVALUE_COUNT_H

#include <CGAL/Spectral_deformation/internal/compiled_core.h>
#include <CGAL/Spectral_deformation/internal/Eigensolvers/Shift_invert.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <cmath>

namespace CGAL {
namespace Spectral_deformation {
namespace internal {
namespace Eigensolvers {

// The number of eigenvalues of Q h = lambda M h (M = diag(mass), positive)
// below `shift`, by Sylvester's law of inertia: Q - shift M is congruent to
// the diagonal D of its factorization L D Lᵀ, so the negative entries of D
// count the eigenvalues below the shift. The factorization does not pivot
// (Eigen's SimplicialLDLT): -1 when it meets a zero or non-finite pivot, the
// shift being (nearly) an eigenvalue of a leading block.
Eigen::Index eigenvalues_below(const Eigen::SparseMatrix<double>& stiffness, const Eigen::VectorXd& mass,
                               double shift);

// Whether `eigenvalues` (ascending, each at or above the eigenvalue of its
// rank, as the Ritz values of a Lanczos method are) are the smallest ones of
// Q h = lambda M h, copies of repeated eigenvalues included. Eigenvalues
// within `relative_gap` of the largest one are a cluster at the top: any of
// its copies will do (a dense solver also returns one choice among them), but
// every eigenvalue below the cluster must be there. At most two sparse
// factorizations of the size of Q.
bool smallest_eigenvalues_complete(const Eigen::SparseMatrix<double>& stiffness,
                                   const Eigen::VectorXd& mass, const Eigen::VectorXd& eigenvalues,
                                   double relative_gap = 1e-5);

} // namespace Eigensolvers
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#if CGAL_SSMD_CORE_DEFINITIONS
#include <CGAL/Spectral_deformation/internal/Eigensolvers/Eigenvalue_count_impl.h>
#endif

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_EIGENVALUE_COUNT_H

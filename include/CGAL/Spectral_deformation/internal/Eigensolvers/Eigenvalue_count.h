// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_EIGENVALUE_COUNT_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_EIGENVALUE_COUNT_H

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
inline Eigen::Index eigenvalues_below(const Eigen::SparseMatrix<double>& stiffness, const Eigen::VectorXd& mass,
                                      double shift)
{
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> factorization(shifted_stiffness(stiffness, mass, shift));
  if(factorization.info() != Eigen::Success)
    return -1;
  const Eigen::VectorXd pivots = factorization.vectorD();
  if(!pivots.allFinite() || (pivots.array() == 0.0).any())
    return -1;
  return (pivots.array() < 0.0).count();
}

// Whether `eigenvalues` (ascending, each at or above the eigenvalue of its
// rank, as the Ritz values of a Lanczos method are) are the smallest ones of
// Q h = lambda M h, copies of repeated eigenvalues included. Eigenvalues
// within `relative_gap` of the largest one are a cluster at the top: any of
// its copies will do (a dense solver also returns one choice among them), but
// every eigenvalue below the cluster must be there. At most two sparse
// factorizations of the size of Q.
inline bool smallest_eigenvalues_complete(const Eigen::SparseMatrix<double>& stiffness,
                                          const Eigen::VectorXd& mass, const Eigen::VectorXd& eigenvalues,
                                          double relative_gap = 1e-5)
{
  const Eigen::Index m = eigenvalues.size();
  if(m == 0)
    return true;
  const double top = eigenvalues(m - 1);
  // Only zero eigenvalues (constant functions, computed as zero to rounding):
  // no shift separates them from the rest. The diagonal of M⁻¹ Q gives the
  // scale of the spectrum.
  const double scale = stiffness.diagonal().cwiseQuotient(mass).cwiseAbs().maxCoeff();
  if(!(top > 1e-10 * scale) || !std::isfinite(top))
    return false;
  const Eigen::Index below_top = eigenvalues_below(stiffness, mass, top * (1.0 + relative_gap));
  if(below_top == m)
    return true;
  if(below_top < m)
    return false;
  const double cluster = top * (1.0 - relative_gap);
  Eigen::Index under_cluster = 0;
  while(under_cluster < m && eigenvalues(under_cluster) < cluster)
    ++under_cluster;
  return eigenvalues_below(stiffness, mass, cluster) == under_cluster;
}

} // namespace Eigensolvers
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_EIGENVALUE_COUNT_H

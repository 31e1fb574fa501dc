// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_EIGENVALUE_COUNT_IMPL_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_EIGENVALUE_COUNT_IMPL_H

// The definitions of the functions declared in Eigenvalue_count.h (see
// internal/compiled_core.h: the compiled core holds them).

#include <CGAL/Spectral_deformation/internal/Eigensolvers/Eigenvalue_count.h>

namespace CGAL {
namespace Spectral_deformation {
namespace internal {
namespace Eigensolvers {

CGAL_SSMD_CORE_FUNCTION Eigen::Index eigenvalues_below(const Eigen::SparseMatrix<double>& stiffness, const Eigen::VectorXd& mass,
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

CGAL_SSMD_CORE_FUNCTION bool smallest_eigenvalues_complete(const Eigen::SparseMatrix<double>& stiffness,
                                                           const Eigen::VectorXd& mass, const Eigen::VectorXd& eigenvalues,
                                                           double relative_gap)
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

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_EIGENVALUE_COUNT_IMPL_H

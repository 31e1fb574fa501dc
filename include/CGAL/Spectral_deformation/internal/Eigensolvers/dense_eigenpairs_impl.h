// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_DENSE_EIGENPAIRS_IMPL_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_DENSE_EIGENPAIRS_IMPL_H

// The definitions of the functions declared in dense_eigenpairs.h (see
// internal/compiled_core.h: the compiled core holds them).

#include <CGAL/Spectral_deformation/internal/Eigensolvers/dense_eigenpairs.h>

namespace CGAL {
namespace Spectral_deformation {
namespace internal {
namespace Eigensolvers {

CGAL_SSMD_CORE_FUNCTION bool dense_generalized_eigenpairs(const Eigen::SparseMatrix<double>& stiffness,
                                                          const Eigen::VectorXd& mass, Eigen::Index m,
                                                          Eigen::VectorXd& eigenvalues, Eigen::MatrixXd& eigenvectors,
                                                          std::string& message)
{
  // M^{-1/2} Q M^{-1/2} y = lambda y with h = M^{-1/2} y is the same problem,
  // symmetric and standard because M is diagonal and positive.
  const Eigen::VectorXd inv_sqrt_mass = mass.cwiseSqrt().cwiseInverse();
  const Eigen::MatrixXd scaled =
      inv_sqrt_mass.asDiagonal() * Eigen::MatrixXd(stiffness) * inv_sqrt_mass.asDiagonal();
  Eigen::MatrixXd vectors;
  if(!smallest_symmetric_eigenpairs(scaled, m, eigenvalues, vectors))
  {
    message = "the dense eigensolver did not converge";
    return false;
  }
  eigenvectors = inv_sqrt_mass.asDiagonal() * vectors;
  return true;
}

} // namespace Eigensolvers
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_DENSE_EIGENPAIRS_IMPL_H

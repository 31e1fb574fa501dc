// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_RAYLEIGH_RITZ_IMPL_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_RAYLEIGH_RITZ_IMPL_H

// The definitions of the functions declared in Rayleigh_ritz.h (see
// internal/compiled_core.h: the compiled core holds them).

#include <CGAL/Spectral_deformation/internal/Eigensolvers/Rayleigh_ritz.h>

namespace CGAL {
namespace Spectral_deformation {
namespace internal {
namespace Eigensolvers {

CGAL_SSMD_CORE_FUNCTION bool rayleigh_ritz(const Block_lanczos_state& state, Eigen::Index k, Eigen::Index wanted,
                                           double tolerance, const Eigen::MatrixXd& R, Ritz_pairs& ritz)
{
  const Eigen::MatrixXd projected =
      0.5 * (state.T.topLeftCorner(k, k) + state.T.topLeftCorner(k, k).transpose());
  if(!largest_symmetric_eigenpairs(projected, wanted, ritz.values, ritz.coordinates))
    return false;
  // Largest theta first: the smallest lambda.
  ritz.converged = 0;
  ritz.slowest = 0;
  for(Eigen::Index i = 0; i < wanted; ++i)
  {
    const Eigen::Index column = wanted - 1 - i;
    const double theta = ritz.values[column];
    const double residual = (R * ritz.coordinates.col(column).tail(state.b)).norm();
    if(residual <= tolerance * std::abs(theta))
      ++ritz.converged;
    ritz.slowest = (std::max)(ritz.slowest, residual / (tolerance * std::abs(theta)));
  }
  return true;
}

CGAL_SSMD_CORE_FUNCTION Eigen::Index first_check_dimension(Eigen::Index m, Eigen::Index b)
{
  return (std::max)(m + b, round_up((3 * m) / 2, b));
}

CGAL_SSMD_CORE_FUNCTION Eigen::VectorXd ritz_eigenvalues(const Ritz_pairs& ritz, Eigen::Index known, double sigma,
                                                         Eigen::Index k, Eigen::MatrixXd& selected)
{
  const Eigen::Index wanted = ritz.values.size();
  selected.resize(k, wanted);
  for(Eigen::Index i = 0; i < wanted; ++i)
    selected.col(i) = ritz.coordinates.col(wanted - 1 - i);
  Eigen::VectorXd values(known + wanted);
  values.head(known).setZero();
  for(Eigen::Index i = 0; i < wanted; ++i)
    values[known + i] = sigma + 1.0 / ritz.values[wanted - 1 - i];
  return values;
}

CGAL_SSMD_CORE_FUNCTION bool verify_eigenpairs(const Eigen::SparseMatrix<double>& stiffness,
                                               const Eigen::VectorXd& mass, const Eigen::VectorXd& eigenvalues,
                                               const Eigen::MatrixXd& eigenvectors, double tolerance)
{
  const Eigen::VectorXd inverse_sqrt_mass = mass.cwiseSqrt().cwiseInverse();
  const double sigma = shift_invert_shift(mass);
  const double scale = (std::max)(1e-6, 1e3 * tolerance) * (eigenvalues.maxCoeff() - sigma);
  for(Eigen::Index i = 0; i < eigenvalues.size(); ++i)
  {
    const Eigen::VectorXd residual =
        stiffness * eigenvectors.col(i) - eigenvalues[i] * mass.cwiseProduct(eigenvectors.col(i));
    if(!(inverse_sqrt_mass.cwiseProduct(residual).norm() <= scale))
      return false;
  }
  return true;
}

} // namespace Eigensolvers
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_RAYLEIGH_RITZ_IMPL_H

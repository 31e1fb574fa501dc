// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_SINGLE_VECTOR_LANCZOS_IMPL_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_SINGLE_VECTOR_LANCZOS_IMPL_H

// The definitions of Single_vector_lanczos.h that are not templates: compiled
// into the package's core library, or inline in a header-only build.

#include <CGAL/Spectral_deformation/internal/Eigensolvers/Single_vector_lanczos.h>

namespace CGAL {
namespace Spectral_deformation {
namespace internal {
namespace Eigensolvers {

CGAL_SSMD_CORE_FUNCTION Lanczos_recurrence::Lanczos_recurrence(Eigen::Index capacity)
  : m_alpha(Eigen::VectorXd::Zero(capacity + 1)), m_beta(Eigen::VectorXd::Zero(capacity + 2)),
    m_previous(Eigen::VectorXd::Zero(capacity + 2)), m_current(Eigen::VectorXd::Zero(capacity + 2)),
    m_next(Eigen::VectorXd::Zero(capacity + 2))
{
  m_current[0] = 1; // omega_{0,0}
}

CGAL_SSMD_CORE_FUNCTION double Lanczos_recurrence::step(Eigen::Index j, double alpha, double beta)
{
  const double eps = std::numeric_limits<double>::epsilon();
  m_alpha[j] = alpha;
  m_beta[j + 1] = beta;
  m_norm = (std::max)(m_norm, std::abs(alpha) + beta + m_beta[j]);
  // Simon's recurrence for omega_{j+1,i}, i < j (omega_{j,j} = omega_{j-1,j-1}
  // = 1 in m_current and m_previous), with one rounding of a step added with
  // the sign that makes it grow.
  double largest = 0;
  for(Eigen::Index i = 0; i < j; ++i)
  {
    double estimate = m_beta[i + 1] * m_current[i + 1] + (m_alpha[i] - alpha) * m_current[i] -
                      m_beta[j] * m_previous[i];
    if(i > 0)
      estimate += m_beta[i] * m_current[i - 1];
    estimate += (estimate < 0 ? -eps : eps) * m_norm;
    m_next[i] = estimate / beta;
    largest = (std::max)(largest, std::abs(m_next[i]));
  }
  m_next[j] = eps; // v_{j+1} was orthogonalized against v_j
  m_next[j + 1] = 1;
  m_previous.swap(m_current);
  m_current.swap(m_next);
  return largest;
}

CGAL_SSMD_CORE_FUNCTION void Lanczos_recurrence::reorthogonalized(Eigen::Index j, double beta)
{
  m_beta[j + 1] = beta;
  m_current.head(j + 1).setConstant(std::numeric_limits<double>::epsilon());
  m_current[j + 1] = 1;
}

CGAL_SSMD_CORE_FUNCTION bool Lanczos_recurrence::rayleigh_ritz(Eigen::Index k, Eigen::Index wanted, double tolerance,
                                                               Ritz_pairs& ritz) const
{
  const Eigen::VectorXd subdiagonal = m_beta.segment(1, k - 1);
  if(!largest_tridiagonal_eigenpairs(m_alpha.head(k), subdiagonal, wanted, ritz.values, ritz.coordinates))
    return false;
  // The residual of a Ritz pair (theta, V s) is beta_k |s_k| (the last
  // coordinate of s).
  ritz.converged = 0;
  ritz.slowest = 0;
  for(Eigen::Index i = 0; i < wanted; ++i)
  {
    const double theta = ritz.values[i];
    const double residual = m_beta[k] * std::abs(ritz.coordinates(k - 1, i));
    if(residual <= tolerance * std::abs(theta))
      ++ritz.converged;
    ritz.slowest = (std::max)(ritz.slowest, residual / (tolerance * std::abs(theta)));
  }
  return true;
}

CGAL_SSMD_CORE_FUNCTION Eigen::Index next_single_vector_check(Convergence_forecast& forecast, Eigen::Index k,
                                                              Eigen::Index n, Eigen::Index wanted,
                                                              const Ritz_pairs& ritz)
{
  const Eigen::Index forecast_check =
      (std::min)(forecast.next_check(k, 1, wanted, ritz), k + (std::max)(Eigen::Index(4), k / 16));
  const Eigen::Index balanced_steps = (std::min)((k * k + n - 1) / (std::max)(n, Eigen::Index(1)), k / 4);
  return (std::max)(forecast_check, k + balanced_steps);
}

} // namespace Eigensolvers
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_SINGLE_VECTOR_LANCZOS_IMPL_H

// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_LINEAR_ALGEBRA_ANDERSON_ACCELERATION_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_LINEAR_ALGEBRA_ANDERSON_ACCELERATION_H

#include <Eigen/Core>
#include <Eigen/QR>

#include <algorithm>
#include <vector>

namespace CGAL {
namespace Spectral_deformation {
namespace internal {
namespace Linear_algebra {

/// Anderson acceleration of a fixed-point iteration x ← G(x) (Walker and Ni,
/// *Anderson acceleration for fixed-point iterations*, SINUM 2011; applied
/// to local-global solvers by Peng, Deng, Zhang and Liu, *Anderson
/// Acceleration for Geometry Optimization and Physics Simulation*, SIGGRAPH
/// 2018). From the last `history()` differences of the iterates G(x) and of
/// the residuals f = G(x) − x it extrapolates the iterate
/// G(x) − Σ θ_j ΔG_j, θ minimizing ‖f − Σ θ_j Δf_j‖, an affine combination of
/// the images G(x): entries equal in all of them (prescribed vertices) stay
/// exactly as they are. The caller decides whether the extrapolated iterate
/// is better than G(x) (the refinement compares their energies) and calls
/// `reset()` when it is not.
///
/// Debian packages no implementation; Eigen's dense least squares does the
/// arithmetic.
///
/// \tparam Matrix the Eigen matrix type of the iterates.
template <class Matrix>
class Anderson_acceleration
{
public:
  /// Keeps the last `history` differences (at least 1).
  explicit Anderson_acceleration(Eigen::Index history = 5) : m_history((std::max<Eigen::Index>)(history, 1)) {}

  Eigen::Index history() const { return m_history; }

  /// Forgets the previous iterates.
  void reset()
  {
    m_count = 0;
    m_next = 0;
    m_has_previous = false;
  }

  /// With `x` the current iterate and `image` = G(x): writes the
  /// extrapolated iterate in `accelerated` and returns true, or returns
  /// false when there is no difference to extrapolate from yet (the first
  /// call after `reset()`), `accelerated` then unchanged.
  bool extrapolate(const Matrix& x, const Matrix& image, Matrix& accelerated)
  {
    const Matrix residual = image - x;
    if(m_has_previous)
    {
      if(static_cast<Eigen::Index>(m_residual_differences.size()) < m_history)
      {
        m_residual_differences.resize(static_cast<std::size_t>(m_history));
        m_image_differences.resize(static_cast<std::size_t>(m_history));
        m_normal_matrix.setZero(m_history, m_history);
      }
      const Eigen::Index slot = m_next;
      m_residual_differences[static_cast<std::size_t>(slot)] = residual - m_previous_residual;
      m_image_differences[static_cast<std::size_t>(slot)] = image - m_previous_image;
      m_count = (std::min)(m_count + 1, m_history);
      m_next = (m_next + 1) % m_history;
      const Matrix& added = m_residual_differences[static_cast<std::size_t>(slot)];
      for(Eigen::Index j = 0; j < m_count; ++j)
      {
        const double product = added.cwiseProduct(m_residual_differences[static_cast<std::size_t>(j)]).sum();
        m_normal_matrix(slot, j) = product;
        m_normal_matrix(j, slot) = product;
      }
    }
    m_previous_residual = residual;
    m_previous_image = image;
    m_has_previous = true;
    if(m_count == 0)
      return false;

    Eigen::VectorXd projections(m_count);
    for(Eigen::Index j = 0; j < m_count; ++j)
      projections(j) = m_residual_differences[static_cast<std::size_t>(j)].cwiseProduct(residual).sum();
    // The normal equations of the small least-squares problem; nearly
    // parallel differences make them singular, which the complete
    // orthogonal decomposition answers with the least-norm solution.
    const Eigen::VectorXd theta =
        m_normal_matrix.topLeftCorner(m_count, m_count).completeOrthogonalDecomposition().solve(projections);
    if(!theta.allFinite())
      return false;
    accelerated = image;
    for(Eigen::Index j = 0; j < m_count; ++j)
      accelerated.noalias() -= theta(j) * m_image_differences[static_cast<std::size_t>(j)];
    return true;
  }

private:
  Eigen::Index m_history;
  Eigen::Index m_count = 0; // differences held
  Eigen::Index m_next = 0;  // the slot the next difference goes to
  bool m_has_previous = false;
  Matrix m_previous_residual, m_previous_image;
  std::vector<Matrix> m_residual_differences, m_image_differences;
  Eigen::MatrixXd m_normal_matrix; // Gram matrix of the residual differences
};

} // namespace Linear_algebra
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_LINEAR_ALGEBRA_ANDERSON_ACCELERATION_H

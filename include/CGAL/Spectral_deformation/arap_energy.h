// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_ARAP_ENERGY_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_ARAP_ENERGY_H

#include <CGAL/Spectral_deformation/cotangent_operators.h>
#include <CGAL/Spectral_deformation/internal/Mesh/Triangle_arrays.h>

#include <Eigen/Dense>
#include <Eigen/SVD>

#include <vector>

namespace CGAL {
namespace Spectral_deformation {
namespace internal {
namespace Deformation {

using Mesh::Positions;
using Mesh::Triangle_arrays;

/// As-rigid-as-possible energy (Sorkine and Alexa 2007) of `deformed` against
/// the rest shape `rest`, with the best rotation per vertex one-ring and the
/// absolute cotangent weights, divided by the weighted sum of squared rest
/// edge lengths so that it is scale invariant: 0 for a rigid motion, about
/// the mean squared relative edge distortion otherwise.
inline double arap_energy(const Triangle_arrays& rest, const Positions& deformed)
{
  const Eigen::SparseMatrix<double> Q = cotangent_stiffness(rest);
  const Eigen::Index n = rest.number_of_vertices();
  std::vector<Eigen::Matrix3d> covariance(static_cast<std::size_t>(n), Eigen::Matrix3d::Zero());
  for(int k = 0; k < Q.outerSize(); ++k)
    for(Eigen::SparseMatrix<double>::InnerIterator it(Q, k); it; ++it)
    {
      if(it.row() == it.col())
        continue;
      const double w = std::abs(it.value());
      const Eigen::Vector3d e = (rest.positions.row(it.row()) - rest.positions.row(it.col())).transpose();
      const Eigen::Vector3d d = (deformed.row(it.row()) - deformed.row(it.col())).transpose();
      covariance[static_cast<std::size_t>(it.row())] += w * e * d.transpose();
    }
  std::vector<Eigen::Matrix3d> rotation(static_cast<std::size_t>(n));
  for(Eigen::Index i = 0; i < n; ++i)
  {
    Eigen::JacobiSVD<Eigen::Matrix3d> svd(covariance[static_cast<std::size_t>(i)],
                                          Eigen::ComputeFullU | Eigen::ComputeFullV);
    Eigen::Matrix3d R = svd.matrixV() * svd.matrixU().transpose();
    if(R.determinant() < 0)
    {
      Eigen::Matrix3d U = svd.matrixU();
      U.col(2) = -U.col(2);
      R = svd.matrixV() * U.transpose();
    }
    rotation[static_cast<std::size_t>(i)] = R;
  }
  double energy = 0, normalization = 0;
  for(int k = 0; k < Q.outerSize(); ++k)
    for(Eigen::SparseMatrix<double>::InnerIterator it(Q, k); it; ++it)
    {
      if(it.row() == it.col())
        continue;
      const double w = std::abs(it.value());
      const Eigen::Vector3d e = (rest.positions.row(it.row()) - rest.positions.row(it.col())).transpose();
      const Eigen::Vector3d d = (deformed.row(it.row()) - deformed.row(it.col())).transpose();
      energy += w * (d - rotation[static_cast<std::size_t>(it.row())] * e).squaredNorm();
      normalization += w * e.squaredNorm();
    }
  return energy / normalization;
}

} // namespace Deformation
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_ARAP_ENERGY_H

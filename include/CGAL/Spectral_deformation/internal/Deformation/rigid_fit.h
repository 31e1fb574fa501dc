// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_RIGID_FIT_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_RIGID_FIT_H

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <Eigen/SVD>

namespace CGAL {
namespace Spectral_deformation {
namespace internal {
namespace Deformation {

/// A rigid motion x -> R x + t.
/// The rotation of a 3×3 matrix `C` closest to it in the Frobenius norm
/// among proper rotations (the Kabsch solution of max tr(Rᵀ C)), from the
/// eigenvectors of CᵀC: R = u₁v₁ᵀ + u₂v₂ᵀ + (u₁×u₂)(v₁×v₂)ᵀ with uₖ = C vₖ/σₖ.
/// Needs σ₂ > 0 (C of rank two at least); returns `fallback` otherwise.
inline Eigen::Matrix3d nearest_rotation(const Eigen::Matrix3d& C,
                                        const Eigen::Matrix3d& fallback = Eigen::Matrix3d::Identity())
{
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen;
  eigen.computeDirect(C.transpose() * C);
  // Eigenvalues ascending: columns 2 and 1 are the two largest.
  const Eigen::Vector3d v1 = eigen.eigenvectors().col(2), v2 = eigen.eigenvectors().col(1);
  Eigen::Vector3d u1 = C * v1;
  const double s1 = u1.norm();
  if(!(s1 > 0))
    return fallback;
  u1 /= s1;
  // Gram-Schmidt keeps u₂ orthogonal to u₁ when σ₂ is much smaller than σ₁.
  Eigen::Vector3d u2 = C * v2;
  u2 -= u2.dot(u1) * u1;
  const double s2 = u2.norm();
  if(!(s2 > 1e-12 * s1))
    return fallback;
  u2 /= s2;
  Eigen::Vector3d w2 = v2 - v2.dot(v1) * v1;
  w2.normalize();
  return u1 * v1.transpose() + u2 * w2.transpose() + u1.cross(u2) * v1.cross(w2).transpose();
}

struct Rigid_motion
{
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();

  Eigen::RowVector3d apply(const Eigen::RowVector3d& x) const
  {
    return (rotation * x.transpose() + translation).transpose();
  }
};

/// The rigid motion that best maps `from` onto `to` (k×3 each) in the least
/// squares sense (Kabsch). With one point, or points on a line, the rotation
/// is underdetermined in at least one direction; the closest rotation to the
/// identity compatible with the data is returned by the SVD, and a single
/// point gives a pure translation.
inline Rigid_motion fit_rigid_motion(const Eigen::Matrix<double, Eigen::Dynamic, 3>& from,
                                     const Eigen::Matrix<double, Eigen::Dynamic, 3>& to)
{
  Rigid_motion motion;
  const Eigen::RowVector3d from_center = from.colwise().mean();
  const Eigen::RowVector3d to_center = to.colwise().mean();
  if(from.rows() > 1)
  {
    const Eigen::Matrix3d covariance =
        (from.rowwise() - from_center).transpose() * (to.rowwise() - to_center);
    const double scale = covariance.cwiseAbs().maxCoeff();
    if(scale > 0)
    {
      Eigen::JacobiSVD<Eigen::Matrix3d> svd(covariance, Eigen::ComputeFullU | Eigen::ComputeFullV);
      // Directions with no spread in the data (collinear points) have zero
      // singular values; they are left unrotated instead of following the
      // arbitrary singular vectors.
      Eigen::Vector3d s = Eigen::Vector3d::Ones();
      const Eigen::Vector3d sv = svd.singularValues();
      Eigen::Matrix3d R = svd.matrixV() * svd.matrixU().transpose();
      if(R.determinant() < 0)
      {
        s[2] = -1;
        R = svd.matrixV() * s.asDiagonal() * svd.matrixU().transpose();
      }
      if(sv[1] > 1e-12 * sv[0])
        motion.rotation = R;
      else
      {
        // Only one direction is known: the rotation taking it to its image.
        const Eigen::Vector3d a = svd.matrixU().col(0), b = svd.matrixV().col(0);
        motion.rotation = Eigen::Quaterniond::FromTwoVectors(a, b).toRotationMatrix();
      }
    }
  }
  motion.translation = to_center.transpose() - motion.rotation * from_center.transpose();
  return motion;
}

} // namespace Deformation
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_RIGID_FIT_H

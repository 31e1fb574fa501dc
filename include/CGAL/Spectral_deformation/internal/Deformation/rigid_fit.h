// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_RIGID_FIT_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_RIGID_FIT_H

#include <Eigen/Dense>
#include <Eigen/SVD>

#include <cmath>

namespace CGAL {
namespace Spectral_deformation {
namespace internal {
namespace Deformation {

/// The rotation of a 3×3 matrix `C` closest to it in the Frobenius norm
/// among proper rotations (the Kabsch solution of max tr(Rᵀ C)); `fallback`
/// when C has rank below two (σ₂ ≤ 1e-12 σ₁) or is not finite.
///
/// Written out rather than taken from Eigen because it runs once per vertex
/// and drag: an eigen-decomposition of CᵀC (the closed-form 3×3 solver uses
/// trigonometric functions) costs several times more, and squaring C loses
/// the small singular values of the nearly flat covariances of one-rings.
///
/// With C = U Σ Vᵀ (U, V proper, σ₃ carrying the sign of det C) the answer is
/// U Vᵀ. C, its cofactor matrix cof C = det(C) C⁻ᵀ and the mixed cofactor
/// K = cof(C, cof C) = ‖C‖² C − C CᵀC share those singular vectors, with
/// singular values σₖ, σᵢσⱼ and σₖ(σᵢ² + σⱼ²), so that
///
///   R = (I₂ C + I₁ cof C + K) / D,  D = I₁ I₂ − I₃ = (σ₁+σ₂)(σ₁+σ₃)(σ₂+σ₃),
///
/// with I₁ = σ₁+σ₂+σ₃, I₂ = σ₁σ₂+σ₁σ₃+σ₂σ₃ and I₃ = det C. Nothing is
/// inverted, so C of rank two is fine; D vanishes exactly when the answer is
/// not unique. I₁ is the largest root of the characteristic quartic of Horn's
/// quaternion matrix, P(λ) = (λ² − ‖C‖²)² − 4‖cof C‖² − 8 det(C) λ, with
/// P'(I₁) = 8D, found by Newton's method from a close starting value; then
/// I₂ = (I₁² − ‖C‖²)/2. Ill-conditioned inputs (σ₂+σ₃ below about 1e-3 σ₁) and
/// non-finite ones go to a Jacobi SVD.
inline Eigen::Matrix3d nearest_rotation(const Eigen::Matrix3d& C,
                                        const Eigen::Matrix3d& fallback = Eigen::Matrix3d::Identity())
{
  const auto by_svd = [&C, &fallback]() -> Eigen::Matrix3d {
    if(!C.allFinite())
      return fallback;
    const Eigen::JacobiSVD<Eigen::Matrix3d> svd(C, Eigen::ComputeFullU | Eigen::ComputeFullV);
    const Eigen::Vector3d s = svd.singularValues();
    if(!(s[1] > 1e-12 * s[0]))
      return fallback;
    Eigen::Matrix3d U = svd.matrixU();
    if((U * svd.matrixV().transpose()).determinant() < 0)
      U.col(2) = -U.col(2);
    return U * svd.matrixV().transpose();
  };

  double a00 = C(0, 0), a01 = C(0, 1), a02 = C(0, 2);
  double a10 = C(1, 0), a11 = C(1, 1), a12 = C(1, 2);
  double a20 = C(2, 0), a21 = C(2, 1), a22 = C(2, 2);
  const auto squared_norm = [&]() {
    return ((a00 * a00 + a01 * a01) + (a02 * a02 + a10 * a10)) + ((a11 * a11 + a12 * a12) + (a20 * a20 + a21 * a21)) +
           a22 * a22;
  };
  double e2 = squared_norm();
  // The invariants below are of degree up to 16 in C: outside this range of
  // ‖C‖² they would overflow or underflow. A power of two rescales exactly.
  if(!(e2 >= 1e-30 && e2 <= 1e30))
  {
    const double largest = C.cwiseAbs().maxCoeff();
    if(!(largest > 0) || !std::isfinite(largest))
      return by_svd();
    int exponent = 0;
    std::frexp(largest, &exponent);
    const double scale = std::ldexp(1.0, -exponent);
    a00 *= scale, a01 *= scale, a02 *= scale, a10 *= scale, a11 *= scale, a12 *= scale;
    a20 *= scale, a21 *= scale, a22 *= scale;
    e2 = squared_norm();
  }

  const double c00 = a11 * a22 - a12 * a21, c01 = a12 * a20 - a10 * a22, c02 = a10 * a21 - a11 * a20;
  const double c10 = a02 * a21 - a01 * a22, c11 = a00 * a22 - a02 * a20, c12 = a01 * a20 - a00 * a21;
  const double c20 = a01 * a12 - a02 * a11, c21 = a02 * a10 - a00 * a12, c22 = a00 * a11 - a01 * a10;
  const double det = (a00 * c00 + a01 * c01) + a02 * c02;
  // ‖cof C‖² = Σ σᵢ²σⱼ², from the minors of C: through CᵀC the small singular
  // values would be lost.
  const double e4 = ((c00 * c00 + c01 * c01) + (c02 * c02 + c10 * c10)) +
                    ((c11 * c11 + c12 * c12) + (c20 * c20 + c21 * c21)) + c22 * c22;

  // Starting value: σ₃² is the smallest root of τ³ − ‖C‖²τ² + ‖cof C‖²τ − det²,
  // close to det²/‖cof C‖² for nearly flat one-rings; one Newton step on that
  // cubic, folded into one division, then σ₁σ₂ = √(‖cof C‖² − τ(‖C‖² − τ)),
  // σ₁+σ₂ = √(‖C‖² − τ + 2σ₁σ₂) and σ₃ = det/(σ₁σ₂). For most one-rings this
  // is I₁ to rounding already.
  const double x = det * det, e4e4e4 = e4 * e4 * e4, xe = e2 * x * e4;
  const double t = x * (e4e4e4 - xe + 2.0 * x * x) / (e4 * (e4e4e4 - 2.0 * xe) + 3.0 * x * x * e4);
  const double u = e2 - t;
  const double s1s2 = std::sqrt(e4 - t * u);
  double l = std::sqrt(u + 2.0 * s1s2) + det / s1s2;

  // Newton on P. An error δ in I₁ moves the singular values of R off 1 by
  // about 16 δ I₁²/P'; the loop stops once the expected error after the step
  // (P''s²/(2P')) makes that below 1e-15. Near a double root this test
  // cannot pass and the conditioning test below sends C to the SVD.
  double r = 0, step = 0, kappa = 0;
  bool converged = false;
  for(int iteration = 0; iteration < 8 && !converged; ++iteration)
  {
    const double l2 = l * l, w = l2 - e2;
    const double p = w * w - 4.0 * e4 - 8.0 * det * l;
    const double dp = 4.0 * l * w - 8.0 * det;
    r = 1.0 / dp;
    step = p * r;
    l -= step;
    kappa = (12.0 * l2 - 4.0 * e2) * step * r; // relative change of P' over the step
    converged = 8.0 * kappa * step * r * l2 <= 1e-15;
  }
  // 1/D = 8/P'(I₁), from the reciprocal of the last step to first order.
  const double inverse = 8.0 * r * (1.0 + kappa + kappa * kappa);
  const double l2 = l * l;
  // Only the largest root has D > 0, λ > 0 and 3λ² > ‖C‖²; below
  // D = 1e-3 λ³ the rounding of P makes λ too inaccurate.
  if(!(converged && l > 0 && inverse > 0 && l2 * l * inverse < 1e3 && 3.0 * l2 > e2))
    return by_svd();

  // K rather than C CᵀC: its terms are of the size of D, not σ₁/(σ₂+σ₃)
  // times larger, so less cancels.
  const double a[3][3] = {{a00, a01, a02}, {a10, a11, a12}, {a20, a21, a22}};
  const double c[3][3] = {{c00, c01, c02}, {c10, c11, c12}, {c20, c21, c22}};
  const double twice_i2 = l2 - e2;
  Eigen::Matrix3d R;
  for(int i = 0; i < 3; ++i)
  {
    const int i1 = (i + 1) % 3, i2 = (i + 2) % 3;
    for(int j = 0; j < 3; ++j)
    {
      const int j1 = (j + 1) % 3, j2 = (j + 2) % 3;
      const double mixed = (a[i1][j1] * c[i2][j2] + c[i1][j1] * a[i2][j2]) -
                           (a[i1][j2] * c[i2][j1] + c[i1][j2] * a[i2][j1]);
      R(i, j) = ((0.5 * a[i][j]) * twice_i2 + (l * c[i][j] + mixed)) * inverse;
    }
  }

  // The rounding of λ scales the singular values of R by 1 + e with e growing
  // like ε (λ³/D)²; where D < 0.1 λ³, one Newton–Schulz step R (3I − RᵀR)/2
  // takes them to 1 − 1.5 e².
  if(l2 * l * inverse > 10.0)
  {
    const Eigen::Matrix3d H = 0.5 * (Eigen::Matrix3d::Identity() - R.transpose() * R);
    R += R * H;
  }
  return R;
}

/// A rigid motion x -> R x + t.
struct Rigid_motion
{
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();

  Eigen::RowVector3d apply(const Eigen::RowVector3d& x) const
  {
    return (rotation * x.transpose() + translation).transpose();
  }
};

/// The rigid motion that best maps `count` points with centroid
/// `from_center` onto points with centroid `to_center` (Kabsch), from their
/// covariance Σ (from_i − from_center)ᵀ (to_i − to_center): see
/// `fit_rigid_motion()`.
inline Rigid_motion rigid_motion_from_moments(const Eigen::RowVector3d& from_center,
                                              const Eigen::RowVector3d& to_center,
                                              const Eigen::Matrix3d& covariance, Eigen::Index count)
{
  Rigid_motion motion;
  if(count > 1)
  {
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

/// The rigid motion that best maps `from` onto `to` (k×3 each) in the least
/// squares sense (Kabsch). With one point, or points on a line, the rotation
/// is underdetermined in at least one direction; the closest rotation to the
/// identity compatible with the data is returned by the SVD, and a single
/// point gives a pure translation.
inline Rigid_motion fit_rigid_motion(const Eigen::Matrix<double, Eigen::Dynamic, 3>& from,
                                     const Eigen::Matrix<double, Eigen::Dynamic, 3>& to)
{
  const Eigen::RowVector3d from_center = from.colwise().mean();
  const Eigen::RowVector3d to_center = to.colwise().mean();
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  if(from.rows() > 1)
    covariance = (from.rowwise() - from_center).transpose() * (to.rowwise() - to_center);
  return rigid_motion_from_moments(from_center, to_center, covariance, from.rows());
}

} // namespace Deformation
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_RIGID_FIT_H

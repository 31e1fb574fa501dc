// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_CONSTRAINT_PRODUCTS_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_CONSTRAINT_PRODUCTS_H

#include <CGAL/Spectral_deformation/internal/Deformation/Constraint_set.h>
#include <CGAL/Spectral_deformation/internal/Deformation/rigid_fit.h>
#include <CGAL/Spectral_deformation/internal/Mesh/Triangle_arrays.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace Spectral_deformation {
namespace internal {
namespace Deformation {

using Mesh::Positions;

/// The product H_cᵀ y of the constrained rows H_c of the basis (k×m) with the
/// smooth targets y (k×3) of `smooth_targets()`, per target change at a cost
/// that grows with the number of constrained vertices only through their
/// rigid fits, not through the rows of the basis.
///
/// The smooth target of vertex i of a group is y_i = R s_i + t + r_i, with
/// (R, t) the rigid motion that best carries the group's rest positions v to
/// its targets c, s the smooth rest positions and r_i = c_i − R v_i − t the
/// non-rigid part of the target. Hence
/// H_cᵀ y = Σ_g (S_g Rᵀ + q_g tᵀ) + Σ_i h_i r_iᵀ, with S_g = Σ_{i∈g} h_i s_iᵀ
/// (m×3) and q_g = Σ_{i∈g} h_i (m) computed once per constraint set. The
/// residuals at the level of round-off of the group's coordinates are left
/// out of the last sum: the fixed ring and rigidly dragged handles cost
/// their rigid fit only; other targets cost their rows of the basis, as
/// they did before.
class Constraint_products
{
public:
  /// Per constraint set: `constrained_rows` the rows of the basis of the
  /// constrained vertices of `set` (in its order), `rest` and `smooth_rest`
  /// the rest positions of the detailed and of the smooth mesh.
  void initialize(const Constraint_set& set, const Eigen::MatrixXd& constrained_rows, const Positions& rest,
                  const Positions& smooth_rest)
  {
    m_groups.clear();
    m_groups.resize(set.groups.size());
    for(std::size_t g = 0; g < set.groups.size(); ++g)
    {
      const std::vector<int>& group = set.groups[g];
      Group& data = m_groups[g];
      data.rest.resize(static_cast<Eigen::Index>(group.size()), 3);
      Positions smooth(static_cast<Eigen::Index>(group.size()), 3);
      Eigen::MatrixXd rows(static_cast<Eigen::Index>(group.size()), constrained_rows.cols());
      for(std::size_t k = 0; k < group.size(); ++k)
      {
        const int vertex = set.constrained[static_cast<std::size_t>(group[k])];
        data.rest.row(static_cast<Eigen::Index>(k)) = rest.row(vertex);
        smooth.row(static_cast<Eigen::Index>(k)) = smooth_rest.row(vertex);
        rows.row(static_cast<Eigen::Index>(k)) = constrained_rows.row(group[k]);
      }
      data.smooth_moment = rows.transpose() * smooth;
      data.row_sum = rows.colwise().sum().transpose();
      data.smooth_center = group.empty() ? Eigen::RowVector3d::Zero() : Eigen::RowVector3d(smooth.colwise().mean());
      data.rest_magnitude = group.empty() ? 0.0 : data.rest.cwiseAbs().maxCoeff();
    }
  }

  /// H_cᵀ y for the `targets` of the constrained vertices (one row each, in
  /// the order of `set`); `set` and `constrained_rows` those of `initialize()`.
  Eigen::MatrixXd product(const Constraint_set& set, const Eigen::MatrixXd& constrained_rows,
                          const Positions& targets) const
  {
    const Eigen::MatrixXd& H = constrained_rows;
    Eigen::MatrixXd result = Eigen::MatrixXd::Zero(H.cols(), 3);
    std::vector<int> non_rigid;
    Positions residuals(targets.rows(), 3);
    for(std::size_t g = 0; g < set.groups.size(); ++g)
    {
      const std::vector<int>& group = set.groups[g];
      const Group& data = m_groups[g];
      Positions to(static_cast<Eigen::Index>(group.size()), 3);
      for(std::size_t k = 0; k < group.size(); ++k)
        to.row(static_cast<Eigen::Index>(k)) = targets.row(group[k]);
      const Rigid_motion motion = fit_rigid_motion(data.rest, to);
      result.noalias() += data.smooth_moment * motion.rotation.transpose();
      result.noalias() += data.row_sum * motion.translation.transpose();
      // Round-off of the coordinates, with a margin for the fit's own.
      const double negligible =
          64 * std::numeric_limits<double>::epsilon() * (std::max)(data.rest_magnitude, to.cwiseAbs().maxCoeff());
      for(std::size_t k = 0; k < group.size(); ++k)
      {
        const Eigen::RowVector3d r = to.row(static_cast<Eigen::Index>(k)) - motion.apply(data.rest.row(static_cast<Eigen::Index>(k)));
        if(!(r.cwiseAbs().maxCoeff() <= negligible))
        {
          residuals.row(static_cast<Eigen::Index>(non_rigid.size())) = r;
          non_rigid.push_back(group[k]);
        }
      }
    }
    if(!non_rigid.empty())
      result.noalias() += H(non_rigid, Eigen::all).transpose() * residuals.topRows(static_cast<Eigen::Index>(non_rigid.size()));
    return result;
  }

  /// The rigid motion that best carries the smooth rest positions s of
  /// group `g` of the set of `initialize()` to its smooth positions
  /// H_g `coefficients` (`fit_rigid_motion()`), from S_g and q_g: the
  /// covariance Σ (s_i − s̄)ᵀ(x_i − x̄) is S_gᵀ c − k s̄ᵀ x̄, x̄ = q_gᵀ c / k,
  /// so the cost does not grow with the size of the group.
  Rigid_motion smooth_motion(std::size_t g, const Eigen::MatrixXd& coefficients) const
  {
    const Group& data = m_groups[g];
    const Eigen::Index count = data.rest.rows();
    if(count == 0)
      return Rigid_motion();
    const Eigen::RowVector3d to_center = (data.row_sum.transpose() * coefficients) / double(count);
    const Eigen::Matrix3d covariance = data.smooth_moment.transpose() * coefficients -
                                       double(count) * data.smooth_center.transpose() * to_center;
    return rigid_motion_from_moments(data.smooth_center, to_center, covariance, count);
  }

private:
  struct Group
  {
    Positions rest;                // rest positions of its vertices
    Eigen::MatrixXd smooth_moment; // S_g
    Eigen::VectorXd row_sum;       // q_g
    Eigen::RowVector3d smooth_center = Eigen::RowVector3d::Zero(); // s̄
    double rest_magnitude = 0;
  };

  std::vector<Group> m_groups;
};

/// Targets of the smooth mesh (DESIGN rule 6): the rigid motion that best
/// carries each group from its rest positions `rest` to its `targets` (one
/// row per constrained vertex) carries the smooth rest positions `smooth`,
/// plus the non-rigid part of the detailed targets. Putting the detailed
/// targets on the smooth mesh instead shears rotated handles.
inline Positions smooth_targets(const Constraint_set& set, const Positions& rest, const Positions& smooth,
                                const Positions& targets)
{
  Positions result(targets.rows(), 3);
  for(const std::vector<int>& group : set.groups)
  {
    Positions from(static_cast<Eigen::Index>(group.size()), 3), to(from.rows(), 3);
    for(std::size_t g = 0; g < group.size(); ++g)
    {
      from.row(static_cast<Eigen::Index>(g)) = rest.row(set.constrained[static_cast<std::size_t>(group[g])]);
      to.row(static_cast<Eigen::Index>(g)) = targets.row(group[g]);
    }
    const Rigid_motion motion = fit_rigid_motion(from, to);
    for(std::size_t g = 0; g < group.size(); ++g)
    {
      const int i = set.constrained[static_cast<std::size_t>(group[g])];
      const Eigen::RowVector3d residual = to.row(static_cast<Eigen::Index>(g)) - motion.apply(rest.row(i));
      result.row(group[g]) = motion.apply(smooth.row(i)) + residual;
    }
  }
  return result;
}

} // namespace Deformation
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_CONSTRAINT_PRODUCTS_H

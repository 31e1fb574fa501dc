// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_TARGET_STAGES_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_TARGET_STAGES_H

#include <CGAL/Spectral_deformation/internal/Deformation/Constraint_set.h>
#include <CGAL/Spectral_deformation/internal/Deformation/rigid_fit.h>

#include <Eigen/Dense>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Spectral_deformation {
namespace internal {
namespace Deformation {

using Mesh::Positions;

/// The largest number of stages `intermediate_targets()` makes: a stage of
/// one degree for a half turn.
constexpr int max_stages = 180;

/// Intermediate targets on the way to targets that turn a group of control
/// vertices by a large angle from where the smooth mesh holds it now.
///
/// The iteration goes from the shape it starts from to a nearby fixed point
/// of its energy. A handle turned far in one call makes the first solve, with
/// the rotations of the current shape, squash the region between the handle
/// and the fixed vertices, and the fixed point near that squashed shape can
/// be folded (a cylinder bent by 120°). Moving the targets there along the
/// rigid path of each group, in stages that turn no group by more than
/// `stage_angle`, each stage starting from the result of the last, keeps
/// every solve close to the rotations it fits, as incremental loading does
/// in nonlinear elasticity.
///
/// For each group of control vertices (the fixed ring does not move), the
/// motion (R₀, t₀) is fitted from the smooth rest positions of the group to
/// its current smooth positions (its rows of the basis times the
/// coefficients), and
/// (R₁, t₁) from its rest positions to its `targets` (with the non-rigid
/// remainder r_i). Stage s of S carries the group by the rotation
/// exp(τ log(R₁R₀ᵀ)) R₀, τ = s/S, about its centroid moved a fraction τ of
/// the way, plus τ r_i. S is the smallest count that keeps every group's
/// turn per stage at most `stage_angle`; the result holds the S − 1 stages
/// before the targets themselves (none when S ≤ 1), S at most
/// `max_stages`. Translations alone are not staged.
///
/// `start_motion(g)` is the rigid motion (R₀, t₀) of group g of `set`
/// (`Constraint_products::smooth_motion()`, which does not read the rows of
/// the basis); `rest` the rest positions of the region's detailed mesh,
/// `targets` one row per constrained vertex of `set`.
template <class Start_motion>
inline std::vector<Positions> intermediate_targets(const Constraint_set& set, const Start_motion& start_motion,
                                                   const Positions& rest, const Positions& targets,
                                                   double stage_angle)
{
  std::vector<Positions> stages;
  if(!(stage_angle > 0))
    return stages;

  struct Path
  {
    const std::vector<int>* group = nullptr;
    Positions detailed_rest;
    Eigen::Matrix3d start_rotation;
    Eigen::AngleAxisd turn;
    Eigen::Vector3d centroid, start_centroid, end_centroid;
    Positions remainder;
  };
  std::vector<Path> paths;
  double largest_turn = 0;
  for(std::size_t g = 0; g < set.groups.size(); ++g)
  {
    const std::vector<int>& group = set.groups[g];
    if(group.empty() || static_cast<std::size_t>(group.front()) < set.number_of_fixed)
      continue;
    const Eigen::Index size = static_cast<Eigen::Index>(group.size());
    Path path;
    path.group = &group;
    path.detailed_rest.resize(size, 3);
    Positions to(size, 3);
    for(Eigen::Index k = 0; k < size; ++k)
    {
      const int position = group[static_cast<std::size_t>(k)];
      path.detailed_rest.row(k) = rest.row(set.constrained[static_cast<std::size_t>(position)]);
      to.row(k) = targets.row(position);
    }
    const Rigid_motion start = start_motion(g);
    const Rigid_motion end = fit_rigid_motion(path.detailed_rest, to);
    path.start_rotation = start.rotation;
    path.turn = Eigen::AngleAxisd(Eigen::Matrix3d(end.rotation * start.rotation.transpose()));
    path.centroid = path.detailed_rest.colwise().mean().transpose();
    path.start_centroid = start.rotation * path.centroid + start.translation;
    path.end_centroid = end.rotation * path.centroid + end.translation;
    path.remainder = to;
    for(Eigen::Index k = 0; k < size; ++k)
      path.remainder.row(k) -= end.apply(path.detailed_rest.row(k));
    if(!std::isfinite(path.turn.angle()))
      return stages;
    largest_turn = (std::max)(largest_turn, std::abs(path.turn.angle()));
    paths.push_back(std::move(path));
  }
  // A turn within a hundredth of a stage of a whole number of stages (a
  // handle turned by 120° with stages of 30°, fitted to rounding) takes
  // that number. Turns are at most 180°, and stages below 1° buy nothing:
  // at most `max_stages`, whatever tiny angle is asked for.
  const double stages_needed = std::ceil(largest_turn / stage_angle - 0.01);
  const int count = static_cast<int>((std::min)(stages_needed, double(max_stages)));
  for(int s = 1; s < count; ++s)
  {
    const double fraction = double(s) / double(count);
    Positions stage = targets;
    for(const Path& path : paths)
    {
      const Eigen::Matrix3d rotation =
          Eigen::AngleAxisd(fraction * path.turn.angle(), path.turn.axis()).toRotationMatrix() * path.start_rotation;
      const Eigen::Vector3d centroid = path.start_centroid + fraction * (path.end_centroid - path.start_centroid);
      const Eigen::Vector3d translation = centroid - rotation * path.centroid;
      for(std::size_t k = 0; k < path.group->size(); ++k)
      {
        const Eigen::Index row = static_cast<Eigen::Index>(k);
        stage.row((*path.group)[k]) =
            (rotation * path.detailed_rest.row(row).transpose() + translation).transpose() +
            fraction * path.remainder.row(row);
      }
    }
    stages.push_back(std::move(stage));
  }
  return stages;
}

/// As above, with (R₀, t₀) fitted from the smooth rest positions of each
/// group to its rows of the basis, `constrained_rows` (one per constrained
/// vertex of `set`), times `coefficients`: the definition that
/// `Constraint_products::smooth_motion()` computes without those rows.
inline std::vector<Positions> intermediate_targets(const Constraint_set& set, const Eigen::MatrixXd& constrained_rows,
                                                   const Eigen::MatrixXd& coefficients, const Positions& rest,
                                                   const Positions& smooth_rest, const Positions& targets,
                                                   double stage_angle)
{
  auto start_motion = [&](std::size_t g) {
    const std::vector<int>& group = set.groups[g];
    const Eigen::Index size = static_cast<Eigen::Index>(group.size());
    Positions smooth(size, 3);
    Eigen::MatrixXd rows(size, constrained_rows.cols());
    for(Eigen::Index k = 0; k < size; ++k)
    {
      const int position = group[static_cast<std::size_t>(k)];
      smooth.row(k) = smooth_rest.row(set.constrained[static_cast<std::size_t>(position)]);
      rows.row(k) = constrained_rows.row(position);
    }
    const Positions now = rows * coefficients;
    return fit_rigid_motion(smooth, now);
  };
  return intermediate_targets(set, start_motion, rest, targets, stage_angle);
}

} // namespace Deformation
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_TARGET_STAGES_H

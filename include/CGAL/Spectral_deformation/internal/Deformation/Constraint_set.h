// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_CONSTRAINT_SET_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_CONSTRAINT_SET_H

#include <CGAL/Spectral_deformation/Spectral_deformation_error.h>
#include <CGAL/Spectral_deformation/internal/Mesh/Region.h>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Spectral_deformation {
namespace internal {
namespace Deformation {

using Mesh::Positions;
using Mesh::Region_geometry;
using Mesh::Triangles;

/// The constrained vertices of a region: the fixed ring first, then the
/// control vertices (local indices), and their groups, each moved by one
/// rigid motion: the fixed ring, and every connected set of control
/// vertices (positions in `constrained`).
struct Constraint_set
{
  std::vector<int> constrained;
  std::size_t number_of_fixed = 0;
  std::vector<std::vector<int>> groups;

  std::size_t size() const { return constrained.size(); }
};

/// One flag per vertex of `region`: whether `set` constrains it (the
/// prescribed unknowns of a Dirichlet system).
inline std::vector<char> prescribed_flags(const Region_geometry& region, const Constraint_set& set)
{
  std::vector<char> prescribed(region.is_fixed.size(), 0);
  for(int i : set.constrained)
    prescribed[static_cast<std::size_t>(i)] = 1;
  return prescribed;
}

/// Groups every connected set of control vertices (positions from
/// `number_of_fixed` in `constrained`), by union-find over the edges of
/// `triangles` joining two of them.
inline std::vector<std::vector<int>> control_vertex_groups(const Triangles& triangles,
                                                         const std::vector<int>& constrained,
                                                         std::size_t number_of_fixed,
                                                         Eigen::Index number_of_vertices)
{
  std::vector<int> position(static_cast<std::size_t>(number_of_vertices), -1);
  for(std::size_t k = number_of_fixed; k < constrained.size(); ++k)
    position[static_cast<std::size_t>(constrained[k])] = static_cast<int>(k);
  std::vector<int> parent(constrained.size());
  for(std::size_t k = 0; k < parent.size(); ++k)
    parent[k] = static_cast<int>(k);
  auto find = [&parent](int k) {
    while(parent[static_cast<std::size_t>(k)] != k)
      k = parent[static_cast<std::size_t>(k)] = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(k)])];
    return k;
  };
  for(Eigen::Index f = 0; f < triangles.rows(); ++f)
    for(int e = 0; e < 3; ++e)
    {
      const int a = position[static_cast<std::size_t>(triangles(f, e))];
      const int b = position[static_cast<std::size_t>(triangles(f, (e + 1) % 3))];
      if(a >= 0 && b >= 0)
        parent[static_cast<std::size_t>(find(a))] = find(b);
    }
  std::vector<std::vector<int>> groups;
  std::vector<int> group_of_root(constrained.size(), -1);
  for(std::size_t k = number_of_fixed; k < constrained.size(); ++k)
  {
    const std::size_t root = static_cast<std::size_t>(find(static_cast<int>(k)));
    if(group_of_root[root] < 0)
    {
      group_of_root[root] = static_cast<int>(groups.size());
      groups.emplace_back();
    }
    groups[static_cast<std::size_t>(group_of_root[root])].push_back(static_cast<int>(k));
  }
  return groups;
}

/// The constraint set of `region` with the local vertices for which
/// `is_control(i)` holds as control vertices. Throws
/// `Spectral_deformation_error` (`INVALID_ARGUMENT`) when there is no
/// constraint at all or a connected part of the region has none.
template <class IsControl>
Constraint_set make_constraint_set(const Region_geometry& region, const IsControl& is_control)
{
  typedef Spectral_deformation_error Error;
  Constraint_set set;
  const std::size_t n = region.is_fixed.size();
  for(std::size_t i = 0; i < n; ++i)
    if(region.is_fixed[i])
      set.constrained.push_back(static_cast<int>(i));
  set.number_of_fixed = set.constrained.size();
  for(std::size_t i = 0; i < n; ++i)
    if(!region.is_fixed[i] && is_control(i))
      set.constrained.push_back(static_cast<int>(i));
  if(set.constrained.empty())
    throw Error(Error::INVALID_ARGUMENT,
                "no constraint: the region of interest is the whole mesh and has no control vertex");

  std::vector<char> has_constraint(static_cast<std::size_t>(region.number_of_components), 0);
  for(int i : set.constrained)
    has_constraint[static_cast<std::size_t>(region.component[static_cast<std::size_t>(i)])] = 1;
  for(char c : has_constraint)
    if(!c)
      throw Error(Error::INVALID_ARGUMENT,
                  "a connected part of the region of interest has neither a control vertex "
                  "nor a fixed neighbour: its position would be undetermined");

  if(set.number_of_fixed > 0)
  {
    set.groups.emplace_back();
    for(std::size_t k = 0; k < set.number_of_fixed; ++k)
      set.groups.back().push_back(static_cast<int>(k));
  }
  for(std::vector<int>& group : control_vertex_groups(region.arrays.triangles, set.constrained,
                                                      set.number_of_fixed, region.number_of_vertices()))
    set.groups.push_back(std::move(group));
  return set;
}

} // namespace Deformation
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_CONSTRAINT_SET_H

// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_FACE_PATCHES_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_FACE_PATCHES_H

#include <CGAL/Spectral_deformation/internal/Mesh/Dual_mesh_operator.h>
#include <CGAL/Spectral_deformation/internal/Mesh/Triangle_arrays.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cstddef>
#include <functional>
#include <limits>
#include <queue>
#include <utility>
#include <vector>

namespace CGAL {
namespace Spectral_deformation {
namespace internal {
namespace Deformation {

using Mesh::Dual_mesh_operator;
using Mesh::Positions;
using Mesh::Triangles;

/// About `count` faces spread over the surface: farthest point sampling of
/// the face `centroids` over a regular subsample of the faces, so that the
/// cost stays count × candidates whatever the size of the mesh.
inline std::vector<int> farthest_point_seeds(const Positions& centroids, std::size_t faces, std::size_t count)
{
  const std::size_t candidate_count = (std::min)(faces, 32 * count);
  const std::size_t stride = faces / candidate_count;
  std::vector<int> candidates(candidate_count);
  // The candidates' centroids side by side: every seed reads all of them.
  Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> points(static_cast<Eigen::Index>(candidate_count), 3);
  for(std::size_t i = 0; i < candidate_count; ++i)
  {
    candidates[i] = static_cast<int>(i * stride);
    points.row(static_cast<Eigen::Index>(i)) = centroids.row(candidates[i]);
  }
  std::vector<double> distance(candidate_count, std::numeric_limits<double>::infinity());
  std::vector<int> seeds;
  seeds.reserve(count);
  std::size_t next = 0;
  for(std::size_t s = 0; s < count; ++s)
  {
    const int seed = candidates[next];
    seeds.push_back(seed);
    const Eigen::RowVector3d p = centroids.row(seed);
    double farthest = -1;
    for(std::size_t i = 0; i < candidate_count; ++i)
    {
      distance[i] = (std::min)(distance[i], (points.row(static_cast<Eigen::Index>(i)) - p).squaredNorm());
      if(distance[i] > farthest)
      {
        farthest = distance[i];
        next = i;
      }
    }
    if(!(farthest > 0))
      break;
  }
  return seeds;
}

/// The patch of every face of `dual`: the patches grow from the `seeds`
/// over the dual graph by the distance between neighbouring face
/// `centroids` (each face joins the seed nearest along the surface), so that
/// patches are about as large on the surface where the triangles are small
/// as where they are large; a part of the surface that no seed reaches
/// becomes a patch of its own. Returns the number of patches.
inline int grow_patches(const Dual_mesh_operator& dual, const Positions& centroids, const std::vector<int>& seeds,
                        std::vector<int>& patch_of_face)
{
  const std::size_t faces = static_cast<std::size_t>(dual.number_of_faces());
  patch_of_face.assign(faces, -1);
  std::vector<double> distance(faces, std::numeric_limits<double>::infinity());
  typedef std::pair<double, int> Entry;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
  int patches = 0;
  for(int seed : seeds)
    if(patch_of_face[static_cast<std::size_t>(seed)] < 0)
    {
      patch_of_face[static_cast<std::size_t>(seed)] = patches++;
      distance[static_cast<std::size_t>(seed)] = 0;
      queue.emplace(0.0, seed);
    }
  const Triangles& neighbours = dual.neighbours();
  auto grow = [&]() {
    while(!queue.empty())
    {
      const auto [d, f] = queue.top();
      queue.pop();
      if(d > distance[static_cast<std::size_t>(f)])
        continue;
      for(int j = 0; j < 3; ++j)
      {
        const int g = neighbours(f, j);
        if(g < 0)
          continue;
        const double through_f = d + (centroids.row(g) - centroids.row(f)).norm();
        if(through_f < distance[static_cast<std::size_t>(g)])
        {
          distance[static_cast<std::size_t>(g)] = through_f;
          patch_of_face[static_cast<std::size_t>(g)] = patch_of_face[static_cast<std::size_t>(f)];
          queue.emplace(through_f, g);
        }
      }
    }
  };
  grow();
  for(std::size_t f = 0; f < faces; ++f)
    if(patch_of_face[f] < 0)
    {
      patch_of_face[f] = patches++;
      distance[f] = 0;
      queue.emplace(0.0, static_cast<int>(f));
      grow();
    }
  return patches;
}

/// The faces of `dual` grouped into about `count` patches of neighbouring
/// faces: seeds spread by farthest point sampling of the face `centroids`
/// (on a regular subsample of them), then grown over the dual graph
/// (`grow_patches()`), so that a patch never jumps across a gap between two
/// parts of the surface. A part of the surface that no seed reaches is a
/// patch of its own. The grouping is made at the first call of
/// `of_face()`, so that a region with no more rows or vertices than patches
/// grows none, and kept: the dual rows and the vertices are grouped from
/// the same patches of faces (`cluster_dual_rows()`, `cluster_vertices()`).
/// Not for concurrent use; `dual` and `centroids` must outlive the object.
class Face_patches
{
public:
  Face_patches(const Dual_mesh_operator& dual, const Positions& centroids, std::size_t count)
      : m_dual(&dual), m_centroids(&centroids), m_count((std::max<std::size_t>)(count, 1))
  {}
  Face_patches(const Dual_mesh_operator&, Positions&&, std::size_t) = delete;

  /// The dual mesh whose faces are grouped.
  const Dual_mesh_operator& dual() const { return *m_dual; }
  /// The number of patches asked for (at least 1).
  std::size_t requested() const { return m_count; }

  /// The patch of every face, numbered from 0 (not every number need hold a row).
  const std::vector<int>& of_face() const
  {
    if(m_patch_of_face.empty() && m_dual->number_of_faces() > 0)
    {
      const std::vector<int> seeds =
          farthest_point_seeds(*m_centroids, static_cast<std::size_t>(m_dual->number_of_faces()), m_count);
      // Kept only once complete: a grouping cut short by an exception is not reused.
      std::vector<int> patch_of_face;
      const int patches = grow_patches(*m_dual, *m_centroids, seeds, patch_of_face);
      m_patch_of_face.swap(patch_of_face);
      m_patches = patches;
    }
    return m_patch_of_face;
  }

  /// The number of patches of `of_face()`.
  int size() const
  {
    of_face();
    return m_patches;
  }

private:
  const Dual_mesh_operator* m_dual;
  const Positions* m_centroids;
  std::size_t m_count;
  mutable std::vector<int> m_patch_of_face;
  mutable int m_patches = 0;
};

/// Groups the rows of `dual` (the dual vertices with three neighbours) into
/// the patches of their faces (`Face_patches`). Returns the patch of each
/// row, numbered from 0 without gaps; at least as many patches requested as
/// rows give every row its own patch.
inline std::vector<int> cluster_dual_rows(const Face_patches& patches)
{
  const std::vector<int>& row_faces = patches.dual().row_faces();
  const std::size_t rows = row_faces.size();
  std::vector<int> result(rows, 0);
  if(patches.requested() >= rows)
  {
    for(std::size_t r = 0; r < rows; ++r)
      result[r] = static_cast<int>(r);
    return result;
  }
  const std::vector<int>& patch_of_face = patches.of_face();
  // Only the rows carry rotations: number the patches that hold a row.
  std::vector<int> renumbered(static_cast<std::size_t>(patches.size()), -1);
  int used = 0;
  for(std::size_t r = 0; r < rows; ++r)
  {
    int& id = renumbered[static_cast<std::size_t>(patch_of_face[static_cast<std::size_t>(row_faces[r])])];
    if(id < 0)
      id = used++;
    result[r] = id;
  }
  return result;
}

/// `cluster_dual_rows()` with about `count` patches grown over the faces of
/// `dual` from their `centroids`.
inline std::vector<int> cluster_dual_rows(const Dual_mesh_operator& dual, const Positions& centroids,
                                          std::size_t count)
{
  return cluster_dual_rows(Face_patches(dual, centroids, count));
}

/// Groups the `n` vertices of the faces of `dual` into the patches of their
/// faces (`Face_patches`): every vertex joins the patch of one of its
/// faces. Returns the patch of each vertex, numbered from 0 without gaps (-1
/// for a vertex of no face); at least `n` patches requested give every
/// vertex its own patch.
inline std::vector<int> cluster_vertices(const Face_patches& patches, Eigen::Index n)
{
  std::vector<int> result(static_cast<std::size_t>(n), -1);
  const Triangles& triangles = patches.dual().triangles();
  if(patches.requested() >= static_cast<std::size_t>(n))
  {
    for(Eigen::Index f = 0; f < triangles.rows(); ++f)
      for(int k = 0; k < 3; ++k)
        result[static_cast<std::size_t>(triangles(f, k))] = triangles(f, k);
  }
  else
  {
    const std::vector<int>& patch_of_face = patches.of_face();
    for(Eigen::Index f = 0; f < triangles.rows(); ++f)
      for(int k = 0; k < 3; ++k)
        result[static_cast<std::size_t>(triangles(f, k))] = patch_of_face[static_cast<std::size_t>(f)];
  }
  std::vector<int> renumbered(static_cast<std::size_t>(n), -1);
  int used = 0;
  for(int& patch : result)
    if(patch >= 0)
    {
      int& id = renumbered[static_cast<std::size_t>(patch)];
      if(id < 0)
        id = used++;
      patch = id;
    }
  return result;
}

/// `cluster_vertices()` with about `count` patches grown over the faces of
/// `dual` from their `centroids`.
inline std::vector<int> cluster_vertices(const Dual_mesh_operator& dual, const Positions& centroids,
                                         Eigen::Index n, std::size_t count)
{
  return cluster_vertices(Face_patches(dual, centroids, count), n);
}

} // namespace Deformation
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_FACE_PATCHES_H

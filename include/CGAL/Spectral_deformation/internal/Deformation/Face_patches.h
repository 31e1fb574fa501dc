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
#include <cmath>
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

/// The farthest point sampling of `points` (rows), started at row 0: each
/// point taken is the one farthest from those taken before (the first of
/// equally far ones), until `count` are taken or the farthest is at
/// distance 0.
///
/// Each new point lowers the distance only of the points closer to it than
/// the largest distance so far, so it visits only the cells of a grid
/// within that radius, and a heap of (distance, index) entries finds the
/// next point. A sampling of thousands of seeds then reads each point a few
/// times instead of once per seed. (Neither CGAL nor Eigen samples points
/// by farthest point sampling; a grid of cells is all the search needs.)
/// The distances and ties are those of the plain loop over all points, so
/// the same points are taken.
class Farthest_point_sampler
{
public:
  typedef Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> Points;

  explicit Farthest_point_sampler(Points points) : m_points(std::move(points))
  {
    const Eigen::Index n = m_points.rows();
    if(n == 0)
      return;
    m_low = m_points.colwise().minCoeff();
    const Eigen::RowVector3d extent = m_points.colwise().maxCoeff() - m_low;
    // Cubic cells, about 4 n of them in the bounding box; a flat or thin
    // set of points counts at least a thousandth of the diagonal per axis,
    // so that the cells stay few.
    const double floor = (std::max)(1e-3 * extent.norm(), std::numeric_limits<double>::min());
    const Eigen::RowVector3d sides = extent.cwiseMax(floor);
    const double cell = std::cbrt(sides.prod() / (4.0 * static_cast<double>(n)));
    if(cell > 0 && std::isfinite(cell)) // else one cell: the points coincide
    {
      m_cell = cell;
      for(int d = 0; d < 3; ++d)
        m_dims[d] = static_cast<int>(std::min<double>(sides[d] / m_cell, 4.0 * static_cast<double>(n))) + 1;
    }
    const std::size_t cells =
        static_cast<std::size_t>(m_dims[0]) * static_cast<std::size_t>(m_dims[1]) * static_cast<std::size_t>(m_dims[2]);
    // The indices of the points sorted by cell (a counting sort): the
    // points of a run of cells along the last axis are consecutive.
    std::vector<std::size_t> cell_of(static_cast<std::size_t>(n));
    m_first.assign(cells + 1, 0);
    for(Eigen::Index i = 0; i < n; ++i)
    {
      cell_of[static_cast<std::size_t>(i)] = cell_index(m_points.row(i));
      ++m_first[cell_of[static_cast<std::size_t>(i)] + 1];
    }
    for(std::size_t c = 1; c <= cells; ++c)
      m_first[c] += m_first[c - 1];
    m_order.resize(static_cast<std::size_t>(n));
    std::vector<int> fill(m_first.begin(), m_first.end() - 1);
    for(Eigen::Index i = 0; i < n; ++i)
      m_order[static_cast<std::size_t>(fill[cell_of[static_cast<std::size_t>(i)]]++)] = static_cast<int>(i);
  }

  /// The indices of the points taken, in the order they were taken.
  std::vector<int> sample(std::size_t count) const
  {
    const std::size_t n = static_cast<std::size_t>(m_points.rows());
    std::vector<int> taken;
    if(n == 0 || count == 0)
      return taken;
    taken.reserve(count);
    std::vector<double> distance(n, std::numeric_limits<double>::infinity());
    // Entries (distance, -index): the largest is the farthest point and,
    // among equally far ones, the first. An entry whose distance is no
    // longer the point's is stale and dropped when it comes up.
    typedef std::pair<double, int> Entry;
    std::vector<Entry> heap;
    int next = 0;
    for(std::size_t s = 0; s < count; ++s)
    {
      taken.push_back(next);
      const Eigen::RowVector3d p = m_points.row(next);
      if(s == 0)
      {
        for(std::size_t i = 0; i < n; ++i)
          distance[i] = (m_points.row(static_cast<Eigen::Index>(i)) - p).squaredNorm();
        heap.reserve(2 * n);
        for(std::size_t i = 0; i < n; ++i)
          heap.emplace_back(distance[i], -static_cast<int>(i));
        std::make_heap(heap.begin(), heap.end());
      }
      else
      {
        // No distance exceeds the new point's, so only points within that
        // radius of it can come closer (one cell more for rounding).
        const double radius = std::sqrt(distance[static_cast<std::size_t>(next)]);
        int low[3], high[3];
        for(int d = 0; d < 3; ++d)
        {
          low[d] = (std::max)(0, cell_coordinate(p[d] - radius, d) - 1);
          high[d] = (std::min)(m_dims[d] - 1, cell_coordinate(p[d] + radius, d) + 1);
        }
        for(int x = low[0]; x <= high[0]; ++x)
          for(int y = low[1]; y <= high[1]; ++y)
          {
            const std::size_t row = (static_cast<std::size_t>(x) * static_cast<std::size_t>(m_dims[1]) +
                                     static_cast<std::size_t>(y)) *
                                    static_cast<std::size_t>(m_dims[2]);
            for(int k = m_first[row + static_cast<std::size_t>(low[2])];
                k < m_first[row + static_cast<std::size_t>(high[2]) + 1]; ++k)
            {
              const int i = m_order[static_cast<std::size_t>(k)];
              const double d = (m_points.row(i) - p).squaredNorm();
              if(d < distance[static_cast<std::size_t>(i)])
              {
                distance[static_cast<std::size_t>(i)] = d;
                heap.emplace_back(d, -i);
                std::push_heap(heap.begin(), heap.end());
              }
            }
          }
      }
      while(heap.front().first != distance[static_cast<std::size_t>(-heap.front().second)])
      {
        std::pop_heap(heap.begin(), heap.end());
        heap.pop_back();
      }
      if(!(heap.front().first > 0))
        break;
      next = -heap.front().second;
    }
    return taken;
  }

private:
  int cell_coordinate(double x, int d) const
  {
    const double c = std::floor((x - m_low[d]) / m_cell);
    return static_cast<int>(std::clamp(c, -1.0, static_cast<double>(m_dims[d])));
  }

  std::size_t cell_index(const Eigen::RowVector3d& p) const
  {
    std::size_t index = 0;
    for(int d = 0; d < 3; ++d)
      index = index * static_cast<std::size_t>(m_dims[d]) +
              static_cast<std::size_t>(std::clamp(cell_coordinate(p[d], d), 0, m_dims[d] - 1));
    return index;
  }

  Points m_points;
  Eigen::RowVector3d m_low = Eigen::RowVector3d::Zero();
  double m_cell = 1;
  int m_dims[3] = {1, 1, 1};
  std::vector<int> m_first, m_order;
};

/// About `count` faces spread over the surface: farthest point sampling of
/// the face `centroids` over a regular subsample of the faces (32 per
/// seed), so that the cost does not grow with the size of the mesh.
inline std::vector<int> farthest_point_seeds(const Positions& centroids, std::size_t faces, std::size_t count)
{
  const std::size_t candidate_count = (std::min)(faces, 32 * count);
  if(candidate_count == 0)
    return {};
  const std::size_t stride = faces / candidate_count;
  Farthest_point_sampler::Points points(static_cast<Eigen::Index>(candidate_count), 3);
  for(std::size_t i = 0; i < candidate_count; ++i)
    points.row(static_cast<Eigen::Index>(i)) = centroids.row(static_cast<Eigen::Index>(i * stride));
  std::vector<int> seeds = Farthest_point_sampler(std::move(points)).sample(count);
  for(int& seed : seeds)
    seed *= static_cast<int>(stride);
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

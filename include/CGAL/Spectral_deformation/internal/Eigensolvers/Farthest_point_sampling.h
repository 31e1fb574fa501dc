// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_FARTHEST_POINT_SAMPLING_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_FARTHEST_POINT_SAMPLING_H

#include <CGAL/Spectral_deformation/internal/compiled_core.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <cstddef>
#include <functional>
#include <limits>
#include <queue>
#include <utility>
#include <vector>

namespace CGAL {
namespace Spectral_deformation {
namespace internal {
namespace Eigensolvers {

// The edges of a mesh as a graph weighted by edge length, in compressed rows.
// Distances along it (Dijkstra) stand in for geodesic distances: they are
// longer by at most the zig-zag of the edges, which only scales the supports
// of the sampled functions a little.
struct Edge_length_graph
{
  std::vector<Eigen::Index> offsets; // n + 1
  std::vector<Eigen::Index> neighbours;
  std::vector<double> lengths;

  Eigen::Index number_of_vertices() const
  {
    return offsets.empty() ? 0 : static_cast<Eigen::Index>(offsets.size()) - 1;
  }
};

// The graph of the off-diagonal pattern of a symmetric sparse matrix (the
// cotangent stiffness: its off-diagonal entries are the mesh edges, stored
// even when the cotangent weight is zero), with Euclidean edge lengths.
Edge_length_graph edge_length_graph(const Eigen::SparseMatrix<double>& pattern,
                                    const Eigen::Matrix<double, Eigen::Dynamic, 3>& positions);

// Dijkstra's search from one source, bounded by a radius, on a reusable
// distance array: `distances` holds +infinity everywhere on entry and on
// return; the vertices reached within `radius` are reported with their
// distance to `visit(vertex, distance)` in increasing order of distance.
class Bounded_dijkstra
{
public:
  explicit Bounded_dijkstra(const Edge_length_graph& graph)
    : m_graph(graph),
      m_distances(static_cast<std::size_t>(graph.number_of_vertices()),
                  std::numeric_limits<double>::infinity())
  {}

  template <class Visit>
  void run(Eigen::Index source, double radius, Visit&& visit)
  {
    typedef std::pair<double, Eigen::Index> Entry;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
    m_touched.clear();
    m_distances[static_cast<std::size_t>(source)] = 0.0;
    m_touched.push_back(source);
    queue.emplace(0.0, source);
    while(!queue.empty())
    {
      const Entry top = queue.top();
      queue.pop();
      const Eigen::Index v = top.second;
      if(top.first > m_distances[static_cast<std::size_t>(v)])
        continue; // a stale entry
      visit(v, top.first);
      for(Eigen::Index e = m_graph.offsets[static_cast<std::size_t>(v)];
          e < m_graph.offsets[static_cast<std::size_t>(v) + 1]; ++e)
      {
        const Eigen::Index w = m_graph.neighbours[static_cast<std::size_t>(e)];
        const double d = top.first + m_graph.lengths[static_cast<std::size_t>(e)];
        double& current = m_distances[static_cast<std::size_t>(w)];
        if(d < current && d <= radius)
        {
          if(current == std::numeric_limits<double>::infinity())
            m_touched.push_back(w);
          current = d;
          queue.emplace(d, w);
        }
      }
    }
    for(Eigen::Index v : m_touched)
      m_distances[static_cast<std::size_t>(v)] = std::numeric_limits<double>::infinity();
  }

private:
  const Edge_length_graph& m_graph;
  std::vector<double> m_distances;
  std::vector<Eigen::Index> m_touched;
};

// Farthest point sampling: each new sample is the vertex farthest (along the
// graph) from the samples chosen so far, the first one the vertex farthest
// from vertex 0. Every connected component gets a sample before any second
// one does (its vertices are infinitely far). After the call, `covering_radius`
// is the largest distance of a vertex to its nearest sample: every vertex lies
// within it of a sample, and samples are at least that far apart.
//
// Each new sample updates the distances only where it is nearer than the
// previous samples (a search that stops at its Voronoi cell), so the whole
// sampling costs about n log n times a small factor, not k n.
std::vector<Eigen::Index> farthest_point_samples(const Edge_length_graph& graph,
                                                 Eigen::Index count,
                                                 double& covering_radius);

} // namespace Eigensolvers
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#if CGAL_SSMD_CORE_DEFINITIONS
#include <CGAL/Spectral_deformation/internal/Eigensolvers/Farthest_point_sampling_impl.h>
#endif

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_FARTHEST_POINT_SAMPLING_H

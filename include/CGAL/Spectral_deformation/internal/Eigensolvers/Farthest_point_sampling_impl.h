// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_FARTHEST_POINT_SAMPLING_IMPL_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_FARTHEST_POINT_SAMPLING_IMPL_H

// The definitions of the functions declared in Farthest_point_sampling.h (see
// internal/compiled_core.h: the compiled core holds them).

#include <CGAL/Spectral_deformation/internal/Eigensolvers/Farthest_point_sampling.h>

namespace CGAL {
namespace Spectral_deformation {
namespace internal {
namespace Eigensolvers {

CGAL_SSMD_CORE_FUNCTION Edge_length_graph edge_length_graph(const Eigen::SparseMatrix<double>& pattern,
                                                            const Eigen::Matrix<double, Eigen::Dynamic, 3>& positions)
{
  Edge_length_graph graph;
  const Eigen::Index n = pattern.cols();
  graph.offsets.assign(static_cast<std::size_t>(n) + 1, 0);
  graph.neighbours.reserve(static_cast<std::size_t>(pattern.nonZeros()));
  graph.lengths.reserve(static_cast<std::size_t>(pattern.nonZeros()));
  for(Eigen::Index j = 0; j < n; ++j)
  {
    for(Eigen::SparseMatrix<double>::InnerIterator it(pattern, j); it; ++it)
    {
      if(it.row() == j)
        continue;
      graph.neighbours.push_back(it.row());
      graph.lengths.push_back((positions.row(it.row()) - positions.row(j)).norm());
    }
    graph.offsets[static_cast<std::size_t>(j) + 1] =
        static_cast<Eigen::Index>(graph.neighbours.size());
  }
  return graph;
}

CGAL_SSMD_CORE_FUNCTION std::vector<Eigen::Index> farthest_point_samples(const Edge_length_graph& graph,
                                                                         Eigen::Index count,
                                                                         double& covering_radius)
{
  const Eigen::Index n = graph.number_of_vertices();
  const double infinity = std::numeric_limits<double>::infinity();
  std::vector<double> nearest(static_cast<std::size_t>(n), infinity);
  std::vector<Eigen::Index> samples;
  covering_radius = 0.0;
  if(n == 0 || count <= 0)
    return samples;

  typedef std::pair<double, Eigen::Index> Entry;
  std::priority_queue<Entry> farthest; // max-heap with stale entries
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;

  // Lowers `nearest` around `source`; pushes the lowered vertices on `farthest`.
  auto add_sample = [&](Eigen::Index source) {
    samples.push_back(source);
    nearest[static_cast<std::size_t>(source)] = 0.0;
    queue.emplace(0.0, source);
    while(!queue.empty())
    {
      const Entry top = queue.top();
      queue.pop();
      const Eigen::Index v = top.second;
      if(top.first > nearest[static_cast<std::size_t>(v)])
        continue;
      farthest.emplace(top.first, v);
      for(Eigen::Index e = graph.offsets[static_cast<std::size_t>(v)];
          e < graph.offsets[static_cast<std::size_t>(v) + 1]; ++e)
      {
        const Eigen::Index w = graph.neighbours[static_cast<std::size_t>(e)];
        const double d = top.first + graph.lengths[static_cast<std::size_t>(e)];
        if(d < nearest[static_cast<std::size_t>(w)])
        {
          nearest[static_cast<std::size_t>(w)] = d;
          queue.emplace(d, w);
        }
      }
    }
  };

  // The farthest vertex from the current samples among the vertices reached
  // by them, -1 when all vertices are samples.
  auto next_farthest = [&](double& distance) -> Eigen::Index {
    while(!farthest.empty())
    {
      const Entry top = farthest.top();
      if(top.first != nearest[static_cast<std::size_t>(top.second)])
      {
        farthest.pop();
        continue;
      }
      distance = top.first;
      return top.first > 0.0 ? top.second : -1;
    }
    distance = 0.0;
    return -1;
  };

  // The first sample: the vertex farthest from vertex 0 in its component.
  {
    add_sample(0);
    double distance = 0.0;
    Eigen::Index first = 0;
    for(Eigen::Index v = 0; v < n; ++v)
      if(nearest[static_cast<std::size_t>(v)] != infinity &&
         nearest[static_cast<std::size_t>(v)] > distance)
      {
        distance = nearest[static_cast<std::size_t>(v)];
        first = v;
      }
    samples.clear();
    std::fill(nearest.begin(), nearest.end(), infinity);
    farthest = std::priority_queue<Entry>();
    add_sample(first);
  }

  // Components without a sample are found by a scan that resumes where it
  // stopped: once all have one, the scan costs nothing more.
  Eigen::Index unreached_scan = 0;
  while(static_cast<Eigen::Index>(samples.size()) < count)
  {
    while(unreached_scan < n && nearest[static_cast<std::size_t>(unreached_scan)] != infinity)
      ++unreached_scan;
    if(unreached_scan < n)
    {
      add_sample(unreached_scan);
      continue;
    }
    double distance = 0.0;
    const Eigen::Index v = next_farthest(distance);
    if(v < 0)
      break;
    add_sample(v);
  }
  while(unreached_scan < n && nearest[static_cast<std::size_t>(unreached_scan)] != infinity)
    ++unreached_scan;
  double distance = 0.0;
  next_farthest(distance);
  covering_radius = (unreached_scan < n) ? infinity : distance;
  return samples;
}

} // namespace Eigensolvers
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_FARTHEST_POINT_SAMPLING_IMPL_H

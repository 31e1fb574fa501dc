// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_PARTITION_OF_UNITY_SPACE_IMPL_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_PARTITION_OF_UNITY_SPACE_IMPL_H

// The definitions of the functions declared in Partition_of_unity_space.h (see
// internal/compiled_core.h: the compiled core holds them).

#include <CGAL/Spectral_deformation/internal/Eigensolvers/Partition_of_unity_space.h>

namespace CGAL {
namespace Spectral_deformation {
namespace internal {
namespace Eigensolvers {

CGAL_SSMD_CORE_FUNCTION double wendland_bump(double t)
{
  if(t >= 1.0)
    return 0.0;
  const double s = 1.0 - t;
  return s * s * s * s * (4.0 * t + 1.0);
}

CGAL_SSMD_CORE_FUNCTION std::vector<std::vector<Support_entry>>
                 sample_supports(const Edge_length_graph& graph, const std::vector<Eigen::Index>& samples, double radius)
{
  const Eigen::Index k = static_cast<Eigen::Index>(samples.size());
  std::vector<std::vector<Support_entry>> supports(static_cast<std::size_t>(k));

  Parallel_exception failure;
#ifdef _OPENMP
#pragma omp parallel if(graph.number_of_vertices() > parallel_loop_items)
#endif
  {
    std::unique_ptr<Bounded_dijkstra> search;
    failure.run([&] { search = std::make_unique<Bounded_dijkstra>(graph); });
#ifdef _OPENMP
#pragma omp for schedule(dynamic, 16)
#endif
    for(Eigen::Index s = 0; s < k; ++s)
      failure.run([&] {
        std::vector<Support_entry>& support = supports[static_cast<std::size_t>(s)];
        search->run(samples[static_cast<std::size_t>(s)], radius, [&](Eigen::Index v, double d) {
          const double bump = wendland_bump(d / radius);
          if(bump > 0.0)
            support.emplace_back(v, bump);
        });
        std::sort(support.begin(), support.end());
      });
  }
  failure.rethrow();
  return supports;
}

CGAL_SSMD_CORE_FUNCTION void support_tangent_planes(const std::vector<std::vector<Support_entry>>& supports,
                                                    const Eigen::Matrix<double, Eigen::Dynamic, 3>& positions, double radius,
                                                    std::vector<Eigen::Matrix<double, 3, 2>>& tangents,
                                                    std::vector<char>& has_linear)
{
  const Eigen::Index k = static_cast<Eigen::Index>(supports.size());
#ifdef _OPENMP
#pragma omp parallel for schedule(static) if(positions.rows() > parallel_loop_items)
#endif
  for(Eigen::Index s = 0; s < k; ++s)
  {
    const std::vector<Support_entry>& support = supports[static_cast<std::size_t>(s)];
    if(support.size() < 6)
      continue;
    double weight = 0.0;
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for(const Support_entry& e : support)
    {
      weight += e.second;
      mean += e.second * positions.row(e.first).transpose();
    }
    mean /= weight;
    Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
    for(const Support_entry& e : support)
    {
      const Eigen::Vector3d d = positions.row(e.first).transpose() - mean;
      covariance += e.second * d * d.transpose();
    }
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen;
    eigen.computeDirect(covariance / weight);
    // Spread along the second direction below 1 % of the radius: the
    // support is nearly a curve, and a second linear function would be
    // nearly a multiple of the first.
    if(!(eigen.eigenvalues()[1] > 1e-4 * radius * radius))
      continue;
    tangents[static_cast<std::size_t>(s)].col(0) = eigen.eigenvectors().col(2);
    tangents[static_cast<std::size_t>(s)].col(1) = eigen.eigenvectors().col(1);
    has_linear[static_cast<std::size_t>(s)] = 1;
  }
}

CGAL_SSMD_CORE_FUNCTION Eigen::SparseMatrix<double>
                 partition_of_unity_functions(const Edge_length_graph& graph,
                                              const Eigen::Matrix<double, Eigen::Dynamic, 3>& positions,
                                              const std::vector<Eigen::Index>& samples, double radius, bool linear)
{
  const Eigen::Index n = graph.number_of_vertices();
  const Eigen::Index k = static_cast<Eigen::Index>(samples.size());
  const std::vector<std::vector<Support_entry>> supports = sample_supports(graph, samples, radius);

  Eigen::VectorXd bump_sum = Eigen::VectorXd::Zero(n);
  for(const std::vector<Support_entry>& support : supports)
    for(const Support_entry& e : support)
      bump_sum[e.first] += e.second;
  if((bump_sum.array() <= 0.0).any())
    throw std::runtime_error("a vertex lies in no support of the sampled functions");

  std::vector<Eigen::Matrix<double, 3, 2>> tangents(static_cast<std::size_t>(k));
  std::vector<char> has_linear(static_cast<std::size_t>(k), 0);
  if(linear)
    support_tangent_planes(supports, positions, radius, tangents, has_linear);

  std::vector<Eigen::Index> first_column(static_cast<std::size_t>(k) + 1, 0);
  Eigen::Index entries = 0;
  for(Eigen::Index s = 0; s < k; ++s)
  {
    const Eigen::Index per_sample = has_linear[static_cast<std::size_t>(s)] ? 3 : 1;
    first_column[static_cast<std::size_t>(s) + 1] = first_column[static_cast<std::size_t>(s)] + per_sample;
    entries += per_sample * static_cast<Eigen::Index>(supports[static_cast<std::size_t>(s)].size());
  }
  const Eigen::Index columns = first_column.back();

  Eigen::SparseMatrix<double> functions(n, columns);
  functions.resizeNonZeros(entries);
  typedef Eigen::SparseMatrix<double>::StorageIndex Storage_index;
  Storage_index* outer = functions.outerIndexPtr();
  Storage_index* inner = functions.innerIndexPtr();
  double* values = functions.valuePtr();
  Eigen::Index position = 0;
  for(Eigen::Index s = 0; s < k; ++s)
  {
    const std::vector<Support_entry>& support = supports[static_cast<std::size_t>(s)];
    const Eigen::Vector3d center = positions.row(samples[static_cast<std::size_t>(s)]).transpose();
    const Eigen::Index per_sample = has_linear[static_cast<std::size_t>(s)] ? 3 : 1;
    for(Eigen::Index c = 0; c < per_sample; ++c)
    {
      outer[first_column[static_cast<std::size_t>(s)] + c] = static_cast<Storage_index>(position);
      for(const Support_entry& e : support)
      {
        double value = e.second / bump_sum[e.first];
        if(c > 0)
          value *= tangents[static_cast<std::size_t>(s)].col(c - 1).dot(
                       positions.row(e.first).transpose() - center) /
                   radius;
        inner[position] = static_cast<Storage_index>(e.first);
        values[position] = value;
        ++position;
      }
    }
  }
  outer[columns] = static_cast<Storage_index>(position);
  return functions;
}

} // namespace Eigensolvers
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_PARTITION_OF_UNITY_SPACE_IMPL_H

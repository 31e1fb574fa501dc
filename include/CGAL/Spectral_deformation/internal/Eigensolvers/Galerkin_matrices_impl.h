// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_GALERKIN_MATRICES_IMPL_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_GALERKIN_MATRICES_IMPL_H

// The definitions of the functions declared in Galerkin_matrices.h (see
// internal/compiled_core.h: the compiled core holds them).

#include <CGAL/Spectral_deformation/internal/Eigensolvers/Galerkin_matrices.h>

namespace CGAL {
namespace Spectral_deformation {
namespace internal {
namespace Eigensolvers {

CGAL_SSMD_CORE_FUNCTION std::vector<Eigen::Index> same_support_groups(const Eigen::SparseMatrix<double>& functions)
{
  typedef Eigen::SparseMatrix<double>::StorageIndex Storage_index;
  const Eigen::Index k = functions.cols();
  const Storage_index* outer = functions.outerIndexPtr();
  const Storage_index* inner = functions.innerIndexPtr();
  const Eigen::Index widest = galerkin_group_width;
  std::vector<Eigen::Index> group_start;
  for(Eigen::Index j = 0; j < k; ++j)
  {
    const bool same = !group_start.empty() && j - group_start.back() < widest &&
                      outer[j + 1] - outer[j] == outer[j] - outer[j - 1] &&
                      std::equal(inner + outer[j], inner + outer[j + 1], inner + outer[j - 1]);
    if(!same)
      group_start.push_back(j);
  }
  group_start.push_back(k);
  return group_start;
}

CGAL_SSMD_CORE_FUNCTION void galerkin_columns_of_group(const Eigen::SparseMatrix<double>& stiffness, const Eigen::VectorXd& mass,
                                                       const Eigen::SparseMatrix<double>& functions,
                                                       const Eigen::SparseMatrix<double, Eigen::RowMajor>& rows, Eigen::Index first,
                                                       Eigen::Index width, Galerkin_work& work, std::vector<Galerkin_column>& columns)
{
  typedef Eigen::SparseMatrix<double>::StorageIndex Storage_index;
  const Eigen::Index widest = galerkin_group_width;
  const Storage_index* outer = functions.outerIndexPtr();
  const Storage_index* inner = functions.innerIndexPtr();
  const double* values = functions.valuePtr();
  std::vector<double>& applied = work.applied;
  std::vector<char>& reached = work.reached;
  std::vector<Eigen::Index>& ring = work.ring;
  std::vector<double>& stiffness_sum = work.stiffness_sum;
  std::vector<double>& mass_sum = work.mass_sum;
  std::vector<char>& touched = work.touched;
  std::vector<Eigen::Index>& touched_list = work.touched_list;
  auto touch = [&](Eigen::Index i) {
    if(!touched[static_cast<std::size_t>(i)])
    {
      touched[static_cast<std::size_t>(i)] = 1;
      touched_list.push_back(i);
    }
  };
  const Eigen::Index length = outer[first + 1] - outer[first];
  ring.clear();
  touched_list.clear();
  for(Eigen::Index e = 0; e < length; ++e)
  {
    const Eigen::Index u = inner[outer[first] + e];
    double p[widest];
    for(Eigen::Index c = 0; c < width; ++c)
      p[c] = values[outer[first + c] + e];
    // M p_j lives on the support only.
    for(Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator r(rows, u); r; ++r)
    {
      const Eigen::Index i = r.col();
      touch(i);
      const double weight = r.value() * mass[u];
      for(Eigen::Index c = 0; c < width; ++c)
        mass_sum[static_cast<std::size_t>(i * widest + c)] += weight * p[c];
    }
    for(Eigen::SparseMatrix<double>::InnerIterator q(stiffness, u); q; ++q)
    {
      const Eigen::Index w = q.row();
      if(!reached[static_cast<std::size_t>(w)])
      {
        reached[static_cast<std::size_t>(w)] = 1;
        ring.push_back(w);
      }
      for(Eigen::Index c = 0; c < width; ++c)
        applied[static_cast<std::size_t>(w * widest + c)] += q.value() * p[c];
    }
  }
  for(Eigen::Index w : ring)
  {
    double a[widest];
    for(Eigen::Index c = 0; c < width; ++c)
    {
      a[c] = applied[static_cast<std::size_t>(w * widest + c)];
      applied[static_cast<std::size_t>(w * widest + c)] = 0.0;
    }
    reached[static_cast<std::size_t>(w)] = 0;
    for(Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator r(rows, w); r; ++r)
    {
      const Eigen::Index i = r.col();
      touch(i);
      for(Eigen::Index c = 0; c < width; ++c)
        stiffness_sum[static_cast<std::size_t>(i * widest + c)] += r.value() * a[c];
    }
  }
  std::sort(touched_list.begin(), touched_list.end());
  for(Eigen::Index c = 0; c < width; ++c)
  {
    Galerkin_column& column = columns[static_cast<std::size_t>(first + c)];
    column.indices = touched_list;
    column.stiffness.reserve(touched_list.size());
    column.mass.reserve(touched_list.size());
    for(Eigen::Index i : touched_list)
    {
      column.stiffness.push_back(stiffness_sum[static_cast<std::size_t>(i * widest + c)]);
      column.mass.push_back(mass_sum[static_cast<std::size_t>(i * widest + c)]);
      stiffness_sum[static_cast<std::size_t>(i * widest + c)] = 0.0;
      mass_sum[static_cast<std::size_t>(i * widest + c)] = 0.0;
    }
  }
  for(Eigen::Index i : touched_list)
    touched[static_cast<std::size_t>(i)] = 0;
}

CGAL_SSMD_CORE_FUNCTION void assemble_galerkin_matrices(const std::vector<Galerkin_column>& columns,
                                                        Eigen::SparseMatrix<double>& reduced_stiffness,
                                                        Eigen::SparseMatrix<double>& reduced_mass)
{
  typedef Eigen::SparseMatrix<double>::StorageIndex Storage_index;
  const Eigen::Index k = static_cast<Eigen::Index>(columns.size());
  Eigen::Index entries = 0;
  for(const Galerkin_column& column : columns)
    entries += static_cast<Eigen::Index>(column.indices.size());
  reduced_stiffness.resize(k, k);
  reduced_mass.resize(k, k);
  reduced_stiffness.resizeNonZeros(entries);
  reduced_mass.resizeNonZeros(entries);
  Eigen::Index position = 0;
  for(Eigen::Index j = 0; j < k; ++j)
  {
    const Galerkin_column& column = columns[static_cast<std::size_t>(j)];
    reduced_stiffness.outerIndexPtr()[j] = static_cast<Storage_index>(position);
    reduced_mass.outerIndexPtr()[j] = static_cast<Storage_index>(position);
    for(std::size_t e = 0; e < column.indices.size(); ++e, ++position)
    {
      reduced_stiffness.innerIndexPtr()[position] = static_cast<Storage_index>(column.indices[e]);
      reduced_mass.innerIndexPtr()[position] = static_cast<Storage_index>(column.indices[e]);
      reduced_stiffness.valuePtr()[position] = column.stiffness[e];
      reduced_mass.valuePtr()[position] = column.mass[e];
    }
  }
  reduced_stiffness.outerIndexPtr()[k] = static_cast<Storage_index>(position);
  reduced_mass.outerIndexPtr()[k] = static_cast<Storage_index>(position);
  // Sums of rounded products are not exactly symmetric.
  reduced_stiffness = 0.5 * (reduced_stiffness + Eigen::SparseMatrix<double>(reduced_stiffness.transpose()));
  reduced_mass = 0.5 * (reduced_mass + Eigen::SparseMatrix<double>(reduced_mass.transpose()));
}

CGAL_SSMD_CORE_FUNCTION void galerkin_matrices(const Eigen::SparseMatrix<double>& stiffness,
                                               const Eigen::VectorXd& mass,
                                               const Eigen::SparseMatrix<double>& functions,
                                               const Eigen::SparseMatrix<double, Eigen::RowMajor>& rows,
                                               Eigen::SparseMatrix<double>& reduced_stiffness,
                                               Eigen::SparseMatrix<double>& reduced_mass)
{
  const Eigen::Index n = functions.rows();
  const Eigen::Index k = functions.cols();
  const std::vector<Eigen::Index> group_start = same_support_groups(functions);
  const Eigen::Index groups = static_cast<Eigen::Index>(group_start.size()) - 1;
  std::vector<Galerkin_column> columns(static_cast<std::size_t>(k));

  Parallel_exception failure;
#ifdef _OPENMP
#pragma omp parallel if(n > parallel_loop_items)
#endif
  {
    std::unique_ptr<Galerkin_work> work;
    failure.run([&] { work = std::make_unique<Galerkin_work>(n, k); });
#ifdef _OPENMP
#pragma omp for schedule(dynamic, 4)
#endif
    for(Eigen::Index g = 0; g < groups; ++g)
      failure.run([&] {
        const Eigen::Index first = group_start[static_cast<std::size_t>(g)];
        const Eigen::Index width = group_start[static_cast<std::size_t>(g) + 1] - first;
        galerkin_columns_of_group(stiffness, mass, functions, rows, first, width, *work, columns);
      });
  }
  failure.rethrow();

  assemble_galerkin_matrices(columns, reduced_stiffness, reduced_mass);
}

} // namespace Eigensolvers
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_GALERKIN_MATRICES_IMPL_H

// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_LAPLACIAN_NULL_SPACE_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_LAPLACIAN_NULL_SPACE_H

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Spectral_deformation {
namespace internal {
namespace Eigensolvers {

// The null space of a stiffness matrix Q whose rows sum to zero (a
// Laplacian): the functions constant on each connected component of the
// graph of its nonzero off-diagonal entries, which are eigenvectors of
// Q h = lambda M h with lambda = 0, known in closed form. `dimension()` is
// zero when some row of Q does not sum to zero (up to rounding): then Q is
// not a Laplacian and nothing is known.
class Laplacian_null_space
{
public:
  Laplacian_null_space(const Eigen::SparseMatrix<double>& stiffness, const Eigen::VectorXd& mass)
    : m_mass(mass) // also when Q is not a Laplacian: basis() then has n rows and no column
  {
    const Eigen::Index n = stiffness.rows();
    std::vector<Eigen::Index> parent(static_cast<std::size_t>(n));
    std::iota(parent.begin(), parent.end(), Eigen::Index(0));
    auto root = [&](Eigen::Index i) {
      while(parent[i] != i)
        i = parent[i] = parent[parent[i]];
      return i;
    };
    Eigen::VectorXd row_sum = Eigen::VectorXd::Zero(n), row_magnitude = Eigen::VectorXd::Zero(n);
    for(Eigen::Index j = 0; j < stiffness.outerSize(); ++j)
      for(Eigen::SparseMatrix<double>::InnerIterator it(stiffness, j); it; ++it)
      {
        row_sum[it.row()] += it.value();
        row_magnitude[it.row()] += std::abs(it.value());
        if(it.row() != it.col() && it.value() != 0)
        {
          const Eigen::Index a = root(it.row()), b = root(it.col());
          if(a != b)
            parent[(std::max)(a, b)] = (std::min)(a, b);
        }
      }
    for(Eigen::Index i = 0; i < n; ++i)
      if(!(std::abs(row_sum[i]) <= 1e-10 * row_magnitude[i]))
        return;
    m_component.resize(static_cast<std::size_t>(n));
    std::vector<Eigen::Index> index_of_root(static_cast<std::size_t>(n), -1);
    for(Eigen::Index i = 0; i < n; ++i)
    {
      Eigen::Index& index = index_of_root[root(i)];
      if(index < 0)
      {
        index = static_cast<Eigen::Index>(m_component_mass.size());
        m_component_mass.push_back(0);
      }
      m_component[i] = index;
      m_component_mass[index] += mass[i];
    }
  }

  // The number of components, 0 when Q is not a Laplacian.
  Eigen::Index dimension() const { return static_cast<Eigen::Index>(m_component_mass.size()); }

  // The M-orthonormal basis of the null space, one column per component
  // numbered by their first vertex.
  Eigen::MatrixXd basis() const
  {
    Eigen::MatrixXd result = Eigen::MatrixXd::Zero(m_mass.size(), dimension());
    if(dimension() == 0)
      return result;
    for(Eigen::Index i = 0; i < m_mass.size(); ++i)
      result(i, m_component[i]) = 1.0 / std::sqrt(m_component_mass[m_component[i]]);
    return result;
  }

  // x -= P x, with P the M-orthogonal projection on the null space.
  void project_out(Eigen::MatrixXd& x) const
  {
    if(dimension() == 0)
      return;
    if(dimension() == 1)
    {
      const Eigen::RowVectorXd means = (m_mass.transpose() * x) / m_component_mass[0];
      x.rowwise() -= means;
      return;
    }
    std::vector<double> sums(m_component_mass.size());
    for(Eigen::Index j = 0; j < x.cols(); ++j)
    {
      std::fill(sums.begin(), sums.end(), 0.0);
      for(Eigen::Index i = 0; i < x.rows(); ++i)
        sums[m_component[i]] += m_mass[i] * x(i, j);
      for(std::size_t c = 0; c < sums.size(); ++c)
        sums[c] /= m_component_mass[c];
      for(Eigen::Index i = 0; i < x.rows(); ++i)
        x(i, j) -= sums[m_component[i]];
    }
  }

private:
  std::vector<Eigen::Index> m_component;
  std::vector<double> m_component_mass;
  Eigen::VectorXd m_mass;
};

} // namespace Eigensolvers
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_LAPLACIAN_NULL_SPACE_H

// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The fastest CGAL ARAP a CGAL user can have, for the benchmarks that run it
// beside the package: CGAL::Surface_mesh_deformation with ORIGINAL_ARAP and
// CHOLMOD's supernodal Cholesky on the symmetric positive definite block of
// its system, as the reference harness (../shared/bench) runs it.
//
// CGAL writes the rows of the constrained vertices as rows of the identity
// and keeps their columns in the free rows, which makes its matrix
// unsymmetric: its default solver is a sparse LU. The traits below factor
// the free block A_ff, which is the cotangent Laplacian restricted to the
// free vertices, and move A_fc x_c to the right-hand side at each solve:
// the same solution as CGAL's SparseLU up to round-off.

#ifndef SSMD_BENCHMARK_CGAL_ARAP_SOLVER_TRAITS_H
#define SSMD_BENCHMARK_CGAL_ARAP_SOLVER_TRAITS_H

#include <CGAL/Eigen_matrix.h>
#include <CGAL/Eigen_vector.h>
#include <CGAL/Surface_mesh_deformation.h>

#include <Eigen/CholmodSupport>
#include <Eigen/Sparse>

#include <vector>

namespace ssmd_benchmark {

/// A model of CGAL's `SparseLinearAlgebraWithFactorTraits_d` for
/// `CGAL::Surface_mesh_deformation`: CHOLMOD on the free block of its system.
class Cgal_arap_cholmod_traits
{
public:
  typedef double NT;
  typedef CGAL::Eigen_sparse_matrix<double> Matrix;
  typedef CGAL::Eigen_vector<double> Vector;
  typedef Eigen::SparseMatrix<double> Sparse;

  bool factor(const Matrix& A, NT& D)
  {
    D = 1;
    const Sparse& M = A.eigen_object();
    const Eigen::Index n = M.rows();
    // A constrained row holds its diagonal alone.
    std::vector<int> entries(static_cast<std::size_t>(n), 0);
    m_constrained_diagonal.assign(static_cast<std::size_t>(n), 0.0);
    for(Eigen::Index k = 0; k < M.outerSize(); ++k)
      for(Sparse::InnerIterator it(M, k); it; ++it)
        if(it.value() != 0)
        {
          ++entries[static_cast<std::size_t>(it.row())];
          if(it.row() == it.col())
            m_constrained_diagonal[static_cast<std::size_t>(it.row())] = it.value();
        }
    m_free_index.assign(static_cast<std::size_t>(n), -1);
    m_free.clear();
    for(Eigen::Index i = 0; i < n; ++i)
    {
      const std::size_t u = static_cast<std::size_t>(i);
      if(entries[u] == 1 && m_constrained_diagonal[u] != 0)
        continue;
      m_constrained_diagonal[u] = 0;
      m_free_index[u] = static_cast<int>(m_free.size());
      m_free.push_back(static_cast<int>(i));
    }
    std::vector<Eigen::Triplet<double>> free_free, free_constrained;
    for(Eigen::Index k = 0; k < M.outerSize(); ++k)
      for(Sparse::InnerIterator it(M, k); it; ++it)
      {
        const int row = m_free_index[static_cast<std::size_t>(it.row())];
        if(row < 0)
          continue;
        const int column = m_free_index[static_cast<std::size_t>(it.col())];
        if(column >= 0)
          free_free.emplace_back(row, column, it.value());
        else
          free_constrained.emplace_back(row, static_cast<int>(it.col()), it.value());
      }
    const Eigen::Index free = static_cast<Eigen::Index>(m_free.size());
    m_free_free.resize(free, free);
    m_free_free.setFromTriplets(free_free.begin(), free_free.end());
    m_free_constrained.resize(free, n);
    m_free_constrained.setFromTriplets(free_constrained.begin(), free_constrained.end());
    m_solver.compute(m_free_free);
    return m_solver.info() == Eigen::Success;
  }

  bool linear_solver(const Vector& B, Vector& X)
  {
    const Eigen::Index n = static_cast<Eigen::Index>(m_free_index.size());
    Eigen::VectorXd constrained = Eigen::VectorXd::Zero(n);
    for(Eigen::Index i = 0; i < n; ++i)
      if(m_free_index[static_cast<std::size_t>(i)] < 0)
        constrained[i] = B[i] / m_constrained_diagonal[static_cast<std::size_t>(i)];
    Eigen::VectorXd rhs(static_cast<Eigen::Index>(m_free.size()));
    for(std::size_t k = 0; k < m_free.size(); ++k)
      rhs[static_cast<Eigen::Index>(k)] = B[m_free[k]];
    rhs -= m_free_constrained * constrained;
    const Eigen::VectorXd solution = m_solver.solve(rhs);
    if(m_solver.info() != Eigen::Success)
      return false;
    X.resize(n);
    for(Eigen::Index i = 0; i < n; ++i)
    {
      const int k = m_free_index[static_cast<std::size_t>(i)];
      X[i] = k < 0 ? constrained[i] : solution[k];
    }
    return true;
  }

private:
  std::vector<int> m_free_index; // per vertex: its row in the free block, or -1
  std::vector<int> m_free;
  std::vector<double> m_constrained_diagonal;
  Sparse m_free_free, m_free_constrained;
  Eigen::CholmodSupernodalLLT<Sparse> m_solver;
};

/// CGAL ARAP as the benchmarks run it beside the package.
template <class Mesh>
using Cgal_arap = CGAL::Surface_mesh_deformation<Mesh, CGAL::Default, CGAL::Default, CGAL::ORIGINAL_ARAP,
                                                 CGAL::Default, Cgal_arap_cholmod_traits>;

} // namespace ssmd_benchmark

#endif // SSMD_BENCHMARK_CGAL_ARAP_SOLVER_TRAITS_H

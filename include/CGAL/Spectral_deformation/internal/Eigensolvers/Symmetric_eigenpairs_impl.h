// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_SYMMETRIC_EIGENPAIRS_IMPL_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_SYMMETRIC_EIGENPAIRS_IMPL_H

// The definitions of the functions declared in Symmetric_eigenpairs.h (see
// internal/compiled_core.h: the compiled core holds them).

#include <CGAL/Spectral_deformation/internal/Eigensolvers/Symmetric_eigenpairs.h>

namespace CGAL {
namespace Spectral_deformation {
namespace internal {
namespace Eigensolvers {

#ifdef CGAL_SSMD_USE_BLAS
CGAL_SSMD_CORE_FUNCTION bool symmetric_eigenpairs_by_divide_and_conquer(Eigen::MatrixXd& A, Eigen::Index first,
                                                                        Eigen::Index count, Eigen::VectorXd& values,
                                                                        Eigen::MatrixXd& vectors)
{
  const int size = static_cast<int>(A.rows());
  Eigen::VectorXd all_values(A.rows());
  double work_size = 0;
  int iwork_size = 0, query = -1, info = 0;
  dsyevd_("V", "L", &size, A.data(), &size, all_values.data(), &work_size, &query, &iwork_size,
          &query, &info);
  if(info != 0)
    return false;
  const int lwork = static_cast<int>(work_size), liwork = iwork_size;
  std::vector<double> work(static_cast<std::size_t>(lwork));
  std::vector<int> iwork(static_cast<std::size_t>(liwork));
  dsyevd_("V", "L", &size, A.data(), &size, all_values.data(), work.data(), &lwork, iwork.data(),
          &liwork, &info);
  if(info != 0)
    return false;
  values = all_values.segment(first, count);
  vectors = A.middleCols(first, count);
  return values.allFinite() && vectors.allFinite();
}
#endif

CGAL_SSMD_CORE_FUNCTION bool symmetric_eigenpairs_in_range(Eigen::MatrixXd A, Eigen::Index first, Eigen::Index count,
                                                           Eigen::VectorXd& values, Eigen::MatrixXd& vectors)
{
  const Eigen::Index n = A.rows();
  if(count < 1 || first < 0 || first + count > n)
    return false;
#ifdef CGAL_SSMD_USE_BLAS
  if(4 * count >= n)
    return symmetric_eigenpairs_by_divide_and_conquer(A, first, count, values, vectors);
  const int size = static_cast<int>(n);
  const int lowest = static_cast<int>(first + 1), highest = static_cast<int>(first + count);
  const double unused = 0, absolute_tolerance = 0;
  int found = 0, info = 0;
  Eigen::VectorXd all_values(n);
  vectors.resize(n, count);
  std::vector<int> support(2 * static_cast<std::size_t>(count));
  // Workspace query, then the solve.
  double work_size = 0;
  int iwork_size = 0, query = -1;
  dsyevr_("V", "I", "L", &size, A.data(), &size, &unused, &unused, &lowest, &highest,
          &absolute_tolerance, &found, all_values.data(), vectors.data(), &size, support.data(),
          &work_size, &query, &iwork_size, &query, &info);
  if(info != 0)
    return false;
  const int lwork = static_cast<int>(work_size), liwork = iwork_size;
  std::vector<double> work(static_cast<std::size_t>(lwork));
  std::vector<int> iwork(static_cast<std::size_t>(liwork));
  dsyevr_("V", "I", "L", &size, A.data(), &size, &unused, &unused, &lowest, &highest,
          &absolute_tolerance, &found, all_values.data(), vectors.data(), &size, support.data(),
          work.data(), &lwork, iwork.data(), &liwork, &info);
  if(info != 0 || found != static_cast<int>(count))
    return false;
  values = all_values.head(count);
  return values.allFinite() && vectors.allFinite();
#else
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(A);
  if(solver.info() != Eigen::Success)
    return false;
  values = solver.eigenvalues().segment(first, count);
  vectors = solver.eigenvectors().middleCols(first, count);
  return true;
#endif
}

CGAL_SSMD_CORE_FUNCTION bool largest_symmetric_eigenpairs(const Eigen::MatrixXd& A, Eigen::Index count,
                                                          Eigen::VectorXd& values, Eigen::MatrixXd& vectors)
{
  return symmetric_eigenpairs_in_range(A, A.rows() - count, count, values, vectors);
}

CGAL_SSMD_CORE_FUNCTION bool largest_tridiagonal_eigenpairs(const Eigen::VectorXd& diagonal,
                                                            const Eigen::VectorXd& subdiagonal, Eigen::Index count,
                                                            Eigen::VectorXd& values, Eigen::MatrixXd& vectors)
{
  const Eigen::Index k = diagonal.size();
  if(count < 1 || count > k || subdiagonal.size() < k - 1)
    return false;
#ifdef CGAL_SSMD_USE_BLAS
  // All of them: dstemr finds a subset by bisection, which cost more than
  // the whole spectrum by dqds on the Lanczos matrices of 150 to 300 rows.
  const int size = static_cast<int>(k);
  const double unused = 0;
  const int unused_index = 0;
  int found = 0, info = 0, try_relative_accuracy = 1;
  Eigen::VectorXd d = diagonal, e = Eigen::VectorXd::Zero(k);
  e.head(k - 1) = subdiagonal.head(k - 1);
  Eigen::VectorXd all_values(k);
  Eigen::MatrixXd all_vectors(k, k);
  std::vector<int> support(2 * static_cast<std::size_t>(k));
  double work_size = 0;
  int iwork_size = 0, query = -1;
  dstemr_("V", "A", &size, d.data(), e.data(), &unused, &unused, &unused_index, &unused_index, &found,
          all_values.data(), all_vectors.data(), &size, &size, support.data(), &try_relative_accuracy, &work_size,
          &query, &iwork_size, &query, &info);
  if(info != 0)
    return false;
  const int lwork = static_cast<int>(work_size), liwork = iwork_size;
  std::vector<double> work(static_cast<std::size_t>(lwork));
  std::vector<int> iwork(static_cast<std::size_t>(liwork));
  try_relative_accuracy = 1;
  dstemr_("V", "A", &size, d.data(), e.data(), &unused, &unused, &unused_index, &unused_index, &found,
          all_values.data(), all_vectors.data(), &size, &size, support.data(), &try_relative_accuracy, work.data(),
          &lwork, iwork.data(), &liwork, &info);
  if(info != 0 || found != size)
    return false;
  values = all_values.tail(count);
  vectors = all_vectors.rightCols(count);
  return values.allFinite() && vectors.allFinite();
#else
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver;
  const Eigen::VectorXd off_diagonal = subdiagonal.head(k - 1);
  solver.computeFromTridiagonal(diagonal, off_diagonal, Eigen::ComputeEigenvectors);
  if(solver.info() != Eigen::Success)
    return false;
  values = solver.eigenvalues().tail(count);
  vectors = solver.eigenvectors().rightCols(count);
  return true;
#endif
}

CGAL_SSMD_CORE_FUNCTION bool smallest_symmetric_eigenpairs(const Eigen::MatrixXd& A, Eigen::Index count,
                                                           Eigen::VectorXd& values, Eigen::MatrixXd& vectors)
{
  return symmetric_eigenpairs_in_range(A, 0, count, values, vectors);
}

} // namespace Eigensolvers
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_SYMMETRIC_EIGENPAIRS_IMPL_H

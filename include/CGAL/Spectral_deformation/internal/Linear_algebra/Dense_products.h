// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_LINEAR_ALGEBRA_DENSE_PRODUCTS_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_LINEAR_ALGEBRA_DENSE_PRODUCTS_H

#include <CGAL/Spectral_deformation/internal/available_threads.h>

#include <Eigen/Dense>

#include <algorithm>
#include <vector>

#ifdef _OPENMP
#include <omp.h>
#endif

// Tall-and-skinny products (n × k by k × b with n ≫ k) dominate the block
// eigensolver. When a BLAS is linked (CGAL_SSMD_USE_BLAS, set by the CMake
// package together with CHOLMOD, which needs one anyway), they go to its
// dgemm, which picks vector instructions at run time (OpenBLAS: AVX2/FMA),
// which Eigen's own product cannot use when compiled without -march.
// Otherwise Eigen computes them.
#ifdef CGAL_SSMD_USE_BLAS
extern "C" void dgemm_(const char* transa, const char* transb, const int* m, const int* n,
                       const int* k, const double* alpha, const double* a, const int* lda,
                       const double* b, const int* ldb, const double* beta, double* c,
                       const int* ldc);
#endif
#ifdef CGAL_SSMD_USE_OPENBLAS
extern "C" int openblas_get_num_threads(void);
extern "C" void openblas_set_num_threads(int);
extern "C" int openblas_get_parallel(void);
#endif

namespace CGAL {
namespace Spectral_deformation {
namespace internal {
namespace Linear_algebra {

typedef Eigen::Ref<const Eigen::MatrixXd, 0, Eigen::OuterStride<>> Const_matrix_ref;
typedef Eigen::Ref<Eigen::MatrixXd, 0, Eigen::OuterStride<>> Matrix_ref;

/// C = beta C + alpha op(A) op(B), op(X) = Xᵀ when the flag is set.
inline void dense_product(bool transpose_a, const Const_matrix_ref& A, bool transpose_b,
                          const Const_matrix_ref& B, double alpha, double beta, Matrix_ref C)
{
  const Eigen::Index inner = transpose_a ? A.rows() : A.cols();
  if(C.rows() == 0 || C.cols() == 0)
    return;
  if(inner == 0)
  {
    C *= beta;
    return;
  }
#ifdef CGAL_SSMD_USE_BLAS
  const int rows = static_cast<int>(C.rows()), cols = static_cast<int>(C.cols());
  const int depth = static_cast<int>(inner);
  const int lda = static_cast<int>(A.outerStride()), ldb = static_cast<int>(B.outerStride());
  const int ldc = static_cast<int>(C.outerStride());
  dgemm_(transpose_a ? "T" : "N", transpose_b ? "T" : "N", &rows, &cols, &depth, &alpha, A.data(),
         &lda, B.data(), &ldb, &beta, C.data(), &ldc);
#else
  if(beta == 0)
    C.setZero();
  else if(beta != 1)
    C *= beta;
  if(transpose_a && transpose_b)
    C.noalias() += alpha * A.transpose() * B.transpose();
  else if(transpose_a)
    C.noalias() += alpha * A.transpose() * B;
  else if(transpose_b)
    C.noalias() += alpha * A * B.transpose();
  else
    C.noalias() += alpha * A * B;
#endif
}

// Whether the linked BLAS runs threads of its own that wait for work by
// spinning: OpenBLAS's pthreads build (the one Debian installs by default)
// with more than one thread.
inline bool blas_runs_spinning_threads()
{
#ifdef CGAL_SSMD_USE_OPENBLAS
  constexpr int pthreads_build = 1;
  return openblas_get_parallel() == pthreads_build && openblas_get_num_threads() > 1;
#else
  return false;
#endif
}

// Gives the cores to one pool of threads for its lifetime: OpenBLAS's idle
// threads wait for work spinning on `sched_yield()` for some 0.1 s after each
// call, and OpenMP teams running beside them got a fraction of the cores,
// their barriers waiting for threads that were not scheduled (a two-thread
// sparse solve ran at one-thread speed; the exact basis of a 13,500-vertex
// region took 1.2-2.7 s, against 0.6-0.7 s with either pool on one thread).
//
// - With `process_wide_tuning`, OpenBLAS runs on one thread and the OpenMP
//   teams do the parallel work (callers split their tall products with
//   `threaded_dense_product()`; bound by memory, they gained little from
//   OpenBLAS's threads). The OpenBLAS thread count is a setting of the whole
//   process: other threads calling OpenBLAS meanwhile run single-threaded
//   too. The package does this only when a traits object was asked to
//   (`set_process_wide_tuning(true)`, see Memory/Process_wide_tuning.h).
// - Otherwise, beside a BLAS with spinning threads, the OpenMP teams that
//   the calling thread starts run on one thread and OpenBLAS keeps its
//   threads for the dense products. Only the calling thread's setting
//   changes (`nthreads-var` is a per-thread setting of OpenMP).
//
// Both settings are restored by the destructor.
class Threads_for_blas_or_openmp
{
public:
  explicit Threads_for_blas_or_openmp(bool process_wide_tuning)
      : m_openmp(!process_wide_tuning && blas_runs_spinning_threads())
  {
#ifdef CGAL_SSMD_USE_OPENBLAS
    if(process_wide_tuning)
    {
      m_blas_threads = openblas_get_num_threads();
      if(m_blas_threads > 1)
        openblas_set_num_threads(1);
    }
#endif
  }
  ~Threads_for_blas_or_openmp()
  {
#ifdef CGAL_SSMD_USE_OPENBLAS
    if(m_blas_threads > 1)
      openblas_set_num_threads(m_blas_threads);
#endif
  }
  Threads_for_blas_or_openmp(const Threads_for_blas_or_openmp&) = delete;
  Threads_for_blas_or_openmp& operator=(const Threads_for_blas_or_openmp&) = delete;

private:
  int m_blas_threads = 0;
  One_thread_scope m_openmp;
};

// dense_product() split over the OpenMP threads along the long dimension of
// a tall product (the rows of C, or the inner dimension of AᵀB), for use
// with a single-threaded BLAS.
inline void threaded_dense_product(bool transpose_a, const Const_matrix_ref& A, bool transpose_b,
                                   const Const_matrix_ref& B, double alpha, double beta,
                                   Matrix_ref C)
{
#ifdef _OPENMP
  const int threads = omp_in_parallel() ? 1 : (std::min)(omp_get_max_threads(), 8);
  const Eigen::Index inner = transpose_a ? A.rows() : A.cols();
  const Eigen::Index minimum_rows = 8192;
  if(threads > 1 && !transpose_b && !transpose_a && C.rows() >= threads * minimum_rows)
  {
#pragma omp parallel for num_threads(threads)
    for(int t = 0; t < threads; ++t)
    {
      const Eigen::Index first = C.rows() * t / threads, last = C.rows() * (t + 1) / threads;
      dense_product(false, A.middleRows(first, last - first), false, B, alpha, beta,
                    C.middleRows(first, last - first));
    }
    return;
  }
  if(threads > 1 && transpose_a && !transpose_b && inner >= threads * minimum_rows)
  {
    std::vector<Eigen::MatrixXd> partial(static_cast<std::size_t>(threads));
#pragma omp parallel for num_threads(threads)
    for(int t = 0; t < threads; ++t)
    {
      const Eigen::Index first = inner * t / threads, last = inner * (t + 1) / threads;
      partial[t].resize(C.rows(), C.cols());
      dense_product(true, A.middleRows(first, last - first), false,
                    B.middleRows(first, last - first), 1.0, 0.0, partial[t]);
    }
    for(int t = 1; t < threads; ++t)
      partial[0] += partial[t];
    if(beta == 0)
      C = alpha * partial[0];
    else
      C = beta * C + alpha * partial[0];
    return;
  }
#endif
  dense_product(transpose_a, A, transpose_b, B, alpha, beta, C);
}

} // namespace Linear_algebra
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_LINEAR_ALGEBRA_DENSE_PRODUCTS_H

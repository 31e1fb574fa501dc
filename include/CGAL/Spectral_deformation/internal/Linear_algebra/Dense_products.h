// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_LINEAR_ALGEBRA_DENSE_PRODUCTS_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_LINEAR_ALGEBRA_DENSE_PRODUCTS_H


#include <Eigen/Dense>

#include <algorithm>
#include <cstddef>
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
//
// The BLAS is called in pieces of at most `blas_piece_multiply_adds()`
// multiply-adds, which OpenBLAS computes on the calling thread: the
// package's products then never wake OpenBLAS's own threads, and its OpenMP
// teams do the parallel work (see `Single_threaded_blas_scope`).
#ifdef CGAL_SSMD_USE_BLAS
extern "C" void dgemm_(const char* transa, const char* transb, const int* m, const int* n,
                       const int* k, const double* alpha, const double* a, const int* lda,
                       const double* b, const int* ldb, const double* beta, double* c,
                       const int* ldc);
#endif
#ifdef CGAL_SSMD_USE_OPENBLAS
extern "C" int openblas_get_num_threads(void);
extern "C" void openblas_set_num_threads(int);
#endif

namespace CGAL {
namespace Spectral_deformation {
namespace internal {
namespace Linear_algebra {

typedef Eigen::Ref<const Eigen::MatrixXd, 0, Eigen::OuterStride<>> Const_matrix_ref;
typedef Eigen::Ref<Eigen::MatrixXd, 0, Eigen::OuterStride<>> Matrix_ref;

// The largest product, in multiply-adds m·n·k, that OpenBLAS's dgemm
// computes on the calling thread: above it, its threaded builds hand the
// product to their own threads (`interface/gemm.c`: 65536 ×
// GEMM_MULTITHREAD_THRESHOLD, 4 by default). Those threads then wait for
// more work spinning on `sched_yield()` for some 0.1 s, beside the OpenMP
// teams that run the package's other loops. Another BLAS is called in
// pieces of the same size; only the speed can differ.
constexpr double blas_piece_multiply_adds() { return 262144.0; }

/// C = beta C + alpha op(A) op(B), op(X) = Xᵀ when the flag is set.
///
/// With a BLAS, the product is computed in pieces of at most
/// `blas_piece_multiply_adds()`, over blocks of C and, for a long inner
/// dimension, in consecutive slices of it accumulated in order: the pieces
/// depend on the sizes only, so the rounding does not depend on OpenBLAS's
/// thread count.
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
  // Pieces of up to 128 columns of C and 256 of the inner dimension, with as
  // many rows as the limit allows, at least 16 (the inner slice shortens
  // for them): shapes on which dgemm keeps most of its speed.
  const double limit = blas_piece_multiply_adds();
  const int column_block = (std::min)(cols, 128);
  int depth_block = (std::min)(depth, 256);
  int row_block = static_cast<int>(limit / (double(column_block) * depth_block));
  const int minimum_rows = (std::min)(rows, 16);
  if(row_block < minimum_rows)
  {
    depth_block = (std::max)(1, (std::min)(depth, static_cast<int>(limit / (double(column_block) * minimum_rows))));
    row_block = (std::max)(1, static_cast<int>(limit / (double(column_block) * depth_block)));
  }
  const char* const op_a = transpose_a ? "T" : "N";
  const char* const op_b = transpose_b ? "T" : "N";
  for(int j = 0; j < cols; j += column_block)
  {
    const int piece_cols = (std::min)(column_block, cols - j);
    for(int i = 0; i < rows; i += row_block)
    {
      const int piece_rows = (std::min)(row_block, rows - i);
      double* const c = C.data() + i + std::ptrdiff_t(j) * ldc;
      for(int l = 0; l < depth; l += depth_block)
      {
        const int piece_depth = (std::min)(depth_block, depth - l);
        const double* const a = transpose_a ? A.data() + l + std::ptrdiff_t(i) * lda
                                            : A.data() + i + std::ptrdiff_t(l) * lda;
        const double* const b = transpose_b ? B.data() + j + std::ptrdiff_t(l) * ldb
                                            : B.data() + l + std::ptrdiff_t(j) * ldb;
        const double piece_beta = l == 0 ? beta : 1.0;
        dgemm_(op_a, op_b, &piece_rows, &piece_cols, &piece_depth, &alpha, a, &lda, b, &ldb, &piece_beta, c,
               &ldc);
      }
    }
  }
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

// With `process_wide_tuning`, OpenBLAS runs on one thread for the lifetime
// of the object, so that the BLAS calls of CHOLMOD (its supernodal
// factorizations and solves) stay on the calling thread too and never wake
// OpenBLAS's threads beside the OpenMP teams. The OpenBLAS thread count is a
// setting of the whole process: other threads calling OpenBLAS meanwhile run
// single-threaded too. The package does this only when a traits object was
// asked to (`set_process_wide_tuning(true)`, see Memory/Process_wide_tuning.h).
// The package's own products need none of it: `dense_product()` keeps them
// on the calling thread whatever OpenBLAS's setting, and the OpenMP teams do
// the parallel work.
//
// The setting is restored by the destructor.
class Single_threaded_blas_scope
{
public:
  explicit Single_threaded_blas_scope(bool process_wide_tuning)
  {
#ifdef CGAL_SSMD_USE_OPENBLAS
    if(process_wide_tuning)
    {
      m_blas_threads = openblas_get_num_threads();
      if(m_blas_threads > 1)
        openblas_set_num_threads(1);
    }
#else
    (void)process_wide_tuning;
#endif
  }
  ~Single_threaded_blas_scope()
  {
#ifdef CGAL_SSMD_USE_OPENBLAS
    if(m_blas_threads > 1)
      openblas_set_num_threads(m_blas_threads);
#endif
  }
  Single_threaded_blas_scope(const Single_threaded_blas_scope&) = delete;
  Single_threaded_blas_scope& operator=(const Single_threaded_blas_scope&) = delete;

private:
  int m_blas_threads = 0;
};

// dense_product() split over the OpenMP threads along the long dimension of
// a tall product (the rows of C, or the inner dimension of AᵀB), in pieces
// of at least 8192 rows whose number depends on the sizes only: the partial
// products of AᵀB are added in the order of their pieces, so that the result
// is the same to the last bit whatever the number of threads.
inline void threaded_dense_product(bool transpose_a, const Const_matrix_ref& A, bool transpose_b,
                                   const Const_matrix_ref& B, double alpha, double beta,
                                   Matrix_ref C)
{
  const Eigen::Index inner = transpose_a ? A.rows() : A.cols();
  const Eigen::Index piece_rows = 8192;
#ifdef _OPENMP
  const int threads = omp_in_parallel() ? 1 : (std::min)(omp_get_max_threads(), 8);
#endif
  if(!transpose_b && !transpose_a && C.rows() >= 2 * piece_rows)
  {
    const Eigen::Index pieces = C.rows() / piece_rows;
#ifdef _OPENMP
#pragma omp parallel for num_threads(threads) schedule(static) if(threads > 1)
#endif
    for(Eigen::Index p = 0; p < pieces; ++p)
    {
      const Eigen::Index first = C.rows() * p / pieces, last = C.rows() * (p + 1) / pieces;
      dense_product(false, A.middleRows(first, last - first), false, B, alpha, beta,
                    C.middleRows(first, last - first));
    }
    return;
  }
  if(transpose_a && !transpose_b && inner >= 2 * piece_rows)
  {
    const Eigen::Index pieces = inner / piece_rows;
    std::vector<Eigen::MatrixXd> partial(static_cast<std::size_t>(pieces));
#ifdef _OPENMP
#pragma omp parallel for num_threads(threads) schedule(static) if(threads > 1)
#endif
    for(Eigen::Index p = 0; p < pieces; ++p)
    {
      const Eigen::Index first = inner * p / pieces, last = inner * (p + 1) / pieces;
      Eigen::MatrixXd& part = partial[static_cast<std::size_t>(p)];
      part.resize(C.rows(), C.cols());
      dense_product(true, A.middleRows(first, last - first), false, B.middleRows(first, last - first), 1.0,
                    0.0, part);
    }
    for(Eigen::Index p = 1; p < pieces; ++p)
      partial[0] += partial[static_cast<std::size_t>(p)];
    if(beta == 0)
      C = alpha * partial[0];
    else
      C = beta * C + alpha * partial[0];
    return;
  }
  dense_product(transpose_a, A, transpose_b, B, alpha, beta, C);
}

} // namespace Linear_algebra
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_LINEAR_ALGEBRA_DENSE_PRODUCTS_H

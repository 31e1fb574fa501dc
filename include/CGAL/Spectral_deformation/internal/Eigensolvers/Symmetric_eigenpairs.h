// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_SYMMETRIC_EIGENPAIRS_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_SYMMETRIC_EIGENPAIRS_H

#include <CGAL/Spectral_deformation/internal/compiled_core.h>

#include <Eigen/Dense>

#include <vector>

// With a LAPACK (CGAL_SSMD_USE_BLAS: OpenBLAS carries one), dsyevr computes
// only the eigenvectors asked for, after the reduction to tridiagonal form;
// Eigen's solver accumulates all of them. On the small meshes solved densely
// (100 of 620 wanted) that is the larger part of the cost. When a quarter
// or more of the eigenpairs are wanted, as in the Rayleigh-Ritz checks of the
// block eigensolver (about 100 of k = 150 to 340), dsyevr's bisection and
// inverse iteration for that many eigenvectors cost more than computing all
// of them by divide and conquer (dsyevd): 1.5 to 2.5 times more on those
// checks (benchmark/NOTES.md, 2026-12-06, fifth).
#ifdef CGAL_SSMD_USE_BLAS
extern "C" void dsyevd_(const char* jobz, const char* uplo, const int* n, double* a,
                        const int* lda, double* w, double* work, const int* lwork, int* iwork,
                        const int* liwork, int* info);
extern "C" void dsyevr_(const char* jobz, const char* range, const char* uplo, const int* n,
                        double* a, const int* lda, const double* vl, const double* vu,
                        const int* il, const int* iu, const double* abstol, int* m, double* w,
                        double* z, const int* ldz, int* isuppz, double* work, const int* lwork,
                        int* iwork, const int* liwork, int* info);
extern "C" void dstemr_(const char* jobz, const char* range, const int* n, double* d, double* e,
                        const double* vl, const double* vu, const int* il, const int* iu, int* m, double* w,
                        double* z, const int* ldz, const int* nzc, int* isuppz, int* tryrac, double* work,
                        const int* lwork, int* iwork, const int* liwork, int* info);
#endif

namespace CGAL {
namespace Spectral_deformation {
namespace internal {
namespace Eigensolvers {

#ifdef CGAL_SSMD_USE_BLAS
/// All eigenpairs of the symmetric matrix `A` by dsyevd, of which those of
/// ranks `first` to `first + count - 1` are returned; `A` is overwritten.
bool symmetric_eigenpairs_by_divide_and_conquer(Eigen::MatrixXd& A, Eigen::Index first,
                                                Eigen::Index count, Eigen::VectorXd& values,
                                                Eigen::MatrixXd& vectors);
#endif

/// The eigenpairs of ranks `first` to `first + count - 1` (ascending order,
/// from 0) of the symmetric matrix `A` (its lower triangle is read):
/// `values` ascending, `vectors` (rows of A × count) orthonormal. Returns
/// false when the eigensolver fails. `A` is taken by value: LAPACK
/// overwrites it.
bool symmetric_eigenpairs_in_range(Eigen::MatrixXd A, Eigen::Index first, Eigen::Index count,
                                   Eigen::VectorXd& values, Eigen::MatrixXd& vectors);

/// The `count` largest eigenpairs of the symmetric matrix `A`, as
/// `symmetric_eigenpairs_in_range()`.
bool largest_symmetric_eigenpairs(const Eigen::MatrixXd& A, Eigen::Index count,
                                  Eigen::VectorXd& values, Eigen::MatrixXd& vectors);

/// The `count` largest eigenpairs of the symmetric tridiagonal matrix with
/// `diagonal` (k values) and `subdiagonal` (its first k - 1 values are
/// read): `values` ascending, `vectors` (k × count) orthonormal. With a
/// LAPACK, by dstemr (relatively robust representations: O(k count) for
/// the vectors; dstevr would hand a subset to bisection and inverse
/// iteration, several times slower on these clustered spectra), else by
/// Eigen's solver, which computes all of them.
/// Returns false when the eigensolver fails.
bool largest_tridiagonal_eigenpairs(const Eigen::VectorXd& diagonal, const Eigen::VectorXd& subdiagonal,
                                    Eigen::Index count, Eigen::VectorXd& values, Eigen::MatrixXd& vectors);

/// The `count` smallest eigenpairs of the symmetric matrix `A`, as
/// `symmetric_eigenpairs_in_range()`.
bool smallest_symmetric_eigenpairs(const Eigen::MatrixXd& A, Eigen::Index count,
                                   Eigen::VectorXd& values, Eigen::MatrixXd& vectors);

} // namespace Eigensolvers
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#if CGAL_SSMD_CORE_DEFINITIONS
#include <CGAL/Spectral_deformation/internal/Eigensolvers/Symmetric_eigenpairs_impl.h>
#endif

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_SYMMETRIC_EIGENPAIRS_H

// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_AVAILABLE_THREADS_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_AVAILABLE_THREADS_H

#ifdef _OPENMP
#include <omp.h>
#endif

#include <cstddef>

namespace CGAL {
namespace Spectral_deformation {
namespace internal {

/// The threads a step may use from here: OpenMP's count outside a parallel
/// region, one inside it, and one in a program built without OpenMP.
inline int available_threads()
{
#ifdef _OPENMP
  return omp_in_parallel() ? 1 : omp_get_max_threads();
#else
  return 1;
#endif
}

/// Loops over the vertices or faces of a region run on all threads from this
/// many items: a few tens of nanoseconds of work per item, so that below it
/// the loop is shorter than starting and joining a team of threads.
constexpr std::ptrdiff_t parallel_loop_items = 20000;
/// Kernels over the rows of the basis (n rows, m columns) run on all threads
/// from this many entries, for the same reason.
constexpr std::ptrdiff_t parallel_basis_entries = 100000;
/// Products of the reduced operators, rows × m, from this many entries (each
/// row's product is longer than a row of the basis alone).
constexpr std::ptrdiff_t parallel_operator_entries = 200000;
/// Products of a sparse matrix by the basis, non-zeros × m, from this many
/// multiply-adds (a few nanoseconds each).
constexpr std::ptrdiff_t parallel_sparse_products = 1000000;

} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_AVAILABLE_THREADS_H

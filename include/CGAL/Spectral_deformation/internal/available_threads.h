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

} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_AVAILABLE_THREADS_H

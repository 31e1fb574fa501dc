// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_COMPILED_CORE_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_COMPILED_CORE_H

// The compiled core: the numerical pipeline of the default deformation
// (default algorithm, eigensolver and sparse solver traits), compiled once
// into a static library that the package's CMake targets link, so that a
// program that deforms does not compile it again (see
// doc/architecture.md). The pipeline's code depends on four switches; a
// translation unit uses the compiled core only when the library was compiled
// with the same ones, and compiles the pipeline from the headers otherwise.
//
// CGAL_SSMD_CONFIGURATION is the switches of this translation unit as a
// number; the library defines CGAL_SSMD_COMPILED_CORE to its own for the
// programs that link it.

#ifdef CGAL_SSMD_USE_CHOLMOD
#define CGAL_SSMD_CONFIGURATION_CHOLMOD 1
#else
#define CGAL_SSMD_CONFIGURATION_CHOLMOD 0
#endif
#ifdef CGAL_SSMD_USE_BLAS
#define CGAL_SSMD_CONFIGURATION_BLAS 2
#else
#define CGAL_SSMD_CONFIGURATION_BLAS 0
#endif
#ifdef CGAL_SSMD_USE_OPENBLAS
#define CGAL_SSMD_CONFIGURATION_OPENBLAS 4
#else
#define CGAL_SSMD_CONFIGURATION_OPENBLAS 0
#endif
#ifdef _OPENMP
#define CGAL_SSMD_CONFIGURATION_OPENMP 8
#else
#define CGAL_SSMD_CONFIGURATION_OPENMP 0
#endif

#define CGAL_SSMD_CONFIGURATION                                                                      \
  (CGAL_SSMD_CONFIGURATION_CHOLMOD + CGAL_SSMD_CONFIGURATION_BLAS + CGAL_SSMD_CONFIGURATION_OPENBLAS + \
   CGAL_SSMD_CONFIGURATION_OPENMP)

#if defined(CGAL_SSMD_COMPILED_CORE) && (CGAL_SSMD_COMPILED_CORE == CGAL_SSMD_CONFIGURATION)
#define CGAL_SSMD_USES_COMPILED_CORE 1
#else
#define CGAL_SSMD_USES_COMPILED_CORE 0
#endif

// The eigensolvers' functions that are not templates (declared in
// internal/Eigensolvers/NAME.h, defined in NAME_impl.h), as CGAL's
// CGAL_HEADER_ONLY and CGAL_INLINE_FUNCTION arrange its compiled parts: a
// translation unit that uses the compiled core sees their declarations only,
// and the core defines them once (CGAL_SSMD_COMPILING_CORE, set by its
// source file); a translation unit without it defines them inline. Their
// bodies instantiate much of Eigen's dense algebra whether or not they are
// called: they were half the compile time of a program that includes
// <CGAL/Spectral_surface_mesh_deformation.h> (benchmark/NOTES.md,
// 2026-12-07, fifth).
#if defined(CGAL_SSMD_COMPILING_CORE)
#define CGAL_SSMD_CORE_DEFINITIONS 1
#define CGAL_SSMD_CORE_FUNCTION
#elif CGAL_SSMD_USES_COMPILED_CORE
#define CGAL_SSMD_CORE_DEFINITIONS 0
#else
#define CGAL_SSMD_CORE_DEFINITIONS 1
#define CGAL_SSMD_CORE_FUNCTION inline
#endif

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_COMPILED_CORE_H

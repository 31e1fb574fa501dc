// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_VERSION_H
#define CGAL_SPECTRAL_DEFORMATION_VERSION_H

/// \file CGAL/Spectral_deformation/version.h
/// \ingroup PkgSpectralSurfaceMeshDeformationRef
/// The version of the package, for code that must compile against several
/// versions (CGAL's own version is `CGAL_VERSION_NR` in `<CGAL/version.h>`).
///
/// The top-level `CMakeLists.txt` reads these macros and stops at configure
/// time when they differ from the version of its `project()` command, so
/// that the header, the CMake package and `CHANGELOG.md` name one version.

/// \ingroup PkgSpectralSurfaceMeshDeformationRef
/// Major version: changes when the API changes in a way that can break
/// existing code (from 1.0 on).
#define CGAL_SSMD_VERSION_MAJOR 0

/// \ingroup PkgSpectralSurfaceMeshDeformationRef
/// Minor version: changes when features are added.
#define CGAL_SSMD_VERSION_MINOR 2

/// \ingroup PkgSpectralSurfaceMeshDeformationRef
/// Patch version: changes with fixes only.
#define CGAL_SSMD_VERSION_PATCH 0

/// \ingroup PkgSpectralSurfaceMeshDeformationRef
/// The version as a string, `"MAJOR.MINOR.PATCH"`.
#define CGAL_SSMD_VERSION_STR "0.2.0"

/// \ingroup PkgSpectralSurfaceMeshDeformationRef
/// The version as one number that grows with every version,
/// `MAJOR * 1000000 + MINOR * 1000 + PATCH` (2000 for 0.2.0), for
/// preprocessor tests such as `#if CGAL_SSMD_VERSION_NR >= 2000`.
#define CGAL_SSMD_VERSION_NR \
  (CGAL_SSMD_VERSION_MAJOR * 1000000 + CGAL_SSMD_VERSION_MINOR * 1000 + CGAL_SSMD_VERSION_PATCH)

#endif // CGAL_SPECTRAL_DEFORMATION_VERSION_H

// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_PIPELINES_FROM_HEADERS_H
#define CGAL_SPECTRAL_DEFORMATION_PIPELINES_FROM_HEADERS_H

/// \file Pipelines_from_headers.h
/// The definitions of the deformation pipelines, for a program that links the
/// package's compiled core (the CMake targets do) and deforms with traits
/// that the core does not hold: sparse solver traits other than the
/// defaults, or eigensolver traits other than
/// `Partition_of_unity_eigensolver_traits<>` and
/// `Block_lanczos_eigensolver_traits<>`. Include it before
/// `<CGAL/Spectral_surface_mesh_deformation.h>`; such a program compiles the
/// pipeline itself, as every program does without the compiled core.

#include <CGAL/Spectral_deformation/internal/Deformation/Spatial_pipeline.h>
#include <CGAL/Spectral_deformation/internal/Deformation/Spectral_pipeline.h>

#endif // CGAL_SPECTRAL_DEFORMATION_PIPELINES_FROM_HEADERS_H

// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_SHIFT_INVERT_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_SHIFT_INVERT_H

#include <CGAL/Spectral_deformation/internal/compiled_core.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>

namespace CGAL {
namespace Spectral_deformation {
namespace internal {
namespace Eigensolvers {

// The shift of both eigensolvers: negative and small against the low end of
// the spectrum (the first non-zero eigenvalue of a sphere of the same area is
// 8 pi / area), so that Q - sigma M is positive definite although Q is
// singular.
double shift_invert_shift(const Eigen::VectorXd& mass);

// Q - sigma M for the diagonal (lumped) mass matrix M.
Eigen::SparseMatrix<double> shifted_stiffness(const Eigen::SparseMatrix<double>& stiffness,
                                              const Eigen::VectorXd& mass, double sigma);

} // namespace Eigensolvers
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#if CGAL_SSMD_CORE_DEFINITIONS
#include <CGAL/Spectral_deformation/internal/Eigensolvers/Shift_invert_impl.h>
#endif

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_SHIFT_INVERT_H

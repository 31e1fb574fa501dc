// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_SHIFT_INVERT_IMPL_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_SHIFT_INVERT_IMPL_H

// The definitions of the functions declared in Shift_invert.h (see
// internal/compiled_core.h: the compiled core holds them).

#include <CGAL/Spectral_deformation/internal/Eigensolvers/Shift_invert.h>

namespace CGAL {
namespace Spectral_deformation {
namespace internal {
namespace Eigensolvers {

CGAL_SSMD_CORE_FUNCTION double shift_invert_shift(const Eigen::VectorXd& mass)
{
  return -1e-2 * 4.0 * 3.14159265358979323846 / mass.sum();
}

CGAL_SSMD_CORE_FUNCTION Eigen::SparseMatrix<double> shifted_stiffness(const Eigen::SparseMatrix<double>& stiffness,
                                                                      const Eigen::VectorXd& mass, double sigma)
{
  Eigen::SparseMatrix<double> shifted = stiffness;
  for(Eigen::Index i = 0; i < mass.size(); ++i)
    shifted.coeffRef(i, i) -= sigma * mass[i];
  return shifted;
}

} // namespace Eigensolvers
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_SHIFT_INVERT_IMPL_H

// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_DENSE_EIGENPAIRS_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_DENSE_EIGENPAIRS_H

#include <CGAL/Spectral_deformation/internal/compiled_core.h>
#include <CGAL/Spectral_deformation/internal/Eigensolvers/Symmetric_eigenpairs.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <string>

namespace CGAL {
namespace Spectral_deformation {
namespace internal {
namespace Eigensolvers {

/// The m smallest eigenpairs of `Q h = lambda M h`, `M = diag(mass)`, by a
/// dense symmetric eigensolver: for the small problems where an iterative
/// method has no advantage. Returns false with `message` set on failure.
bool dense_generalized_eigenpairs(const Eigen::SparseMatrix<double>& stiffness,
                                  const Eigen::VectorXd& mass, Eigen::Index m,
                                  Eigen::VectorXd& eigenvalues, Eigen::MatrixXd& eigenvectors,
                                  std::string& message);

} // namespace Eigensolvers
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#if CGAL_SSMD_CORE_DEFINITIONS
#include <CGAL/Spectral_deformation/internal/Eigensolvers/dense_eigenpairs_impl.h>
#endif

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_DENSE_EIGENPAIRS_H

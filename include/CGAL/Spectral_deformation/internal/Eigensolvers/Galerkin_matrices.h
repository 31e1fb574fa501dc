// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_GALERKIN_MATRICES_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_GALERKIN_MATRICES_H

#include <CGAL/Spectral_deformation/internal/available_threads.h>
#include <CGAL/Spectral_deformation/internal/compiled_core.h>
#include <CGAL/Spectral_deformation/internal/Eigensolvers/Parallel_exception.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <algorithm>
#include <cstddef>
#include <memory>
#include <vector>

namespace CGAL {
namespace Spectral_deformation {
namespace internal {
namespace Eigensolvers {

// The most consecutive columns of P with the same rows that are done
// together: a bound known at compile time keeps their values of one row in
// arrays on the stack.
constexpr Eigen::Index galerkin_group_width = 4;

// The first column of each group of consecutive columns of `functions` with
// the same rows (the functions of one sample), at most
// `galerkin_group_width` of them, followed by the number of columns.
std::vector<Eigen::Index> same_support_groups(const Eigen::SparseMatrix<double>& functions);

// One column of Pᵀ Q P and of Pᵀ M P: its rows, sorted, and their values.
struct Galerkin_column
{
  std::vector<Eigen::Index> indices;
  std::vector<double> stiffness, mass;
};

// The work arrays of one thread, left zero after each group.
struct Galerkin_work
{
  Galerkin_work(Eigen::Index n, Eigen::Index k)
    : applied(static_cast<std::size_t>(n * galerkin_group_width), 0.0), reached(static_cast<std::size_t>(n), 0),
      stiffness_sum(static_cast<std::size_t>(k * galerkin_group_width), 0.0),
      mass_sum(static_cast<std::size_t>(k * galerkin_group_width), 0.0), touched(static_cast<std::size_t>(k), 0)
  {}
  std::vector<double> applied; // Q p_j, j in the group
  std::vector<char> reached;
  std::vector<Eigen::Index> ring;
  std::vector<double> stiffness_sum; // Pᵀ Q p_j
  std::vector<double> mass_sum;      // Pᵀ M p_j
  std::vector<char> touched;
  std::vector<Eigen::Index> touched_list;
};

// The columns [first, first + width) of Pᵀ Q P and Pᵀ M P into `columns`,
// for columns of P with the same rows: Q p_j and M p_j are summed over
// those rows, then Pᵀ is applied to them on the rows of P they reach.
void galerkin_columns_of_group(const Eigen::SparseMatrix<double>& stiffness, const Eigen::VectorXd& mass,
                               const Eigen::SparseMatrix<double>& functions,
                               const Eigen::SparseMatrix<double, Eigen::RowMajor>& rows, Eigen::Index first,
                               Eigen::Index width, Galerkin_work& work, std::vector<Galerkin_column>& columns);

// Pᵀ Q P and Pᵀ M P from their `columns`.
void assemble_galerkin_matrices(const std::vector<Galerkin_column>& columns,
                                Eigen::SparseMatrix<double>& reduced_stiffness,
                                Eigen::SparseMatrix<double>& reduced_mass);

// The Galerkin matrices Pᵀ Q P and Pᵀ M P (M = diag(mass)), column by column
// on all threads: column j is Pᵀ (Q p_j), where Q p_j lives on the support
// of p_j and one ring around it, and Pᵀ applied to it reads the rows of P
// there. Consecutive columns with the same support (the functions of one
// sample) are done together, so that those rows are read once for all of
// them. This touches far fewer entries than a general sparse product, which
// also runs on one thread only.
void galerkin_matrices(const Eigen::SparseMatrix<double>& stiffness,
                       const Eigen::VectorXd& mass,
                       const Eigen::SparseMatrix<double>& functions,
                       const Eigen::SparseMatrix<double, Eigen::RowMajor>& rows,
                       Eigen::SparseMatrix<double>& reduced_stiffness,
                       Eigen::SparseMatrix<double>& reduced_mass);

} // namespace Eigensolvers
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#if CGAL_SSMD_CORE_DEFINITIONS
#include <CGAL/Spectral_deformation/internal/Eigensolvers/Galerkin_matrices_impl.h>
#endif

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_GALERKIN_MATRICES_H

// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Must not compile: traits classes that miss a member their concept
// requires, or that declare an optional group of members without them; each
// must stop at the static_assert that names the member (checked by
// check_compile_fail.cmake).
#include <CGAL/Manifold_harmonics_basis.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Spectral_deformation/Partition_of_unity_eigensolver_traits.h>
#include <CGAL/Surface_mesh.h>

typedef CGAL::Surface_mesh<CGAL::Simple_cartesian<double>::Point_3> Mesh;
typedef CGAL::Eigen_sparse_spd_solver_traits<Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>> Eigen_solver;

// SparseSPDSolverTraits without solve().
struct Sparse_solver_without_solve
{
  bool factor(const Eigen::SparseMatrix<double>&) { return true; }
};

// Declares row updates, with the member misspelled.
struct Sparse_solver_with_a_misspelled_option : Eigen_solver
{
  typedef CGAL::Tag_true Supports_row_updates;
  bool refactor_row(const Eigen::SparseMatrix<double>& A, const std::vector<int>&) { return factor(A); }
};

// ManifoldHarmonicsEigensolverTraits without error_message().
struct Eigensolver_without_error_message
{
  bool compute(const Eigen::SparseMatrix<double>&, const Eigen::VectorXd&, Eigen::Index, Eigen::VectorXd&,
               Eigen::MatrixXd&)
  {
    return false;
  }
};

// Declares that it takes the vertex positions, without the member.
struct Eigensolver_without_positions : CGAL::Block_lanczos_eigensolver_traits<>
{
  typedef CGAL::Tag_true Uses_vertex_positions;
};

// Declares eigenvectors in float, without the member.
struct Eigensolver_without_float_eigenvectors : CGAL::Block_lanczos_eigensolver_traits<>
{
  typedef CGAL::Tag_true Supports_single_precision_eigenvectors;
};

int main()
{
  CGAL::Block_lanczos_eigensolver_traits<Sparse_solver_without_solve> a;
  CGAL::Partition_of_unity_eigensolver_traits<Sparse_solver_with_a_misspelled_option> b;
  CGAL::Manifold_harmonics_basis<Mesh, Eigensolver_without_error_message> c;
  CGAL::Manifold_harmonics_basis<Mesh, Eigensolver_without_positions> d;
  CGAL::Manifold_harmonics_basis<Mesh, Eigensolver_without_float_eigenvectors> e;
  return 0;
}

// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Must not compile: each instantiation below is a mistake a program written
// for CGAL's class can make, and each must stop at the static_assert that
// says what to write instead (checked by check_compile_fail.cmake).
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Spectral_surface_mesh_deformation.h>
#include <CGAL/Surface_mesh.h>

typedef CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> Mesh;

// A constraint policy where the algorithm goes.
typedef CGAL::Spectral_surface_mesh_deformation<Mesh, CGAL::Default, CGAL::Default, CGAL::SOFT_CONSTRAINTS>
    Wrong_tag;
// A sparse solver where the eigensolver (or CGAL's weight calculator) goes.
typedef CGAL::Spectral_surface_mesh_deformation<Mesh, CGAL::Default, CGAL::Default, CGAL::SPECTRAL_DUAL_LAPLACIAN,
                                                CGAL::Default_sparse_spd_solver_traits>
    Wrong_eigensolver;
// An eigensolver where the sparse solver goes.
typedef CGAL::Spectral_surface_mesh_deformation<Mesh, CGAL::Default, CGAL::Default, CGAL::SPECTRAL_DUAL_LAPLACIAN,
                                                CGAL::Default, CGAL::Block_lanczos_eigensolver_traits<>>
    Wrong_sparse_solver;
// A sparse solver whose solve() is not const.
struct Non_const_solve
{
  bool factor(const Eigen::SparseMatrix<double>&) { return true; }
  bool solve(const Eigen::MatrixXd&, Eigen::MatrixXd&) { return true; }
};
typedef CGAL::Spectral_surface_mesh_deformation<Mesh, CGAL::Default, CGAL::Default, CGAL::SPECTRAL_DUAL_LAPLACIAN,
                                                CGAL::Default, Non_const_solve>
    Sparse_solver_missing_a_member;

int main()
{
  Mesh mesh;
  Wrong_tag a(mesh);
  Wrong_eigensolver b(mesh);
  Wrong_sparse_solver c(mesh);
  Sparse_solver_missing_a_member d(mesh);
  return 0;
}

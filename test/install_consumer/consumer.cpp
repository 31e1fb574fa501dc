// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Deforms a flat grid with the installed package: one side fixed, the other
// lifted. Checks the lifted side reached its target, the middle followed,
// and the program was compiled with the back-ends its build asked for.
// The spatial algorithm instantiates no eigensolver, the shortest compile of
// the five builds of scripts/test_install.sh; the test suite compiles the
// others.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Spectral_deformation/version.h>
#include <CGAL/Spectral_surface_mesh_deformation.h>
#include <CGAL/Surface_mesh.h>

#include <cmath>
#include <iostream>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;
typedef Mesh::Vertex_index Vertex;

#ifdef CGAL_SSMD_USE_CHOLMOD
constexpr bool has_cholmod = true;
#else
constexpr bool has_cholmod = false;
#endif
#ifdef CGAL_SSMD_USE_OPENBLAS
constexpr bool has_openblas = true;
#else
constexpr bool has_openblas = false;
#endif
#ifdef _OPENMP
constexpr bool has_openmp = true;
#else
constexpr bool has_openmp = false;
#endif
static_assert(has_cholmod == bool(SSMD_EXPECT_CHOLMOD), "CHOLMOD: not what the build asked for");
static_assert(has_openblas == bool(SSMD_EXPECT_OpenBLAS), "OpenBLAS: not what the build asked for");
static_assert(has_openmp == bool(SSMD_EXPECT_OpenMP), "OpenMP: not what the build asked for");
// The targets link the compiled core of the components asked for, and the
// consumer, compiled with the same ones, uses it instead of compiling the
// pipelines.
static_assert(CGAL_SSMD_USES_COMPILED_CORE, "the compiled core of the components is not used");
static_assert(CGAL_SSMD_VERSION_NR >= 2000, "the version header names 0.2.0 or later");

int main()
{
  const int n = 12; // cells per side of the unit square
  Mesh mesh;
  std::vector<Vertex> grid;
  for(int j = 0; j <= n; ++j)
    for(int i = 0; i <= n; ++i)
      grid.push_back(mesh.add_vertex(Kernel::Point_3(double(i) / n, double(j) / n, 0)));
  const auto at = [&](int i, int j) { return grid[j * (n + 1) + i]; };
  for(int j = 0; j < n; ++j)
    for(int i = 0; i < n; ++i)
    {
      mesh.add_face(at(i, j), at(i + 1, j), at(i + 1, j + 1));
      mesh.add_face(at(i, j), at(i + 1, j + 1), at(i, j + 1));
    }

  // Column 0 stays outside the region of interest (fixed), column n is the handle.
  CGAL::Spectral_surface_mesh_deformation<Mesh, CGAL::Default, CGAL::Default, CGAL::SPATIAL_DUAL_LAPLACIAN>
      deformation(mesh);
  for(int j = 0; j <= n; ++j)
    for(int i = 1; i <= n; ++i)
      deformation.insert_roi_vertex(at(i, j));
  for(int j = 0; j <= n; ++j)
    deformation.insert_control_vertex(at(n, j));
  const Kernel::Vector_3 lift(0, 0, 0.25);
  for(int j = 0; j <= n; ++j)
    deformation.set_target_position(at(n, j), mesh.point(at(n, j)) + lift);
  deformation.deform();
  if(!deformation.deform_report().success)
  {
    std::cerr << "deform() failed: " << deformation.deform_report().message << "\n";
    return 1;
  }

  const double handle_z = mesh.point(at(n, n / 2)).z();
  const double middle_z = mesh.point(at(n / 2, n / 2)).z();
  const double fixed_z = mesh.point(at(0, n / 2)).z();
  std::cout << "SSMD " << CGAL_SSMD_VERSION_STR << " (CHOLMOD " << has_cholmod << ", OpenBLAS "
            << has_openblas << ", OpenMP " << has_openmp << "): handle z = " << handle_z
            << ", middle z = " << middle_z << ", fixed z = " << fixed_z << "\n";
  const bool ok = std::abs(handle_z - 0.25) < 1e-6 && middle_z > 0.01 && middle_z < 0.25 && fixed_z == 0;
  return ok ? 0 : 1;
}

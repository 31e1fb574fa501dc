// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
// A program that includes only the main header and deforms with the default
// algorithm and traits: its compile time and the libraries it links are what
// a new user of the package pays. Timed by time_compile.sh.
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Spectral_surface_mesh_deformation.h>

#include <iostream>

typedef CGAL::Simple_cartesian<double> Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;

int main(int argc, char** argv)
{
  Mesh mesh;
  if(argc < 2 || !CGAL::IO::read_polygon_mesh(argv[1], mesh))
    return 1;
  CGAL::Spectral_surface_mesh_deformation<Mesh> deformation(mesh);
  deformation.insert_roi_vertices(vertices(mesh).begin(), vertices(mesh).end());
  deformation.insert_control_vertex(*vertices(mesh).begin());
  deformation.translate(*vertices(mesh).begin(), Kernel::Vector_3(0, 0, 0.1));
  deformation.deform();
  std::cout << deformation.deform_report().iterations << std::endl;
  return 0;
}

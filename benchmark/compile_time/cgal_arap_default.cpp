// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
// The program of main_header_default_tag.cpp written for CGAL's
// Surface_mesh_deformation (ARAP, its default solver): the yardstick of the
// compile time, timed by time_compile.sh in the same run.
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_deformation.h>

#include <iostream>

typedef CGAL::Simple_cartesian<double> Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;

int main(int argc, char** argv)
{
  Mesh mesh;
  if(argc < 2 || !CGAL::IO::read_polygon_mesh(argv[1], mesh))
    return 1;
  CGAL::Surface_mesh_deformation<Mesh> deformation(mesh);
  deformation.insert_roi_vertices(vertices(mesh).begin(), vertices(mesh).end());
  deformation.insert_control_vertex(*vertices(mesh).begin());
  deformation.translate(*vertices(mesh).begin(), Kernel::Vector_3(0, 0, 0.1));
  deformation.deform();
  std::cout << deformation.iterations() << std::endl;
  return 0;
}

// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
// An OpenMesh mesh deformed through CGAL's graph traits for OpenMesh: the
// whole mesh is the region of interest, the vertex of largest y is moved up by
// a tenth of the height and the vertex of smallest y stays where it is. The
// mesh is read and written with OpenMesh's own IO.
//
// OpenMesh's default traits store float points, and CGAL's vertex point map
// of an OpenMesh mesh hands out CGAL points (Epick) and writes through float:
// the deformation computes in double, the mesh keeps float. For points kept in
// double, see the manual (OpenMesh::Vec3d and CGAL_USE_OM_POINTS).
//
// Usage: openmesh_example mesh.off [output.off]
#include <CGAL/boost/graph/graph_traits_TriMesh_ArrayKernelT.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/Spectral_surface_mesh_deformation.h>

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <vector>

typedef OpenMesh::TriMesh_ArrayKernelT<> Mesh;
typedef boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
typedef CGAL::Spectral_surface_mesh_deformation<Mesh> Deformation;
typedef Deformation::Point Point;

int main(int argc, char** argv)
{
  if(argc < 2)
  {
    std::cerr << "usage: " << argv[0] << " mesh.off [output.off]\n";
    return EXIT_FAILURE;
  }
  Mesh mesh;
  if(!OpenMesh::IO::read_mesh(mesh, argv[1]) || !CGAL::is_triangle_mesh(mesh))
  {
    std::cerr << "cannot read a triangle mesh from " << argv[1] << "\n";
    return EXIT_FAILURE;
  }

  Deformation deformation(mesh);
  const std::vector<vertex_descriptor> all(vertices(mesh).begin(), vertices(mesh).end());
  deformation.insert_roi_vertices(all.begin(), all.end());

  auto y = [&](vertex_descriptor v) { return get(CGAL::vertex_point, mesh, v).y(); };
  auto by_y = [&](vertex_descriptor a, vertex_descriptor b) { return y(a) < y(b); };
  const vertex_descriptor top = *std::max_element(all.begin(), all.end(), by_y);
  const vertex_descriptor bottom = *std::min_element(all.begin(), all.end(), by_y);
  deformation.insert_control_vertex(top);
  deformation.insert_control_vertex(bottom);

  const Point p = get(CGAL::vertex_point, mesh, top);
  const Point target(p.x(), p.y() + 0.1 * (y(top) - y(bottom)), p.z());
  deformation.set_target_position(top, target);
  deformation.deform();
  if(!deformation.deform_report().success)
  {
    std::cerr << "deform failed: " << deformation.deform_report().message << "\n";
    return EXIT_FAILURE;
  }

  // The control vertex is on its target, to the float rounding of the mesh.
  const double miss = std::sqrt(CGAL::squared_distance(get(CGAL::vertex_point, mesh, top), target));
  std::cout << mesh.n_vertices() << " vertices deformed in " << deformation.deform_report().iterations
            << " iterations; the moved vertex is " << miss << " from its target\n";
  if(!(miss <= 1e-5 * (y(top) - y(bottom))))
  {
    std::cerr << "the moved vertex missed its target\n";
    return EXIT_FAILURE;
  }
  if(argc > 2 && !OpenMesh::IO::write_mesh(mesh, argv[2]))
  {
    std::cerr << "cannot write " << argv[2] << "\n";
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}

// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
// The whole mesh is the region of interest; two vertices are control
// vertices: one is moved, the other one stays. The same generic code runs on
// a Surface_mesh and on a Polyhedron_3 with vertex ids, and both give the same
// positions.
//
// Usage: all_roi_example mesh.off [output.off]
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Polyhedron_items_with_id_3.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Spectral_surface_mesh_deformation.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <cstdlib>
#include <iostream>
#include <iterator>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Surface_mesh;
typedef CGAL::Polyhedron_3<Kernel, CGAL::Polyhedron_items_with_id_3> Polyhedron;

template <class Mesh>
bool deform(Mesh& mesh, std::vector<Point>& result)
{
  typedef CGAL::Spectral_surface_mesh_deformation<Mesh> Deformation;
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;

  Deformation deformation(mesh);
  const std::vector<vertex_descriptor> all(vertices(mesh).begin(), vertices(mesh).end());
  deformation.insert_roi_vertices(all.begin(), all.end());

  // The vertex of largest y moves up by a tenth of the height; the vertex of
  // smallest y stays where it is.
  auto y = [&](vertex_descriptor v) { return get(CGAL::vertex_point, mesh, v).y(); };
  const vertex_descriptor top = *std::max_element(all.begin(), all.end(),
                                                  [&](auto a, auto b) { return y(a) < y(b); });
  const vertex_descriptor bottom = *std::min_element(all.begin(), all.end(),
                                                     [&](auto a, auto b) { return y(a) < y(b); });
  deformation.insert_control_vertex(top);
  deformation.insert_control_vertex(bottom);
  if(!deformation.preprocess())
  {
    std::cerr << "preprocess failed: " << deformation.preprocess_report().message << "\n";
    return false;
  }
  const Point p = get(CGAL::vertex_point, mesh, top);
  deformation.set_target_position(top, Point(p.x(), p.y() + 0.1 * (y(top) - y(bottom)), p.z()));
  deformation.deform(); // also possible: deformation.deform(iterations, tolerance)
  if(!deformation.deform_report().success)
  {
    std::cerr << "deform failed: " << deformation.deform_report().message << "\n";
    return false;
  }
  std::cout << "deformed in " << deformation.deform_report().iterations << " iterations, "
            << deformation.deform_report().total_seconds << " s\n";
  result.clear();
  for(vertex_descriptor v : all)
    result.push_back(get(CGAL::vertex_point, mesh, v));
  return true;
}

int main(int argc, char** argv)
{
  if(argc < 2)
  {
    std::cerr << "usage: " << argv[0] << " mesh.off [output.off]\n";
    return EXIT_FAILURE;
  }
  Surface_mesh surface_mesh;
  Polyhedron polyhedron;
  if(!CGAL::IO::read_polygon_mesh(argv[1], surface_mesh) ||
     !CGAL::IO::read_polygon_mesh(argv[1], polyhedron))
  {
    std::cerr << "cannot read " << argv[1] << "\n";
    return EXIT_FAILURE;
  }
  CGAL::set_halfedgeds_items_id(polyhedron);

  std::vector<Point> from_surface_mesh, from_polyhedron;
  if(!deform(surface_mesh, from_surface_mesh) || !deform(polyhedron, from_polyhedron))
    return EXIT_FAILURE;
  if(from_surface_mesh != from_polyhedron)
  {
    std::cerr << "Surface_mesh and Polyhedron_3 disagree\n";
    return EXIT_FAILURE;
  }
  std::cout << "Surface_mesh and Polyhedron_3 give the same positions\n";
  if(argc > 2 && !CGAL::IO::write_polygon_mesh(argv[2], surface_mesh, CGAL::parameters::stream_precision(17)))
    return EXIT_FAILURE;
  return EXIT_SUCCESS;
}

// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Deforms a Polyhedron_3 without vertex ids through property maps of the
// user's own: the vertex and halfedge indices are stored in std::maps (as in
// CGAL's Surface_mesh_deformation example with custom property maps), and
// the positions are read from and written to a std::map as well, so that the
// polyhedron itself keeps its rest shape. The result is checked against the
// same deformation of a Surface_mesh with the default maps.
//
// Usage: custom_property_maps_example mesh.off [output.off]
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Spectral_surface_mesh_deformation.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <map>
#include <set>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point;
typedef Kernel::Vector_3 Vector;
typedef CGAL::Polyhedron_3<Kernel> Polyhedron;
typedef CGAL::Surface_mesh<Point> Surface_mesh;

typedef boost::graph_traits<Polyhedron>::vertex_descriptor vertex_descriptor;
typedef boost::graph_traits<Polyhedron>::halfedge_descriptor halfedge_descriptor;

// The user's own maps: indices and positions keyed by the descriptors.
typedef std::map<vertex_descriptor, std::size_t> Vertex_index_storage;
typedef boost::associative_property_map<Vertex_index_storage> Vertex_index_map;
typedef std::map<halfedge_descriptor, std::size_t> Halfedge_index_storage;
typedef boost::associative_property_map<Halfedge_index_storage> Halfedge_index_map;
typedef std::map<vertex_descriptor, Point> Position_storage;
typedef boost::associative_property_map<Position_storage> Vertex_point_map;

// The algorithm and the traits keep their defaults; the point map is the
// last template parameter, as in CGAL's Surface_mesh_deformation.
typedef CGAL::Spectral_surface_mesh_deformation<Polyhedron, Vertex_index_map, Halfedge_index_map,
                                                CGAL::SPECTRAL_DUAL_LAPLACIAN, CGAL::Default,
                                                CGAL::Default, CGAL::Default, Vertex_point_map>
    Polyhedron_deformation;
typedef CGAL::Spectral_surface_mesh_deformation<Surface_mesh> Surface_mesh_deformation;

// The region of interest and the handle, as vertex numbers given by `index`:
// the handle is the vertex of largest y and its neighbours, the region of
// interest the vertices at most `rings` edges away from it.
template <class Mesh, class IndexOf>
void select_vertices(const Mesh& mesh, IndexOf index, std::size_t rings,
                     std::vector<std::size_t>& roi, std::vector<std::size_t>& handle)
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor Vertex;
  std::vector<Vertex> all(vertices(mesh).begin(), vertices(mesh).end());
  const Vertex top = *std::max_element(all.begin(), all.end(), [&](Vertex a, Vertex b) {
    return get(CGAL::vertex_point, mesh, a).y() < get(CGAL::vertex_point, mesh, b).y();
  });
  std::set<Vertex> reached = {top};
  std::vector<Vertex> front = {top};
  for(std::size_t ring = 0; ring < rings; ++ring)
  {
    std::vector<Vertex> next;
    for(Vertex v : front)
      for(Vertex w : CGAL::vertices_around_target(v, mesh))
        if(reached.insert(w).second)
          next.push_back(w);
    if(ring == 0)
    {
      handle.push_back(index(top));
      for(Vertex w : next)
        handle.push_back(index(w));
    }
    front.swap(next);
  }
  for(Vertex v : reached)
    roi.push_back(index(v));
  std::sort(roi.begin(), roi.end());
  std::sort(handle.begin(), handle.end());
}

int main(int argc, char** argv)
{
  if(argc < 2)
  {
    std::cerr << "usage: " << argv[0] << " mesh.off [output.off]\n";
    return EXIT_FAILURE;
  }
  Polyhedron polyhedron;
  Surface_mesh surface_mesh;
  if(!CGAL::IO::read_polygon_mesh(argv[1], polyhedron) ||
     !CGAL::IO::read_polygon_mesh(argv[1], surface_mesh) || !CGAL::is_triangle_mesh(polyhedron))
  {
    std::cerr << "cannot read a triangle mesh from " << argv[1] << "\n";
    return EXIT_FAILURE;
  }

  // Fill the user's maps: indices in the traversal order (the order of the
  // file), positions copied from the polyhedron.
  Vertex_index_storage vertex_indices;
  Vertex_index_map vertex_index_map(vertex_indices);
  Position_storage positions;
  Vertex_point_map vertex_point_map(positions);
  std::vector<vertex_descriptor> vertex_of;
  for(vertex_descriptor v : vertices(polyhedron))
  {
    put(vertex_index_map, v, vertex_of.size());
    put(vertex_point_map, v, v->point());
    vertex_of.push_back(v);
  }
  Halfedge_index_storage halfedge_indices;
  Halfedge_index_map halfedge_index_map(halfedge_indices);
  std::size_t counter = 0;
  for(halfedge_descriptor h : halfedges(polyhedron))
    put(halfedge_index_map, h, counter++);

  std::vector<std::size_t> roi, handle;
  select_vertices(polyhedron, [&](vertex_descriptor v) { return get(vertex_index_map, v); }, 8,
                  roi, handle);
  const Vector lift(0, 0.1, 0.05);

  // The polyhedron, through the user's maps.
  Polyhedron_deformation deformation(polyhedron, vertex_index_map, halfedge_index_map,
                                     vertex_point_map);
  for(std::size_t i : roi)
    deformation.insert_roi_vertex(vertex_of[i]);
  for(std::size_t i : handle)
    deformation.insert_control_vertex(vertex_of[i]);
  for(std::size_t i : handle)
    deformation.translate(vertex_of[i], lift);
  deformation.deform();
  if(!deformation.deform_report().success)
  {
    std::cerr << "the deformation of the polyhedron failed: " << deformation.deform_report().message
              << "\n";
    return EXIT_FAILURE;
  }

  // The same deformation of the Surface_mesh, with its default maps. Both
  // meshes number their vertices in the order of the file.
  Surface_mesh_deformation reference(surface_mesh);
  for(std::size_t i : roi)
    reference.insert_roi_vertex(Surface_mesh::Vertex_index(static_cast<Surface_mesh::size_type>(i)));
  for(std::size_t i : handle)
  {
    const Surface_mesh::Vertex_index v(static_cast<Surface_mesh::size_type>(i));
    reference.insert_control_vertex(v);
    reference.translate(v, lift);
  }
  reference.deform();
  if(!reference.deform_report().success)
  {
    std::cerr << "the deformation of the surface mesh failed: " << reference.deform_report().message
              << "\n";
    return EXIT_FAILURE;
  }

  // The deformed positions are in the user's point map; the polyhedron's own
  // points are untouched.
  // (A polyhedron moved in place would show no motion at all.)
  double largest_difference = 0, largest_motion = 0;
  for(std::size_t i = 0; i < vertex_of.size(); ++i)
  {
    const Point& mine = get(vertex_point_map, vertex_of[i]);
    const Point& rest = vertex_of[i]->point();
    const Point& theirs =
        surface_mesh.point(Surface_mesh::Vertex_index(static_cast<Surface_mesh::size_type>(i)));
    largest_difference = (std::max)(largest_difference, std::sqrt(CGAL::squared_distance(mine, theirs)));
    largest_motion = (std::max)(largest_motion, std::sqrt(CGAL::squared_distance(mine, rest)));
  }
  std::cout << roi.size() << " vertices in the region of interest, " << handle.size()
            << " control vertices lifted by " << std::sqrt(lift.squared_length()) << "\n"
            << "largest motion: " << largest_motion << "\n"
            << "largest difference between the polyhedron with custom maps and the surface mesh: "
            << largest_difference << "\n";
  if(largest_motion < 0.5 * std::sqrt(lift.squared_length()) || largest_difference > 1e-9)
  {
    std::cerr << "the two deformations disagree\n";
    return EXIT_FAILURE;
  }

  if(argc > 2)
  {
    // Write the result: copy the positions of the user's map into the polyhedron.
    for(vertex_descriptor v : vertices(polyhedron))
      v->point() = get(vertex_point_map, v);
    if(!CGAL::IO::write_polygon_mesh(argv[2], polyhedron, CGAL::parameters::stream_precision(17)))
    {
      std::cerr << "cannot write " << argv[2] << "\n";
      return EXIT_FAILURE;
    }
    std::cout << "wrote " << argv[2] << "\n";
  }
  return EXIT_SUCCESS;
}

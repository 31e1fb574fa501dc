// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
// A region of interest made of the k-ring of a vertex, its 1-ring as control
// vertices; the targets are translated, then rotated, then deformed again:
// each deform() continues from the previous result and reuses the basis.
//
// Usage: k_ring_roi_translate_rotate_example mesh.off [output.off]
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Spectral_surface_mesh_deformation.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/boost/graph/iterator.h>

#include <Eigen/Geometry>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <iterator>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;
typedef Mesh::Vertex_index vertex_descriptor;
typedef CGAL::Spectral_surface_mesh_deformation<Mesh> Deformation;

namespace {

// The vertices within `k` rings of `seed`, by breadth-first search.
std::vector<vertex_descriptor> k_ring(const Mesh& mesh, vertex_descriptor seed, unsigned int k)
{
  std::vector<vertex_descriptor> ring = {seed};
  std::vector<bool> seen(mesh.number_of_vertices(), false);
  seen[seed.idx()] = true;
  std::size_t begin = 0;
  for(unsigned int step = 0; step < k; ++step)
  {
    const std::size_t end = ring.size();
    for(std::size_t i = begin; i < end; ++i)
      for(vertex_descriptor w : CGAL::vertices_around_target(mesh.halfedge(ring[i]), mesh))
        if(!seen[w.idx()])
        {
          seen[w.idx()] = true;
          ring.push_back(w);
        }
    begin = end;
  }
  return ring;
}

} // namespace

int main(int argc, char** argv)
{
  if(argc < 2)
  {
    std::cerr << "usage: " << argv[0] << " mesh.off [output.off]\n";
    return EXIT_FAILURE;
  }
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(argv[1], mesh) || !CGAL::is_triangle_mesh(mesh))
  {
    std::cerr << "cannot read a triangle mesh from " << argv[1] << "\n";
    return EXIT_FAILURE;
  }
  const vertex_descriptor seed = *mesh.vertices().begin();
  const std::vector<vertex_descriptor> roi = k_ring(mesh, seed, 8);
  const std::vector<vertex_descriptor> control = k_ring(mesh, seed, 1);

  Deformation deformation(mesh);
  deformation.insert_roi_vertices(roi.begin(), roi.end());
  deformation.insert_control_vertices(control.begin(), control.end());
  if(!deformation.preprocess())
  {
    std::cerr << "preprocess failed: " << deformation.preprocess_report().message << "\n";
    return EXIT_FAILURE;
  }
  std::cout << "region of " << deformation.preprocess_report().number_of_region_vertices
            << " vertices, " << deformation.preprocess_report().number_of_frequencies
            << " frequencies\n";

  // Pull the control vertices along the normal direction of the seed's
  // neighbourhood, by a quarter of the size of the ROI.
  const Kernel::Vector_3 normal = CGAL::Polygon_mesh_processing::compute_vertex_normal(seed, mesh);
  double extent = 0;
  for(vertex_descriptor v : roi)
    extent = std::max(extent, std::sqrt(CGAL::squared_distance(mesh.point(v), mesh.point(seed))));
  const Eigen::Vector3d pull(0.25 * extent * normal.x(), 0.25 * extent * normal.y(),
                             0.25 * extent * normal.z());
  deformation.translate(control.begin(), control.end(), pull);
  deformation.deform();
  std::cout << "translated: " << deformation.deform_report().iterations << " iterations\n";

  // Then turn them by 45 degrees about the normal, around the seed.
  const Kernel::Point_3& center = deformation.target_position(seed);
  const Eigen::Quaternion<double> quarter(
      Eigen::AngleAxisd(CGAL_PI / 4, Eigen::Vector3d(normal.x(), normal.y(), normal.z()).normalized()));
  deformation.rotate(control.begin(), control.end(), Eigen::Vector3d(center.x(), center.y(), center.z()),
                     quarter);
  deformation.deform();
  std::cout << "rotated: " << deformation.deform_report().iterations << " iterations, basis reused: "
            << (deformation.preprocess_report().basis_computed ? "no" : "yes") << "\n";
  if(!deformation.deform_report().success)
  {
    std::cerr << "deform failed: " << deformation.deform_report().message << "\n";
    return EXIT_FAILURE;
  }
  if(argc > 2 && !CGAL::IO::write_polygon_mesh(argv[2], mesh, CGAL::parameters::stream_precision(17)))
    return EXIT_FAILURE;
  return EXIT_SUCCESS;
}

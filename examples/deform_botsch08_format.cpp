// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Deforms a mesh given in the format of the Botsch and Sorkine 2008 benchmark:
// mesh.off, mesh.sel (one status per vertex: 0 fixed, 1 region of interest,
// 2 handle) and mesh.def (a 4x4 matrix moving the handle), and writes the
// deformed mesh and the smooth shapes of the pipeline.
//
// Usage: deform_botsch08_format mesh.off mesh.sel mesh.def output_dir [m]
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Spectral_surface_mesh_deformation.h>
#include <CGAL/Spectral_deformation/IO/deformation_selection.h>
#include <CGAL/Surface_mesh.h>

#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef CGAL::Spectral_surface_mesh_deformation<Mesh> Deformation;

namespace {

// Writes a copy of `mesh` whose points are given by `position`.
template <class PositionOf>
bool write_shape(const Mesh& mesh, const std::filesystem::path& file, PositionOf position)
{
  Mesh copy = mesh;
  for(Mesh::Vertex_index v : copy.vertices())
    copy.point(v) = position(v);
  return CGAL::IO::write_polygon_mesh(file.string(), copy, CGAL::parameters::stream_precision(17));
}

} // namespace

int main(int argc, char** argv)
{
  if(argc < 5)
  {
    std::cerr << "usage: " << argv[0] << " mesh.off mesh.sel mesh.def output_dir [m]\n";
    return EXIT_FAILURE;
  }
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(argv[1], mesh) || !CGAL::is_triangle_mesh(mesh))
  {
    std::cerr << "cannot read a triangle mesh from " << argv[1] << "\n";
    return EXIT_FAILURE;
  }
  const std::filesystem::path output_dir = argv[4];
  std::filesystem::create_directories(output_dir);

  Deformation deformation(mesh);
  // A program that owns its process may let the solvers change process-wide
  // state to run faster (OpenBLAS threads, SuiteSparse's allocator); a
  // library embedding the package should not.
  Deformation::Eigensolver_traits eigensolver;
  eigensolver.set_process_wide_tuning(true);
  deformation.set_eigensolver_traits(eigensolver);
  try
  {
    const auto status = CGAL::IO::read_selection(argv[2], mesh.number_of_vertices());
    const Eigen::Matrix4d handle_motion = CGAL::IO::read_handle_transformation(argv[3]);
    if(argc > 5)
      deformation.set_number_of_frequencies(std::stoul(argv[5]));

    // Vertices of a freshly read Surface_mesh are indexed in file order.
    for(Mesh::Vertex_index v : mesh.vertices())
      if(status[v.idx()] != CGAL::IO::FIXED_VERTEX)
        deformation.insert_roi_vertex(v);
    for(Mesh::Vertex_index v : mesh.vertices())
      if(status[v.idx()] == CGAL::IO::HANDLE_VERTEX)
        deformation.insert_control_vertex(v);

    if(!deformation.preprocess())
    {
      std::cerr << "preprocess failed: " << deformation.preprocess_report().message << "\n";
      return EXIT_FAILURE;
    }
    const CGAL::Spectral_preprocess_report& pre = deformation.preprocess_report();
    std::cout << "preprocess: " << pre.number_of_region_vertices << " region vertices, "
              << pre.number_of_frequencies << " frequencies, basis " << pre.basis_seconds
              << " s, region total " << pre.region_seconds << " s, factorization "
              << pre.factorization_seconds << " s\n";

    for(Mesh::Vertex_index v : mesh.vertices())
      if(status[v.idx()] == CGAL::IO::HANDLE_VERTEX)
      {
        const Point& p = mesh.point(v);
        const Eigen::Vector4d q = handle_motion * Eigen::Vector4d(p.x(), p.y(), p.z(), 1.0);
        deformation.set_target_position(v, Point(q[0], q[1], q[2]));
      }
  }
  catch(const CGAL::Spectral_deformation_error& e)
  {
    std::cerr << "error: " << e.what() << "\n";
    return EXIT_FAILURE;
  }

  deformation.deform();
  const CGAL::Spectral_deformation_report& report = deformation.deform_report();
  if(!report.success)
  {
    std::cerr << "deformation failed: " << report.message << "\n";
    return EXIT_FAILURE;
  }
  std::cout << "deform: " << report.iterations << " iterations (last step " << report.last_step
            << "), solve " << report.solve_seconds << " s, detail transfer "
            << report.detail_transfer_seconds << " s, total " << report.total_seconds
            << " s; largest control residual " << report.max_control_residual
            << " of the region diagonal\n";

  const bool written =
      CGAL::IO::write_polygon_mesh((output_dir / "deformed.off").string(), mesh,
                                   CGAL::parameters::stream_precision(17)) &&
      write_shape(mesh, output_dir / "smooth_rest.off",
                  [&](Mesh::Vertex_index v) { return deformation.smoothed_rest_point(v); }) &&
      write_shape(mesh, output_dir / "smooth_deformed.off",
                  [&](Mesh::Vertex_index v) { return deformation.smoothed_deformed_point(v); });
  if(!written)
  {
    std::cerr << "cannot write into " << output_dir << "\n";
    return EXIT_FAILURE;
  }
  std::cout << "wrote deformed.off, smooth_rest.off and smooth_deformed.off into "
            << output_dir.string() << "\n";
  return EXIT_SUCCESS;
}

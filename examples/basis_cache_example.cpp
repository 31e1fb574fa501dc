// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Computes the manifold harmonics basis of a mesh once and reuses it:
//
// 1. a Manifold_harmonics_basis is computed (with a progress report of the
//    eigensolver), saved to a file and loaded back, and a deformation object
//    is handed the loaded basis with set_basis();
// 2. a deformation object saves the basis of its region with save_basis(),
//    and a second deformation object reads it with load_basis();
//
// in both cases the second deformation skips the eigensolve
// (preprocess_report().basis_computed is false) and gives the same result.
//
// Usage: basis_cache_example mesh.off cache_directory [m]
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Manifold_harmonics_basis.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Spectral_surface_mesh_deformation.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef Mesh::Vertex_index Vertex_index;
typedef CGAL::Block_lanczos_eigensolver_traits<> Eigensolver_traits;
typedef CGAL::Manifold_harmonics_basis<Mesh> Basis;
typedef CGAL::Spectral_surface_mesh_deformation<Mesh> Deformation;

namespace {

// The whole mesh is the region of interest (so that a basis of the whole
// mesh fits the region); the vertex of largest y is lifted, the vertex of
// smallest y stays.
void set_up(Deformation& deformation, const Mesh& mesh, std::size_t m)
{
  deformation.set_number_of_frequencies(m);
  deformation.insert_roi_vertices(mesh.vertices().begin(), mesh.vertices().end());
  auto by_height = [&](Vertex_index a, Vertex_index b) { return mesh.point(a).y() < mesh.point(b).y(); };
  const Vertex_index top = *std::max_element(mesh.vertices().begin(), mesh.vertices().end(), by_height);
  const Vertex_index bottom = *std::min_element(mesh.vertices().begin(), mesh.vertices().end(), by_height);
  deformation.insert_control_vertex(top);
  deformation.insert_control_vertex(bottom);
  deformation.translate(top, Kernel::Vector_3(0, 0.1 * (mesh.point(top).y() - mesh.point(bottom).y()), 0));
}

// Preprocesses and deforms; prints and returns in `eigensolve_ran` whether
// the eigensolve ran (read before deform(), whose own call to preprocess()
// finds nothing to do and resets the report).
bool run(Deformation& deformation, const std::string& name, bool& eigensolve_ran)
{
  if(!deformation.preprocess())
  {
    std::cerr << name << ": preprocess failed: " << deformation.preprocess_report().message << "\n";
    return false;
  }
  const CGAL::Spectral_preprocess_report& report = deformation.preprocess_report();
  eigensolve_ran = report.basis_computed;
  std::cout << name << ": preprocess " << report.region_seconds << " s, "
            << (report.basis_computed ? "eigensolve " + std::to_string(report.basis_seconds) + " s"
                                      : std::string("no eigensolve (cached basis)"))
            << "\n";
  deformation.deform();
  if(!deformation.deform_report().success)
  {
    std::cerr << name << ": deform failed: " << deformation.deform_report().message << "\n";
    return false;
  }
  return true;
}

double largest_distance(const std::vector<Point>& a, const std::vector<Point>& b)
{
  double largest = 0;
  for(std::size_t i = 0; i < a.size(); ++i)
    largest = (std::max)(largest, std::sqrt(CGAL::squared_distance(a[i], b[i])));
  return largest;
}

} // namespace

int main(int argc, char** argv)
{
  if(argc < 3)
  {
    std::cerr << "usage: " << argv[0] << " mesh.off cache_directory [m]\n";
    return EXIT_FAILURE;
  }
  const std::filesystem::path cache_directory = argv[2];
  const std::size_t m = (argc > 3) ? std::stoul(argv[3]) : 50;
  std::filesystem::create_directories(cache_directory);

  // Three copies of the mesh, one per deformation: every deformation starts
  // from the rest shape (a basis only fits the geometry it was computed on).
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(argv[1], mesh) || !CGAL::is_triangle_mesh(mesh))
  {
    std::cerr << "cannot read a triangle mesh from " << argv[1] << "\n";
    return EXIT_FAILURE;
  }
  Mesh first_mesh = mesh, second_mesh = mesh, third_mesh = mesh;

  try
  {
    // 1. A basis computed on its own, with a progress report, saved and
    // loaded back. load() checks that the file belongs to this mesh.
    Eigensolver_traits eigensolver;
    std::size_t solves = 0;
    eigensolver.set_progress_callback([&solves](const Eigensolver_traits::Progress& progress) {
      if(progress.stage == Eigensolver_traits::Progress::ITERATION)
        solves = progress.solves;
    });
    const Basis computed(mesh, m, CGAL::parameters::default_values(), eigensolver);
    std::cout << "basis of " << computed.number_of_frequencies() << " functions computed with "
              << solves << " Lanczos solves (0: the dense solver)\n";
    const std::filesystem::path basis_file = cache_directory / "mesh.mhb";
    {
      std::ofstream out(basis_file, std::ios::binary);
      computed.save(out);
    }
    Basis loaded;
    {
      std::ifstream in(basis_file, std::ios::binary);
      loaded.load(in, mesh);
    }
    std::cout << "basis saved to and loaded from " << basis_file.string() << ", largest difference "
              << (computed.basis() - loaded.basis()).cwiseAbs().maxCoeff() << "\n";

    bool first_eigensolve = false, second_eigensolve = false, third_eigensolve = false;

    // 2. A deformation that computes its own basis and saves it.
    Deformation first(first_mesh);
    set_up(first, first_mesh, m);
    if(!run(first, "first deformation", first_eigensolve))
      return EXIT_FAILURE;
    const std::filesystem::path region_file = cache_directory / "region.mhb";
    {
      std::ofstream out(region_file, std::ios::binary);
      first.save_basis(out);
    }

    // 3. A deformation handed the basis of step 1.
    Deformation second(second_mesh);
    set_up(second, second_mesh, m);
    second.set_basis(loaded);
    if(!run(second, "deformation with set_basis()", second_eigensolve))
      return EXIT_FAILURE;

    // 4. A deformation that reads the file saved by the first one.
    Deformation third(third_mesh);
    set_up(third, third_mesh, m);
    {
      std::ifstream in(region_file, std::ios::binary);
      third.load_basis(in); // throws MESH_MISMATCH if it belongs to another region
    }
    if(!run(third, "deformation with load_basis()", third_eigensolve))
      return EXIT_FAILURE;

    if(!first_eigensolve || second_eigensolve || third_eigensolve)
    {
      std::cerr << "expected one eigensolve, in the first deformation only\n";
      return EXIT_FAILURE;
    }
  }
  catch(const CGAL::Spectral_deformation_error& e)
  {
    std::cerr << "error: " << e.what() << "\n";
    return EXIT_FAILURE;
  }

  auto points = [](const Mesh& mesh) {
    std::vector<Point> result;
    for(Vertex_index v : mesh.vertices())
      result.push_back(mesh.point(v));
    return result;
  };
  // The file saved by the first deformation holds its own basis: the third
  // result is the first one. The basis handed in was computed on the whole
  // mesh with its vertices in the mesh's order rather than the region's, to
  // the eigensolver's tolerance: the second result agrees closely, relative
  // to the size of the mesh.
  const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(mesh);
  const double diagonal = std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                                    CGAL::square(box.zmax() - box.zmin()));
  const double from_file = largest_distance(points(first_mesh), points(third_mesh)) / diagonal;
  const double handed_in = largest_distance(points(first_mesh), points(second_mesh)) / diagonal;
  std::cout << "largest difference to the first result, over the bounding-box diagonal: " << from_file
            << " (load_basis()), " << handed_in << " (set_basis())\n";
  if(from_file > 1e-12 || handed_in > 1e-6)
  {
    std::cerr << "the deformations with a cached basis differ from the first one\n";
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}

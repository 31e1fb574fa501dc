// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Low-pass reconstructions of a mesh with its manifold harmonics basis (the
// paper's Figure 2): the basis of the largest requested frequency count is
// computed once, then the coordinates are projected onto its first k
// functions for every requested k.
//
// Usage: manifold_harmonics_low_pass mesh.off output_dir [k1 k2 ...]
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Manifold_harmonics_basis.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;

int main(int argc, char** argv)
{
  if(argc < 3)
  {
    std::cerr << "usage: " << argv[0] << " mesh.off output_dir [k1 k2 ...]\n";
    return EXIT_FAILURE;
  }
  const std::filesystem::path output_dir = argv[2];
  std::vector<std::size_t> frequencies;
  for(int i = 3; i < argc; ++i)
    frequencies.push_back(std::stoul(argv[i]));
  if(frequencies.empty())
    frequencies = {10, 50, 100, 200};

  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(argv[1], mesh))
  {
    std::cerr << "cannot read a polygon mesh from " << argv[1] << "\n";
    return EXIT_FAILURE;
  }
  std::filesystem::create_directories(output_dir);

  const std::size_t m = *std::max_element(frequencies.begin(), frequencies.end());
  // This program owns its process: the eigensolver may change settings of
  // the whole process while it runs (OpenBLAS threads, SuiteSparse's
  // allocator, huge pages), which makes it faster. A library would leave
  // this off, the default.
  CGAL::Block_lanczos_eigensolver_traits<> eigensolver;
  eigensolver.set_process_wide_tuning(true);
  const auto start = std::chrono::steady_clock::now();
  CGAL::Manifold_harmonics_basis<Mesh> basis;
  try
  {
    basis.compute(mesh, m, CGAL::parameters::default_values(), eigensolver);
  }
  catch(const CGAL::Spectral_deformation_error& e)
  {
    std::cerr << "the basis cannot be computed: " << e.what() << "\n";
    return EXIT_FAILURE;
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << "basis of " << m << " functions on " << mesh.number_of_vertices()
            << " vertices computed in " << seconds << " s\n";

  // Surface_mesh indices are contiguous here (freshly read), so v.idx() is the
  // row of the vertex, as in the initialized vertex index map.
  Eigen::MatrixXd positions(mesh.number_of_vertices(), 3);
  for(Mesh::Vertex_index v : mesh.vertices())
  {
    const Kernel::Point_3& p = mesh.point(v);
    positions.row(v.idx()) << p.x(), p.y(), p.z();
  }

  for(std::size_t k : frequencies)
  {
    const Eigen::MatrixXd smooth = basis.low_pass(positions, k);
    Mesh filtered = mesh;
    for(Mesh::Vertex_index v : filtered.vertices())
      filtered.point(v) =
          Kernel::Point_3(smooth(v.idx(), 0), smooth(v.idx(), 1), smooth(v.idx(), 2));
    const std::filesystem::path file = output_dir / ("low_pass_" + std::to_string(k) + ".off");
    if(!CGAL::IO::write_polygon_mesh(file.string(), filtered, CGAL::parameters::stream_precision(17)))
    {
      std::cerr << "cannot write " << file << "\n";
      return EXIT_FAILURE;
    }
    std::cout << "wrote " << file.string() << "\n";
  }
  return EXIT_SUCCESS;
}

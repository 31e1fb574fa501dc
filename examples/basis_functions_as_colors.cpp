// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Writes manifold harmonics as vertex colours: one PLY file per requested
// basis function, the mesh coloured blue where the function is negative,
// white where it vanishes and red where it is positive (the scale is
// symmetric, so that the nodal lines, where the function changes sign, are
// white). The colours are a Surface_mesh property "v:color", which the PLY
// writer stores as red, green and blue vertex properties; f3d and MeshLab
// show them (f3d --scalars --comp=-2 file.ply: direct colours).
//
// Usage: basis_functions_as_colors mesh.off output_dir [k1 k2 ...]
//        (default k: 1 2 3 6 10 30, the index of the function in the basis;
//         function 0 is the constant)
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/Color.h>
#include <CGAL/Manifold_harmonics_basis.h>
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
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;
typedef CGAL::Manifold_harmonics_basis<Mesh> Basis;

namespace {

// Blue (-1) to white (0) to red (+1).
CGAL::IO::Color diverging_color(double t)
{
  t = (std::max)(-1.0, (std::min)(1.0, t));
  auto channel = [](double c) { return static_cast<unsigned char>(std::lround(255 * c)); };
  if(t < 0)
    return CGAL::IO::Color(channel(1 + t), channel(1 + t), 255);
  return CGAL::IO::Color(255, channel(1 - t), channel(1 - t));
}

} // namespace

int main(int argc, char** argv)
{
  if(argc < 3)
  {
    std::cerr << "usage: " << argv[0] << " mesh.off output_dir [k1 k2 ...]\n";
    return EXIT_FAILURE;
  }
  const std::filesystem::path output_dir = argv[2];
  std::vector<std::size_t> functions;
  for(int i = 3; i < argc; ++i)
    functions.push_back(std::stoul(argv[i]));
  if(functions.empty())
    functions = {1, 2, 3, 6, 10, 30};

  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(argv[1], mesh) || !CGAL::is_triangle_mesh(mesh))
  {
    std::cerr << "cannot read a triangle mesh from " << argv[1] << "\n";
    return EXIT_FAILURE;
  }
  std::filesystem::create_directories(output_dir);

  const std::size_t m = *std::max_element(functions.begin(), functions.end()) + 1;
  Basis basis;
  try
  {
    basis.compute(mesh, m);
  }
  catch(const CGAL::Spectral_deformation_error& e)
  {
    std::cerr << "error: " << e.what() << "\n";
    return EXIT_FAILURE;
  }

  // Rows of the basis follow the vertex index map, which for a Surface_mesh
  // without removed elements is Vertex_index::idx().
  Mesh::Property_map<Mesh::Vertex_index, CGAL::IO::Color> color =
      mesh.add_property_map<Mesh::Vertex_index, CGAL::IO::Color>("v:color").first;
  for(std::size_t k : functions)
  {
    const Eigen::VectorXd h = basis.basis().col(static_cast<Eigen::Index>(k));
    const double scale = h.cwiseAbs().maxCoeff();
    for(Mesh::Vertex_index v : mesh.vertices())
      color[v] = diverging_color(scale > 0 ? h[v.idx()] / scale : 0.0);

    const std::filesystem::path file = output_dir / ("basis_function_" + std::to_string(k) + ".ply");
    std::ofstream out(file, std::ios::binary);
    if(!CGAL::IO::write_PLY(out, mesh))
    {
      std::cerr << "cannot write " << file.string() << "\n";
      return EXIT_FAILURE;
    }
    std::cout << "function " << k << " (eigenvalue " << basis.eigenvalues()[static_cast<Eigen::Index>(k)]
              << ") written to " << file.string() << "\n";
  }
  return EXIT_SUCCESS;
}

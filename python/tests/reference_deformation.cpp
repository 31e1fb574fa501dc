// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The deformation the Python tests compare against, through the C++ API.
// Reads from standard input:
//   n f / n lines "x y z" / f lines "a b c" / r then r ROI indices /
//   k then k handle indices / k lines of targets /
//   algorithm (spectral|linear|spatial) policy (exact|soft) m iterations tolerance
// and writes the n deformed positions, one "x y z" line each, to standard
// output with 17 significant digits.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Spectral_surface_mesh_deformation.h>
#include <CGAL/Surface_mesh.h>

#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef Mesh::Vertex_index Vertex_index;

struct Input
{
  Mesh mesh;
  std::vector<std::size_t> roi, handles;
  std::vector<Point> targets;
  std::string algorithm, policy;
  std::size_t m = 0;
  unsigned int iterations = 0;
  double tolerance = 0;
};

template <CGAL::Spectral_deformation_algorithm_tag TAG>
int deform(Input& in)
{
  CGAL::Spectral_surface_mesh_deformation<Mesh, CGAL::Default, CGAL::Default, TAG> d(in.mesh);
  if constexpr(decltype(d)::has_basis)
  {
    d.set_number_of_frequencies(in.m);
    d.set_constraint_policy(in.policy == "soft" ? CGAL::SOFT_CONSTRAINTS : CGAL::EXACT_CONSTRAINTS);
  }
  for(std::size_t v : in.roi)
    d.insert_roi_vertex(Vertex_index(static_cast<Mesh::size_type>(v)));
  for(std::size_t v : in.handles)
    d.insert_control_vertex(Vertex_index(static_cast<Mesh::size_type>(v)));
  if(!d.preprocess())
  {
    std::cerr << "preprocess() failed: " << d.preprocess_report().message << "\n";
    return 1;
  }
  for(std::size_t i = 0; i < in.handles.size(); ++i)
    d.set_target_position(Vertex_index(static_cast<Mesh::size_type>(in.handles[i])), in.targets[i]);
  d.deform(in.iterations, in.tolerance);
  if(!d.deform_report().success)
  {
    std::cerr << "deform() failed: " << d.deform_report().message << "\n";
    return 1;
  }
  for(Vertex_index v : in.mesh.vertices())
  {
    const Point& p = in.mesh.point(v);
    std::printf("%.17g %.17g %.17g\n", p.x(), p.y(), p.z());
  }
  return 0;
}

int main()
{
  Input in;
  std::size_t n = 0, f = 0;
  std::cin >> n >> f;
  for(std::size_t i = 0; i < n; ++i)
  {
    double x, y, z;
    std::cin >> x >> y >> z;
    in.mesh.add_vertex(Point(x, y, z));
  }
  for(std::size_t j = 0; j < f; ++j)
  {
    Mesh::size_type a, b, c;
    std::cin >> a >> b >> c;
    in.mesh.add_face(Vertex_index(a), Vertex_index(b), Vertex_index(c));
  }
  std::size_t count = 0;
  std::cin >> count;
  in.roi.resize(count);
  for(std::size_t& v : in.roi)
    std::cin >> v;
  std::cin >> count;
  in.handles.resize(count);
  for(std::size_t& v : in.handles)
    std::cin >> v;
  for(std::size_t i = 0; i < count; ++i)
  {
    double x, y, z;
    std::cin >> x >> y >> z;
    in.targets.emplace_back(x, y, z);
  }
  std::cin >> in.algorithm >> in.policy >> in.m >> in.iterations >> in.tolerance;
  if(!std::cin)
  {
    std::cerr << "malformed input\n";
    return 2;
  }
  if(in.algorithm == "spectral")
    return deform<CGAL::SPECTRAL_DUAL_LAPLACIAN>(in);
  if(in.algorithm == "linear")
    return deform<CGAL::SPECTRAL_LINEAR>(in);
  return deform<CGAL::SPATIAL_DUAL_LAPLACIAN>(in);
}

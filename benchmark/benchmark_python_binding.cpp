// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The C++ side of the Python binding's cost (run_python_binding_benchmark.sh):
// writes a case of quality/cases (optionally Loop-subdivided) as raw arrays
// for the Python side, then times, on the same arrays, what ssmd.Deformation
// does: the mesh built from the arrays, the deformation object, preprocess()
// and a first deform(10), positions copied out; then drags (new targets,
// deform(10), positions copied out). Prints one line of medians, in seconds.

#include "benchmark_support.h"
#include "deformation_cases.h"

#include <CGAL/Spectral_surface_mesh_deformation.h>

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

using namespace ssmd_benchmark;

namespace {

template <class T>
void write_raw(const std::string& file, const std::vector<T>& values)
{
  std::ofstream out(file, std::ios::binary);
  out.write(reinterpret_cast<const char*>(values.data()), std::streamsize(values.size() * sizeof(T)));
  if(!out)
    throw std::runtime_error("cannot write " + file);
}

struct Arrays
{
  std::vector<double> V;
  std::vector<std::int64_t> F, roi, handles;
  std::vector<double> targets;
};

// The drag k: the final targets scaled back along the path from the rest.
std::vector<Point> drag_targets(const Arrays& a, int k, int drags)
{
  const double s = 0.5 + 0.5 * double(k + 1) / double(drags);
  std::vector<Point> t;
  for(std::size_t i = 0; i < a.handles.size(); ++i)
  {
    const double* rest = &a.V[3 * std::size_t(a.handles[i])];
    const double* end = &a.targets[3 * i];
    t.emplace_back(rest[0] + s * (end[0] - rest[0]), rest[1] + s * (end[1] - rest[1]),
                   rest[2] + s * (end[2] - rest[2]));
  }
  return t;
}

std::vector<double> copy_out(const Mesh& mesh)
{
  std::vector<double> x(3 * mesh.number_of_vertices());
  for(vertex_descriptor v : mesh.vertices())
  {
    const Point& p = mesh.point(v);
    x[3 * std::size_t(v)] = p.x();
    x[3 * std::size_t(v) + 1] = p.y();
    x[3 * std::size_t(v) + 2] = p.z();
  }
  return x;
}

} // namespace

int main(int argc, char** argv)
{
  if(argc < 4)
  {
    std::cerr << "usage: benchmark_python_binding CASE_FILE LEVELS OUTPUT_DIR [REPETITIONS [DRAGS]]\n";
    return 2;
  }
  const unsigned int levels = static_cast<unsigned int>(std::stoul(argv[2]));
  const std::string out = argv[3];
  const int repetitions = argc > 4 ? std::stoi(argv[4]) : 3;
  const int drags = argc > 5 ? std::stoi(argv[5]) : 10;
  Deformation_case c = read_case_file(argv[1], SSMD_BENCHMARK_DEFAULT_MESH_DIR, levels);

  Arrays a;
  for(vertex_descriptor v : c.mesh.vertices())
  {
    const Point& p = c.mesh.point(v);
    a.V.insert(a.V.end(), {p.x(), p.y(), p.z()});
  }
  for(auto f : c.mesh.faces())
    for(vertex_descriptor v : CGAL::vertices_around_face(c.mesh.halfedge(f), c.mesh))
      a.F.push_back(std::int64_t(std::size_t(v)));
  for(vertex_descriptor v : c.roi)
    a.roi.push_back(std::int64_t(std::size_t(v)));
  std::sort(a.roi.begin(), a.roi.end());
  for(std::size_t i = 0; i < c.handles.size(); ++i)
  {
    a.handles.push_back(std::int64_t(std::size_t(c.handles[i])));
    a.targets.insert(a.targets.end(), {c.targets[i].x(), c.targets[i].y(), c.targets[i].z()});
  }
  write_raw(out + "/V.f64", a.V);
  write_raw(out + "/F.i64", a.F);
  write_raw(out + "/roi.i64", a.roi);
  write_raw(out + "/handles.i64", a.handles);
  write_raw(out + "/targets.f64", a.targets);

  typedef CGAL::Spectral_surface_mesh_deformation<Mesh> Deformation;
  std::vector<double> first, drag;
  std::vector<double> result;
  for(int r = 0; r < repetitions; ++r)
  {
    const Clock::time_point start = Clock::now();
    Mesh mesh;
    const std::size_t n = a.V.size() / 3;
    for(std::size_t i = 0; i < n; ++i)
      mesh.add_vertex(Point(a.V[3 * i], a.V[3 * i + 1], a.V[3 * i + 2]));
    for(std::size_t j = 0; j < a.F.size(); j += 3)
      mesh.add_face(vertex_descriptor(Mesh::size_type(a.F[j])), vertex_descriptor(Mesh::size_type(a.F[j + 1])),
                    vertex_descriptor(Mesh::size_type(a.F[j + 2])));
    Deformation d(mesh);
    std::vector<vertex_descriptor> roi;
    for(std::int64_t v : a.roi)
      roi.push_back(vertex_descriptor(Mesh::size_type(v)));
    d.insert_roi_vertices(roi.begin(), roi.end());
    for(std::int64_t v : a.handles)
      d.insert_control_vertex(vertex_descriptor(Mesh::size_type(v)));
    if(!d.preprocess())
    {
      std::cerr << "preprocess() failed: " << d.preprocess_report().message << "\n";
      return 1;
    }
    const std::vector<Point> t = drag_targets(a, drags - 1, drags);
    for(std::size_t i = 0; i < a.handles.size(); ++i)
      d.set_target_position(vertex_descriptor(Mesh::size_type(a.handles[i])), t[i]);
    d.deform(10, 1e-4);
    result = copy_out(mesh);
    first.push_back(seconds_since(start));
    if(r + 1 == repetitions)
    {
      d.reset();
      for(int k = 0; k < drags; ++k)
      {
        const Clock::time_point drag_start = Clock::now();
        const std::vector<Point> tk = drag_targets(a, k, drags);
        for(std::size_t i = 0; i < a.handles.size(); ++i)
          d.set_target_position(vertex_descriptor(Mesh::size_type(a.handles[i])), tk[i]);
        d.deform(10, 1e-4);
        result = copy_out(mesh);
        drag.push_back(seconds_since(drag_start));
      }
    }
  }
  write_raw(out + "/cpp_result.f64", result);
  std::cout << "vertices " << a.V.size() / 3 << " first_result " << median(first) << " drag " << median(drag)
            << " machine \"" << first_line_value("/proc/cpuinfo", "model name") << "\" compiler \""
            << compiler() << "\" flags \"" << SSMD_BENCHMARK_CXX_FLAGS_BUILD_TYPE << "\"\n";
  return 0;
}

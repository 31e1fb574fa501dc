// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This program is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.
//
// Validates the basis kept in single precision
// (set_single_precision_basis_threshold(), the default on regions of 200,000
// vertices and more) against double precision: two
// Spectral_surface_mesh_deformation objects with the same basis (the second
// loads the first's, kept in float), the case deformed alternately with each
// (reset(), then deform(iterations, 0)), and reports the median time of
// deform() with each basis, their ratio, and the largest vertex distance
// between the two results over the bounding-box diagonal D.
//
// Usage: benchmark_single_precision [--case NAME] [--level L] [--frequencies M]
//          [--repetitions N] [--iterations K] [--mesh-directory DIR]
//          [--case-directory DIR] [--output FILE]

#include "deformation_cases.h"

#include <CGAL/Spectral_surface_mesh_deformation.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#ifndef SSMD_BENCHMARK_BUILD_TYPE
#define SSMD_BENCHMARK_BUILD_TYPE "unknown"
#endif
#ifndef SSMD_BENCHMARK_CXX_FLAGS_BUILD_TYPE
#define SSMD_BENCHMARK_CXX_FLAGS_BUILD_TYPE "unknown"
#endif
#include "benchmark_support.h"

using namespace ssmd_benchmark;

int main(int argc, char** argv)
{
  std::string name = "armadillo_arm";
  std::string mesh_directory = SSMD_BENCHMARK_DEFAULT_MESH_DIR;
  std::string case_directory = SSMD_BENCHMARK_DEFAULT_CASE_DIR;
  std::string output;
  unsigned int level = 1;
  std::size_t m = 100;
  int repetitions = 5;
  unsigned int iterations = 10;
  try
  {
    for(int i = 1; i < argc; ++i)
    {
      const std::string arg = argv[i];
      if(i + 1 >= argc)
        throw std::runtime_error("usage: see the head of benchmark_single_precision.cpp");
      const std::string value = argv[++i];
      if(arg == "--case")
        name = value;
      else if(arg == "--level")
        level = static_cast<unsigned int>(std::stoul(value));
      else if(arg == "--frequencies")
        m = std::stoul(value);
      else if(arg == "--repetitions")
        repetitions = std::stoi(value);
      else if(arg == "--iterations")
        iterations = static_cast<unsigned int>(std::stoul(value));
      else if(arg == "--mesh-directory")
        mesh_directory = value;
      else if(arg == "--case-directory")
        case_directory = value;
      else if(arg == "--output")
        output = value;
      else
        throw std::runtime_error("unknown option " + arg);
    }
    if(repetitions < 1 || iterations < 1)
      throw std::runtime_error("--repetitions and --iterations must be positive");

    const Deformation_case c = read_case_file(case_directory + "/" + name + ".case", mesh_directory, level);
    typedef CGAL::Spectral_surface_mesh_deformation<Mesh> Deformation;
    Mesh meshes[2] = {c.mesh, c.mesh};
    Deformation in_double_precision(meshes[0]), in_single_precision(meshes[1]);
    Deformation* deformations[2] = {&in_double_precision, &in_single_precision};
    in_double_precision.set_single_precision_basis_threshold(std::numeric_limits<std::size_t>::max());
    in_single_precision.set_single_precision_basis_threshold(0);
    for(Deformation* deformation : deformations)
    {
      deformation->set_number_of_frequencies(m);
      deformation->insert_roi_vertices(c.roi.begin(), c.roi.end());
      deformation->insert_control_vertices(c.handles.begin(), c.handles.end());
    }
    if(!in_double_precision.preprocess())
      throw std::runtime_error("preprocess() failed on " + c.name);
    std::stringstream basis;
    in_double_precision.save_basis(basis);
    in_single_precision.load_basis(basis);
    if(!in_single_precision.preprocess() || !in_single_precision.preprocess_report().single_precision_basis)
      throw std::runtime_error("preprocess() with the basis in float failed on " + c.name);
    const Positions rest = positions_of(c.mesh);
    const double diagonal = (rest.colwise().maxCoeff() - rest.colwise().minCoeff()).norm();

    std::vector<double> seconds[2];
    Positions result[2];
    for(int r = 0; r < repetitions; ++r)
      for(int single = 0; single < 2; ++single)
      {
        Deformation& deformation = *deformations[single];
        Mesh& mesh = meshes[single];
        deformation.reset();
        for(std::size_t k = 0; k < c.handles.size(); ++k)
          deformation.set_target_position(c.handles[k], c.targets[k]);
        const Clock::time_point start = Clock::now();
        deformation.deform(iterations, 0.0);
        seconds[single].push_back(seconds_since(start));
        result[single] = positions_of(mesh);
      }
    const double deviation = (result[1] - result[0]).rowwise().norm().maxCoeff() / diagonal;
    const double in_double = median(seconds[0]), in_float = median(seconds[1]);

    std::ostringstream out;
    out << "# The basis kept in single precision in the deformation iteration\n\n"
        << "- Date: " << utc_time(std::time(nullptr)) << ", machine: " << first_line_value("/proc/cpuinfo", "model name")
        << ", compiler: " << compiler() << ", build: `CMAKE_BUILD_TYPE=" << SSMD_BENCHMARK_BUILD_TYPE
        << "`, flags `" << SSMD_BENCHMARK_CXX_FLAGS_BUILD_TYPE << "`\n"
        << "- Case: " << c.name << (level == 0 ? std::string() : ", Loop ×" + std::to_string(level)) << ", "
        << num_vertices(c.mesh) << " vertices, " << c.roi.size() << " region vertices, m = " << m
        << ", default policy; `deform(" << iterations << ", 0)` after `reset()`, the two bases "
        << "alternating, " << repetitions << " runs each\n\n"
        << "| basis kept in | deform() median | per solve (deform() / " << iterations + 1
        << ") | speed-up | deviation from double / D |\n"
        << "|---|--:|--:|--:|--:|\n"
        << "| double | " << duration(in_double) << " | " << duration(in_double / (iterations + 1))
        << " | 1 | 0 |\n"
        << "| float | " << duration(in_float) << " | " << duration(in_float / (iterations + 1)) << " | "
        << fixed(in_double / in_float, 2) << "× | " << scientific(deviation) << " |\n\n"
        << "The quality benchmark's measures must not change (see the manual, *Memory*).\n";
    std::cout << out.str();
    if(!output.empty())
    {
      std::ofstream file(output);
      file << out.str();
      if(!file)
        throw std::runtime_error("cannot write " + output);
    }
  }
  catch(const std::exception& e)
  {
    std::cerr << "error: " << e.what() << "\n";
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}

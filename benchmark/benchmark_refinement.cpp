// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Energy against time on the way to the optimum of the as-rigid-as-possible
// energy, same run, same case: the package with its defaults (the spectral
// result of deform(), then refine()) and CGAL ARAP from the rest pose
// (ORIGINAL_ARAP with CHOLMOD on its SPD block, cgal_arap_solver_traits.h).
// Both iterate in chunks that grow by half each time; after each chunk the
// clock stops and the shape is measured with the quality report's measures
// (ARAP energy over the whole mesh with the absolute cotangent weights,
// volume change, folded face pairs), so that both are judged by the same
// yardstick. CGAL's converged energy is the lowest it reached; the summary
// gives each one's time to come within 1 % of it.
//
// Usage: benchmark_refinement --output FILE.md [--data FILE.tsv] [--case FILE.case] [--levels 0,1]
//        [--cgal-iterations N] [--package-iterations N] [--keep-volume] [--mesh-output DIR]
//        [--cgal-data FILE.tsv]
// --cgal-data reads CGAL ARAP's curves from an earlier run's --data instead of
// running it again (at 416k vertices it runs for more than an hour).

#include "cgal_arap_solver_traits.h"
#include "deformation_cases.h"

#include <CGAL/Spectral_surface_mesh_deformation.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

namespace {

using namespace ssmd_benchmark;

struct Options
{
  std::string output;
  std::string data;
  std::string case_file = SSMD_BENCHMARK_DEFAULT_CASE_DIR "/armadillo_arm.case";
  std::string mesh_directory = SSMD_BENCHMARK_DEFAULT_MESH_DIR;
  std::vector<unsigned int> levels{0, 1};
  unsigned int cgal_iterations = 2000;
  unsigned int package_iterations = 500;
  bool keep_volume = false;
  std::string mesh_output; // directory for the last shapes of both; empty: none
  std::string cgal_data;   // CGAL ARAP's curves from an earlier run's --data; empty: run CGAL ARAP
};

void print_usage(const char* program)
{
  std::cerr << "usage: " << program
            << " --output FILE.md [--data FILE.tsv] [--case FILE.case] [--meshes DIR] [--levels 0,1]\n"
               "       [--cgal-iterations N (2000)] [--package-iterations N (500)] [--keep-volume]\n"
               "       [--mesh-output DIR (the last shapes, NAME_LEVEL_package.off and ..._cgal.off)]\n"
               "       [--cgal-data FILE.tsv (CGAL ARAP's curve read from an earlier run's --data, not run again)]\n";
}

Options parse_options(int argc, char** argv)
{
  Options o;
  for(int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if(i + 1 >= argc)
        throw std::runtime_error(a + " needs a value");
      return argv[++i];
    };
    if(a == "--output")
      o.output = value();
    else if(a == "--data")
      o.data = value();
    else if(a == "--case")
      o.case_file = value();
    else if(a == "--meshes")
      o.mesh_directory = value();
    else if(a == "--levels")
    {
      o.levels.clear();
      std::stringstream list(value());
      for(std::string item; std::getline(list, item, ',');)
        o.levels.push_back(static_cast<unsigned int>(std::stoul(item)));
    }
    else if(a == "--cgal-iterations")
      o.cgal_iterations = static_cast<unsigned int>(std::stoul(value()));
    else if(a == "--package-iterations")
      o.package_iterations = static_cast<unsigned int>(std::stoul(value()));
    else if(a == "--keep-volume")
      o.keep_volume = true;
    else if(a == "--mesh-output")
      o.mesh_output = value();
    else if(a == "--cgal-data")
      o.cgal_data = value();
    else
      throw std::runtime_error("unknown option " + a);
  }
  if(o.output.empty())
    throw std::runtime_error("--output is required");
  if(!o.cgal_data.empty() && !o.mesh_output.empty())
    throw std::runtime_error("--mesh-output needs CGAL ARAP's last shape: not with --cgal-data");
  return o;
}

struct Point_on_curve
{
  unsigned int iterations = 0; // of refine() for the package, of ARAP for CGAL
  double seconds = 0;          // since the constructor, measurements excluded
  Quality quality;
};

struct Curve
{
  std::string name;
  std::vector<Point_on_curve> points;
  Mesh last; // the shape at the last checkpoint
};

// Chunks of 1, 1, 2, 3, 4, 6, 9, ... iterations: checkpoints close together
// at first, then spread over the slow tail.
unsigned int next_chunk(unsigned int done) { return std::max(1u, done / 2); }

// The iterations of CGAL's deform() with its default settings.
constexpr unsigned int cgal_default_iterations = 10;

// The checkpoint after `iterations` iterations, or null.
const Point_on_curve* at_iterations(const Curve& curve, unsigned int iterations)
{
  for(const Point_on_curve& p : curve.points)
    if(p.iterations == iterations)
      return &p;
  return nullptr;
}

Curve run_package(const Deformation_case& c, const Case_geometry& g, const Options& o)
{
  Curve curve;
  curve.name = o.keep_volume ? "package, volume kept" : "package";
  Mesh mesh = c.mesh;
  double seconds = 0;
  auto start = Clock::now();
  CGAL::Spectral_surface_mesh_deformation<Mesh> d(mesh);
  d.set_volume_preservation(o.keep_volume);
  d.insert_roi_vertices(c.roi.begin(), c.roi.end());
  d.insert_control_vertices(c.handles.begin(), c.handles.end());
  for(std::size_t k = 0; k < c.handles.size(); ++k)
    d.set_target_position(c.handles[k], c.targets[k]);
  d.deform();
  if(!d.deform_report().success)
    throw std::runtime_error("package: " + d.deform_report().message);
  seconds += seconds_since(start);
  curve.points.push_back({0, seconds, measure(g, positions_of(mesh))});
  unsigned int done = 0;
  while(done < o.package_iterations)
  {
    const unsigned int chunk = std::min(next_chunk(done), o.package_iterations - done);
    start = Clock::now();
    if(!d.refine(chunk, 0.0))
      throw std::runtime_error("package: " + d.refine_report().message);
    seconds += seconds_since(start);
    done += chunk;
    curve.points.push_back({done, seconds, measure(g, positions_of(mesh))});
    if(done >= o.package_iterations)
      curve.last = mesh;
    std::cerr << "  package, " << done << " refinement iterations: " << seconds << " s, energy "
              << curve.points.back().quality.arap_energy << " (region: " << d.refine_report().energy_before
              << " -> " << d.refine_report().energy_after << " in " << d.refine_report().iterations
              << " iterations)\n";
  }
  return curve;
}

Curve run_cgal(const Deformation_case& c, const Case_geometry& g, const Options& o)
{
  Curve curve;
  curve.name = "CGAL ARAP";
  Mesh mesh = c.mesh;
  double seconds = 0;
  auto start = Clock::now();
  Cgal_arap<Mesh> d(mesh);
  d.insert_roi_vertices(c.roi.begin(), c.roi.end());
  d.insert_control_vertices(c.handles.begin(), c.handles.end());
  if(!d.preprocess())
    throw std::runtime_error("CGAL ARAP: preprocess() failed");
  for(std::size_t k = 0; k < c.handles.size(); ++k)
    d.set_target_position(c.handles[k], c.targets[k]);
  seconds += seconds_since(start);
  unsigned int done = 0;
  double previous = std::numeric_limits<double>::infinity();
  while(done < o.cgal_iterations)
  {
    unsigned int chunk = std::min(next_chunk(done), o.cgal_iterations - done);
    if(done < cgal_default_iterations)
      chunk = std::min(chunk, cgal_default_iterations - done); // a checkpoint at CGAL's deform(10)
    start = Clock::now();
    d.deform(chunk, 0.0);
    seconds += seconds_since(start);
    done += chunk;
    curve.points.push_back({done, seconds, measure(g, positions_of(mesh))});
    const double energy = curve.points.back().quality.arap_energy;
    std::cerr << "  CGAL ARAP, " << done << " iterations: " << seconds << " s, energy " << energy << "\n";
    // Converged: a chunk of a third of the iterations so far no longer
    // lowers the energy by a part in a million.
    if(done > 50 && !(energy < previous * (1 - 1e-6)))
      break;
    previous = energy;
  }
  curve.last = mesh;
  return curve;
}

// CGAL ARAP's curve on `vertices` vertices from a file that --data wrote:
// the long runs of CGAL ARAP (an hour and more at 416k) need not be repeated
// to measure a change of the package.
Curve read_cgal_curve(const std::string& file, std::size_t vertices)
{
  std::ifstream in(file);
  if(!in)
    throw std::runtime_error("cannot read " + file);
  Curve curve;
  curve.name = "CGAL ARAP";
  std::string line;
  std::getline(in, line); // header
  while(std::getline(in, line))
  {
    std::stringstream fields(line);
    std::string n, method, iterations, seconds, energy, volume_change, folded_pairs;
    if(!std::getline(fields, n, '\t') || !std::getline(fields, method, '\t') ||
       !std::getline(fields, iterations, '\t') || !std::getline(fields, seconds, '\t') ||
       !std::getline(fields, energy, '\t') || !std::getline(fields, volume_change, '\t') ||
       !std::getline(fields, folded_pairs, '\t'))
      throw std::runtime_error(file + ": a line without the seven columns of --data");
    if(method != curve.name || std::stoul(n) != vertices)
      continue;
    Point_on_curve p;
    p.iterations = static_cast<unsigned int>(std::stoul(iterations));
    p.seconds = std::stod(seconds);
    p.quality.arap_energy = std::stod(energy);
    p.quality.volume_change = std::stod(volume_change);
    p.quality.folded_pairs = static_cast<std::size_t>(std::stoul(folded_pairs));
    curve.points.push_back(p);
  }
  if(curve.points.empty())
    throw std::runtime_error(file + " has no curve of CGAL ARAP on " + std::to_string(vertices) + " vertices");
  return curve;
}

double lowest_energy(const Curve& curve)
{
  double lowest = std::numeric_limits<double>::infinity();
  for(const Point_on_curve& p : curve.points)
    lowest = std::min(lowest, p.quality.arap_energy);
  return lowest;
}

// The first checkpoint at or below `energy`, or null.
const Point_on_curve* first_reaching(const Curve& curve, double energy)
{
  for(const Point_on_curve& p : curve.points)
    if(p.quality.arap_energy <= energy)
      return &p;
  return nullptr;
}

} // namespace

int main(int argc, char** argv)
{
  Options o;
  try
  {
    o = parse_options(argc, argv);
  }
  catch(const std::exception& e)
  {
    std::cerr << e.what() << "\n";
    print_usage(argv[0]);
    return 2;
  }
  std::ostringstream report;
  std::ofstream data;
  if(!o.data.empty())
  {
    data.open(o.data);
    data << "vertices\tmethod\titerations\tseconds\tenergy\tvolume_change\tfolded_pairs\n";
  }
  report << "# Refinement towards the ARAP optimum against CGAL ARAP\n\n"
         << "Case `" << o.case_file << "`; the package with its defaults"
         << (o.keep_volume ? " and `set_volume_preservation(true)`" : "")
         << " (`deform()`, then `refine()` in chunks), CGAL ARAP with `ORIGINAL_ARAP` and CHOLMOD on its SPD "
            "block from the rest pose (`deform(k, 0)` in chunks). Seconds from the constructor, measurements "
            "excluded. Energy: ARAP energy of the whole mesh against the rest shape (absolute cotangent "
            "weights, scale-free)"
         << (o.cgal_data.empty() ? std::string()
                                 : ". CGAL ARAP's curves read from `" +
                                       std::filesystem::path(o.cgal_data).filename().string() +
                                       "`, written by an earlier run of this program")
         << ". Build: "
         << SSMD_BENCHMARK_BUILD_TYPE << ", `" << SSMD_BENCHMARK_CXX_FLAGS_BUILD_TYPE << " "
         << SSMD_BENCHMARK_CXX_FLAGS << "`.\n";
  try
  {
    for(unsigned int level : o.levels)
    {
      Deformation_case c = read_case_file(o.case_file, o.mesh_directory, level);
      finish_case(c);
      const Case_geometry g = case_geometry(c);
      const std::size_t n = num_vertices(c.mesh);
      std::cerr << c.name << " @" << level << ": " << n << " vertices\n";
      const Curve package = run_package(c, g, o);
      const Curve cgal = o.cgal_data.empty() ? run_cgal(c, g, o) : read_cgal_curve(o.cgal_data, n);
      const double converged = lowest_energy(cgal);
      if(!o.mesh_output.empty())
      {
        const std::string stem = o.mesh_output + "/" + c.name + "_" + std::to_string(level);
        CGAL::IO::write_OFF(stem + (o.keep_volume ? "_package_volume.off" : "_package.off"), package.last,
                            CGAL::parameters::stream_precision(17));
        CGAL::IO::write_OFF(stem + "_cgal.off", cgal.last, CGAL::parameters::stream_precision(17));
      }
      report << "\n## " << c.name << " @" << level << ": " << n << " vertices, ROI " << c.roi.size() << "\n\n";
      const Point_on_curve* cgal_reach = first_reaching(cgal, 1.01 * converged);
      const Point_on_curve* package_reach = first_reaching(package, 1.01 * converged);
      report << "CGAL ARAP's lowest energy: " << scientific(converged) << " after " << cgal.points.back().iterations
             << " iterations (" << duration(cgal.points.back().seconds) << "). Within 1 % of it: CGAL ARAP after "
             << (cgal_reach ? duration(cgal_reach->seconds) + " (" + std::to_string(cgal_reach->iterations) +
                                  " iterations)"
                            : std::string("never"))
             << ", the package after "
             << (package_reach ? duration(package_reach->seconds) + " (" +
                                     std::to_string(package_reach->iterations) + " refinement iterations)"
                               : std::string("not within its iterations"));
      if(cgal_reach && package_reach)
        report << ": " << fixed(cgal_reach->seconds / package_reach->seconds, 1) << "× sooner";
      report << ". The package's lowest energy: " << scientific(lowest_energy(package)) << " ("
             << fixed(lowest_energy(package) / converged, 4) << " × CGAL's)";
      if(const Point_on_curve* ten = at_iterations(cgal, cgal_default_iterations))
        report << "; CGAL ARAP's `deform(10)`: " << scientific(ten->quality.arap_energy)
               << " (the package's lowest is " << fixed(lowest_energy(package) / ten->quality.arap_energy, 3)
               << " × it)";
      report << ". Last shapes: volume change " << percent(package.points.back().quality.volume_change)
             << " (package), " << percent(cgal.points.back().quality.volume_change)
             << " (CGAL ARAP); folded pairs " << package.points.back().quality.folded_pairs << " and "
             << cgal.points.back().quality.folded_pairs << ".\n\n"
             << "| method | iterations | seconds | ARAP energy | / CGAL's lowest | volume change | folded pairs |\n"
             << "|---|--:|--:|--:|--:|--:|--:|\n";
      for(const Curve* curve : {&package, &cgal})
        for(const Point_on_curve& p : curve->points)
        {
          report << "| " << curve->name << " | " << p.iterations << " | " << fixed(p.seconds, 3) << " | "
                 << scientific(p.quality.arap_energy) << " | " << fixed(p.quality.arap_energy / converged, 3)
                 << " | " << (std::isfinite(p.quality.volume_change) ? percent(p.quality.volume_change) : "–")
                 << " | " << p.quality.folded_pairs << " |\n";
          if(data.is_open())
            data << n << "\t" << curve->name << "\t" << p.iterations << "\t" << p.seconds << "\t"
                 << p.quality.arap_energy << "\t" << p.quality.volume_change << "\t" << p.quality.folded_pairs
                 << "\n";
        }
    }
  }
  catch(const std::exception& e)
  {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
  std::ofstream out(o.output);
  out << report.str();
  std::cout << report.str();
  return out ? 0 : 1;
}

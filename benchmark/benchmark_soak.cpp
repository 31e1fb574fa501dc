// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Soak run of a deformation object: many drags with random handle targets
// on one mesh, with occasional constraint changes and resets, as an
// interactive session would make them. Checks that every result is finite,
// counts folded face pairs, and records the resident memory over time, which
// must not grow after the warm-up. Not a test: a run of 10,000 drags on the
// 104k armadillo takes tens of minutes (see run_soak_benchmark.sh).
#include "deformation_cases.h"

#include <CGAL/Spectral_surface_mesh_deformation.h>

#include <filesystem>
#include <iostream>
#include <random>

using namespace ssmd_benchmark;

namespace {

struct Options
{
  std::string case_file = std::string(SSMD_BENCHMARK_DEFAULT_CASE_DIR) + "/armadillo_arm.case";
  std::string mesh_directory = SSMD_BENCHMARK_DEFAULT_MESH_DIR;
  unsigned int level = 1;
  int drags = 10000;
  int constraint_change_every = 250; // drags between two changes of the control vertices
  int reset_every = 1000;
  int memory_every = 50;
  unsigned int seed = 1;
  std::string output = "soak.md";
  std::string memory_table = "soak_memory.tsv";
};

void usage(const char* program)
{
  std::cerr << "Usage: " << program
            << " [--case FILE.case] [--meshes DIR] [--level L] [--drags N]\n"
               "       [--constraint-change-every N] [--reset-every N] [--memory-every N]\n"
               "       [--seed S] [--output REPORT.md] [--memory-table MEMORY.tsv]\n";
}

Options parse(int argc, char** argv)
{
  Options o;
  for(int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if(i + 1 >= argc)
        throw std::runtime_error("missing value after " + a);
      return argv[++i];
    };
    if(a == "--case") o.case_file = value();
    else if(a == "--meshes") o.mesh_directory = value();
    else if(a == "--level") o.level = static_cast<unsigned int>(std::stoul(value()));
    else if(a == "--drags") o.drags = std::stoi(value());
    else if(a == "--constraint-change-every") o.constraint_change_every = std::stoi(value());
    else if(a == "--reset-every") o.reset_every = std::stoi(value());
    else if(a == "--memory-every") o.memory_every = std::stoi(value());
    else if(a == "--seed") o.seed = static_cast<unsigned int>(std::stoul(value()));
    else if(a == "--output") o.output = value();
    else if(a == "--memory-table") o.memory_table = value();
    else if(a == "--help" || a == "-h") { usage(argv[0]); std::exit(0); }
    else throw std::runtime_error("unknown option " + a);
  }
  return o;
}

// A random rigid motion of the handle about its centroid: a rotation of at
// most 60 degrees about a random axis and a translation of at most a tenth
// of the bounding-box diagonal.
Eigen::Isometry3d random_motion(std::mt19937& random, const Eigen::Vector3d& centroid, double diagonal)
{
  std::normal_distribution<double> normal(0.0, 1.0);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  const Eigen::Vector3d axis = Eigen::Vector3d(normal(random), normal(random), normal(random)).normalized();
  const double angle = uniform(random) * pi / 3;
  const Eigen::Vector3d shift =
      Eigen::Vector3d(normal(random), normal(random), normal(random)).normalized() * (0.1 * diagonal * uniform(random));
  Eigen::Isometry3d m = Eigen::Isometry3d::Identity();
  m.translate(centroid + shift);
  m.rotate(Eigen::AngleAxisd(angle, axis));
  m.translate(-centroid);
  return m;
}

std::size_t folded_pairs(const Case_geometry& g, const Positions& x)
{
  std::size_t folded = 0;
  for(const auto& pair : g.flat_face_pairs)
    if(face_normal(x, g.faces[static_cast<std::size_t>(pair.first)])
           .dot(face_normal(x, g.faces[static_cast<std::size_t>(pair.second)])) < 0)
      ++folded;
  return folded;
}

} // namespace

int main(int argc, char** argv)
{
  try
  {
    const Options o = parse(argc, argv);
    Deformation_case c = read_case_file(o.case_file, o.mesh_directory, o.level);
    const Case_geometry g = case_geometry(c);
    typedef CGAL::Spectral_surface_mesh_deformation<Mesh> Deformation;
    Deformation deformation(c.mesh);
    deformation.insert_roi_vertices(c.roi.begin(), c.roi.end());
    deformation.insert_control_vertices(c.handles.begin(), c.handles.end());
    const Clock::time_point start = Clock::now();
    if(!deformation.preprocess())
      throw std::runtime_error("preprocess() failed: " + deformation.preprocess_report().message);
    const double first_preprocess = seconds_since(start);

    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    for(vertex_descriptor v : c.handles)
      centroid += vector_of(c.mesh.point(v));
    centroid /= static_cast<double>(c.handles.size());

    std::mt19937 random(o.seed);
    std::ofstream memory(o.memory_table);
    memory << "drag\tseconds\trss_mib\n";
    std::vector<double> drag_seconds;
    std::size_t failures = 0, non_finite = 0, constraint_changes = 0, resets = 0, max_folds = 0;
    std::size_t drags_with_folds = 0;
    std::vector<vertex_descriptor> active = c.handles;
    std::string first_failure;
    for(int drag = 1; drag <= o.drags; ++drag)
    {
      if(o.constraint_change_every > 0 && drag % o.constraint_change_every == 0)
      {
        // Alternately a random half of the handle and the whole handle.
        deformation.clear_control_vertices();
        active = c.handles;
        if(constraint_changes % 2 == 0)
        {
          std::shuffle(active.begin(), active.end(), random);
          active.resize(std::max<std::size_t>(1, active.size() / 2));
        }
        deformation.insert_control_vertices(active.begin(), active.end());
        ++constraint_changes;
      }
      if(o.reset_every > 0 && drag % o.reset_every == 0)
      {
        deformation.reset();
        ++resets;
      }
      const Eigen::Isometry3d motion = random_motion(random, centroid, g.diagonal);
      for(vertex_descriptor v : active)
      {
        const Eigen::Vector3d rest = g.rest.row(static_cast<Eigen::Index>(v.idx())).transpose();
        const Eigen::Vector3d p = motion * rest;
        deformation.set_target_position(v, Point(p[0], p[1], p[2]));
      }
      const Clock::time_point drag_start = Clock::now();
      deformation.deform();
      drag_seconds.push_back(seconds_since(drag_start));
      if(!deformation.deform_report().success)
      {
        ++failures;
        if(first_failure.empty())
          first_failure = "drag " + std::to_string(drag) + ": " + deformation.deform_report().message;
      }
      const Positions x = positions_of(c.mesh);
      if(!x.allFinite())
        ++non_finite;
      else
      {
        const std::size_t folds = folded_pairs(g, x);
        max_folds = std::max(max_folds, folds);
        drags_with_folds += (folds > 0);
      }
      if(drag % o.memory_every == 0 || drag == 1)
      {
        memory << drag << '\t' << seconds_since(start) << '\t'
               << static_cast<double>(proc_field_kib("/proc/self/status", "VmRSS")) / 1024.0 << '\n'
               << std::flush;
        std::cerr << "drag " << drag << ": RSS "
                  << static_cast<double>(proc_field_kib("/proc/self/status", "VmRSS")) / 1024.0 << " MiB\n";
      }
    }

    std::vector<double> sorted = drag_seconds;
    std::sort(sorted.begin(), sorted.end());
    auto quantile = [&sorted](double q) { return sorted[static_cast<std::size_t>(q * double(sorted.size() - 1))]; };
    std::ofstream out(o.output);
    out << "# Soak run: " << o.drags << " drags on " << c.name << "@" << o.level << "\n\n"
        << "- " << c.title << "; " << num_vertices(c.mesh) << " vertices, ROI " << c.roi.size()
        << ", handle " << c.handles.size() << " vertices\n"
        << "- random rigid handle motions (rotation up to 60 degrees about a random axis through the "
           "handle centroid, translation up to 0.1 of the diagonal), seed "
        << o.seed << "; every " << o.constraint_change_every
        << " drags the control vertices change (a random half of the handle, then the whole handle), every "
        << o.reset_every << " drags a reset()\n"
        << "- defaults otherwise (spectral, m = 100, exact constraints, 10 iterations); "
        << utc_time(std::time(nullptr)) << ", " << compiler() << ", " << sparse_solver() << "\n\n"
        << "| measure | value |\n|---|--:|\n"
        << "| first preprocess() | " << fixed(first_preprocess, 2) << " s |\n"
        << "| drags | " << o.drags << " |\n"
        << "| failed deform() | " << failures << " |\n"
        << "| results with non-finite coordinates | " << non_finite << " |\n"
        << "| constraint changes / resets | " << constraint_changes << " / " << resets << " |\n"
        << "| drag time median / p95 / max | " << fixed(quantile(0.5), 3) << " / " << fixed(quantile(0.95), 3)
        << " / " << fixed(sorted.back(), 3) << " s |\n"
        << "| drags with folded face pairs / most folded pairs | " << drags_with_folds << " / " << max_folds
        << " |\n"
        << "| total | " << fixed(seconds_since(start), 0) << " s |\n";
    if(!first_failure.empty())
      out << "\nFirst failure: " << first_failure << "\n";
    // The report names the table by its file name: both sit in results/.
    out << "\nResident memory over time: `" << std::filesystem::path(o.memory_table).filename().string()
        << "` (plotted by `benchmark/plot_soak_memory.py`).\n";
    std::cerr << "report written to " << o.output << "\n";
    return (failures == 0 && non_finite == 0) ? 0 : 1;
  }
  catch(const std::exception& e)
  {
    std::cerr << "benchmark_soak: " << e.what() << "\n";
    return 2;
  }
}

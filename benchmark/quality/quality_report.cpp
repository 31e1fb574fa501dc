// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This program is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.
//
// Compares the quality of the deformations computed by
// CGAL::Surface_mesh_deformation (as-rigid-as-possible, both energies) and by
// the algorithms of CGAL::Spectral_surface_mesh_deformation on the same
// cases, and writes a markdown report.
//
// Cases:
//   - the four cases of Botsch and Sorkine 2008 (bar, cactus, cylinder,
//     plane: NAME.off, NAME.sel, NAME.def) when their directory is given with
//     --botsch08 (skipped otherwise);
//   - every file *.case of the case directory (see read_case_file() for the
//     format), on meshes of the mesh directory.
//
// Every algorithm deforms its own copy of the input mesh with the same region
// of interest, control vertices and targets; the result is measured on the
// whole mesh (see write_definitions() for the exact definitions). The case
// reader and the measures are in ../deformation_cases.h, which the timing
// benchmark (../benchmark_deformation.cpp) shares.
//
// Usage: quality_report --output FILE [options], see print_usage().

#include <CGAL/Spectral_surface_mesh_deformation.h>
#include <CGAL/Spectral_deformation/IO/deformation_selection.h>
#include <CGAL/Spectral_deformation/Sparse_spd_solver_traits.h>
#include <CGAL/Spectral_deformation/Partition_of_unity_eigensolver_traits.h>
#include <CGAL/Spectral_deformation/arap_energy.h>
#include <CGAL/Surface_mesh_deformation.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/version.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <Spectra/Util/Version.h>

#include <unistd.h>

#include "../deformation_cases.h" // cases, measures, formatting (shared with benchmark_deformation)

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <numeric>
#include <sstream>
#include <stdexcept>
#include <type_traits>
#include <string>
#include <utility>
#include <vector>

#ifndef SSMD_QUALITY_BUILD_TYPE
#define SSMD_QUALITY_BUILD_TYPE "unknown"
#endif
#ifndef SSMD_QUALITY_CXX_FLAGS_BUILD_TYPE
#define SSMD_QUALITY_CXX_FLAGS_BUILD_TYPE "unknown"
#endif
#ifndef SSMD_QUALITY_CXX_FLAGS
#define SSMD_QUALITY_CXX_FLAGS ""
#endif
#ifndef SSMD_QUALITY_COMPILE_OPTIONS
#define SSMD_QUALITY_COMPILE_OPTIONS ""
#endif
#ifndef SSMD_QUALITY_DEFAULT_MESH_DIR
#define SSMD_QUALITY_DEFAULT_MESH_DIR "data/meshes"
#endif
#ifndef SSMD_QUALITY_DEFAULT_CASE_DIR
#define SSMD_QUALITY_DEFAULT_CASE_DIR "cases"
#endif

namespace {

using namespace ssmd_benchmark;
// The deformation class's default settings, read from an object with its
// defaults, so that the report follows them.
struct Default_settings
{
  std::size_t rotation_patches;
  CGAL::Spectral_smooth_energy smooth_energy;
  double stage_angle; // degrees
};

const Default_settings& default_settings()
{
  static const Default_settings settings = [] {
    Mesh empty;
    const CGAL::Spectral_surface_mesh_deformation<Mesh> defaults(empty);
    return Default_settings{defaults.rotation_patches(), defaults.smooth_energy(), defaults.stage_angle()};
  }();
  return settings;
}

// ----------------------------------------------------------------------------
// Command line

struct Options
{
  std::string output;
  std::string botsch08_directory; // empty: the Botsch & Sorkine cases are skipped
  std::string mesh_directory = SSMD_QUALITY_DEFAULT_MESH_DIR;
  std::string case_directory = SSMD_QUALITY_DEFAULT_CASE_DIR;
  std::string mesh_output_directory; // empty: no mesh is written
  std::vector<std::string> only;     // names of the cases to run; empty: all
  std::size_t frequencies = 100;
  // The class's defaults, read from its settings so that the report follows them.
  std::size_t rotation_patches = default_settings().rotation_patches; // 0: the full iteration
  CGAL::Spectral_smooth_energy smooth_energy = default_settings().smooth_energy; // of the iteration
  double stage_angle = default_settings().stage_angle; // degrees
  bool volume_preservation = false;       // set_volume_preservation() of the spectral algorithms
  bool partition_of_unity_basis = true; // the class's default, the approximate basis; false: the exact one
  Eigen::Index basis_samples = 0;         // of the approximate basis; 0: its default
  unsigned int long_iterations = 1000;      // of the additional runs
  double refine_tolerance = -1;             // >= 0: a run of refine() after deform() (spectral, iterated)
  unsigned int refine_iterations = 1000;    // its cap
  unsigned int arap_large_iterations = 200; // of the additional CGAL runs on large ROIs
  double arap_tolerance = 1e-4;             // of the additional CGAL runs (the class's default)
  std::size_t large_roi = 20000;
  std::vector<std::string> notes;
  bool selection_only = false; // write the selections and stop
  std::vector<unsigned int> levels{0};              // Loop subdivision levels of the case files
  std::map<std::string, std::vector<unsigned int>> case_levels; // per case, replaces `levels`
};

void print_usage(const char* program)
{
  std::cerr
      << "Usage: " << program << " --output FILE [options]\n"
      << "  --output FILE                 the markdown report\n"
      << "  --botsch08 DIR                directory of the Botsch & Sorkine 2008 cases\n"
      << "                                (NAME.off, NAME.sel, NAME.def for bar, cactus,\n"
      << "                                cylinder, plane); skipped when not given or absent\n"
      << "  --meshes DIR                  meshes named by the case files\n"
      << "                                (default " SSMD_QUALITY_DEFAULT_MESH_DIR ")\n"
      << "  --cases DIR                   the *.case files (default " SSMD_QUALITY_DEFAULT_CASE_DIR
         ")\n"
      << "  --only a,b,...                run only the cases of these names\n"
      << "  --frequencies m               basis size of the spectral algorithms (default 100)\n"
      << "  --rotation-patches k          rotation patches of the iteration (default: the\n"
      << "                                class's, " << default_settings().rotation_patches << "; 0: the full iteration)\n"
      << "  --basis B                     partition-of-unity (default, the class's:\n"
      << "                                Partition_of_unity_eigensolver_traits) or exact\n"
      << "                                (Block_lanczos_eigensolver_traits)\n"
      << "  --basis-samples k             samples of the partition-of-unity basis (default: its own)\n"
      << "  --smooth-energy E             dual-laplacian-and-arap (default), dual-laplacian or\n"
      << "                                arap: the energy of the iteration\n"
      << "  --stage-angle DEGREES         the largest turn of a handle per stage of deform()\n"
      << "                                (default: the class's, 30; 0: one stage)\n"
      << "  --volume-preservation         the detail transfer keeps the enclosed volume\n"
      << "                                (set_volume_preservation(true))\n"
      << "  --long-iterations N           iteration cap of the additional runs made when the\n"
      << "                                default deform() does not converge (default 1000)\n"
      << "  --refine T                    also refine() the result of the spectral iteration's\n"
      << "                                deform() to the ARAP optimum (tolerance T)\n"
      << "  --refine-iterations N         the cap of --refine (default 1000)\n"
      << "  --large-roi N                 ROIs with more vertices are large (default 20000)\n"
      << "  --arap-tolerance T            energy tolerance of the additional CGAL runs\n"
      << "                                (default 1e-4, the class's; e.g. 1e-9 with a large\n"
      << "                                --long-iterations: ARAP run to convergence)\n"
      << "  --arap-large-iterations N     cap of the additional CGAL runs on large ROIs\n"
      << "                                (default 200)\n"
      << "  --mesh-output DIR             write the input, the selection (.vtk, scalar\n"
      << "                                'status') and every result (.off) there, with the\n"
      << "                                smooth meshes of the spectral ones (.smooth_rest.off,\n"
      << "                                .smooth_deformed.off)\n"
      << "  --selection-only              with --mesh-output: write the inputs and selections,\n"
      << "                                print their sizes and run nothing (to check the\n"
      << "                                shapes of a case file)\n"
      << "  --note TEXT                   a line added to the notes of the report\n"
      << "  --levels l1,l2,...            run every case also on its mesh Loop-subdivided\n"
      << "                                l times (default 0: native only); on subdivided\n"
      << "                                meshes, CGAL ARAP (spokes and rims) and the spectral\n"
      << "                                algorithm (both policies) run deform() only\n"
      << "  --case-levels NAME=l1,l2,...  the levels of the case NAME (repeatable)\n";
}

std::vector<std::string> split(const std::string& text, char separator)
{
  std::vector<std::string> parts;
  std::istringstream in(text);
  std::string part;
  while(std::getline(in, part, separator))
    if(!part.empty())
      parts.push_back(part);
  return parts;
}

unsigned int to_positive_int(const std::string& text, const std::string& option)
{
  char* end = nullptr;
  const long value = std::strtol(text.c_str(), &end, 10);
  if(end == text.c_str() || *end != '\0' || value < 1 || value > 1000000000L)
    throw std::invalid_argument(option + " expects a positive integer, got '" + text + "'");
  return static_cast<unsigned int>(value);
}

Options parse_options(int argc, char** argv)
{
  Options options;
  for(int i = 1; i < argc; ++i)
  {
    const std::string argument = argv[i];
    auto value = [&]() -> std::string {
      if(i + 1 >= argc)
        throw std::invalid_argument(argument + " expects a value");
      return argv[++i];
    };
    if(argument == "--help" || argument == "-h")
    {
      print_usage(argv[0]);
      std::exit(EXIT_SUCCESS);
    }
    else if(argument == "--output")
      options.output = value();
    else if(argument == "--botsch08")
      options.botsch08_directory = value();
    else if(argument == "--meshes")
      options.mesh_directory = value();
    else if(argument == "--cases")
      options.case_directory = value();
    else if(argument == "--only")
      options.only = split(value(), ',');
    else if(argument == "--frequencies")
      options.frequencies = to_positive_int(value(), argument);
    else if(argument == "--smooth-energy")
    {
      const std::string energy = value();
      if(energy == "arap")
        options.smooth_energy = CGAL::ARAP_ENERGY;
      else if(energy == "dual-laplacian-and-arap")
        options.smooth_energy = CGAL::DUAL_LAPLACIAN_AND_ARAP_ENERGY;
      else if(energy == "dual-laplacian")
        options.smooth_energy = CGAL::DUAL_LAPLACIAN_ENERGY;
      else
        throw std::invalid_argument("--smooth-energy: dual-laplacian, arap or dual-laplacian-and-arap");
    }
    else if(argument == "--basis")
    {
      const std::string basis = value();
      if(basis == "partition-of-unity")
        options.partition_of_unity_basis = true;
      else if(basis == "exact")
        options.partition_of_unity_basis = false;
      else
        throw std::invalid_argument("--basis: exact or partition-of-unity");
    }
    else if(argument == "--stage-angle")
    {
      const std::string text = value();
      char* end = nullptr;
      options.stage_angle = std::strtod(text.c_str(), &end);
      if(end == text.c_str() || *end != '\0' || !(options.stage_angle >= 0) || !std::isfinite(options.stage_angle))
        throw std::invalid_argument("--stage-angle expects an angle of at least 0 degrees, got '" + text + "'");
    }
    else if(argument == "--volume-preservation")
      options.volume_preservation = true;
    else if(argument == "--basis-samples")
      options.basis_samples = to_positive_int(value(), argument);
    else if(argument == "--rotation-patches")
      options.rotation_patches = static_cast<std::size_t>(std::stoul(value()));
    else if(argument == "--long-iterations")
      options.long_iterations = to_positive_int(value(), argument);
    else if(argument == "--refine")
      options.refine_tolerance = std::stod(value());
    else if(argument == "--refine-iterations")
      options.refine_iterations = to_positive_int(value(), argument);
    else if(argument == "--large-roi")
      options.large_roi = to_positive_int(value(), argument);
    else if(argument == "--arap-tolerance")
    {
      options.arap_tolerance = std::stod(value());
      if(!(options.arap_tolerance >= 0))
        throw std::invalid_argument("--arap-tolerance must be a number >= 0");
    }
    else if(argument == "--arap-large-iterations")
      options.arap_large_iterations = to_positive_int(value(), argument);
    else if(argument == "--mesh-output")
      options.mesh_output_directory = value();
    else if(argument == "--note")
      options.notes.push_back(value());
    else if(argument == "--selection-only")
      options.selection_only = true;
    else if(argument == "--levels" || argument == "--case-levels")
    {
      std::string text = value();
      std::string name;
      if(argument == "--case-levels")
      {
        const std::size_t equal = text.find('=');
        if(equal == std::string::npos)
          throw std::invalid_argument("--case-levels expects NAME=l1,l2,...");
        name = text.substr(0, equal);
        text = text.substr(equal + 1);
      }
      std::vector<unsigned int> levels;
      for(const std::string& part : split(text, ','))
        levels.push_back(part == "0" ? 0u : to_positive_int(part, argument));
      if(levels.empty())
        throw std::invalid_argument(argument + " expects at least one level");
      if(name.empty())
        options.levels = levels;
      else
        options.case_levels[name] = levels;
    }
    else
      throw std::invalid_argument("unknown argument '" + argument + "'");
  }
  if(options.selection_only && options.mesh_output_directory.empty())
    throw std::invalid_argument("--selection-only needs --mesh-output");
  if(options.output.empty() && !options.selection_only)
    throw std::invalid_argument("--output is required");
  return options;
}


// ----------------------------------------------------------------------------
// Runs

struct Run_result
{
  std::string label; // as shown in the report
  std::string key;   // in the names of the written meshes
  bool success = false;
  std::string message; // why not
  double preprocess_seconds = not_a_number;
  bool preprocess_reused = false;
  double deform_seconds = not_a_number;
  std::string iterations;
  Positions after;
  // The smooth mesh at rest and deformed (spectral algorithms; empty otherwise).
  Positions smooth_rest, smooth_deformed;
  Quality quality;
};

template <class Deformation>
void select_vertices(Deformation& deformation, const Deformation_case& c)
{
  deformation.insert_roi_vertices(c.roi.begin(), c.roi.end());
  deformation.insert_control_vertices(c.handles.begin(), c.handles.end());
}

template <class Deformation>
void set_targets(Deformation& deformation, const Deformation_case& c)
{
  for(std::size_t k = 0; k < c.handles.size(); ++k)
    deformation.set_target_position(c.handles[k], c.targets[k]);
}

template <CGAL::Deformation_algorithm_tag TAG>
using Cgal_deformation = CGAL::Surface_mesh_deformation<Mesh, CGAL::Default, CGAL::Default, TAG>;

/// The number of iterations a call `deform(cap, tolerance)` of CGAL's class
/// performed (the class does not tell): a new object repeats `deform(1, 0)`,
/// which performs the same operations one iteration at a time, until its
/// result is bitwise equal to `result`. 0 if it never is.
template <CGAL::Deformation_algorithm_tag TAG>
unsigned int count_cgal_iterations(const Deformation_case& c, const Positions& result, unsigned int cap)
{
  Mesh mesh = c.mesh;
  Cgal_deformation<TAG> deformation(mesh);
  select_vertices(deformation, c);
  if(!deformation.preprocess())
    return 0;
  set_targets(deformation, c);
  for(unsigned int k = 1; k <= cap; ++k)
  {
    deformation.deform(1, 0.0);
    if(positions_of(mesh) == result)
      return k;
  }
  return 0;
}

/// What a run of CGAL's class did: the iterations it performed (0 when
/// unknown), its cap and its tolerance.
struct Cgal_iterations
{
  unsigned int performed = 0;
  unsigned int cap = 0;
  double tolerance = 0;
};

/// CGAL's `deform(iterations, tolerance)` on a new object;
/// `iterations == 0` means `deform()` with the defaults of the class.
template <CGAL::Deformation_algorithm_tag TAG>
Cgal_iterations run_cgal(const Deformation_case& c, unsigned int iterations, double tolerance,
                         Run_result& result)
{
  Mesh mesh = c.mesh;
  Cgal_deformation<TAG> deformation(mesh);
  select_vertices(deformation, c);
  Cgal_iterations run;
  run.cap = iterations == 0 ? deformation.iterations() : iterations;
  run.tolerance = iterations == 0 ? deformation.tolerance() : tolerance;
  const Clock::time_point start = Clock::now();
  const bool preprocessed = deformation.preprocess();
  result.preprocess_seconds = seconds_since(start);
  if(!preprocessed)
  {
    result.message = "preprocess() failed";
    result.iterations = "failed";
    return run;
  }
  set_targets(deformation, c);
  const Clock::time_point deform_start = Clock::now();
  if(iterations == 0)
    deformation.deform();
  else
    deformation.deform(iterations, run.tolerance);
  result.deform_seconds = seconds_since(deform_start);
  result.after = positions_of(mesh);
  result.success = true;
  run.performed = count_cgal_iterations<TAG>(c, result.after, run.cap);
  std::ostringstream text;
  if(run.performed == 0)
    text << "? (cap " << run.cap << ")";
  else if(run.performed < run.cap)
    text << run.performed << ", tolerance reached";
  else
    text << run.performed << " (cap), tolerance not reached";
  result.iterations = text.str();
  return run;
}

// The exact basis unless a run asks for another (the class's default is the
// partition-of-unity basis).
template <CGAL::Spectral_deformation_algorithm_tag TAG, class ET = CGAL::Block_lanczos_eigensolver_traits<>>
using Spectral_deformation =
    CGAL::Spectral_surface_mesh_deformation<Mesh, CGAL::Default, CGAL::Default, TAG, ET>;

typedef CGAL::Partition_of_unity_eigensolver_traits<> Partition_of_unity_traits;


// ----------------------------------------------------------------------------
// Runs of the package's algorithms

std::string spectral_iterations(const CGAL::Spectral_deformation_report& report, bool linear)
{
  if(!report.success)
    return "failed";
  std::ostringstream text;
  text << report.iterations;
  if(report.stages > 1)
    text << " in " << report.stages << " stages";
  if(linear)
    text << " (no iteration)";
  else if(report.converged)
    text << ", converged";
  else
    text << " (cap), last step " << scientific(report.last_step);
  return text.str();
}

template <class Deformation>
void record_deformation(const Deformation& deformation, bool linear, bool keep_smooth_meshes,
                        double seconds, const Mesh& mesh, Run_result& result)
{
  const CGAL::Spectral_deformation_report& report = deformation.deform_report();
  result.deform_seconds = seconds;
  result.success = report.success;
  result.message = report.message;
  result.iterations = spectral_iterations(report, linear);
  result.after = positions_of(mesh);
  if(!keep_smooth_meshes)
    return;
  if constexpr(Deformation::has_basis)
  {
    result.smooth_rest.resize(result.after.rows(), 3);
    result.smooth_deformed.resize(result.after.rows(), 3);
    Eigen::Index i = 0;
    for(auto v : vertices(mesh))
    {
      const auto rest = deformation.smoothed_rest_point(v);
      const auto deformed = deformation.smoothed_deformed_point(v);
      result.smooth_rest.row(i) << rest.x(), rest.y(), rest.z();
      result.smooth_deformed.row(i) << deformed.x(), deformed.y(), deformed.z();
      ++i;
    }
  }
}

/// Runs `deform()` with the defaults of the class and, when it stops at its
/// iteration cap, `deform(long_iterations, tolerance)` after `reset()` (same
/// region, basis and factorizations).
template <CGAL::Spectral_deformation_algorithm_tag TAG, class ET = CGAL::Default>
void run_package_algorithm(const Deformation_case& c, const Options& options,
                           CGAL::Spectral_constraint_policy policy, const std::string& label,
                           const std::string& key, std::vector<Run_result>& results)
{
  const bool linear = (TAG == CGAL::SPECTRAL_LINEAR);
  const bool keep_smooth_meshes = !options.mesh_output_directory.empty(); // to write them
  Mesh mesh = c.mesh;
  Spectral_deformation<TAG, ET> deformation(mesh);
  select_vertices(deformation, c);
  if constexpr(Spectral_deformation<TAG, ET>::has_basis)
  {
    deformation.set_number_of_frequencies(options.frequencies);
    deformation.set_rotation_patches(options.rotation_patches);
    deformation.set_smooth_energy(options.smooth_energy);
    deformation.set_stage_angle(options.stage_angle);
    deformation.set_volume_preservation(options.volume_preservation);
    deformation.set_constraint_policy(policy);
    // This program owns its process: the solvers may change process-wide
    // state (OpenBLAS threads, SuiteSparse's allocator) to run faster.
    typename Spectral_deformation<TAG, ET>::Eigensolver_traits eigensolver;
    if constexpr(std::is_same_v<ET, Partition_of_unity_traits>)
      eigensolver.set_number_of_samples(options.basis_samples);
    else
      eigensolver.set_process_wide_tuning(true);
    deformation.set_eigensolver_traits(eigensolver);
  }

  Run_result first;
  first.label = label + ", `deform()`";
  first.key = key;
  const Clock::time_point start = Clock::now();
  const bool preprocessed = deformation.preprocess();
  first.preprocess_seconds = seconds_since(start);
  if(!preprocessed)
  {
    first.message = "preprocess() failed: " + deformation.preprocess_report().message;
    first.iterations = "failed";
    results.push_back(first);
    return;
  }
  set_targets(deformation, c);
  const Clock::time_point deform_start = Clock::now();
  deformation.deform();
  record_deformation(deformation, linear, keep_smooth_meshes, seconds_since(deform_start), mesh, first);
  results.push_back(first);

  if(!linear && first.success && options.refine_tolerance >= 0)
  {
    Run_result refined = first;
    refined.label = label + ", `deform()`, `refine(" + std::to_string(options.refine_iterations) + ", " +
                    scientific(options.refine_tolerance) + ")`";
    refined.key = key + "_refined";
    refined.preprocess_reused = true;
    const Clock::time_point refine_start = Clock::now();
    const bool success = deformation.refine(options.refine_iterations, options.refine_tolerance);
    refined.deform_seconds += seconds_since(refine_start);
    const CGAL::Spectral_refinement_report& r = deformation.refine_report();
    refined.success = success;
    refined.message = r.message;
    refined.iterations = first.iterations + " + " + std::to_string(r.iterations) +
                         (r.converged ? " (converged)" : " (cap)");
    refined.after = positions_of(mesh);
    results.push_back(refined);
  }

  const CGAL::Spectral_deformation_report& report = deformation.deform_report();
  if(linear || !report.success || report.converged ||
     options.long_iterations <= deformation.iterations())
    return;
  Run_result second;
  second.label = label + ", `deform(" + std::to_string(options.long_iterations) + ", " +
                 scientific(deformation.tolerance()) + ")`";
  second.key = key + "_long";
  second.preprocess_reused = true;
  deformation.reset();
  set_targets(deformation, c);
  const Clock::time_point long_start = Clock::now();
  deformation.deform(options.long_iterations, deformation.tolerance());
  record_deformation(deformation, linear, keep_smooth_meshes, seconds_since(long_start), mesh, second);
  results.push_back(second);
}

/// Runs CGAL's `deform()` with the defaults of the class and, when it stops
/// at its iteration cap, `deform(long_iterations, long_tolerance)` on a new object.
template <CGAL::Deformation_algorithm_tag TAG>
void run_cgal_algorithm(const Deformation_case& c, unsigned int long_iterations, double long_tolerance,
                        const std::string& label, const std::string& key,
                        std::vector<Run_result>& results)
{
  Run_result first;
  first.label = label + ", `deform()`";
  first.key = key;
  const Cgal_iterations run = run_cgal<TAG>(c, 0, 0.0, first);
  results.push_back(first);
  if(!first.success || (run.performed != 0 && run.performed < run.cap) || long_iterations <= run.cap)
    return;
  Run_result second;
  second.label = label + ", `deform(" + std::to_string(long_iterations) + ", " +
                 scientific(long_tolerance) + ")`";
  second.key = key + "_long";
  run_cgal<TAG>(c, long_iterations, long_tolerance, second);
  results.push_back(second);
}

// ----------------------------------------------------------------------------
// Output of meshes

void write_off(const std::string& filename, const Mesh& mesh, const Positions& x)
{
  Mesh copy = mesh;
  for(vertex_descriptor v : vertices(copy))
  {
    const Eigen::Index i = static_cast<Eigen::Index>(v.idx());
    copy.point(v) = Point(x(i, 0), x(i, 1), x(i, 2));
  }
  std::ofstream out(filename);
  out.precision(17);
  if(!CGAL::IO::write_OFF(out, copy))
    throw std::runtime_error("cannot write " + filename);
}

/// The mesh with the status of every vertex as point data `status`
/// (0 fixed, 1 ROI, 2 handle), in the legacy VTK format.
void write_selection(const std::string& filename, const Deformation_case& c, const Case_geometry& g)
{
  std::ofstream out(filename);
  out.precision(17);
  out << "# vtk DataFile Version 3.0\n" << c.name << " selection\nASCII\nDATASET POLYDATA\n"
      << "POINTS " << g.rest.rows() << " double\n";
  for(Eigen::Index i = 0; i < g.rest.rows(); ++i)
    out << g.rest(i, 0) << ' ' << g.rest(i, 1) << ' ' << g.rest(i, 2) << '\n';
  out << "POLYGONS " << g.faces.size() << ' ' << 4 * g.faces.size() << '\n';
  for(const auto& t : g.faces)
    out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
  out << "POINT_DATA " << g.rest.rows() << "\nSCALARS status int 1\nLOOKUP_TABLE default\n";
  for(Status s : c.status)
    out << static_cast<int>(s) << '\n';
  if(!out)
    throw std::runtime_error("cannot write " + filename);
}

// ----------------------------------------------------------------------------
// Report

struct Case_report
{
  std::string name, title, source;
  std::string skipped; // why the case did not run; empty when it ran
  std::size_t vertices = 0, faces = 0, roi = 0, handles = 0, fixed = 0;
  std::size_t interior_edges = 0, flat_pairs = 0;
  double diagonal = 0;
  std::string transformation;
  unsigned int cgal_long_iterations = 0;
  unsigned int level = 0; // Loop subdivision steps applied to the mesh of the case
  double seconds = 0;
  std::vector<Run_result> results;
};



std::string sparse_solver()
{
#ifdef CGAL_SSMD_USE_CHOLMOD
  return "CHOLMOD " + std::to_string(CHOLMOD_MAIN_VERSION) + "." +
         std::to_string(CHOLMOD_SUB_VERSION) + "." + std::to_string(CHOLMOD_SUBSUB_VERSION) +
         " (`CGAL_SSMD_USE_CHOLMOD` defined)";
#else
  return "Eigen `SimplicialLDLT` (`CGAL_SSMD_USE_CHOLMOD` not defined)";
#endif
}


struct Run_info
{
  std::time_t start = std::time(nullptr);
  double load_at_start = load_average();
  Clock::time_point clock_start = Clock::now();
};

void write_definitions(std::ostream& out, const Options& options)
{
  out << "## Definitions\n\n"
      << "Every algorithm deforms its own copy of the input with the same region of interest "
         "(ROI: statuses 1 and 2), control vertices (the handle: status 2) and targets (the "
         "handle transformation applied to the rest positions of the handle vertices); "
         "vertices of status 0 are outside the ROI. All measures are taken on the whole mesh "
         "against the input. *D* is the bounding-box diagonal of the input mesh.\n\n"
      << "- *iterations*: for this package, `deform_report().iterations` (solves of the "
         "reduced or spatial system; *converged* when the relative step fell below the "
         "tolerance, otherwise the last step is given). CGAL's class does not report its "
         "iterations: they are counted by repeating `deform(1, 0)` on a new object (the same "
         "operations, one iteration per call) until the result is bitwise equal to that of "
         "the timed call (this count is not timed); *tolerance reached* means that CGAL's "
         "energy criterion stopped before the cap.\n"
      << "- *preprocess*: wall time of an explicit `preprocess()` after the ROI and control "
         "vertices were inserted (for this package: region, manifold harmonics basis, "
         "reduced matrices and factorizations; for CGAL: region of solution and "
         "factorization). *reused*: the run continues on the object of the row above after "
         "`reset()`, nothing is recomputed.\n"
      << "- *deform*: wall time of the `deform` call, targets set beforehand.\n"
      << "- *handle residual*: max and RMS over the handle vertices of the distance to the "
         "target, divided by *D*.\n"
      << "- *outside ROI*: the largest displacement of a vertex outside the ROI, divided by "
         "*D*; must be exactly 0.\n"
      << "- *ARAP energy*: `CGAL::arap_energy(input, result)` on the whole mesh: "
         "Σ w_ij ‖(x'_i − x'_j) − R_i (x_i − x_j)‖² / Σ w_ij ‖x_i − x_j‖² over the directed "
         "edges, w_ij = |cotangent weight| of the input, R_i the best rotation of the one-ring "
         "of i; 0 for a rigid motion, about the mean squared relative distortion otherwise.\n"
      << "- *edge change*: |ℓ' − ℓ| / ℓ over the edges with at least one ROI vertex "
         "(ℓ rest length, ℓ' deformed length); mean and max. *ROI border*: the max over the "
         "edges joining a vertex outside the ROI to a ROI vertex (a seam between the fixed "
         "part and the ROI shows there).\n"
      << "- *folded pairs*: interior edges whose two face normals make an angle below 89° "
         "in the input and above 90° in the result (a fold or a sharp crease created by the "
         "deformation). Only pairs below 89° at rest are candidates (their number is given "
         "per case): right-angled creases of the input, such as the edges of the bar, cross "
         "90° by hundredths of a degree under any deformation.\n"
      << "- *volume change*: the relative change of the volume enclosed by the mesh "
         "(closed meshes only).\n"
      << "- *non-finite*: coordinates of the result that are NaN or infinite (the other "
         "measures are then not computed).\n"
      << "- CGAL ARAP: `CGAL::Surface_mesh_deformation<Surface_mesh>` with its default "
         "weights and sparse solver (Eigen `SparseLU`), tags `SPOKES_AND_RIMS` (default) and "
         "`ORIGINAL_ARAP`. `deform()` runs at most 5 iterations with the energy tolerance "
         "1e-4; when it stops at the cap, a new object runs `deform(N, "
      << scientific(options.arap_tolerance) << ")` with N = " << options.long_iterations << ", capped at N = " << options.arap_large_iterations
         << " when the ROI has more than " << options.large_roi
         << " vertices (to bound the run time; see each case).\n"
      << "- This package: `CGAL::Spectral_surface_mesh_deformation<Surface_mesh, Default, "
         "Default, TAG>`, m = "
      << options.frequencies
      << " frequencies (`set_number_of_frequencies`), otherwise defaults (constraint weight "
         "1, at most 10 iterations, tolerance 1e-4); *exact* and *soft* are the "
         "`EXACT_CONSTRAINTS` and `SOFT_CONSTRAINTS` policies. When `deform()` stops at its "
         "cap, the same object continues with `reset()`, the same targets and `deform("
      << options.long_iterations << ", 1e-4)`.\n";
}

std::string signed_percent(double value)
{
  if(std::isnan(value))
    return "–";
  return (value > 0 ? "+" : "") + format("%.1f", 100.0 * value) + " %";
}

/// One table over all cases and levels: the default `deform()` of CGAL ARAP
/// and of the spectral algorithm (both policies), the measures that show a
/// broken result (folds, stretched edges) and the ARAP energy against CGAL's.
void write_sweep(std::ostream& out, const std::vector<Case_report>& cases)
{
  out << "\n## Summary over all cases and resolutions\n\n"
      << "`deform()` with the defaults of each class (CGAL: at most 5 iterations; this package: "
         "at most 10). *@k*: the mesh of the case Loop-subdivided k times. *energy / CGAL*: the "
         "ARAP energy of the result over that of CGAL ARAP (spokes and rims) on the same "
         "input. *limit*: on a subdivided mesh, 1.5 × the maximal edge change of the same "
         "algorithm on the native mesh + 10 %, the bound a result free of resolution artefacts "
         "stays under.\n\n"
      << "| case | vertices | algorithm | folded pairs | edge change max | limit | edge change mean | "
         "ARAP energy | energy / CGAL | volume change |\n"
      << "|---|--:|---|--:|--:|--:|--:|--:|--:|--:|\n";
  auto native_max_edge_change = [&cases](const std::string& name, const std::string& key) {
    const std::string base = name.substr(0, name.find('@'));
    for(const Case_report& c : cases)
      if(c.name == base && c.skipped.empty())
        for(const Run_result& r : c.results)
          if(r.key == key && r.success)
            return r.quality.max_edge_change;
    return not_a_number;
  };
  for(const Case_report& c : cases)
  {
    if(!c.skipped.empty())
      continue;
    double cgal_energy = not_a_number;
    for(const Run_result& r : c.results)
      if(r.key == "cgal_spokes_and_rims" && r.success)
        cgal_energy = r.quality.arap_energy;
    for(const Run_result& r : c.results)
    {
      if(r.key != "cgal_spokes_and_rims" && r.key != "spectral_exact" && r.key != "spectral_soft")
        continue;
      const std::string name = r.key == "cgal_spokes_and_rims" ? "CGAL ARAP"
                               : r.key == "spectral_exact"     ? "spectral, exact"
                                                               : "spectral, soft";
      out << "| " << c.name << " | " << c.vertices << " | " << name << " | ";
      if(!r.success)
      {
        out << "failed | | | | | | |\n";
        continue;
      }
      const Quality& q = r.quality;
      std::string limit = "–";
      if(c.level > 0)
      {
        const double bound = 1.5 * native_max_edge_change(c.name, r.key) + 0.1;
        if(!std::isnan(bound))
          limit = percent(bound) + (q.max_edge_change <= bound ? "" : " **exceeded**");
      }
      out << q.folded_pairs << " | " << percent(q.max_edge_change) << " | " << limit << " | "
          << percent(q.mean_edge_change) << " | " << scientific(q.arap_energy) << " | "
          << format("%.2f", q.arap_energy / cgal_energy) << " | " << signed_percent(q.volume_change)
          << " |\n";
    }
  }
}

void write_report(const std::string& filename, const Options& options, const Run_info& run,
                  const std::vector<Case_report>& cases, bool complete)
{
  std::ofstream out(filename);
  if(!out)
    throw std::runtime_error("cannot write " + filename);
  const double minutes = std::chrono::duration<double>(Clock::now() - run.clock_start).count() / 60.0;
  out << "# Deformation quality: CGAL ARAP and the algorithms of this package\n\n";
  if(!complete)
    out << "**Incomplete: the run was still in progress when this was written.**\n\n";
  out << "- Date: " << utc_time(run.start) << ", whole run " << fixed(minutes, 1)
      << " min, load average (1 min) " << fixed(run.load_at_start, 2) << " at start, "
      << fixed(load_average(), 2) << " at the end\n"
      << "- Machine: " << first_line_value("/proc/cpuinfo", "model name") << ", "
      << ::sysconf(_SC_NPROCESSORS_ONLN) << " logical CPUs, " << fixed(memory_gib(), 1)
      << " GiB RAM\n"
      << "- Compiler: " << compiler() << "\n"
      << "- Build: `CMAKE_BUILD_TYPE=" << SSMD_QUALITY_BUILD_TYPE << "`, flags of the build type `"
      << SSMD_QUALITY_CXX_FLAGS_BUILD_TYPE << "`, `CMAKE_CXX_FLAGS` `" << SSMD_QUALITY_CXX_FLAGS
      << "`, compile options `" << SSMD_QUALITY_COMPILE_OPTIONS << "`"
#ifdef NDEBUG
      << ", `NDEBUG` defined\n"
#else
      << ", **`NDEBUG` not defined (assertions on)**\n"
#endif
      << "- Libraries: CGAL " << CGAL_VERSION_STR << ", Eigen " << EIGEN_WORLD_VERSION << "."
      << EIGEN_MAJOR_VERSION << "." << EIGEN_MINOR_VERSION << ", Spectra " << SPECTRA_MAJOR_VERSION
      << "." << SPECTRA_MINOR_VERSION << "." << SPECTRA_PATCH_VERSION
      << "; sparse SPD solver of this package: " << sparse_solver() << "\n"
      << "- Settings: m = " << options.frequencies << ", smooth energy "
      << (options.smooth_energy == CGAL::ARAP_ENERGY                      ? "ARAP"
          : options.smooth_energy == CGAL::DUAL_LAPLACIAN_AND_ARAP_ENERGY ? "dual Laplacian + ARAP"
                                                                          : "dual Laplacian")
      << ", basis "
      << (options.partition_of_unity_basis
              ? "partition of unity (" +
                    (options.basis_samples > 0 ? std::to_string(options.basis_samples)
                                               : std::string("default number of")) +
                    " samples)"
              : std::string("exact"))
      << ", rotation patches "
      << options.rotation_patches
      << " (0: the full iteration), stage angle "
      << fixed(options.stage_angle, 0) << "°"
      << (options.volume_preservation ? ", volume preservation" : "")
      << ", additional runs `deform("
      << options.long_iterations << ", 1e-4)` (CGAL: tolerance " << scientific(options.arap_tolerance)
      << ", on ROIs above " << options.large_roi << " vertices at most " << options.arap_large_iterations
      << "); definitions of the columns at the end\n";
  for(const std::string& note : options.notes)
    out << "- Note: " << note << "\n";
  write_sweep(out, cases);

  for(const Case_report& c : cases)
  {
    out << "\n## " << c.title << "\n\n";
    if(!c.skipped.empty())
    {
      out << "Skipped: " << c.skipped << "\n";
      continue;
    }
    out << "- Case `" << c.name << "`: " << c.source << "; " << c.vertices << " vertices, "
        << c.faces << " faces, D = " << format("%.4g", c.diagonal) << "\n"
        << "- Selection: ROI " << c.roi << " vertices (of which " << c.handles
        << " handle vertices), " << c.fixed << " vertices outside the ROI\n"
        << "- Handle transformation: " << c.transformation << "\n"
        << "- Folding candidates: " << c.flat_pairs << " of " << c.interior_edges
        << " interior edges; CGAL's additional runs capped at " << c.cgal_long_iterations
        << " iterations; case run in " << fixed(c.seconds, 1) << " s\n\n";
    out << "| algorithm | iterations | preprocess | deform | handle residual max / D | "
           "handle residual RMS / D | outside ROI / D | ARAP energy | edge change mean | "
           "edge change max | ROI border edge change max | folded pairs | volume change | non-finite |\n"
        << "|---|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|\n";
    for(const Run_result& r : c.results)
    {
      out << "| " << r.label << " | " << r.iterations << " | "
          << (r.preprocess_reused ? std::string("reused") : duration(r.preprocess_seconds)) << " | "
          << duration(r.deform_seconds) << " | ";
      if(!r.success)
      {
        out << "failed: " << r.message << " | | | | | | | | | |\n";
        continue;
      }
      const Quality& q = r.quality;
      out << scientific(q.max_residual) << " | " << scientific(q.rms_residual) << " | "
          << scientific(q.max_outside_displacement) << " | " << scientific(q.arap_energy) << " | "
          << percent(q.mean_edge_change) << " | " << percent(q.max_edge_change) << " | "
          << percent(q.max_border_edge_change) << " | "
          << (q.non_finite ? std::string("n/a") : std::to_string(q.folded_pairs)) << " | "
          << signed_percent(q.volume_change) << " | " << q.non_finite << " |\n";
    }
  }
  out << "\n";
  write_definitions(out, options);
}

// ----------------------------------------------------------------------------
// Driver

// The Loop subdivision levels the case `name` runs at.
const std::vector<unsigned int>& levels_of(const Options& options, const std::string& name)
{
  const auto specific = options.case_levels.find(name);
  return specific != options.case_levels.end() ? specific->second : options.levels;
}

std::string level_suffix(unsigned int level) { return level == 0 ? std::string() : "@" + std::to_string(level); }

std::string subdivided_title(const std::string& title, unsigned int level)
{
  return level == 0 ? title
                    : title + ", Loop-subdivided " + std::to_string(level) + (level == 1 ? " time" : " times");
}

bool selected(const Options& options, const std::string& name)
{
  return options.only.empty() ||
         std::find(options.only.begin(), options.only.end(), name) != options.only.end();
}

void run_case(const Deformation_case& c, const Options& options, unsigned int level,
              Case_report& report)
{
  const Clock::time_point start = Clock::now();
  const Case_geometry g = case_geometry(c);
  report.name = c.name;
  report.title = c.title;
  report.source = c.source;
  report.vertices = num_vertices(c.mesh);
  report.faces = num_faces(c.mesh);
  report.roi = c.roi.size();
  report.handles = c.handles.size();
  report.fixed = g.outside_indices.size();
  report.interior_edges = g.interior_edges;
  report.flat_pairs = g.flat_face_pairs.size();
  report.diagonal = g.diagonal;
  report.transformation = describe_transformation(c, g);
  report.cgal_long_iterations =
      c.roi.size() > options.large_roi ? options.arap_large_iterations : options.long_iterations;
  if(!g.energy_error.empty())
    std::cerr << "  warning: no ARAP energy: " << g.energy_error << "\n";
  const std::string base = options.mesh_output_directory + "/" + c.name;
  if(!options.mesh_output_directory.empty())
  {
    write_off(base + ".input.off", c.mesh, g.rest);
    write_selection(base + ".selection.vtk", c, g);
  }
  if(options.selection_only)
  {
    std::cerr << "  " << report.vertices << " vertices, ROI " << report.roi << ", handle "
              << report.handles << ", outside the ROI " << report.fixed << "; "
              << report.transformation << "\n";
    return;
  }

  std::vector<Run_result>& results = report.results;
  std::size_t reported = 0;
  auto progress = [&results, &c, &reported](Clock::time_point since) {
    for(; reported < results.size(); ++reported)
      std::cerr << "  " << c.name << ": " << results[reported].label << ": "
                << results[reported].iterations << std::endl;
    std::cerr << "    (" << duration(seconds_since(since)) << ")" << std::endl;
  };
  // On subdivided meshes (the resolution sweep) only the default calls of
  // CGAL ARAP (spokes and rims) and of the spectral algorithm run.
  const bool sweep_only = level > 0;
  Options spectral_options = options;
  if(sweep_only)
    spectral_options.long_iterations = 0;
  const std::string m = "m = " + std::to_string(options.frequencies);
  Clock::time_point step = Clock::now();
  run_cgal_algorithm<CGAL::SPOKES_AND_RIMS>(c, sweep_only ? 0 : report.cgal_long_iterations,
                                            options.arap_tolerance,
                                            "CGAL ARAP, spokes and rims", "cgal_spokes_and_rims",
                                            results);
  progress(step);
  if(!sweep_only)
  {
    step = Clock::now();
    run_cgal_algorithm<CGAL::ORIGINAL_ARAP>(c, report.cgal_long_iterations, options.arap_tolerance,
                                            "CGAL ARAP, original",
                                            "cgal_original", results);
    progress(step);
  }
  // The spectral algorithm with the basis of the options.
  auto run_spectral = [&](CGAL::Spectral_constraint_policy policy, const std::string& label,
                          const std::string& key) {
    if(options.partition_of_unity_basis)
      run_package_algorithm<CGAL::SPECTRAL_DUAL_LAPLACIAN, Partition_of_unity_traits>(
          c, spectral_options, policy, label, key, results);
    else
      run_package_algorithm<CGAL::SPECTRAL_DUAL_LAPLACIAN>(c, spectral_options, policy, label, key, results);
  };
  step = Clock::now();
  run_spectral(CGAL::EXACT_CONSTRAINTS, "spectral dual Laplacian, exact, " + m, "spectral_exact");
  progress(step);
  step = Clock::now();
  run_spectral(CGAL::SOFT_CONSTRAINTS, "spectral dual Laplacian, soft, " + m, "spectral_soft");
  progress(step);
  if(!sweep_only)
  {
    step = Clock::now();
    run_package_algorithm<CGAL::SPECTRAL_LINEAR>(c, options, CGAL::EXACT_CONSTRAINTS,
                                                 "spectral linear, exact, " + m, "spectral_linear",
                                                 results);
    progress(step);
    step = Clock::now();
    run_package_algorithm<CGAL::SPATIAL_DUAL_LAPLACIAN>(c, options, CGAL::EXACT_CONSTRAINTS,
                                                        "spatial dual Laplacian", "spatial", results);
    progress(step);
  }

  for(Run_result& r : results)
    if(r.success)
      r.quality = measure(g, r.after);

  if(!options.mesh_output_directory.empty())
    for(const Run_result& r : results)
      if(r.success)
      {
        write_off(base + "." + r.key + ".off", c.mesh, r.after);
        if(r.smooth_rest.rows() > 0)
        {
          write_off(base + "." + r.key + ".smooth_rest.off", c.mesh, r.smooth_rest);
          write_off(base + "." + r.key + ".smooth_deformed.off", c.mesh, r.smooth_deformed);
        }
      }
  for(Run_result& r : results)
  {
    r.after.resize(0, 3);
    r.smooth_rest.resize(0, 3);
    r.smooth_deformed.resize(0, 3);
  }
  report.seconds = seconds_since(start);
}

} // namespace

int main(int argc, char** argv)
{
  Options options;
  try
  {
    options = parse_options(argc, argv);
  }
  catch(const std::exception& e)
  {
    std::cerr << "error: " << e.what() << "\n";
    print_usage(argv[0]);
    return EXIT_FAILURE;
  }
  try
  {
    const Run_info run;
    if(!options.mesh_output_directory.empty())
      std::filesystem::create_directories(options.mesh_output_directory);
    std::vector<Case_report> reports;
    auto run_and_report = [&](const Deformation_case& c, unsigned int level, Case_report& report) {
      std::cerr << "case " << c.name << std::endl;
      run_case(c, options, level, report);
      report.level = level;
      reports.push_back(std::move(report));
      if(!options.selection_only)
        write_report(options.output, options, run, reports, false);
    };

    // The Botsch & Sorkine 2008 cases.
    for(const std::string name : {"bar", "cactus", "cylinder", "plane"})
    {
      if(!selected(options, name))
        continue;
      for(unsigned int level : levels_of(options, name))
      {
        Case_report report;
        report.name = name + level_suffix(level);
        report.title = subdivided_title(name + " (Botsch & Sorkine 2008)", level);
        Deformation_case c;
        std::string why_not;
        if(options.botsch08_directory.empty())
          report.skipped = "no directory of the Botsch & Sorkine 2008 cases given (--botsch08)";
        else if(!read_botsch08_case(options.botsch08_directory, name, c, why_not, level))
          report.skipped = why_not;
        else
        {
          c.name = report.name;
          c.title = report.title;
          run_and_report(c, level, report);
          continue;
        }
        reports.push_back(std::move(report));
        if(!options.selection_only)
          write_report(options.output, options, run, reports, false);
        if(options.botsch08_directory.empty())
          break;
      }
    }

    // The cases of the case directory, by file name.
    std::vector<std::string> case_files;
    if(std::filesystem::is_directory(options.case_directory))
      for(const auto& entry : std::filesystem::directory_iterator(options.case_directory))
        if(entry.path().extension() == ".case")
          case_files.push_back(entry.path().string());
    std::sort(case_files.begin(), case_files.end());
    if(case_files.empty())
      std::cerr << "warning: no .case file in " << options.case_directory << "\n";
    for(const std::string& file : case_files)
    {
      const std::string stem = std::filesystem::path(file).stem().string();
      for(unsigned int level : levels_of(options, stem))
      {
        Case_report report;
        Deformation_case c;
        const std::string suffix = level_suffix(level);
        try
        {
          c = read_case_file(file, options.mesh_directory, level);
        }
        catch(const std::exception& e)
        {
          report.name = report.title = stem + suffix;
          if(!selected(options, stem))
            continue;
          report.skipped = e.what();
          std::cerr << "skipped: " << e.what() << "\n";
          reports.push_back(std::move(report));
          continue;
        }
        if(!selected(options, c.name))
          continue;
        c.name += suffix;
        c.title = subdivided_title(c.title, level);
        run_and_report(c, level, report);
      }
    }
    if(!options.selection_only)
    {
      write_report(options.output, options, run, reports, true);
      std::cerr << "wrote " << options.output << "\n";
    }
  }
  catch(const std::exception& e)
  {
    std::cerr << "error: " << e.what() << "\n";
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}

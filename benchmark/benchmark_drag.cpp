// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A handle dragged along a path: successive target changes on one object,
// each `deform(10, 0)` continuing from the last result, as in an interactive
// editor. Per drag, the wall time of the package with the full iteration and
// with rotation patches (its parts: iteration, detail transfer, output), and
// of CGAL ARAP `deform(10)` in the same run, on a case of quality/cases
// Loop-subdivided to several sizes.
//
// CGAL ARAP runs as the reference harness (../shared/bench) runs it, the
// fastest a CGAL user can have: ORIGINAL_ARAP with CHOLMOD on the symmetric
// positive definite block of its system (cgal_arap_solver_traits.h). With
// SPOKES_AND_RIMS and its default SparseLU, the configuration of this
// benchmark before 0.3, an iteration costs 1.2-1.5 times more and a drag
// about 1.85 times more at 104,000 vertices.
//
// Usage: benchmark_drag --output FILE [--data FILE.tsv] [options], see print_usage().

#include "cgal_arap_solver_traits.h"
#include "deformation_cases.h"

#include <CGAL/Spectral_surface_mesh_deformation.h>
#include <CGAL/Spectral_deformation/Partition_of_unity_eigensolver_traits.h>
#include <CGAL/Surface_mesh_deformation.h>

#include <algorithm>
#include <chrono>
#include <iostream>
#include <map>

namespace {

using namespace ssmd_benchmark;

const char* const cgal_solver_name = "ORIGINAL_ARAP, CHOLMOD on the SPD block of its system";
typedef ssmd_benchmark::Cgal_arap<Mesh> Cgal_arap;
typedef CGAL::Spectral_surface_mesh_deformation<Mesh, CGAL::Default, CGAL::Default, CGAL::SPECTRAL_DUAL_LAPLACIAN,
                                                CGAL::Block_lanczos_eigensolver_traits<>>
    Spectral;
typedef CGAL::Spectral_surface_mesh_deformation<Mesh, CGAL::Default, CGAL::Default, CGAL::SPECTRAL_DUAL_LAPLACIAN,
                                                CGAL::Partition_of_unity_eigensolver_traits<>>
    Spectral_partition_of_unity;

struct Options
{
  std::string output;
  std::string data; // tab-separated drags, for plot_drag.py; empty: none
  std::string case_file = SSMD_BENCHMARK_DEFAULT_CASE_DIR "/armadillo_arm.case";
  std::string mesh_directory = SSMD_BENCHMARK_DEFAULT_MESH_DIR;
  std::vector<unsigned int> levels{0, 1, 2};
  std::size_t frequencies = 100;
  std::vector<std::size_t> patches{1000}; // besides the full iteration
  std::vector<std::size_t> approximate_patches; // variants with the partition-of-unity basis (0: full)
  bool skip_exact = false;                     // no variant with the exact basis
  bool skip_full = false;                      // no variant with the full iteration
  std::size_t basis_samples = 0;               // of the partition-of-unity basis (0: its default)
  long long single_precision_threshold = -1;   // region vertices from which the basis is float (-1: the class's)
  int constraint_changes = 0;                  // new constraint sets after the path
  std::size_t changed_vertices = 1;            // handle vertices released and taken by each
  int drags = 30;
  int cgal_drags = 30;
  int cgal_drags_large = 5;          // above large_mesh vertices
  std::size_t large_mesh = 300000;
  bool skip_cgal = false;
  bool paper_energy = false; // also every exact-basis variant with the dual Laplacian energy in one stage
};

void print_usage(const char* program)
{
  std::cerr << "Usage: " << program << " --output FILE [options]\n"
            << "  --output FILE          the markdown report\n"
            << "  --data FILE            every drag, tab-separated (for plot_drag.py)\n"
            << "  --case FILE            the case (default quality/cases/armadillo_arm.case)\n"
            << "  --meshes DIR           meshes named by the case file\n"
            << "  --levels l1,l2,...     Loop subdivision levels (default 0,1,2)\n"
            << "  --frequencies m        basis size (default 100)\n"
            << "  --patches k1,k2,...    rotation patches besides the full iteration (default 1000)\n"
            << "  --approximate-basis k1,k2,...  also run these numbers of patches (0: the full\n"
            << "                         iteration) with Partition_of_unity_eigensolver_traits\n"
            << "  --drags N              target changes along the path (default 30)\n"
            << "  --cgal-drags N         of CGAL ARAP (default 30)\n"
            << "  --cgal-drags-large N   of CGAL ARAP above --large-mesh vertices (default 5)\n"
            << "  --large-mesh N         (default 300000)\n"
            << "  --skip-exact           only the variants of --approximate-basis\n"
            << "  --skip-full            no variant with the full iteration (patches only)\n"
            << "  --basis-samples k      samples of the partition-of-unity basis (default: its own)\n"
            << "  --single-precision-threshold N  region vertices from which the basis is kept in\n"
            << "                         float (default: the class's, 200000)\n"
            << "  --constraint-changes N after the path, N new constraint sets (handle vertices\n"
            << "                         released, then taken again), each timed (default 0)\n"
            << "  --changed-vertices K   the last K handle vertices change (default 1)\n"
            << "  --skip-cgal            no CGAL ARAP\n"
            << "  --dual-laplacian-energy  also the exact-basis variants with\n"
            << "                         DUAL_LAPLACIAN_ENERGY in one stage (the paper's iteration;\n"
            << "                         the other variants use the class's defaults)\n";
}

template <class T>
std::vector<T> parse_list(const std::string& text)
{
  std::vector<T> values;
  std::stringstream in(text);
  std::string item;
  while(std::getline(in, item, ','))
    values.push_back(static_cast<T>(std::stoul(item)));
  return values;
}

Options parse_options(int argc, char** argv)
{
  Options o;
  for(int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if(i + 1 >= argc)
        throw std::invalid_argument(a + " expects a value");
      return argv[++i];
    };
    if(a == "--help" || a == "-h")
    {
      print_usage(argv[0]);
      std::exit(0);
    }
    else if(a == "--output") o.output = value();
    else if(a == "--data") o.data = value();
    else if(a == "--case") o.case_file = value();
    else if(a == "--meshes") o.mesh_directory = value();
    else if(a == "--levels") o.levels = parse_list<unsigned int>(value());
    else if(a == "--frequencies") o.frequencies = std::stoul(value());
    else if(a == "--patches") o.patches = parse_list<std::size_t>(value());
    else if(a == "--approximate-basis") o.approximate_patches = parse_list<std::size_t>(value());
    else if(a == "--skip-exact") o.skip_exact = true;
    else if(a == "--skip-full") o.skip_full = true;
    else if(a == "--basis-samples") o.basis_samples = parse_list<std::size_t>(value()).at(0);
    else if(a == "--single-precision-threshold") o.single_precision_threshold = std::stoll(value());
    else if(a == "--constraint-changes") o.constraint_changes = std::stoi(value());
    else if(a == "--changed-vertices") o.changed_vertices = std::stoul(value());
    else if(a == "--drags") o.drags = std::stoi(value());
    else if(a == "--cgal-drags") o.cgal_drags = std::stoi(value());
    else if(a == "--cgal-drags-large") o.cgal_drags_large = std::stoi(value());
    else if(a == "--large-mesh") o.large_mesh = std::stoul(value());
    else if(a == "--skip-cgal") o.skip_cgal = true;
    else if(a == "--dual-laplacian-energy") o.paper_energy = true;
    else
      throw std::invalid_argument("unknown option " + a);
  }
  if(o.output.empty())
    throw std::invalid_argument("--output is required");
  return o;
}

/// The handle's targets at `t` of the path from rest (0) to the case's
/// transformation (1): the rotation angle and the translation scaled by t.
std::vector<Point> targets_at(const Deformation_case& c, double t)
{
  const Eigen::Matrix3d R = c.transformation.topLeftCorner<3, 3>();
  const Eigen::Vector3d b = c.transformation.topRightCorner<3, 1>();
  const Eigen::AngleAxisd full(R);
  const Eigen::Matrix3d Rt = Eigen::AngleAxisd(t * full.angle(), full.axis()).toRotationMatrix();
  std::vector<Point> targets;
  for(vertex_descriptor v : c.handles)
  {
    const Eigen::Vector3d p = Rt * vector_of(c.mesh.point(v)) + t * b;
    targets.emplace_back(p[0], p[1], p[2]);
  }
  return targets;
}

struct Drag
{
  double total = 0, iteration = 0, transfer = 0, output = 0;
};

struct Variant_result
{
  std::string name;
  std::size_t patches = 0; // 0: full
  double first_result = 0; // constructor, preprocess and the first drag
  double peak_gib = 0;      // peak resident size of the process during the variant
  double start_gib = 0;     // resident size when the variant starts (the case's own data)
  double region_seconds = -1, basis_seconds = -1, factorization_seconds = -1; // of the first result (package)
  std::vector<double> constraint_changes; // factorization of each new constraint set after the path (package)
  std::vector<double> constraint_change_deforms; // the whole deform() of each
  std::vector<Drag> drags;
  Quality last;
};

double quantile(std::vector<double> values, double q)
{
  if(values.empty())
    return not_a_number;
  std::sort(values.begin(), values.end());
  const double position = q * double(values.size() - 1);
  const std::size_t low = static_cast<std::size_t>(std::floor(position));
  const std::size_t high = (std::min)(low + 1, values.size() - 1);
  return values[low] + (position - double(low)) * (values[high] - values[low]);
}

template <class Member>
std::vector<double> column(const std::vector<Drag>& drags, Member member)
{
  std::vector<double> values;
  for(const Drag& d : drags)
    values.push_back(d.*member);
  return values;
}

template <class Deformation = Spectral>
Variant_result run_package(const Deformation_case& c, const Case_geometry& g, const Options& o,
                           std::size_t patches, bool paper_energy = false)
{
  constexpr bool approximate = std::is_same_v<Deformation, Spectral_partition_of_unity>;
  Variant_result result;
  result.patches = patches;
  result.name = std::string(approximate ? "spectral, partition-of-unity basis, " : "spectral, ") +
                (approximate && o.basis_samples > 0 ? std::to_string(o.basis_samples) + " samples, " : "") +
                (patches == 0 ? "full iteration" : std::to_string(patches) + " patches") +
                (paper_energy ? ", dual Laplacian energy, one stage" : "") +
                (o.single_precision_threshold >= 0
                     ? ", float basis from " + std::to_string(o.single_precision_threshold) + " vertices"
                     : "");
  reset_peak_resident_size();
  result.start_gib = double(proc_field_kib("/proc/self/status", "VmRSS")) / (1024.0 * 1024.0);
  Mesh mesh = c.mesh;
  const auto start = Clock::now();
  Deformation d(mesh);
  if constexpr(!approximate)
  {
    typename Spectral::Eigensolver_traits eigensolver;
    // This program owns its process (OpenBLAS threads, SuiteSparse's allocator).
    eigensolver.set_process_wide_tuning(true);
    d.set_eigensolver_traits(eigensolver);
  }
  else if(o.basis_samples > 0)
  {
    typename Deformation::Eigensolver_traits eigensolver;
    eigensolver.set_number_of_samples(o.basis_samples);
    d.set_eigensolver_traits(eigensolver);
  }
  d.set_number_of_frequencies(o.frequencies);
  if(o.single_precision_threshold >= 0)
    d.set_single_precision_basis_threshold(static_cast<std::size_t>(o.single_precision_threshold));
  d.set_rotation_patches(patches);
  if(paper_energy)
  {
    d.set_smooth_energy(CGAL::DUAL_LAPLACIAN_ENERGY);
    d.set_stage_angle(0);
  }
  d.insert_roi_vertices(c.roi.begin(), c.roi.end());
  d.insert_control_vertices(c.handles.begin(), c.handles.end());
  for(int i = 1; i <= o.drags; ++i)
  {
    const std::vector<Point> targets = targets_at(c, double(i) / o.drags);
    for(std::size_t k = 0; k < c.handles.size(); ++k)
      d.set_target_position(c.handles[k], targets[k]);
    const auto drag_start = Clock::now();
    d.deform(10, 0.0);
    const double seconds = seconds_since(drag_start);
    const auto& report = d.deform_report();
    if(!report.success)
      throw std::runtime_error(result.name + ": " + report.message);
    if(i == 1)
    {
      result.first_result = seconds_since(start);
      const auto& preprocess = d.preprocess_report();
      result.region_seconds = preprocess.region_seconds;
      result.basis_seconds = preprocess.basis_seconds;
      result.factorization_seconds = preprocess.factorization_seconds;
    }
    else // the first drag includes the basis and the factorizations
    {
      Drag drag;
      drag.total = seconds;
      drag.iteration = report.solve_seconds;
      drag.transfer = report.detail_transfer_seconds;
      drag.output = seconds - report.solve_seconds - report.detail_transfer_seconds;
      result.drags.push_back(drag);
    }
  }
  // New constraint sets: the last handle vertices released, then taken
  // again (their targets the end of the path); each deform() prepares the
  // new set.
  const std::vector<Point> final_targets = targets_at(c, 1.0);
  const std::size_t changed = std::min(o.changed_vertices, c.handles.size() - 1);
  for(int j = 0; j < o.constraint_changes; ++j)
  {
    for(std::size_t h = c.handles.size() - changed; h < c.handles.size(); ++h)
      if(j % 2 == 0)
        d.erase_control_vertex(c.handles[h]);
      else
      {
        d.insert_control_vertex(c.handles[h]);
        d.set_target_position(c.handles[h], final_targets[h]);
      }
    const auto start = std::chrono::steady_clock::now();
    d.deform(10, 0.0);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if(!d.deform_report().success)
      throw std::runtime_error(result.name + ": " + d.deform_report().message);
    result.constraint_changes.push_back(d.preprocess_report().factorization_seconds);
    result.constraint_change_deforms.push_back(seconds);
  }
  // Read before the quality measures, whose own arrays (a cotangent matrix
  // and per-edge terms of the whole mesh) are not the deformation's.
  result.peak_gib = double(proc_field_kib("/proc/self/status", "VmHWM")) / (1024.0 * 1024.0);
  result.last = measure(g, positions_of(mesh));
  return result;
}

Variant_result run_cgal(const Deformation_case& c, const Case_geometry& g, int drags, int path_length)
{
  Variant_result result;
  result.name = std::string("CGAL ARAP, ") + cgal_solver_name;
  reset_peak_resident_size();
  result.start_gib = double(proc_field_kib("/proc/self/status", "VmRSS")) / (1024.0 * 1024.0);
  Mesh mesh = c.mesh;
  const auto start = Clock::now();
  Cgal_arap d(mesh);
  d.insert_roi_vertices(c.roi.begin(), c.roi.end());
  d.insert_control_vertices(c.handles.begin(), c.handles.end());
  // The same path as the package's, its first `drags` + 1 steps.
  for(int i = 1; i <= (std::min)(drags + 1, path_length); ++i)
  {
    const std::vector<Point> targets = targets_at(c, double(i) / path_length);
    for(std::size_t k = 0; k < c.handles.size(); ++k)
      d.set_target_position(c.handles[k], targets[k]);
    const auto drag_start = Clock::now();
    d.deform(10, 0.0);
    const double seconds = seconds_since(drag_start);
    if(i == 1)
      result.first_result = seconds_since(start);
    else
    {
      Drag drag;
      drag.total = drag.iteration = seconds;
      result.drags.push_back(drag);
    }
  }
  // Read before the quality measures, whose own arrays (a cotangent matrix
  // and per-edge terms of the whole mesh) are not the deformation's.
  result.peak_gib = double(proc_field_kib("/proc/self/status", "VmHWM")) / (1024.0 * 1024.0);
  result.last = measure(g, positions_of(mesh));
  return result;
}

std::string ms(double seconds)
{
  if(!(seconds == seconds))
    return "–";
  return seconds < 0.01 ? fixed(1000 * seconds, 2) + " ms" : fixed(1000 * seconds, 1) + " ms";
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
  const std::time_t started = std::time(nullptr);
  std::ostringstream tables;
  std::ofstream data;
  if(!o.data.empty())
  {
    data.open(o.data);
    data << "vertices\tvariant\tpatches\tdrag\ttotal\titeration\tdetail_transfer\toutput\n";
  }
  for(unsigned int level : o.levels)
  {
    Deformation_case c = read_case_file(o.case_file, o.mesh_directory, level);
    finish_case(c);
    const Case_geometry g = case_geometry(c);
    const std::size_t n = num_vertices(c.mesh);
    std::cerr << c.name << " @" << level << ": " << n << " vertices\n";
    std::vector<Variant_result> results;
    if(!o.skip_exact)
    {
      if(!o.skip_full)
        results.push_back(run_package(c, g, o, 0));
      for(std::size_t k : o.patches)
        results.push_back(run_package(c, g, o, k));
      if(o.paper_energy)
      {
        if(!o.skip_full)
          results.push_back(run_package(c, g, o, 0, true));
        for(std::size_t k : o.patches)
          results.push_back(run_package(c, g, o, k, true));
      }
    }
    for(std::size_t k : o.approximate_patches)
      results.push_back(run_package<Spectral_partition_of_unity>(c, g, o, k));
    if(!o.skip_cgal)
      results.push_back(run_cgal(c, g, n > o.large_mesh ? o.cgal_drags_large : o.cgal_drags, o.drags));
    const double cgal_p50 = o.skip_cgal ? not_a_number : quantile(column(results.back().drags, &Drag::total), 0.5);

    tables << "\n### " << c.name << " @" << level << ": " << n << " vertices, ROI " << c.roi.size()
           << ", " << c.handles.size() << " handle vertices\n\n"
           << "| algorithm | drags | p50 per drag | p95 | drags/s (p50) | CGAL p50 / p50 | iteration p50 | "
              "detail transfer p50 | output p50 | first result | ARAP energy, last drag | folded pairs | "
              "edge change max | peak memory |\n"
           << "|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|\n";
    for(const Variant_result& r : results)
    {
      const double p50 = quantile(column(r.drags, &Drag::total), 0.5);
      const bool cgal = r.name.rfind("CGAL", 0) == 0;
      tables << "| " << r.name << " | " << r.drags.size() << " | " << ms(p50) << " | "
             << ms(quantile(column(r.drags, &Drag::total), 0.95)) << " | " << fixed(1.0 / p50, 1) << " | "
             << (cgal ? "1" : fixed(cgal_p50 / p50, 1)) << " | "
             << ms(quantile(column(r.drags, &Drag::iteration), 0.5)) << " | "
             << (cgal ? "–" : ms(quantile(column(r.drags, &Drag::transfer), 0.5))) << " | "
             << (cgal ? "–" : ms(quantile(column(r.drags, &Drag::output), 0.5))) << " | "
             << duration(r.first_result) << " | " << scientific(r.last.arap_energy) << " | "
             << r.last.folded_pairs << " | " << percent(r.last.max_edge_change) << " | "
             << fixed(r.peak_gib, 2) << " GiB (" << fixed(r.start_gib, 2) << " before) |\n";
      if(data.is_open())
        for(std::size_t i = 0; i < r.drags.size(); ++i)
          data << n << "\t" << r.name << "\t" << (cgal ? -1 : static_cast<long>(r.patches)) << "\t" << i + 2
               << "\t" << r.drags[i].total << "\t" << r.drags[i].iteration << "\t" << r.drags[i].transfer
               << "\t" << r.drags[i].output << "\n";
    }
    tables << "\nThe first result of the package (`preprocess_report()`):\n\n"
           << "| algorithm | first result | region | of which basis | factorization | the rest |\n"
           << "|---|--:|--:|--:|--:|--:|\n";
    for(const Variant_result& r : results)
      if(r.region_seconds >= 0)
        tables << "| " << r.name << " | " << duration(r.first_result) << " | " << duration(r.region_seconds) << " | "
               << duration(r.basis_seconds) << " | " << duration(r.factorization_seconds) << " | "
               << duration(r.first_result - r.region_seconds - r.factorization_seconds) << " |\n";
    if(o.constraint_changes > 0)
    {
      tables << "\nA new constraint set after the path, " << o.changed_vertices
             << " handle vertices released or taken again: `preprocess_report().factorization_seconds`"
                " (the whole `deform(10, 0)` in brackets):\n\n"
             << "| algorithm | first set | each new set |\n|---|--:|--:|\n";
      for(const Variant_result& r : results)
        if(!r.constraint_changes.empty())
        {
          tables << "| " << r.name << " | " << duration(r.factorization_seconds) << " |";
          for(std::size_t k = 0; k < r.constraint_changes.size(); ++k)
            tables << " " << duration(r.constraint_changes[k]) << " (" << duration(r.constraint_change_deforms[k])
                   << ")";
          tables << " |\n";
        }
    }
    std::cerr << tables.str();
  }

  std::ofstream out(o.output);
  out << "# Drags: a handle dragged along a path, the package against CGAL ARAP\n\n"
      << "- Date: " << utc_time(started) << ", whole run " << duration(double(std::time(nullptr) - started))
      << "\n- Machine: " << first_line_value("/proc/cpuinfo", "model name") << ", "
      << sysconf(_SC_NPROCESSORS_ONLN) << " logical CPUs\n"
      << "- Compiler: " << compiler() << "; build `" << SSMD_BENCHMARK_BUILD_TYPE << "`, flags `"
      << SSMD_BENCHMARK_CXX_FLAGS_BUILD_TYPE << " " << SSMD_BENCHMARK_CXX_FLAGS << "`\n"
      << "- Package: m = " << o.frequencies << ", `deform(10, 0)` per drag, exact constraints, the class's default energy (dual Laplacian + ARAP) and stage angle (30°) unless the variant says otherwise, sparse solver "
      << sparse_solver() << "; CGAL ARAP: `deform(10, 0)` per drag, " << cgal_solver_name
      << " (CGAL's system is not symmetric: CHOLMOD's LLᵀ does not apply)\n"
      << "- Path: " << o.drags << " target changes from rest to the case's transformation (rotation angle "
      << "and translation scaled by i/" << o.drags << "); each continues from the last result. The first "
      << "drag, which includes the basis and the factorizations, is reported as *first result* (constructor "
      << "to the first deformed mesh) and left out of the per-drag figures. CGAL ARAP runs the first "
      << o.cgal_drags << " steps of the path (" << o.cgal_drags_large << " above " << o.large_mesh
      << " vertices).\n"
      << "- *iteration*: `deform_report().solve_seconds`; *detail transfer*: "
      << "`deform_report().detail_transfer_seconds`; *output*: the rest of the drag (targets, writing the "
      << "mesh). For CGAL, the whole `deform()`.\n"
      << "- *peak memory*: the process's peak resident size (VmHWM, reset before each variant) from the "
      << "constructor to the last drag, including the case's own copy of the mesh; in brackets, the "
      << "resident size when the variant starts (the program's own copies of the case), part of the peak.\n"
      << tables.str();
  std::cerr << "wrote " << o.output << "\n";
  return 0;
}

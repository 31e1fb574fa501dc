// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This program is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.
//
// Times the computation of the manifold harmonics basis, phase by phase, and
// writes a markdown report.
//
// For every mesh and every number of frequencies m, one case measures:
//   - the assembly of Q and M: extraction of the triangle arrays (with
//     validation), cotangent stiffness, lumped mass;
//   - the factorization of Q - sigma M alone, with
//     CGAL::Default_sparse_spd_solver_traits and the shift of the default
//     eigensolver traits;
//   - the basis: the CGAL::Manifold_harmonics_basis constructor with the
//     default traits, end to end (it repeats the two phases above, then runs
//     the eigensolver iteration);
//   - the peak resident memory of the basis computation;
//   - the accuracy of the result: max |HᵀMH - I| and the eigen-residuals.
//
// Every case runs in a child process of its own (fork), started when the
// process holds nothing but the mesh: VmHWM of /proc/self/status only grows
// within a process, and freed memory is not always returned to the system, so
// measuring several cases in one process would mix their peaks. In the child
// the peak is also reset (/proc/self/clear_refs, Linux >= 4.0) before the
// basis is computed; the report gives the peak and its increase over the
// resident size at that moment (the mesh, the libraries).
//
// Usage: benchmark_basis [mesh_directory] [options], see print_usage().

#include <CGAL/Manifold_harmonics_basis.h>
#include <CGAL/Spectral_deformation/Sparse_spd_solver_traits.h>
#include <CGAL/Spectral_deformation/cotangent_operators.h>
#include <CGAL/Spectral_deformation/cotangent_operators.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/subdivision_method_3.h>
#include <CGAL/version.h>

#include <Eigen/Core>
#include <Spectra/Util/Version.h>

#include <sys/mman.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>
#ifdef __GLIBC__
#include <malloc.h>
#endif

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <iostream>
#include <limits>
#include <memory>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#ifndef SSMD_BENCHMARK_BUILD_TYPE
#define SSMD_BENCHMARK_BUILD_TYPE "unknown"
#endif
#ifndef SSMD_BENCHMARK_CXX_FLAGS_BUILD_TYPE
#define SSMD_BENCHMARK_CXX_FLAGS_BUILD_TYPE "unknown"
#endif
#ifndef SSMD_BENCHMARK_CXX_FLAGS
#define SSMD_BENCHMARK_CXX_FLAGS ""
#endif
#include "benchmark_support.h"

#ifndef SSMD_BENCHMARK_COMPILE_OPTIONS
#define SSMD_BENCHMARK_COMPILE_OPTIONS ""
#endif
#ifndef SSMD_BENCHMARK_DEFAULT_MESH_DIR
#define SSMD_BENCHMARK_DEFAULT_MESH_DIR "data/meshes"
#endif

namespace {

using namespace ssmd_benchmark;

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;
typedef CGAL::Manifold_harmonics_basis<Mesh> Basis;

// The default eigensolver, allowed to tune the process (OpenBLAS threads,
// SuiteSparse's allocator, huge pages): this program owns its process, and
// measures every phase at its speed.
Basis::Eigensolver_traits tuned_eigensolver()
{
  Basis::Eigensolver_traits traits;
  traits.set_process_wide_tuning(true);
  return traits;
}

// ----------------------------------------------------------------------------
// Command line

struct Mesh_spec
{
  std::string name;  // as given to --meshes
  std::string label; // as shown in the report
  std::string file;  // in the mesh directory
  unsigned int subdivision_levels;
};

const std::vector<Mesh_spec>& known_meshes()
{
  static const std::vector<Mesh_spec> meshes = {
      {"armadillo", "armadillo", "armadillo.off", 0},
      {"refined_elephant", "refined_elephant", "refined_elephant.off", 0},
      {"armadillo_loop1", "armadillo, Loop ×1", "armadillo.off", 1},
      {"armadillo_loop2", "armadillo, Loop ×2", "armadillo.off", 2}};
  return meshes;
}

struct Options
{
  std::string mesh_directory = SSMD_BENCHMARK_DEFAULT_MESH_DIR;
  std::string output; // empty: standard output only
  std::vector<std::string> meshes = {"armadillo", "refined_elephant", "armadillo_loop1",
                                     "armadillo_loop2"};
  std::vector<int> frequencies = {50, 100, 200};
  int repetitions = 3;             // of the basis constructor
  int cheap_repetitions = 10;      // of assembly and factorization
  int large_mesh_repetitions = 1;  // of the basis constructor on large meshes
  long large_mesh_vertices = 200000;
  std::vector<std::string> notes;
};

void print_usage(const char* program)
{
  std::cerr
      << "Usage: " << program << " [mesh_directory] [options]\n"
      << "  mesh_directory                 holds armadillo.off and refined_elephant.off\n"
      << "                                 (default " SSMD_BENCHMARK_DEFAULT_MESH_DIR ")\n"
      << "  --output FILE                  also write the markdown report to FILE\n"
      << "  --meshes a,b,...               among armadillo, refined_elephant,\n"
      << "                                 armadillo_loop1, armadillo_loop2 (default: all)\n"
      << "  --frequencies m1,m2,...        numbers of basis functions (default 50,100,200)\n"
      << "  --repetitions N                runs of the basis constructor (default 3)\n"
      << "  --cheap-repetitions N          runs of assembly and factorization (default 10)\n"
      << "  --large-mesh-repetitions N     runs of the basis constructor on meshes with more\n"
      << "                                 than --large-mesh-vertices vertices (default 1)\n"
      << "  --large-mesh-vertices N        (default 200000)\n"
      << "  --note TEXT                    a line added to the notes of the report\n";
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

int to_positive_int(const std::string& text, const std::string& option)
{
  char* end = nullptr;
  const long value = std::strtol(text.c_str(), &end, 10);
  if(end == text.c_str() || *end != '\0' || value < 1 || value > std::numeric_limits<int>::max())
    throw std::invalid_argument(option + " expects a positive integer, got '" + text + "'");
  return static_cast<int>(value);
}

Options parse_options(int argc, char** argv)
{
  Options options;
  bool directory_given = false;
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
    else if(argument == "--meshes")
      options.meshes = split(value(), ',');
    else if(argument == "--frequencies")
    {
      options.frequencies.clear();
      for(const std::string& m : split(value(), ','))
        options.frequencies.push_back(to_positive_int(m, argument));
    }
    else if(argument == "--repetitions")
      options.repetitions = to_positive_int(value(), argument);
    else if(argument == "--cheap-repetitions")
      options.cheap_repetitions = to_positive_int(value(), argument);
    else if(argument == "--large-mesh-repetitions")
      options.large_mesh_repetitions = to_positive_int(value(), argument);
    else if(argument == "--large-mesh-vertices")
      options.large_mesh_vertices = to_positive_int(value(), argument);
    else if(argument == "--note")
      options.notes.push_back(value());
    else if(!argument.empty() && argument[0] != '-' && !directory_given)
    {
      options.mesh_directory = argument;
      directory_given = true;
    }
    else
      throw std::invalid_argument("unknown argument '" + argument + "'");
  }
  for(const std::string& name : options.meshes)
    if(std::none_of(known_meshes().begin(), known_meshes().end(),
                    [&](const Mesh_spec& spec) { return spec.name == name; }))
      throw std::invalid_argument("unknown mesh '" + name + "'");
  if(options.meshes.empty() || options.frequencies.empty())
    throw std::invalid_argument("no mesh or no number of frequencies to run");
  return options;
}

// ----------------------------------------------------------------------------
// Measurements

typedef std::chrono::steady_clock Clock;

template <class Function>
double seconds_of(Function&& function)
{
  const Clock::time_point start = Clock::now();
  function();
  return std::chrono::duration<double>(Clock::now() - start).count();
}

/// Repeated measurements of one phase, in seconds.
struct Sample
{
  std::vector<double> values;

  bool empty() const { return values.empty(); }
  double min() const { return *std::min_element(values.begin(), values.end()); }
  double max() const { return *std::max_element(values.begin(), values.end()); }
  double median() const
  {
    std::vector<double> sorted = values;
    std::sort(sorted.begin(), sorted.end());
    const std::size_t half = sorted.size() / 2;
    return (sorted.size() % 2 == 1) ? sorted[half] : 0.5 * (sorted[half - 1] + sorted[half]);
  }
};

/// The time, in microseconds per page, of the first write to freshly mapped
/// memory (page fault and zeroing). On bare metal it is a fraction of a
/// microsecond; on some virtual machines it is tens of times more, which then
/// shows in every phase that allocates large arrays.
double first_touch_microseconds_per_page()
{
  const std::size_t page = static_cast<std::size_t>(::sysconf(_SC_PAGESIZE));
  const std::size_t size = std::size_t(64) << 20;
  void* block = ::mmap(nullptr, size, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if(block == MAP_FAILED)
    return std::numeric_limits<double>::quiet_NaN();
  volatile char* bytes = static_cast<volatile char*>(block);
  const double seconds = seconds_of([&] {
    for(std::size_t offset = 0; offset < size; offset += page)
      bytes[offset] = 1;
  });
  ::munmap(block, size);
  return 1e6 * seconds / static_cast<double>(size / page);
}

/// The load average over the last minute.
double load_average()
{
  std::ifstream in("/proc/loadavg");
  double load = std::numeric_limits<double>::quiet_NaN();
  in >> load;
  return load;
}

struct Case_result
{
  Sample assembly;      // extraction, Q, M
  Sample factorization; // Q - sigma M
  Sample basis;         // the Manifold_harmonics_basis constructor, end to end
  long resident_before_kib = -1;
  long peak_kib = -1;
  bool peak_was_reset = false;
  double orthonormality_error = std::numeric_limits<double>::quiet_NaN();
  double relative_residual = std::numeric_limits<double>::quiet_NaN();
  double load = std::numeric_limits<double>::quiet_NaN();
  std::string error; // set when the case failed
};

void report_progress(const std::string& what, const std::string& phase, int run, double seconds)
{
  std::cerr << "  " << what << ": " << phase << ' ' << run << ": " << seconds << " s"
            << std::endl;
}

/// Runs one case in the current process; meant for a fresh child process.
Case_result run_case(const Mesh& mesh, int m, int repetitions, int cheap_repetitions,
                     const std::string& what)
{
  Case_result result;

  // The basis first, while the process holds only the mesh, so that the
  // increase of the peak is the memory the constructor needs. At most one
  // basis is alive at a time.
  result.peak_was_reset = reset_peak_resident_size();
  result.resident_before_kib = proc_field_kib("/proc/self/status", "VmRSS");
  std::unique_ptr<Basis> basis;
  for(int run = 1; run <= repetitions; ++run)
  {
    basis.reset();
    result.basis.values.push_back(
        seconds_of([&] {
          basis = std::make_unique<Basis>(mesh, static_cast<std::size_t>(m),
                                          CGAL::parameters::default_values(), tuned_eigensolver());
        }));
    report_progress(what, "basis", run, result.basis.values.back());
  }
  result.peak_kib = proc_field_kib("/proc/self/status", "VmHWM");

  // Assembly of Q and M with the package's public operators (each checks the
  // mesh). The results of the previous run are released outside of the
  // timed region.
  Eigen::SparseMatrix<double> stiffness;
  Eigen::VectorXd mass;
  for(int run = 1; run <= cheap_repetitions; ++run)
  {
    Eigen::SparseMatrix<double> Q, M;
    result.assembly.values.push_back(seconds_of([&] {
      Q = CGAL::cotangent_stiffness_matrix(mesh);
      M = CGAL::lumped_mass_matrix(mesh);
    }));
    stiffness.swap(Q);
    mass = M.diagonal();
  }
  report_progress(what, "assembly median of", cheap_repetitions, result.assembly.median());

  // Factorization of Q - sigma M alone, with a shift of the order of the one
  // the eigensolver traits use: a hundredth of the first non-zero eigenvalue
  // of a sphere of the same area, below zero (the cost hardly depends on its
  // value).
  const double sigma = -1e-2 * 4.0 * 3.14159265358979323846 / mass.sum();
  Eigen::SparseMatrix<double> shifted = stiffness;
  for(Eigen::Index i = 0; i < mass.size(); ++i)
    shifted.coeffRef(i, i) -= sigma * mass[i];
  for(int run = 1; run <= cheap_repetitions; ++run)
  {
    CGAL::Default_sparse_spd_solver_traits solver;
    bool factored = false;
    result.factorization.values.push_back(
        seconds_of([&] { factored = solver.factor(shifted); }));
    if(!factored)
      throw std::runtime_error("the factorization of Q - sigma M failed");
  }
  report_progress(what, "factorization median of", cheap_repetitions,
                  result.factorization.median());

  // Accuracy of the last basis: M-orthonormality, and the residuals
  // r = Q h - lambda M h in the M^-1 norm (a bound on the error of lambda for
  // an M-unit h), relative to the largest eigenvalue computed.
  const Eigen::MatrixXd& H = basis->basis();
  const Eigen::VectorXd& lambda = basis->eigenvalues();
  const Eigen::MatrixXd MH = basis->mass().asDiagonal() * H;
  result.orthonormality_error =
      (H.transpose() * MH - Eigen::MatrixXd::Identity(m, m)).cwiseAbs().maxCoeff();
  const Eigen::MatrixXd residuals = stiffness * H - MH * lambda.asDiagonal();
  const Eigen::VectorXd inverse_mass = basis->mass().cwiseInverse();
  double largest_residual = 0;
  for(Eigen::Index k = 0; k < residuals.cols(); ++k)
    largest_residual = (std::max)(
        largest_residual, std::sqrt(residuals.col(k).cwiseAbs2().dot(inverse_mass)));
  result.relative_residual = largest_residual / lambda.cwiseAbs().maxCoeff();
  result.load = load_average();
  return result;
}

// ----------------------------------------------------------------------------
// One child process per case; the result comes back as text through a pipe.

void write_sample(std::ostream& out, const char* key, const Sample& sample)
{
  out << key;
  for(double value : sample.values)
    out << ' ' << value;
  out << '\n';
}

std::string serialize(const Case_result& result)
{
  std::ostringstream out;
  out.precision(17);
  write_sample(out, "assembly", result.assembly);
  write_sample(out, "factorization", result.factorization);
  write_sample(out, "basis", result.basis);
  out << "resident_before_kib " << result.resident_before_kib << '\n'
      << "peak_kib " << result.peak_kib << '\n'
      << "peak_was_reset " << result.peak_was_reset << '\n'
      << "orthonormality_error " << result.orthonormality_error << '\n'
      << "relative_residual " << result.relative_residual << '\n'
      << "load " << result.load << '\n';
  if(!result.error.empty())
  {
    std::string error = result.error;
    std::replace(error.begin(), error.end(), '\n', ' ');
    out << "error " << error << '\n';
  }
  return out.str();
}

double to_double(const std::string& text)
{
  return std::strtod(text.c_str(), nullptr); // also reads "nan" and "inf"
}

Case_result parse(const std::string& text)
{
  Case_result result;
  std::istringstream in(text);
  std::string line;
  while(std::getline(in, line))
  {
    std::istringstream fields(line);
    std::string key, word;
    fields >> key;
    if(key == "error")
    {
      std::getline(fields >> std::ws, result.error);
      continue;
    }
    std::vector<double> values;
    while(fields >> word)
      values.push_back(to_double(word));
    if(key == "assembly")
      result.assembly.values = values;
    else if(key == "factorization")
      result.factorization.values = values;
    else if(key == "basis")
      result.basis.values = values;
    else if(values.size() == 1)
    {
      if(key == "resident_before_kib")
        result.resident_before_kib = static_cast<long>(values[0]);
      else if(key == "peak_kib")
        result.peak_kib = static_cast<long>(values[0]);
      else if(key == "peak_was_reset")
        result.peak_was_reset = (values[0] != 0);
      else if(key == "orthonormality_error")
        result.orthonormality_error = values[0];
      else if(key == "relative_residual")
        result.relative_residual = values[0];
      else if(key == "load")
        result.load = values[0];
    }
  }
  return result;
}

Case_result run_case_in_child(const Mesh& mesh, int m, int repetitions, int cheap_repetitions,
                              const std::string& what)
{
  int channel[2];
  if(::pipe(channel) != 0)
    throw std::runtime_error("pipe() failed");
  std::cout.flush();
  std::cerr.flush();
  const pid_t child = ::fork();
  if(child < 0)
    throw std::runtime_error("fork() failed");
  if(child == 0)
  {
    ::close(channel[0]);
    Case_result result;
    try
    {
      result = run_case(mesh, m, repetitions, cheap_repetitions, what);
    }
    catch(const std::exception& e)
    {
      result.error = e.what();
    }
    write_all(channel[1], serialize(result));
    ::close(channel[1]);
    std::cerr.flush();
    ::_exit(result.error.empty() ? EXIT_SUCCESS : EXIT_FAILURE);
  }

  ::close(channel[1]);
  const std::string text = read_all(channel[0]);
  ::close(channel[0]);
  int status = 0;
  while(::waitpid(child, &status, 0) < 0 && errno == EINTR)
  {
  }
  Case_result result = parse(text);
  if(WIFSIGNALED(status))
    result.error = "the case was killed by signal " + std::to_string(WTERMSIG(status)) +
                   " (out of memory?)";
  else if(text.empty())
    result.error = "the case reported nothing";
  return result;
}

// ----------------------------------------------------------------------------
// Report

struct Row
{
  std::string mesh;
  long vertices;
  int m;
  Case_result result;
};

std::string fixed(double value, int decimals)
{
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), "%.*f", decimals, value);
  return buffer;
}

/// About three significant digits.
std::string short_number(double value)
{
  const double magnitude = std::abs(value);
  return fixed(value, magnitude < 10 ? 2 : (magnitude < 100 ? 1 : 0));
}

/// `median [min–max]`, in ms below one second.
std::string format_times(const Sample& sample)
{
  if(sample.empty())
    return "–";
  const double median = sample.median();
  const bool milliseconds = std::abs(median) < 1.0;
  const double scale = milliseconds ? 1e3 : 1.0;
  std::string text = short_number(median * scale) + (milliseconds ? " ms" : " s");
  if(sample.values.size() > 1)
    text += " [" + short_number(sample.min() * scale) + "–" + short_number(sample.max() * scale) +
            "]";
  return text;
}

std::string scientific(double value)
{
  if(!std::isfinite(value))
    return "–";
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), "%.1e", value);
  return buffer;
}

struct Run_info
{
  std::time_t start = std::time(nullptr);
  double load_at_start = load_average();
  double first_touch_microseconds = first_touch_microseconds_per_page();
  Clock::time_point clock_start = Clock::now();
};

void write_report(std::ostream& out, const Options& options, const Run_info& run,
                  const std::vector<Row>& rows, bool complete)
{
  const double memory_gib = proc_field_kib("/proc/meminfo", "MemTotal") / (1024.0 * 1024.0);
  const double minutes =
      std::chrono::duration<double>(Clock::now() - run.clock_start).count() / 60.0;

  out << "# Manifold harmonics basis: timings\n\n";
  if(!complete)
    out << "**Incomplete: the run was still in progress when this was written.**\n\n";
  out << "- Date: " << utc_time(run.start) << ", whole run " << fixed(minutes, 1)
      << " min, load average (1 min) " << fixed(run.load_at_start, 2) << " at start, "
      << fixed(load_average(), 2) << " at the end\n"
      << "- Machine: " << first_line_value("/proc/cpuinfo", "model name") << ", "
      << ::sysconf(_SC_NPROCESSORS_ONLN) << " logical CPUs (nproc), " << fixed(memory_gib, 1)
      << " GiB RAM; first touch of fresh memory " << short_number(run.first_touch_microseconds)
      << " µs per " << ::sysconf(_SC_PAGESIZE) / 1024 << " KiB page\n"
      << "- Compiler: " << compiler() << "\n"
      << "- Build: `CMAKE_BUILD_TYPE=" << SSMD_BENCHMARK_BUILD_TYPE
      << "`, flags of the build type `" << SSMD_BENCHMARK_CXX_FLAGS_BUILD_TYPE
      << "`, `CMAKE_CXX_FLAGS` `" << SSMD_BENCHMARK_CXX_FLAGS << "`, compile options `"
      << SSMD_BENCHMARK_COMPILE_OPTIONS << "`"
#ifdef NDEBUG
      << ", `NDEBUG` defined\n"
#else
      << ", **`NDEBUG` not defined (assertions on)**\n"
#endif
      << "- Sparse SPD solver: " << sparse_solver() << "; BLAS/LAPACK loaded: " << loaded_blas()
      << "\n"
      << "- Libraries: CGAL " << CGAL_VERSION_STR << ", Eigen " << EIGEN_WORLD_VERSION << "."
      << EIGEN_MAJOR_VERSION << "." << EIGEN_MINOR_VERSION << ", Spectra "
      << SPECTRA_MAJOR_VERSION << "." << SPECTRA_MINOR_VERSION << "." << SPECTRA_PATCH_VERSION
      << "\n"
      << "- Eigensolver: the default, `Block_lanczos_eigensolver_traits<>` (block shift-invert "
         "Lanczos, tolerance "
      << tuned_eigensolver().tolerance()
      << ", blocks of max(8, m/32)) with `set_process_wide_tuning(true)`; "
         "`benchmark_eigensolvers` compares it with Spectra's solver\n"
      << "- Repetitions: basis constructor " << options.repetitions << " (meshes above "
      << options.large_mesh_vertices << " vertices: " << options.large_mesh_repetitions
      << "), assembly and factorization " << options.cheap_repetitions
      << "; see the `runs` column\n\n";

  out << "| mesh | n | m | assembly Q, M | factorization Q − σM | eigensolve | "
         "total (constructor) | peak RSS (increase) | max abs(HᵀMH − I) | "
         "max residual | runs | load |\n"
      << "|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|\n";
  for(const Row& row : rows)
  {
    const Case_result& r = row.result;
    out << "| " << row.mesh << " | " << row.vertices << " | " << row.m << " | ";
    if(!r.error.empty())
    {
      out << "failed: " << r.error << " | | | | | | | | |\n";
      continue;
    }
    // The iterations: the constructor minus the two phases it repeats.
    Sample eigensolve = r.basis;
    for(double& value : eigensolve.values)
      value -= r.assembly.median() + r.factorization.median();
    const double peak_mib = r.peak_kib / 1024.0;
    const double increase_mib = (r.peak_kib - r.resident_before_kib) / 1024.0;
    out << format_times(r.assembly) << " | " << format_times(r.factorization) << " | "
        << format_times(eigensolve) << " | " << format_times(r.basis) << " | "
        << fixed(peak_mib, 0) << " MiB (+" << fixed(increase_mib, 0) << ")"
        << (r.peak_was_reset ? "" : ", peak not reset") << " | "
        << scientific(r.orthonormality_error) << " | " << scientific(r.relative_residual)
        << " | " << r.basis.values.size() << " / " << r.assembly.values.size() << " | "
        << fixed(r.load, 2) << " |\n";
  }

  out << "\nColumns:\n\n"
      << "- Times are `median [min–max]` over the runs, wall clock.\n"
      << "- *assembly*: `extract_triangle_arrays` (with validation), `cotangent_stiffness`, "
         "`lumped_mass`.\n"
      << "- *factorization*: `Default_sparse_spd_solver_traits::factor(Q − σM)` with the "
         "shift of the default eigensolver traits (symbolic analysis included; it does not "
         "depend on m).\n"
      << "- *total*: the `Manifold_harmonics_basis` constructor with default traits, end to "
         "end; it performs the assembly and the factorization itself.\n"
      << "- *eigensolve*: the rest of the constructor, i.e. total minus the medians of "
         "assembly and factorization: the eigensolver iteration with its solves, plus the sign "
         "normalization and the fingerprint of the mesh.\n"
      << "- Large arrays are allocated fresh in every run (glibc's mmap threshold is fixed at "
         "128 KiB), as in a single computation in a new process, so the times include the "
         "first touch of that memory (see *Machine*).\n"
      << "- *peak RSS*: VmHWM of the process that computed the basis, and in parentheses its "
         "increase over the resident size just before (mesh and libraries). Each case runs in "
         "a forked process of its own, with the peak reset through /proc/self/clear_refs; the "
         "basis is computed before the other phases and at most one basis is alive at a "
         "time.\n"
      << "- *max residual*: max over the columns of ‖Q h − λ M h‖ in the M⁻¹ norm, "
         "relative to the largest eigenvalue computed (for an M-unit h it bounds the error of "
         "λ).\n"
      << "- *runs*: runs of the constructor / of assembly and factorization. *load*: 1-minute "
         "load average at the end of the case (the benchmark itself accounts for about 1).\n";
  if(!options.notes.empty())
  {
    out << "\nNotes:\n\n";
    for(const std::string& note : options.notes)
      out << "- " << note << "\n";
  }
}

void save_report(const Options& options, const Run_info& run, const std::vector<Row>& rows,
                 bool complete)
{
  if(options.output.empty())
    return;
  std::ofstream file(options.output);
  write_report(file, options, run, rows, complete);
  if(!file)
    throw std::runtime_error("cannot write " + options.output);
}

Mesh load_mesh(const Options& options, const Mesh_spec& spec)
{
  const std::string path = options.mesh_directory + "/" + spec.file;
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(path, mesh) || is_empty(mesh))
    throw std::runtime_error("cannot read the mesh " + path +
                             " (run benchmark/run_basis_benchmark.sh, or pass the directory "
                             "holding it)");
  if(spec.subdivision_levels > 0)
    CGAL::Subdivision_method_3::Loop_subdivision(
        mesh, CGAL::parameters::number_of_iterations(static_cast<int>(spec.subdivision_levels)));
  return mesh;
}

} // namespace

int main(int argc, char** argv)
{
#ifdef __GLIBC__
  // glibc raises its mmap threshold when a large block is freed, so that the
  // repetitions after the first would reuse memory that is already mapped
  // while the first pays for fresh pages. A fixed threshold (glibc's initial
  // one) gives every repetition the allocation cost of a single computation
  // in a fresh process.
  mallopt(M_MMAP_THRESHOLD, 128 * 1024);
#endif
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
    Run_info run;
    std::vector<Row> rows;
    for(const std::string& name : options.meshes)
    {
      const Mesh_spec& spec = *std::find_if(known_meshes().begin(), known_meshes().end(),
                                            [&](const Mesh_spec& s) { return s.name == name; });
      Mesh mesh;
      const double load_seconds = seconds_of([&] { mesh = load_mesh(options, spec); });
      const long n = static_cast<long>(num_vertices(mesh));
      std::cerr << spec.label << ": " << n << " vertices, " << num_faces(mesh)
                << " faces (read and subdivided in " << load_seconds << " s)" << std::endl;
      const int repetitions =
          (n > options.large_mesh_vertices) ? options.large_mesh_repetitions : options.repetitions;
      for(int m : options.frequencies)
      {
        const std::string what = spec.label + ", m = " + std::to_string(m);
        rows.push_back({spec.label, n, m,
                        run_case_in_child(mesh, m, repetitions, options.cheap_repetitions, what)});
        if(!rows.back().result.error.empty())
          std::cerr << "  " << what << ": failed: " << rows.back().result.error << std::endl;
        save_report(options, run, rows, false);
      }
    }
    save_report(options, run, rows, true);
    write_report(std::cout, options, run, rows, true);
  }
  catch(const std::exception& e)
  {
    std::cerr << "error: " << e.what() << "\n";
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}

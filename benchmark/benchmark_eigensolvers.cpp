// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This program is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.
//
// The default eigensolver (CGAL::Block_lanczos_eigensolver_traits) side by
// side with the reference (CGAL::Spectra_eigensolver_traits, Spectra's
// shift-invert Lanczos), in one run, on the meshes of the deformation cases
// (optionally Loop-subdivided), for several numbers of frequencies m:
//   - the time of the Manifold_harmonics_basis constructor with each solver
//     (medians, min-max), and their ratio;
//   - the accuracy of the fast basis against the reference: relative errors
//     of the eigenvalues, the largest principal angle between the two
//     m-dimensional subspaces (M inner product), M-orthonormality and the
//     eigen-residuals of both;
//   - the deformation of the case (spectral solver, m frequencies, exact
//     policy, deform(10, 0)) with each solver computing the basis of the
//     region: the largest vertex distance between the two results relative
//     to the bounding-box diagonal, and the first preprocess() of each.
//
// Usage: benchmark_eigensolvers [options], see print_usage().

#include "deformation_cases.h"

#include <CGAL/Manifold_harmonics_basis.h>
// Deformations with other traits than the compiled core holds.
#include <CGAL/Spectral_deformation/Pipelines_from_headers.h>
#include <CGAL/Spectral_surface_mesh_deformation.h>
#include <CGAL/Spectral_deformation/Spectra_eigensolver_traits.h>
#include <CGAL/Spectral_deformation/cotangent_operators.h>
#include <CGAL/version.h>

#include <Eigen/Dense>
#include <Spectra/Util/Version.h>

#ifdef _OPENMP
#include <omp.h>
#endif

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
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

using namespace ssmd_benchmark;

namespace {

typedef CGAL::Spectra_eigensolver_traits<> Reference_traits;
typedef CGAL::Block_lanczos_eigensolver_traits<> Fast_traits;
typedef CGAL::Manifold_harmonics_basis<Mesh, Reference_traits> Reference_basis;
typedef CGAL::Manifold_harmonics_basis<Mesh, Fast_traits> Fast_basis;
template <class Traits>
using Deformation = CGAL::Spectral_surface_mesh_deformation<Mesh, CGAL::Default, CGAL::Default,
                                                            CGAL::SPECTRAL_DUAL_LAPLACIAN, Traits>;

struct Options
{
  std::string mesh_directory = SSMD_BENCHMARK_DEFAULT_MESH_DIR;
  std::string case_directory = SSMD_BENCHMARK_DEFAULT_CASE_DIR;
  std::vector<std::string> cases{"armadillo_arm"};
  std::vector<unsigned int> levels{1, 2};
  std::vector<Eigen::Index> frequencies{100, 200};
  int repetitions = 3;
  int large_repetitions = 2;
  std::size_t large_vertices = 200000;
  bool deformation = true;
  bool check = false;
  double tolerance = 0; // 0: the default of Fast_traits
  std::string output;
  std::string note;
};

void print_usage(const char* program)
{
  std::cerr
      << "Usage: " << program << " [options]\n"
      << "  --cases a,b,...            case files of --case-directory (default armadillo_arm)\n"
      << "  --levels l1,l2,...         Loop subdivision levels of each case's mesh (default 1,2)\n"
      << "  --frequencies m1,m2,...    (default 100,200)\n"
      << "  --repetitions N            basis constructions per solver (default 3)\n"
      << "  --large-repetitions N      on meshes above --large-vertices (default 2)\n"
      << "  --large-vertices N         (default 200000)\n"
      << "  --no-deformation           skip the deformation comparison\n"
      << "  --tolerance T              tolerance of the block Lanczos solver (default: its own)\n"
      << "  --check                    exit with a failure when the fast basis is not accurate:\n"
      << "                             eigenvalue relative errors above 1e-8, M-orthonormality\n"
      << "                             error above 1e-9, residual above max(1e-6, 1e3 tolerance),\n"
      << "                             deformation deviation above 1e-4 of the bounding-box\n"
      << "                             diagonal\n"
      << "  --mesh-directory DIR       (default " SSMD_BENCHMARK_DEFAULT_MESH_DIR ")\n"
      << "  --case-directory DIR       (default " SSMD_BENCHMARK_DEFAULT_CASE_DIR ")\n"
      << "  --output FILE              also write the markdown report to FILE\n"
      << "  --note TEXT                a line added to the notes of the report\n";
}

std::vector<std::string> split(const std::string& text)
{
  std::vector<std::string> parts;
  std::stringstream in(text);
  std::string part;
  while(std::getline(in, part, ','))
    if(!part.empty())
      parts.push_back(part);
  return parts;
}

bool parse(int argc, char** argv, Options& options)
{
  for(int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    auto value = [&]() -> std::string {
      if(i + 1 >= argc)
        throw std::runtime_error(arg + " needs a value");
      return argv[++i];
    };
    if(arg == "--cases")
      options.cases = split(value());
    else if(arg == "--levels")
    {
      options.levels.clear();
      for(const std::string& s : split(value()))
        options.levels.push_back(static_cast<unsigned int>(std::stoul(s)));
    }
    else if(arg == "--frequencies")
    {
      options.frequencies.clear();
      for(const std::string& s : split(value()))
        options.frequencies.push_back(static_cast<Eigen::Index>(std::stol(s)));
    }
    else if(arg == "--repetitions")
      options.repetitions = std::stoi(value());
    else if(arg == "--large-repetitions")
      options.large_repetitions = std::stoi(value());
    else if(arg == "--large-vertices")
      options.large_vertices = static_cast<std::size_t>(std::stoul(value()));
    else if(arg == "--no-deformation")
      options.deformation = false;
    else if(arg == "--check")
      options.check = true;
    else if(arg == "--tolerance")
      options.tolerance = std::stod(value());
    else if(arg == "--mesh-directory")
      options.mesh_directory = value();
    else if(arg == "--case-directory")
      options.case_directory = value();
    else if(arg == "--output")
      options.output = value();
    else if(arg == "--note")
      options.note = value();
    else
    {
      print_usage(argv[0]);
      return false;
    }
  }
  return options.repetitions > 0 && options.large_repetitions > 0;
}

struct Timing
{
  std::vector<double> seconds;
  double median() const
  {
    std::vector<double> s = seconds;
    std::sort(s.begin(), s.end());
    const std::size_t n = s.size();
    return n % 2 == 1 ? s[n / 2] : 0.5 * (s[n / 2 - 1] + s[n / 2]);
  }
  std::string text() const
  {
    const auto range = std::minmax_element(seconds.begin(), seconds.end());
    return duration(median()) + " [" + duration(*range.first) + "–" + duration(*range.second) + "]";
  }
};

// The largest principal angle between span(A) and span(B), both M-orthonormal.
double largest_principal_angle(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B,
                               const Eigen::VectorXd& mass)
{
  const Eigen::MatrixXd cosines = A.transpose() * mass.asDiagonal() * B;
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(cosines);
  const double smallest = svd.singularValues().minCoeff();
  return std::acos((std::min)(1.0, (std::max)(-1.0, smallest)));
}

double orthonormality_error(const Eigen::MatrixXd& H, const Eigen::VectorXd& mass)
{
  const Eigen::MatrixXd gram = H.transpose() * mass.asDiagonal() * H;
  return (gram - Eigen::MatrixXd::Identity(H.cols(), H.cols())).cwiseAbs().maxCoeff();
}

// max over the columns of ‖Q h − λ M h‖ in the M⁻¹ norm, relative to the
// largest eigenvalue (as in benchmark_basis).
double largest_residual(const Eigen::SparseMatrix<double>& Q, const Eigen::VectorXd& mass,
                        const Eigen::VectorXd& lambda, const Eigen::MatrixXd& H)
{
  double largest = 0;
  const Eigen::VectorXd inverse_sqrt_mass = mass.cwiseSqrt().cwiseInverse();
  for(Eigen::Index k = 0; k < H.cols(); ++k)
  {
    const Eigen::VectorXd r = Q * H.col(k) - lambda[k] * mass.cwiseProduct(H.col(k));
    largest = (std::max)(largest, inverse_sqrt_mass.cwiseProduct(r).norm());
  }
  return largest / lambda.maxCoeff();
}

template <class Traits>
Positions deform(const Deformation_case& c, Eigen::Index m, const Traits& traits,
                 double& preprocess_seconds, double& deform_seconds)
{
  Mesh mesh = c.mesh;
  Deformation<Traits> deformation(mesh);
  deformation.set_eigensolver_traits(traits);
  deformation.set_number_of_frequencies(static_cast<std::size_t>(m));
  deformation.insert_roi_vertices(c.roi.begin(), c.roi.end());
  deformation.insert_control_vertices(c.handles.begin(), c.handles.end());
  const Clock::time_point start = Clock::now();
  if(!deformation.preprocess())
    throw std::runtime_error("preprocess() failed on " + c.name);
  preprocess_seconds = seconds_since(start);
  for(std::size_t k = 0; k < c.handles.size(); ++k)
    deformation.set_target_position(c.handles[k], c.targets[k]);
  const Clock::time_point deform_start = Clock::now();
  deformation.deform(10, 0.0);
  deform_seconds = seconds_since(deform_start);
  return positions_of(mesh);
}

// Both solvers may tune the process (OpenBLAS threads, SuiteSparse's
// allocator, huge pages): this program owns its process, and measures the
// solvers at their speed.
Fast_traits fast_traits(const Options& options)
{
  Fast_traits traits = options.tolerance > 0 ? Fast_traits(options.tolerance) : Fast_traits();
  traits.set_process_wide_tuning(true);
  return traits;
}

Reference_traits reference_traits()
{
  Reference_traits traits;
  traits.set_process_wide_tuning(true);
  return traits;
}

struct Row
{
  std::string mesh;
  std::size_t vertices = 0;
  Eigen::Index m = 0;
  Timing reference, fast;
  double max_eigenvalue_error = 0, median_eigenvalue_error = 0, angle = 0;
  double reference_orthonormality = 0, fast_orthonormality = 0;
  double reference_residual = 0, fast_residual = 0;
  bool deformed = false;
  double deviation = 0, reference_preprocess = 0, fast_preprocess = 0;
  double reference_deform = 0, fast_deform = 0;
  double load = 0;
};

Row run_case(const Deformation_case& c, const std::string& label, Eigen::Index m,
             const Options& options)
{
  Row row;
  row.mesh = label;
  row.vertices = num_vertices(c.mesh);
  row.m = m;
  const int repetitions =
      row.vertices > options.large_vertices ? options.large_repetitions : options.repetitions;
  Eigen::VectorXd reference_values, fast_values, mass;
  Eigen::MatrixXd reference_vectors, fast_vectors;
  // Alternate the solvers so that a change of machine load hits both alike.
  for(int r = 0; r < repetitions; ++r)
  {
    {
      const Clock::time_point start = Clock::now();
      Reference_basis basis(c.mesh, static_cast<std::size_t>(m), CGAL::parameters::default_values(),
                            reference_traits());
      row.reference.seconds.push_back(seconds_since(start));
      if(r == 0)
      {
        reference_values = basis.eigenvalues();
        reference_vectors = basis.basis();
        mass = basis.mass();
      }
    }
    {
      const Clock::time_point start = Clock::now();
      Fast_basis basis(c.mesh, static_cast<std::size_t>(m), CGAL::parameters::default_values(),
                       fast_traits(options));
      row.fast.seconds.push_back(seconds_since(start));
      if(r == 0)
      {
        fast_values = basis.eigenvalues();
        fast_vectors = basis.basis();
      }
    }
    std::cerr << "  " << label << " m = " << m << " run " << r + 1 << "/" << repetitions
              << ": reference " << duration(row.reference.seconds.back()) << ", block Lanczos "
              << duration(row.fast.seconds.back()) << "\n";
  }
  // Eigenvalue errors from k = 1 on: the first eigenvalue is 0 up to rounding.
  std::vector<double> errors;
  for(Eigen::Index k = 1; k < m; ++k)
    errors.push_back(std::abs(fast_values[k] - reference_values[k]) / std::abs(reference_values[k]));
  std::sort(errors.begin(), errors.end());
  row.max_eigenvalue_error = errors.back();
  row.median_eigenvalue_error = errors[errors.size() / 2];
  row.angle = largest_principal_angle(reference_vectors, fast_vectors, mass);
  row.reference_orthonormality = orthonormality_error(reference_vectors, mass);
  row.fast_orthonormality = orthonormality_error(fast_vectors, mass);
  const Eigen::SparseMatrix<double> Q = CGAL::cotangent_stiffness_matrix(c.mesh);
  row.reference_residual = largest_residual(Q, mass, reference_values, reference_vectors);
  row.fast_residual = largest_residual(Q, mass, fast_values, fast_vectors);

  if(options.deformation)
  {
    const Positions reference =
        deform(c, m, reference_traits(), row.reference_preprocess, row.reference_deform);
    const Positions fast = deform(c, m, fast_traits(options), row.fast_preprocess, row.fast_deform);
    const Positions rest = positions_of(c.mesh);
    const double diagonal = (rest.colwise().maxCoeff() - rest.colwise().minCoeff()).norm();
    row.deviation = (reference - fast).rowwise().norm().maxCoeff() / diagonal;
    row.deformed = true;
  }
  row.load = load_average();
  return row;
}

// The accuracy asked of the fast basis by --check: the measured values
// (benchmark/results/eigensolvers.md) are orders of magnitude below; the
// deformation deviation allowed by the package's goal is 1e-3 (measured:
// 7.7e-6 at 26k vertices, m = 50, with the default tolerance 1e-6). The residual
// follows the tolerance of the block solver (relative to theta in the
// shift-inverted problem, to the largest eigenvalue here).
std::vector<std::string> accuracy_failures(const std::vector<Row>& rows, double tolerance)
{
  std::vector<std::string> failures;
  for(const Row& r : rows)
  {
    const std::string where = r.mesh + ", m = " + std::to_string(r.m) + ": ";
    if(!(r.max_eigenvalue_error <= 1e-8))
      failures.push_back(where + "eigenvalue relative error " + scientific(r.max_eigenvalue_error));
    if(!(r.fast_orthonormality <= 1e-9))
      failures.push_back(where + "M-orthonormality error " + scientific(r.fast_orthonormality));
    if(!(r.fast_residual <= (std::max)(1e-6, 1e3 * tolerance)))
      failures.push_back(where + "residual " + scientific(r.fast_residual));
    if(r.deformed && !(r.deviation <= 1e-4))
      failures.push_back(where + "deformation deviation " + scientific(r.deviation) + " D");
  }
  return failures;
}

std::string report(const Options& options, const std::vector<Row>& rows, double total_seconds,
                   double load_start)
{
  std::ostringstream out;
  out << "# Manifold harmonics: block Lanczos against the reference eigensolver\n\n";
  out << "- Date: " << utc_time(std::time(nullptr)) << ", whole run " << duration(total_seconds)
      << ", load average (1 min) " << fixed(load_start, 2) << " at start, "
      << fixed(load_average(), 2) << " at the end\n";
  out << "- Machine: " << first_line_value("/proc/cpuinfo", "model name") << ", "
      << sysconf(_SC_NPROCESSORS_ONLN) << " logical CPUs, " << fixed(memory_gib(), 1)
      << " GiB RAM\n";
  out << "- Compiler: " << compiler() << "\n";
  out << "- Build: `CMAKE_BUILD_TYPE=" SSMD_BENCHMARK_BUILD_TYPE "`, flags of the build type `"
      << SSMD_BENCHMARK_CXX_FLAGS_BUILD_TYPE << "`, `CMAKE_CXX_FLAGS` `" SSMD_BENCHMARK_CXX_FLAGS
      << "`"
#ifdef _OPENMP
      << ", OpenMP on (" << omp_get_max_threads() << " threads)"
#endif
#ifdef CGAL_SSMD_USE_BLAS
      << ", `CGAL_SSMD_USE_BLAS` defined (dense products through dgemm)"
#endif
      << "\n";
  out << "- Sparse SPD solver: " << sparse_solver() << "; BLAS/LAPACK loaded: " << loaded_blas()
      << "\n";
  out << "- Libraries: CGAL " << CGAL_VERSION_STR << ", Eigen " << EIGEN_WORLD_VERSION << "."
      << EIGEN_MAJOR_VERSION << "." << EIGEN_MINOR_VERSION << ", Spectra " << SPECTRA_MAJOR_VERSION
      << "." << SPECTRA_MINOR_VERSION << "." << SPECTRA_PATCH_VERSION << "\n";
  out << "- Solvers: reference `Spectra_eigensolver_traits<>` (shift-invert Lanczos, tolerance "
         "1e-10, ncv = max(2m + 1, m + 20)); fast `Block_lanczos_eigensolver_traits<>` "
         "(tolerance "
      << fast_traits(options).tolerance()
      << (options.tolerance > 0 ? " set by --tolerance" : ", its default")
      << ", blocks of max(8, m/32), no restart, partial reorthogonalization, "
         "constants deflated), each with its default sparse solver: the reference CHOLMOD's "
         "supernodal factor, the block method its simplicial factor (factored in supernodal form "
         "above 200 flops per entry, then converted) solved by subtrees split over two "
         "threads, and OpenBLAS set to one thread during its solve (its tall "
         "products are split by OpenMP); both with `set_process_wide_tuning(true)`\n\n";

  out << "| mesh | n | m | reference | block Lanczos | speed-up | max rel. error λ | median rel. "
         "error λ | largest principal angle | max abs(HᵀMH − I) ref / fast | max residual ref / "
         "fast | deformation deviation / D | first preprocess() ref / fast | load |\n";
  out << "|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|\n";
  for(const Row& r : rows)
  {
    out << "| " << r.mesh << " | " << r.vertices << " | " << r.m << " | " << r.reference.text()
        << " | " << r.fast.text() << " | **" << fixed(r.reference.median() / r.fast.median(), 2)
        << "×** | " << scientific(r.max_eigenvalue_error) << " | "
        << scientific(r.median_eigenvalue_error) << " | " << scientific(r.angle) << " rad | "
        << scientific(r.reference_orthonormality) << " / " << scientific(r.fast_orthonormality)
        << " | " << scientific(r.reference_residual) << " / " << scientific(r.fast_residual)
        << " | " << (r.deformed ? scientific(r.deviation) : std::string("—")) << " | "
        << (r.deformed ? duration(r.reference_preprocess) + " / " + duration(r.fast_preprocess)
                       : std::string("—"))
        << " | " << fixed(r.load, 2) << " |\n";
  }
  out << "\nColumns:\n\n"
      << "- *reference*, *block Lanczos*: the `Manifold_harmonics_basis` constructor on the whole "
         "mesh (assembly, factorization, eigensolve), wall clock, `median [min–max]`; the two "
         "solvers alternate run by run. *speed-up*: ratio of the medians.\n"
      << "- *rel. error λ*: |λ_fast − λ_ref| / λ_ref over k = 1 … m − 1 (λ_0 = 0).\n"
      << "- *largest principal angle*: between the spans of the two bases, from the singular "
         "values of H_refᵀ M H_fast.\n"
      << "- *max residual*: max over the columns of ‖Q h − λ M h‖ in the M⁻¹ norm, relative "
         "to the largest eigenvalue.\n"
      << "- *deformation deviation / D*: the case deformed by the spectral solver (exact policy, "
         "m frequencies, `deform(10, 0)`), once with each eigensolver computing the basis of the "
         "region: largest vertex distance between the two results over the bounding-box "
         "diagonal D. *first preprocess()*: of those two runs, basis of the region included.\n"
      << "- *load*: 1-minute load average at the end of the row (the benchmark accounts for "
         "about 1).\n";
  if(!options.note.empty())
    out << "\nNote: " << options.note << "\n";
  return out.str();
}

} // namespace

int main(int argc, char** argv)
{
  Options options;
  try
  {
    if(!parse(argc, argv, options))
      return EXIT_FAILURE;
    const double load_start = load_average();
    const Clock::time_point start = Clock::now();
    std::vector<Row> rows;
    for(const std::string& name : options.cases)
      for(unsigned int level : options.levels)
      {
        const Deformation_case c =
            read_case_file(options.case_directory + "/" + name + ".case", options.mesh_directory, level);
        const std::string label =
            c.name + (level == 0 ? std::string() : ", Loop ×" + std::to_string(level));
        for(Eigen::Index m : options.frequencies)
          rows.push_back(run_case(c, label, m, options));
      }
    const std::string text = report(options, rows, seconds_since(start), load_start);
    std::cout << text;
    if(!options.output.empty())
    {
      std::ofstream out(options.output);
      out << text;
      if(!out)
        throw std::runtime_error("cannot write " + options.output);
    }
    if(options.check)
    {
      const std::vector<std::string> failures = accuracy_failures(rows, fast_traits(options).tolerance());
      for(const std::string& failure : failures)
        std::cerr << "check failed: " << failure << "\n";
      if(!failures.empty())
        return EXIT_FAILURE;
      std::cerr << "check passed: the fast basis is within the accuracy asked of it\n";
    }
  }
  catch(const std::exception& e)
  {
    std::cerr << "error: " << e.what() << "\n";
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}

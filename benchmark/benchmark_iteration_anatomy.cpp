// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This program is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.
//
// The iteration of the spectral solver taken apart, on one case: the only
// benchmark that reaches into the package's internal headers, since its
// probes time the solver's kernels one by one. On the basis of the
// deformation class (saved, then read back), it times
//   - two streaming passes over the basis matrix H (HᵀX and HY, X n×3,
//     Y m×3) with Eigen, and a plain read of H (the memory bandwidth);
//   - the same products as the solver makes them (internal::Stored_basis),
//     with H kept in double and in float;
//   - the steps of one iteration of the internal solver on the same region:
//     the shape HṼ, the dual normals, the sparse product (L̂F)ᵀ, the
//     projection Hᵀ, the reduced solve; and the detail transfer's steps;
// and sets them against the iteration of the class (from deform(10, 0) and
// deform(1, 0)): one iteration should cost at most two streaming passes over
// H, twice over.
//
// Usage: benchmark_iteration_anatomy [--case NAME] [--level L] [--frequencies M]
//          [--repetitions N] [--mesh-directory DIR] [--case-directory DIR]
//          [--output FILE]

#include "deformation_cases.h"

#include <CGAL/Spectral_surface_mesh_deformation.h>
#include <CGAL/Spectral_deformation/Sparse_spd_solver_traits.h>
#include <CGAL/Spectral_deformation/internal/Basis/basis_io.h>
#include <CGAL/Spectral_deformation/internal/Deformation/Detail_transfer.h>
#include <CGAL/Spectral_deformation/internal/Deformation/Spectral_dual_laplacian_solver.h>
#include <CGAL/Spectral_deformation/internal/Mesh/Dual_mesh_operator.h>
#include <CGAL/Spectral_deformation/internal/Mesh/Region.h>

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
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

namespace {

namespace SD = CGAL::Spectral_deformation::internal;

template <class Function>
double seconds_of(Function&& function)
{
  const Clock::time_point start = Clock::now();
  function();
  return seconds_since(start);
}

/// The timings of the probes (seconds, one per run) and the sizes.
struct Anatomy
{
  std::map<std::string, std::vector<double>> samples;
  std::map<std::string, double> values;

  double median_of(const std::string& name) const
  {
    const auto found = samples.find(name);
    return found == samples.end() ? not_a_number : median(found->second);
  }
};

// The region of the class, cut by the package's own function (vertices in
// its spatial order), and the local indices of the constrained vertices
// (fixed ring first, then the control vertices).
struct Region_arrays
{
  SD::Mesh::Triangle_arrays arrays;
  std::vector<int> constrained;
  std::vector<char> is_handle; // local
};

Region_arrays region_arrays(const Deformation_case& c)
{
  const Mesh& mesh = c.mesh;
  std::vector<char> is_roi(num_vertices(mesh), 0);
  std::vector<Point> rest;
  for(vertex_descriptor v : vertices(mesh))
  {
    is_roi[v.idx()] = c.status[v.idx()] != CGAL::IO::FIXED_VERTEX;
    rest.push_back(mesh.point(v));
  }
  const auto region =
      SD::Mesh::extract_region(mesh, [](vertex_descriptor v) { return std::size_t(v.idx()); }, is_roi, rest);
  Region_arrays r;
  r.arrays = region.arrays;
  r.is_handle.assign(region.vertices.size(), 0);
  for(std::size_t i = 0; i < region.vertices.size(); ++i)
    if(region.is_fixed[i])
      r.constrained.push_back(static_cast<int>(i));
  for(std::size_t i = 0; i < region.vertices.size(); ++i)
    if(c.status[region.vertices[i].idx()] == CGAL::IO::HANDLE_VERTEX)
    {
      r.constrained.push_back(static_cast<int>(i));
      r.is_handle[i] = 1;
    }
  return r;
}

template <class Function>
void time_into(Anatomy& row, const std::string& name, int repetitions, Function&& function)
{
  for(int run = 0; run < repetitions; ++run)
    row.samples[name].push_back(seconds_of(function));
}

/// The iteration of the spectral solver taken apart, on the basis of the
/// class (saved and read back), with the internal solver of the package.
template <class Deformation>
Anatomy measure_anatomy(Deformation& d, const Deformation_case& c, int repetitions)
{
  Anatomy row;
  std::stringstream cache;
  d.save_basis(cache);
  const SD::Basis::Basis_data data = SD::Basis::read_basis(cache);
  const Eigen::MatrixXd& H = data.basis;
  const Eigen::Index n = H.rows(), m = H.cols();
  row.values["n"] = static_cast<double>(n);
  row.values["m"] = static_cast<double>(m);
  double sink = 0;

  // Two streaming passes over H, as in an iteration: HᵀX (n×3 -> m×3) and HY.
  const Eigen::MatrixXd X = Eigen::MatrixXd::Random(n, 3);
  const Eigen::MatrixXd Y = Eigen::MatrixXd::Random(m, 3);
  time_into(row, "pass_HtX", repetitions, [&] {
    const Eigen::MatrixXd r = H.transpose() * X;
    sink += r(0, 0);
  });
  time_into(row, "pass_HY", repetitions, [&] {
    const SD::Mesh::Positions r = H * Y;
    sink += r(0, 0);
  });
  // A pure read of H (the sum of its entries): the streaming bandwidth.
  time_into(row, "read_H", repetitions, [&] { sink += H.sum(); });
  // The same two products as the package's solver makes them
  // (internal::Stored_basis), in double and in float.
  SD::Linear_algebra::Stored_basis panels;
  panels.assign(Eigen::MatrixXd(H), false);
  {
    SD::Linear_algebra::Stored_basis panels_float;
    panels_float.assign(Eigen::MatrixXd(H), true);
    SD::Mesh::Positions S;
    Eigen::MatrixXd P;
    time_into(row, "panel_HY", repetitions, [&] { panels.multiply(Y, S); sink += S(0, 0); });
    time_into(row, "panel_HtX", repetitions, [&] { panels.multiply_transpose(X, P); sink += P(0, 0); });
    time_into(row, "panel_HY_float", repetitions, [&] { panels_float.multiply(Y, S); sink += S(0, 0); });
    time_into(row, "panel_HtX_float", repetitions,
              [&] { panels_float.multiply_transpose(X, P); sink += P(0, 0); });
  }

  // The internal solver on the same region and basis.
  const Region_arrays region = region_arrays(c);
  row.values["fingerprint_matches"] = (SD::Mesh::fingerprint(region.arrays) == data.fingerprint) ? 1.0 : 0.0;
  if(SD::Mesh::fingerprint(region.arrays) != data.fingerprint || region.arrays.positions.rows() != n)
    throw std::runtime_error("anatomy: the region rebuilt here is not the region of the class (" + std::to_string(region.arrays.positions.rows()) + " vertices, " + std::to_string(n) + " in the basis)");
  SD::Linear_algebra::Stored_basis stored;
  stored.assign(Eigen::MatrixXd(H), false);
  SD::Deformation::Spectral_dual_laplacian_solver solver;
  solver.initialize(stored, data.mass, region.arrays);
  if(!solver.preprocess(region.constrained, 1.0))
    throw std::runtime_error("anatomy: the reduced system is not positive definite");
  const SD::Mesh::Positions& smooth = solver.smooth_rest();
  SD::Mesh::Positions smooth_targets(static_cast<Eigen::Index>(region.constrained.size()), 3);
  const Eigen::Matrix3d R = c.transformation.topLeftCorner<3, 3>();
  const Eigen::Vector3d t = c.transformation.topRightCorner<3, 1>();
  for(std::size_t k = 0; k < region.constrained.size(); ++k)
  {
    const int i = region.constrained[k];
    const Eigen::Vector3d p = smooth.row(i).transpose();
    const Eigen::Vector3d q = region.is_handle[static_cast<std::size_t>(i)] ? Eigen::Vector3d(R * p + t) : p;
    smooth_targets.row(static_cast<Eigen::Index>(k)) = q.transpose();
  }
  Eigen::MatrixXd coefficients;
  for(int run = 0; run < repetitions; ++run)
  {
    Eigen::MatrixXd one = solver.rest_coefficients(), ten = solver.rest_coefficients();
    const double t1 = seconds_of([&] { solver.solve(smooth_targets, one, 0, 0.0); });
    const double t10 = seconds_of([&] { solver.solve(smooth_targets, ten, 9, 0.0); });
    row.samples["solver_iteration"].push_back((t10 - t1) / 9.0);
    coefficients = ten;
  }

  // The steps of one iteration, at the state after 10 solves, with the
  // kernels of the solver.
  const SD::Mesh::Dual_mesh_operator& dual = solver.dual_mesh();
  const SD::Mesh::Dual_coordinates rest = dual.evaluate(smooth);
  const Eigen::VectorXd negative_heights = -rest.heights;
  SD::Mesh::Positions shape;
  time_into(row, "step_shape", repetitions, [&] { panels.multiply(coefficients, shape); });
  SD::Mesh::Positions centroids, normals = rest.normals;
  time_into(row, "step_dual", repetitions, [&] { dual.update_normals(shape, centroids, normals); });
  SD::Mesh::Positions faces, spread;
  time_into(row, "step_sparse", repetitions,
            [&] { dual.apply_transpose(rest.weights, negative_heights, normals, faces, spread); });
  Eigen::MatrixXd projected;
  time_into(row, "step_project", repetitions, [&] { panels.multiply_transpose(spread, projected); });
  const Eigen::LLT<Eigen::MatrixXd> llt(Eigen::MatrixXd(Eigen::MatrixXd::Identity(m, m) * 2.0));
  time_into(row, "step_reduced_solve", repetitions, [&] {
    const Eigen::MatrixXd next = llt.solve(projected);
    sink += next(0, 0);
  });
  row.values["dual_rows"] = static_cast<double>(dual.number_of_rows());

  // The detail transfer of the exact policy, taken apart.
  SD::Deformation::Detail_transfer<CGAL::Default_sparse_spd_solver_traits> transfer;
  transfer.initialize(region.arrays, smooth);
  std::vector<char> prescribed(static_cast<std::size_t>(n), 0);
  for(int i : region.constrained)
    prescribed[static_cast<std::size_t>(i)] = 1;
  if(!transfer.prepare_dirichlet(prescribed))
    throw std::runtime_error("anatomy: the detail transfer factorization failed");
  SD::Mesh::Positions prescribed_positions = region.arrays.positions;
  SD::Mesh::Positions result;
  time_into(row, "transfer_shape", repetitions, [&] { panels.multiply(coefficients, shape); });
  time_into(row, "transfer_rhs", repetitions, [&] {
    const Eigen::MatrixXd rhs = transfer.right_hand_side(shape);
    sink += rhs(0, 0);
  });
  time_into(row, "transfer_exact", repetitions,
            [&] { transfer.transfer_exact(shape, prescribed_positions, result); });
  row.values["sink"] = sink == 12345.678 ? 1.0 : 0.0; // keeps the products alive
  return row;
}


// The exact basis, as in the recorded results of benchmark_deformation.
typedef CGAL::Spectral_surface_mesh_deformation<Mesh, CGAL::Default, CGAL::Default, CGAL::SPECTRAL_DUAL_LAPLACIAN,
                                                CGAL::Block_lanczos_eigensolver_traits<>>
    Deformation;

/// The iteration of the class: the difference of deform(10, 0) and
/// deform(1, 0) from the rest shape, over 9.
std::vector<double> class_iterations(Deformation& d, const Deformation_case& c, int repetitions)
{
  std::vector<double> iterations;
  auto deform_from_rest = [&](unsigned int n) {
    d.reset();
    for(std::size_t k = 0; k < c.handles.size(); ++k)
      d.set_target_position(c.handles[k], c.targets[k]);
    return seconds_of([&] { d.deform(n, 0.0); });
  };
  for(int run = 0; run < repetitions; ++run)
  {
    const double one = deform_from_rest(1), ten = deform_from_rest(10);
    iterations.push_back((ten - one) / 9.0);
  }
  return iterations;
}

std::string report(const Deformation_case& c, unsigned int level, const Anatomy& a, int repetitions)
{
  const double iteration = a.median_of("class_iteration");
  const double passes = 2 * a.median_of("read_H");
  const double steps = a.median_of("step_dual") + a.median_of("step_sparse") + a.median_of("step_reduced_solve");
  const double in_float = a.median_of("panel_HY_float") + a.median_of("panel_HtX_float") + steps;
  std::ostringstream out;
  auto line = [&](const std::string& what, const std::string& name) {
    out << "| " << what << " | " << duration(a.median_of(name)) << " |\n";
  };
  out << "# The iteration of the spectral solver taken apart\n\n"
      << "- Date: " << utc_time(std::time(nullptr)) << ", machine: " << first_line_value("/proc/cpuinfo", "model name")
      << ", compiler: " << compiler() << ", build: `CMAKE_BUILD_TYPE=" << SSMD_BENCHMARK_BUILD_TYPE << "`, flags `"
      << SSMD_BENCHMARK_CXX_FLAGS_BUILD_TYPE << "`\n"
      << "- Case: " << c.name << (level == 0 ? std::string() : ", Loop ×" + std::to_string(level)) << ", "
      << num_vertices(c.mesh) << " vertices, region n = " << fixed(a.values.at("n"), 0) << ", m = "
      << fixed(a.values.at("m"), 0) << ", exact policy, library defaults; medians of " << repetitions << " runs\n\n"
      << "| step | median |\n|---|--:|\n";
  line("one iteration of the class (`deform(10, 0)` − `deform(1, 0)`, over 9)", "class_iteration");
  line("one iteration of the internal solver (`solve()`, 10 − 1 solves, over 9)", "solver_iteration");
  line("shape S = HṼ (n×m by m×3, `Stored_basis::multiply`)", "step_shape");
  line("dual normals of S (`Dual_mesh_operator::update_normals`, " + fixed(a.values.at("dual_rows"), 0) + " rows)",
       "step_dual");
  line("(L̂F)ᵀ(−h n̂) (`Dual_mesh_operator::apply_transpose`: faces, then vertices)", "step_sparse");
  line("Hᵀ (…) (m×n by n×3, `Stored_basis::multiply_transpose`)", "step_project");
  line("reduced solve (m×m Cholesky, 3 right-hand sides)", "step_reduced_solve");
  line("HᵀX, Eigen", "pass_HtX");
  line("HY, Eigen", "pass_HY");
  line("HᵀX, as the solver makes it, H in double", "panel_HtX");
  line("HY, as the solver makes it, H in double", "panel_HY");
  line("HᵀX, H in float", "panel_HtX_float");
  line("HY, H in float", "panel_HY_float");
  line("one read of H (the sum of its entries: the streaming bandwidth)", "read_H");
  line("detail transfer (exact): HṼ", "transfer_shape");
  line("detail transfer: Poisson right-hand side (per face)", "transfer_rhs");
  line("detail transfer: right-hand side + Dirichlet back-substitution", "transfer_exact");
  out << "\n**Bound.** One iteration against two streaming passes over H (two reads of H): "
      << duration(iteration) << " against " << duration(passes) << ", " << fixed(iteration / passes, 2)
      << "× (target ≤ 2×). With the two passes at the streaming bandwidth an iteration would take "
      << duration(2 * a.median_of("read_H") + steps) << "; with H stored in float " << duration(in_float) << ".\n";
  return out.str();
}

} // namespace

int main(int argc, char** argv)
{
  std::string name = "armadillo_arm";
  std::string mesh_directory = SSMD_BENCHMARK_DEFAULT_MESH_DIR;
  std::string case_directory = SSMD_BENCHMARK_DEFAULT_CASE_DIR;
  std::string output;
  unsigned int level = 1;
  std::size_t m = 100;
  int repetitions = 11;
  try
  {
    for(int i = 1; i < argc; ++i)
    {
      const std::string arg = argv[i];
      if(i + 1 >= argc)
        throw std::runtime_error("usage: see the head of benchmark_iteration_anatomy.cpp");
      const std::string value = argv[++i];
      if(arg == "--case")
        name = value;
      else if(arg == "--level")
        level = static_cast<unsigned int>(std::stoul(value));
      else if(arg == "--frequencies")
        m = std::stoul(value);
      else if(arg == "--repetitions")
        repetitions = std::stoi(value);
      else if(arg == "--mesh-directory")
        mesh_directory = value;
      else if(arg == "--case-directory")
        case_directory = value;
      else if(arg == "--output")
        output = value;
      else
        throw std::runtime_error("unknown option " + arg);
    }
    if(repetitions < 1)
      throw std::runtime_error("--repetitions must be positive");

    const Deformation_case c = read_case_file(case_directory + "/" + name + ".case", mesh_directory, level);
    Mesh mesh = c.mesh;
    Deformation d(mesh);
    d.set_number_of_frequencies(m);
    d.set_constraint_policy(CGAL::EXACT_CONSTRAINTS);
    d.insert_roi_vertices(c.roi.begin(), c.roi.end());
    d.insert_control_vertices(c.handles.begin(), c.handles.end());
    if(!d.preprocess())
      throw std::runtime_error("preprocess() failed on " + c.name + ": " + d.preprocess_report().message);
    const std::vector<double> iterations = class_iterations(d, c, repetitions);
    Anatomy anatomy = measure_anatomy(d, c, repetitions);
    anatomy.samples["class_iteration"] = iterations;

    const std::string text = report(c, level, anatomy, repetitions);
    std::cout << text;
    if(!output.empty())
    {
      std::ofstream file(output);
      file << text;
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

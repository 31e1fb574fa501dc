// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_SPATIAL_DUAL_LAPLACIAN_SOLVER_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_SPATIAL_DUAL_LAPLACIAN_SOLVER_H

#include <CGAL/Spectral_deformation/Sparse_spd_solver_traits.h>
#include <CGAL/Spectral_deformation/internal/Linear_algebra/Dirichlet_system.h>
#include <CGAL/Spectral_deformation/internal/Mesh/Dual_mesh_operator.h>
#include <CGAL/Spectral_deformation/internal/Deformation/Iteration_report.h>
#include <CGAL/Spectral_deformation/internal/Mesh/Triangle_arrays.h>

#include <Eigen/Sparse>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace CGAL {
namespace Spectral_deformation {
namespace internal {
namespace Deformation {

using Linear_algebra::Dirichlet_system;
using Mesh::Dual_coordinates;
using Mesh::Dual_mesh_operator;
using Mesh::Positions;
using Mesh::Triangle_arrays;
using Mesh::connected_components;

/// Dual Laplacian editing in the spatial domain (Au et al. 2006), the
/// reference solver of the paper: least squares of [L̂F; w C] V = [l̂; w c]
/// through the normal equations, factored once per constraint set, with
/// iterations that turn every dual coordinate to the current dual normal
/// while keeping its signed rest length.
///
/// Constraints are exact (`preprocess_exact()`: the constrained vertices are
/// eliminated and land on their targets) or soft (`preprocess_soft()`: met
/// in the least-squares sense with a weight w).
template <class SparseSPDSolverTraits = Default_sparse_spd_solver_traits>
class Spatial_dual_laplacian_solver
{
public:
  typedef Eigen::Matrix<double, Eigen::Dynamic, 3> Positions;

  /// `rest` must have been validated.
  explicit Spatial_dual_laplacian_solver(const Triangle_arrays& rest)
    : m_rest(rest.positions),
      m_dual(rest.triangles, rest.number_of_vertices())
  {
    m_rest_coordinates = m_dual.evaluate(m_rest);
    m_LF = m_dual.laplacian_operator(m_rest_coordinates.weights);
    m_LF_transpose = m_LF.transpose();
    m_diagonal = (m_rest.colwise().maxCoeff() - m_rest.colwise().minCoeff()).norm();
    m_component = connected_components(rest.triangles, rest.number_of_vertices(),
                                       m_number_of_components);
  }

  /// Lets the sparse solvers change process-wide state to run faster
  /// (`SparseSPDSolverTraits::set_process_wide_tuning()`, when it has it).
  void set_process_wide_tuning(bool enabled)
  {
    m_hard_system.set_process_wide_tuning(enabled);
    Memory::set_process_wide_tuning_if_supported(m_solver, enabled);
  }

  const Dual_mesh_operator& dual_mesh() const { return m_dual; }
  const Dual_coordinates& rest_coordinates() const { return m_rest_coordinates; }
  double bounding_box_diagonal() const { return m_diagonal; }

  /// Sets the constrained vertices, which then land exactly on their
  /// targets (they are eliminated), and factors the system.
  /// Throws `Spectral_deformation_error` when a connected component has no
  /// constrained vertex, an index is out of range, or the factorization fails.
  void preprocess_exact(const std::vector<int>& constrained)
  {
    set_constrained(constrained);
    m_hard = true;
    m_weight = 0.0;
    if(!m_hard_system.factor(m_LF_transpose * m_LF, m_is_constrained))
      throw Error(Error::SOLVER_FAILURE, singular_system);
    m_factored = true;
  }

  /// Sets the constrained vertices, met in the least-squares sense with the
  /// positive `weight` (the paper's soft constraints), and factors the
  /// system. Throws as `preprocess_exact()`, and when `weight` is not
  /// positive and finite.
  void preprocess_soft(const std::vector<int>& constrained, double weight)
  {
    if(!(weight > 0 && std::isfinite(weight)))
      throw Error(Error::INVALID_ARGUMENT, "the constraint weight must be positive and finite");
    set_constrained(constrained);
    m_hard = false;
    m_weight = weight;
    Eigen::SparseMatrix<double> A = m_LF_transpose * m_LF;
    for(int i : constrained)
      A.coeffRef(i, i) += m_weight * m_weight;
    if(!m_solver.factor(A))
      throw Error(Error::SOLVER_FAILURE, singular_system);
    m_factored = true;
  }

  /// Deforms from `start` (n×3) towards the targets of the constrained
  /// vertices (k×3, in the order given to `preprocess()`): the first solve
  /// uses the rest coordinates turned to the dual normals of `start`, then at
  /// most `max_iterations` updates follow. From the rest shape with 0
  /// iterations this is the linear solution; from a previous result it
  /// continues that iteration. Stops when the RMS step
  /// falls below `tolerance` times the bounding-box diagonal. On failure
  /// (non-finite values, an RMS step above half the diagonal after the third
  /// iteration) `result` is left untouched and `Spectral_deformation_error`
  /// is thrown.
  Iteration_report solve(const Positions& targets, const Positions& start, Positions& result,
                         int max_iterations, double tolerance) const
  {
    Iteration_report report;
    if(!m_factored)
      throw Error(Error::SOLVER_FAILURE, "the solver is not preprocessed");
    if(targets.rows() != static_cast<Eigen::Index>(m_constrained.size()) || !targets.allFinite())
      throw Error(Error::INVALID_ARGUMENT, "the targets must be finite, one per constrained vertex");

    Positions current = start;
    Positions previous_normals = m_rest_coordinates.normals;
    const double scale = m_diagonal * std::sqrt(double(m_rest.rows()));
    for(int iteration = 0; iteration <= max_iterations; ++iteration)
    {
      // The rest coordinates turned to the dual normals of the current shape;
      // from the rest shape, the first solve is the linear solution.
      const Dual_coordinates now = m_dual.evaluate(current, &previous_normals);
      const Positions coordinates = (-m_rest_coordinates.heights).asDiagonal() * now.normals;
      previous_normals = now.normals;
      Positions next;
      if(!solve_once(coordinates, targets, next))
        throw Error(Error::SOLVER_FAILURE, "a back-substitution failed");
      if(!next.allFinite())
        throw Error(Error::SOLVER_FAILURE, "the iteration produced non-finite positions");
      const double step = (next - current).norm() / scale;
      current.swap(next);
      if(report.stop_after(iteration, step, tolerance))
        break;
    }
    result.swap(current);
    return report;
  }

private:
  typedef Spectral_deformation_error Error;
  static constexpr const char* singular_system =
      "the dual Laplacian system is singular: every connected part of the mesh needs a constrained vertex";

  void set_constrained(const std::vector<int>& constrained)
  {
    m_factored = false;
    const Eigen::Index n = m_rest.rows();
    if(constrained.empty())
      throw Error(Error::INVALID_ARGUMENT, "no constrained vertex");
    m_is_constrained.assign(static_cast<std::size_t>(n), 0);
    for(int i : constrained)
    {
      if(i < 0 || i >= n)
        throw Error(Error::INVALID_ARGUMENT, "constrained vertex index " + std::to_string(i) + " out of range");
      m_is_constrained[static_cast<std::size_t>(i)] = 1;
    }
    std::vector<char> component_constrained(static_cast<std::size_t>(m_number_of_components), 0);
    for(int i : constrained)
      component_constrained[static_cast<std::size_t>(m_component[static_cast<std::size_t>(i)])] = 1;
    for(int c = 0; c < m_number_of_components; ++c)
      if(!component_constrained[static_cast<std::size_t>(c)])
        throw Error(Error::INVALID_ARGUMENT, "connected component " + std::to_string(c) +
                                                 " has no constrained vertex: its position would be undetermined");
    m_constrained = constrained;
  }

  bool solve_once(const Positions& coordinates, const Positions& targets, Positions& out) const
  {
    const Eigen::Index n = m_rest.rows();
    const Eigen::MatrixXd rhs_all = m_LF_transpose * coordinates;
    out.resize(n, 3);
    if(m_hard)
    {
      Eigen::MatrixXd prescribed(n, 3);
      for(std::size_t k = 0; k < m_constrained.size(); ++k)
        prescribed.row(m_constrained[k]) = targets.row(static_cast<Eigen::Index>(k));
      Eigen::MatrixXd x;
      if(!m_hard_system.solve(rhs_all, prescribed, x))
        return false;
      out = x;
      return true;
    }
    Eigen::MatrixXd rhs = rhs_all;
    for(std::size_t k = 0; k < m_constrained.size(); ++k)
      rhs.row(m_constrained[k]) += m_weight * m_weight * targets.row(static_cast<Eigen::Index>(k));
    Eigen::MatrixXd x;
    if(!m_solver.solve(rhs, x))
      return false;
    out = x;
    return true;
  }

  Positions m_rest;
  Dual_mesh_operator m_dual;
  Dual_coordinates m_rest_coordinates;
  Eigen::SparseMatrix<double> m_LF;
  Eigen::SparseMatrix<double> m_LF_transpose;
  double m_diagonal = 0;
  std::vector<int> m_component;
  int m_number_of_components = 0;

  std::vector<int> m_constrained;
  std::vector<char> m_is_constrained;
  Dirichlet_system<SparseSPDSolverTraits> m_hard_system;
  bool m_hard = true;
  double m_weight = 0;
  bool m_factored = false;
  SparseSPDSolverTraits m_solver;
};

} // namespace Deformation
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_SPATIAL_DUAL_LAPLACIAN_SOLVER_H

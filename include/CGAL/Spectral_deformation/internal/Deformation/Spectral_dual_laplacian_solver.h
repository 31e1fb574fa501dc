// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_SPECTRAL_DUAL_LAPLACIAN_SOLVER_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_SPECTRAL_DUAL_LAPLACIAN_SOLVER_H

#include <CGAL/Spectral_deformation/Deformation_options.h>
#include <CGAL/Spectral_deformation/cotangent_operators.h>
#include <CGAL/Spectral_deformation/internal/Deformation/Clustered_rotations.h>
#include <CGAL/Spectral_deformation/internal/Deformation/Face_patches.h>
#include <CGAL/Spectral_deformation/internal/Deformation/Rotated_edges.h>
#include <CGAL/Spectral_deformation/internal/Linear_algebra/Dense_products.h>
#include <CGAL/Spectral_deformation/internal/Linear_algebra/Operators_in_basis.h>
#include <CGAL/Spectral_deformation/internal/Linear_algebra/Stored_basis.h>
#include <CGAL/Spectral_deformation/internal/Mesh/Dual_mesh_operator.h>
#include <CGAL/Spectral_deformation/internal/Deformation/Iteration_report.h>
#include <CGAL/Spectral_deformation/internal/Mesh/Triangle_arrays.h>

#include <Eigen/Cholesky>
#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <cmath>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Spectral_deformation {
namespace internal {
namespace Deformation {

using Linear_algebra::Stored_basis;
using Mesh::Dual_coordinates;
using Mesh::Dual_mesh_operator;
using Mesh::Positions;
using Mesh::Triangle_arrays;

/// Dual Laplacian editing in the space of a manifold harmonics basis (the
/// paper, eq. 6-7): positions S = H Ṽ, least squares of
/// [L̂F H; w H_c] Ṽ = [l̂; w c] with the normal matrix
/// Ã = G₀ + w² H_cᵀ H_c, G₀ = Hᵀ (L̂F)ᵀ L̂F H precomputed per mesh. Weights and
/// signed heights of the dual coordinates are those of the smooth rest mesh
/// S₀ = H Hᵀ M V, so that the residual at rest is zero.
///
/// With `ARAP_ENERGY`, the same iteration minimizes instead the
/// as-rigid-as-possible energy of the smooth mesh,
/// Σ_ij w_ij ‖(S_i − S_j) − R_i(S₀_i − S₀_j)‖², plus the constraints:
/// G₀ = Hᵀ Q H (Q the cotangent stiffness of the region) and the
/// coordinates' part of the right-hand side is Hᵀ b(R), b the right-hand
/// side of the global step of as-rigid-as-possible deformation with the
/// rotations of the one-rings of the current smooth shape
/// (`Rotated_edges`). At rest b = Q S₀, so the residual at rest is zero too.
/// `DUAL_LAPLACIAN_AND_ARAP_ENERGY` adds the two systems, the ARAP one
/// scaled so that both matrices have the same trace.
class Spectral_dual_laplacian_solver
{
public:
  typedef Eigen::Matrix<double, Eigen::Dynamic, 3> Positions;

  /// `basis` n×m M-orthonormal, `mass` its lumped mass, `positions` the rest
  /// positions (n×3), `triangles` the faces. The solver reads `basis`, which
  /// must outlive it and stay unchanged.
  void initialize(const Stored_basis& basis, const Eigen::VectorXd& mass,
                  const Triangle_arrays& rest)
  {
    initialize(basis, mass, rest, nullptr);
  }

  /// As above, with `stiffness` the cotangent stiffness of `rest`
  /// (`cotangent_stiffness()`), already computed by the caller.
  void initialize(const Stored_basis& basis, const Eigen::VectorXd& mass, const Triangle_arrays& rest,
                  const Eigen::SparseMatrix<double>& stiffness)
  {
    initialize(basis, mass, rest, &stiffness);
  }

private:
  void initialize(const Stored_basis& basis, const Eigen::VectorXd& mass, const Triangle_arrays& rest,
                  const Eigen::SparseMatrix<double>* stiffness)
  {
    m_basis = &basis;
    m_mass = mass;
    m_dual = Dual_mesh_operator(rest.triangles, rest.number_of_vertices());
    basis.visit([this, &mass, &rest](const auto& H) {
      if constexpr(std::is_same<typename std::decay_t<decltype(H)>::Scalar, double>::value)
      {
        m_rest_coefficients = H.transpose() * (mass.asDiagonal() * rest.positions);
        m_smooth_rest = H * m_rest_coefficients;
      }
      else
      {
        m_basis->multiply_transpose(Positions(mass.asDiagonal() * rest.positions), m_rest_coefficients);
        m_basis->multiply(m_rest_coefficients, m_smooth_rest);
      }
    });
    release_rest_coordinates(); // those of an earlier mesh or smooth rest shape
    if(uses_dual_energy())
    {
      make_rest_coordinates();
      const Dual_coordinates& rest_coordinates = m_rest_coordinates;
      basis.visit([this, &rest_coordinates](const auto& H) {
        Linear_algebra::gram_in_basis(
            m_dual.number_of_rows(),
            [this, &rest_coordinates](Eigen::Index r, const auto* h) {
              return m_dual.apply_row(rest_coordinates.weights, r, h);
            },
            H, m_G0);
      });
    }
    else
      m_G0.setZero(basis.cols(), basis.cols());
    m_arap_scale = 1;
    if(uses_arap_energy())
    {
      Eigen::SparseMatrix<double> computed;
      if(stiffness == nullptr)
      {
        computed = cotangent_stiffness(rest);
        stiffness = &computed;
      }
      const Eigen::SparseMatrix<double>& Q = *stiffness;
      m_rotated_edges.initialize(Smooth_rotation_field::make_shared(Q, m_smooth_rest), nullptr);
      Eigen::MatrixXd arap;
      basis.visit([&Q, &arap](const auto& H) { Linear_algebra::sparse_in_basis(Q, H, arap); });
      // The sum weighs the two energies alike: its two matrices get the same
      // trace (their ratio depends on the resolution of the mesh).
      if(uses_dual_energy() && arap.trace() > 0)
        m_arap_scale = m_G0.trace() / arap.trace();
      m_G0 += m_arap_scale * arap;
    }
    else
      m_rotated_edges = Rotated_edges();
    m_G0 = 0.5 * (m_G0 + m_G0.transpose()).eval();
    m_scale = std::sqrt(mass.sum()) *
              (rest.positions.colwise().maxCoeff() - rest.positions.colwise().minCoeff()).norm();
    m_factored = false;
    build_patches();
  }

public:

  /// The energy the iteration minimizes (default `DUAL_LAPLACIAN_ENERGY`).
  Spectral_smooth_energy smooth_energy() const { return m_energy; }
  /// Sets smooth_energy(); takes effect at the next `initialize()`.
  void set_smooth_energy(Spectral_smooth_energy energy) { m_energy = energy; }

  /// The number of rotation patches of the iteration; 0 (the default) turns
  /// every dual vertex by its own rotation, the full iteration.
  std::size_t rotation_patches() const { return m_patch_count; }
  /// Sets rotation_patches(); an initialized solver groups its dual vertices
  /// again (the basis and the factorization are kept).
  void set_rotation_patches(std::size_t count)
  {
    if(count == m_patch_count)
      return;
    m_patch_count = count;
    if(m_basis != nullptr)
      build_patches();
  }

  const Positions& smooth_rest() const { return m_smooth_rest; }
  /// The rotation field of the ARAP energy, fitted on the one-rings of
  /// `smooth_rest()` with the stiffness of `initialize()`, for the detail
  /// transfer to share (null when the energy has no ARAP term).
  std::shared_ptr<const Smooth_rotation_field> shared_rotation_field() const
  {
    return uses_arap_energy() ? m_rotated_edges.shared_rotation_field() : nullptr;
  }
  /// The smooth shape H `coefficients` (n×3).
  Positions shape(const Eigen::MatrixXd& coefficients) const
  {
    Positions result;
    multiply(coefficients, result);
    return result;
  }
  /// As `shape()`, into `result`, whose storage is reused.
  void shape(const Eigen::MatrixXd& coefficients, Positions& result) const { multiply(coefficients, result); }
  /// As `shape()`, transposed (one column per vertex), into `result`, whose
  /// storage is reused.
  void shape(const Eigen::MatrixXd& coefficients, Linear_algebra::row_blocks::Rows3& result) const
  {
    multiply(coefficients, result);
  }
  const Eigen::MatrixXd& rest_coefficients() const { return m_rest_coefficients; }
  /// H_c: the rows of the basis of the constrained vertices of `preprocess()`.
  const Eigen::MatrixXd& constrained_rows() const { return m_constrained_rows; }
  const Dual_mesh_operator& dual_mesh() const { return m_dual; }

  /// Factors Ã for the constrained vertices. Returns false when Ã is not
  /// positive definite.
  bool preprocess(const std::vector<int>& constrained, double weight)
  {
    m_constrained = constrained;
    m_weight = weight;
    m_constrained_rows.resize(static_cast<Eigen::Index>(constrained.size()), m_basis->cols());
    m_basis->visit([this, &constrained](const auto& H) {
      for(std::size_t k = 0; k < constrained.size(); ++k)
        m_constrained_rows.row(static_cast<Eigen::Index>(k)) = H.row(constrained[k]).template cast<double>();
    });
    Eigen::MatrixXd A = m_G0;
    A.selfadjointView<Eigen::Lower>().rankUpdate(m_constrained_rows.transpose(), weight * weight);
    A.triangularView<Eigen::StrictlyUpper>() = A.transpose();
    m_regularization = 0;
    m_cholesky.compute(A);
    if(m_cholesky.info() != Eigen::Success || !clearly_definite(m_cholesky))
    {
      // A constraint set can leave directions free (a tube held by one ring
      // may stretch along its axis at no cost): a tiny Tikhonov term, towards
      // the current shape in solve(), makes Ã definite and picks the solution
      // that moves least in those directions. Rounding can let the
      // factorization of such a singular Ã succeed with pivots at the level
      // of rounding errors, whose solution is then made of rounding errors:
      // that counts as singular too.
      m_regularization = 1e-10 * A.trace() / double(A.rows());
      A.diagonal().array() += m_regularization;
      m_cholesky.compute(A);
    }
    m_factored = (m_cholesky.info() == Eigen::Success);
    return m_factored;
  }

  // Whether every pivot of the factor is above the rounding errors of the
  // largest one.
  static bool clearly_definite(const Eigen::LLT<Eigen::MatrixXd>& cholesky)
  {
    const Eigen::ArrayXd pivots = cholesky.matrixLLT().diagonal().array().square();
    return pivots.size() == 0 || pivots.minCoeff() > 1e-12 * pivots.maxCoeff();
  }

  /// Iterates from the coefficients `coefficients` (m×3, in/out) towards the
  /// smooth targets (k×3) of the constrained vertices: at most
  /// 1 + max_iterations solves, each with the rest coordinates turned to the
  /// dual normals of the current smooth shape. Stops when the M-norm of the
  /// step, relative to √area × bounding-box diagonal, is below `tolerance`.
  /// On failure `coefficients` is left untouched and
  /// `Spectral_deformation_error` is thrown.
  Iteration_report solve(const Positions& smooth_targets, Eigen::MatrixXd& coefficients,
                         int max_iterations, double tolerance) const
  {
    return solve_with_constraint_products(m_constrained_rows.transpose() * smooth_targets, coefficients,
                                          max_iterations, tolerance);
  }

  /// As `solve()`, given the products H_cᵀ y (m×3) of the constrained rows
  /// of the basis and the smooth targets (see `Constraint_products`).
  Iteration_report solve_with_constraint_products(const Eigen::MatrixXd& constraint_products,
                                                  Eigen::MatrixXd& coefficients, int max_iterations,
                                                  double tolerance) const
  {
    typedef Spectral_deformation_error Error;
    Iteration_report report;
    if(!m_factored)
      throw Error(Error::SOLVER_FAILURE, "the spectral solver is not preprocessed");
    const Eigen::MatrixXd constraint_rhs = m_weight * m_weight * constraint_products;
    Eigen::MatrixXd current = coefficients;
    if(uses_patches())
    {
      iterate_with_patches(constraint_rhs, current, max_iterations, tolerance, report);
      coefficients = current;
      return report;
    }
    Workspace& w = m_workspace;
    multiply(current, w.shape);
    if(uses_dual_energy())
      w.normals = m_rest_coordinates.normals;
    for(int iteration = 0; iteration <= max_iterations; ++iteration)
    {
      if(uses_dual_energy())
      {
        // The rest coordinates turned to the dual normals of the current
        // shape, l̂ = -h n̂, brought back to the reduced space: Hᵀ (L̂F)ᵀ l̂.
        m_dual.update_normals(w.shape, w.centroids, w.normals);
        m_dual.apply_transpose(m_rest_coordinates.weights, m_negative_heights, w.normals, w.faces,
                               w.vertices);
        multiply_transpose(w.vertices, w.rhs);
      }
      if(uses_arap_energy())
      {
        // The rest edges of the smooth mesh turned by the rotations of its
        // current one-rings, brought back to the reduced space: Hᵀ b(R).
        if(uses_dual_energy())
        {
          multiply_transpose(m_rotated_edges.evaluate(w.shape), w.arap_rhs);
          w.rhs += m_arap_scale * w.arap_rhs;
        }
        else
          multiply_transpose(m_rotated_edges.evaluate(w.shape), w.rhs);
      }
      if(take_step(w.rhs, constraint_rhs, current, iteration, tolerance, report))
        break;
      if(iteration < max_iterations)
        multiply(current, w.shape);
    }
    coefficients = current;
    return report;
  }

  /// The coefficients (m×3) of the smooth field that meets `residuals` (k×3,
  /// one row per constrained vertex of `preprocess()`) as the reduced system
  /// meets its targets: the least squares solution of
  /// [L̂F H; w H_c] α = [0; w residuals], with the factorization of Ã.
  Eigen::MatrixXd fit_constraints(const Positions& residuals) const
  {
    return m_cholesky.solve(m_weight * m_weight * (m_constrained_rows.transpose() * residuals));
  }

private:
  // The patches pay off only when each groups several dual vertices: a
  // patch iteration costs O(m) per patch and a full one O(m) per vertex with
  // smaller constants. Measured per drag (10 iterations, m = 100, 1000
  // patches): 4 ms against 2 ms for the full iteration on a region of 550
  // vertices (1.1 faces per patch), 7-10 ms against 14-16 ms on one of 3,400
  // vertices (6.8 faces per patch). Below this many faces per patch the
  // region is iterated in full, which is also the more accurate iteration.
  static constexpr Eigen::Index minimum_faces_per_patch = 4;

  bool uses_patches() const
  {
    return m_patch_count > 0 &&
           m_dual.number_of_faces() >= minimum_faces_per_patch * static_cast<Eigen::Index>(m_patch_count);
  }

  // The dual Laplacian coordinates of the smooth rest mesh, per dual vertex
  // (as many as the faces of the region), are read by the full iteration
  // and to make the patches, not by the patched iteration: the patches
  // release them, and they are made again, the same, when the full
  // iteration or new patches need them.
  void make_rest_coordinates()
  {
    // Made anew unless whole (a throw while patches were made can leave them in part).
    if(!uses_dual_energy() || (m_negative_heights.size() != 0 && m_rest_coordinates.normals.rows() != 0))
      return;
    m_rest_coordinates = m_dual.evaluate(m_smooth_rest);
    m_negative_heights = -m_rest_coordinates.heights;
    m_rest_coordinates.heights = Eigen::VectorXd(); // read as m_negative_heights
  }

  void release_rest_coordinates()
  {
    m_rest_coordinates = Dual_coordinates();
    m_negative_heights = Eigen::VectorXd();
  }

  void build_patches()
  {
    m_patches = Clustered_rotation_rhs();
    m_arap_patches = Clustered_rotation_rhs();
    make_rest_coordinates();
    if(!uses_patches())
      return;
    m_rest_coordinates.normals = Positions(); // the patches read the weights and the coordinates
    // Both groupings come from one grouping of the faces, whose centroids
    // are freed before the products are made.
    std::vector<int> patch_of_vertex, patch_of_row;
    {
      const Positions centroids = m_dual.centroids(m_smooth_rest);
      const Face_patches face_patches(m_dual, centroids, m_patch_count);
      if(uses_arap_energy())
        patch_of_vertex = cluster_vertices(face_patches, m_smooth_rest.rows());
      if(uses_dual_energy())
        patch_of_row = cluster_dual_rows(face_patches);
    }
    if(uses_arap_energy())
      m_basis->visit([this, &patch_of_vertex](const auto& H) {
        m_arap_patches.initialize_arap(H, m_rotated_edges.rotation_field().adjacency(), m_smooth_rest,
                                       patch_of_vertex);
      });
    std::vector<int>().swap(patch_of_vertex);
    if(uses_dual_energy())
      m_basis->visit([this, &patch_of_row](const auto& H) {
        m_patches.initialize(H, m_dual, m_rest_coordinates.weights, m_rest_coordinates.coordinates,
                             m_smooth_rest, patch_of_row);
      });
    release_rest_coordinates();
  }

  // The iteration of solve() with the rotations of the patches: no step
  // reads the n×m basis.
  void iterate_with_patches(const Eigen::MatrixXd& constraint_rhs, Eigen::MatrixXd& current,
                            int max_iterations, double tolerance, Iteration_report& report) const
  {
    Eigen::MatrixXd rhs, arap_rhs;
    for(int iteration = 0; iteration <= max_iterations; ++iteration)
    {
      if(!uses_dual_energy())
        m_arap_patches.evaluate(current, rhs);
      else
      {
        m_patches.evaluate(current, rhs);
        if(uses_arap_energy())
        {
          m_arap_patches.evaluate(current, arap_rhs);
          rhs += m_arap_scale * arap_rhs;
        }
      }
      if(take_step(rhs, constraint_rhs, current, iteration, tolerance, report))
        break;
    }
  }

  // One solve of the iteration from the coordinates' part `rhs` of the
  // right-hand side: `current` becomes the solution; returns whether the
  // iteration stops there.
  bool take_step(Eigen::MatrixXd& rhs, const Eigen::MatrixXd& constraint_rhs, Eigen::MatrixXd& current,
                 int iteration, double tolerance, Iteration_report& report) const
  {
    typedef Spectral_deformation_error Error;
    rhs += constraint_rhs + m_regularization * current;
    const Eigen::MatrixXd next = m_cholesky.solve(rhs);
    if(!next.allFinite())
      throw Error(Error::SOLVER_FAILURE, "the iteration produced non-finite values");
    const double step = (next - current).norm() / m_scale;
    current = next;
    return report.stop_after(iteration, step, tolerance);
  }

  template <typename Shape>
  void multiply(const Eigen::MatrixXd& coefficients, Shape& shape) const
  {
    m_basis->multiply(coefficients, shape);
  }

  template <class Values>
  void multiply_transpose(const Values& values, Eigen::MatrixXd& result) const
  {
    m_basis->multiply_transpose(values, result);
  }

  // Buffers of the iteration, kept between calls: the first touch of fresh
  // pages costs more than the arithmetic on them.
  struct Workspace
  {
    Positions shape, centroids, normals, faces, vertices;
    Eigen::MatrixXd rhs, arap_rhs;
  };

  bool uses_dual_energy() const { return m_energy != ARAP_ENERGY; }
  bool uses_arap_energy() const { return m_energy != DUAL_LAPLACIAN_ENERGY; }

  const Stored_basis* m_basis = nullptr;

  Eigen::VectorXd m_mass;
  Dual_mesh_operator m_dual;
  Eigen::MatrixXd m_rest_coefficients;
  Positions m_smooth_rest;
  Spectral_smooth_energy m_energy = DUAL_LAPLACIAN_ENERGY;
  Rotated_edges m_rotated_edges;       // the ARAP energy
  double m_arap_scale = 1;             // its weight in the sum
  Dual_coordinates m_rest_coordinates; // the dual Laplacian energy
  Eigen::VectorXd m_negative_heights;
  Eigen::MatrixXd m_G0;
  double m_scale = 1;

  std::vector<int> m_constrained;
  Eigen::MatrixXd m_constrained_rows;
  double m_weight = 1;
  double m_regularization = 0;
  Eigen::LLT<Eigen::MatrixXd> m_cholesky;
  bool m_factored = false;
  mutable Workspace m_workspace;
  std::size_t m_patch_count = 0;
  Clustered_rotation_rhs m_patches, m_arap_patches;
};

} // namespace Deformation
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_SPECTRAL_DUAL_LAPLACIAN_SOLVER_H

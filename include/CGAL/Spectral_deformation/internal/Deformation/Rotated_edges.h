// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_ROTATED_EDGES_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_ROTATED_EDGES_H

#include <CGAL/Spectral_deformation/internal/available_threads.h>
#include <CGAL/Spectral_deformation/internal/Deformation/Smooth_rotation_field.h>
#include <CGAL/Spectral_deformation/internal/Mesh/Triangle_arrays.h>

#include <CGAL/assertions.h>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <cstddef>
#include <memory>
#include <vector>

namespace CGAL {
namespace Spectral_deformation {
namespace internal {
namespace Deformation {

using Mesh::Positions;

/// The right-hand side of the global step of as-rigid-as-possible
/// deformation, b_i = Σ_j w_ij ½(R_i + R_j)(v_i − v_j), with the rotations
/// R of a `Smooth_rotation_field` (fitted on the one-rings of a smooth mesh)
/// and the rest edges v_i − v_j of a mesh of the same connectivity: the
/// detailed mesh in the detail transfer, the smooth mesh itself in the
/// as-rigid-as-possible iteration of the reduced space. Identity rotations
/// give Q v, Q the cotangent stiffness.
class Rotated_edges
{
public:
  /// `stiffness` the cotangent stiffness of the mesh (its weights weigh the
  /// edges), `edge_rest` the positions whose edges are turned,
  /// `rotation_rest` the smooth rest positions the rotations are fitted from.
  void initialize(const Eigen::SparseMatrix<double>& stiffness, const Positions& edge_rest,
                  const Positions& rotation_rest)
  {
    initialize(Smooth_rotation_field::make_shared(stiffness, rotation_rest), &edge_rest);
  }

  /// With the rotations of `rotations`, shared (by the detail transfer and
  /// the iteration of the reduced space, which fit them on the same smooth
  /// mesh: on large regions its adjacency is among the largest arrays of a
  /// deformation), and the rest edges of `edge_rest`, or those of the
  /// smooth rest mesh of `rotations` when `edge_rest` is null. The field's
  /// `compute()` uses buffers of its own: the `Rotated_edges` that share a
  /// field must not evaluate at the same time.
  void initialize(std::shared_ptr<const Smooth_rotation_field> rotations, const Positions* edge_rest)
  {
    CGAL_precondition(rotations != nullptr);
    m_rotations = std::move(rotations);
    // The weighted rest edges ½ w_ij (v_i − v_j) are formed at each
    // evaluation from the positions, one vertex per cache line, rather than
    // stored per edge (six times the memory, and as long to stream).
    if(edge_rest != nullptr)
      m_edge_rest_vertex_major = edge_rest->transpose();
    else
      m_edge_rest_vertex_major.resize(3, 0);
  }

  const Smooth_rotation_field& rotation_field() const
  {
    CGAL_precondition(m_rotations != nullptr);
    return *m_rotations;
  }
  /// The field, to be shared by another `Rotated_edges` (null before `initialize()`).
  const std::shared_ptr<const Smooth_rotation_field>& shared_rotation_field() const { return m_rotations; }

  /// b for the rotations that carry the smooth rest mesh to `smooth_deformed`
  /// (n×3, valid until the next call).
  const Eigen::MatrixXd& evaluate(const Positions& smooth_deformed) const
  {
    CGAL_precondition(m_rotations != nullptr);
    m_rotations->compute(smooth_deformed, m_rotation_workspace);
    return evaluate_with_rotations();
  }

  /// As above, with the positions one column per vertex.
  const Eigen::MatrixXd& evaluate(const Smooth_rotation_field::Vertex_major_positions& smooth_deformed) const
  {
    CGAL_precondition(m_rotations != nullptr);
    m_rotations->compute(smooth_deformed, m_rotation_workspace);
    return evaluate_with_rotations();
  }

private:
  const Eigen::MatrixXd& evaluate_with_rotations() const
  {
    const std::vector<Eigen::Matrix3d>& R = m_rotation_workspace;
    const Cotangent_adjacency& a = m_rotations->adjacency();
    const Smooth_rotation_field::Vertex_major_positions& v = edge_rest();
    const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(v.cols());
    Eigen::MatrixXd& rhs = m_right_hand_side;
    rhs.resize(n, 3);
#ifdef _OPENMP
#pragma omp parallel for schedule(static) if(n > parallel_loop_items)
#endif
    for(std::ptrdiff_t i = 0; i < n; ++i)
    {
      // Σ_j ½ w_ij R_i (v_i − v_j) = R_i Σ_j ½ w_ij (v_i − v_j): the half that
      // turns with the vertex's own rotation is one product; the other half
      // turns with each neighbour's rotation.
      const int begin = a.start[static_cast<std::size_t>(i)], end = a.start[static_cast<std::size_t>(i) + 1];
      const Eigen::Vector3d vi = v.col(i);
      Eigen::Vector3d own_half = Eigen::Vector3d::Zero();
      for(int s = begin; s < end; ++s)
        own_half += half_edge(a, v, s, vi);
      Eigen::Vector3d sum = R[static_cast<std::size_t>(i)] * own_half;
      for(int s = begin; s < end; ++s)
        sum.noalias() += R[static_cast<std::size_t>(a.neighbours[static_cast<std::size_t>(s)])] * half_edge(a, v, s, vi);
      rhs.row(i) = sum.transpose();
    }
    return rhs;
  }

  // ½ w_ij (v_i − v_j) for the edge s of the adjacency, j its neighbour.
  static Eigen::Vector3d half_edge(const Cotangent_adjacency& a, const Smooth_rotation_field::Vertex_major_positions& v,
                                   int s, const Eigen::Vector3d& vi)
  {
    return (0.5 * a.weights[static_cast<std::size_t>(s)]) * (vi - v.col(a.neighbours[static_cast<std::size_t>(s)]));
  }

  // v: the rest positions whose edges are turned.
  const Smooth_rotation_field::Vertex_major_positions& edge_rest() const
  {
    return m_edge_rest_vertex_major.cols() != 0 ? m_edge_rest_vertex_major : m_rotations->rest_vertex_major();
  }

  std::shared_ptr<const Smooth_rotation_field> m_rotations;
  Smooth_rotation_field::Vertex_major_positions m_edge_rest_vertex_major; // v, when not the smooth rest
  // Buffers of an evaluation, kept between calls: on large meshes, fresh
  // pages for them cost more than the arithmetic.
  mutable std::vector<Eigen::Matrix3d> m_rotation_workspace;
  mutable Eigen::MatrixXd m_right_hand_side;
};

} // namespace Deformation
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_ROTATED_EDGES_H

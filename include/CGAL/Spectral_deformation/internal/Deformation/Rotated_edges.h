// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_ROTATED_EDGES_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_ROTATED_EDGES_H

#include <CGAL/Spectral_deformation/internal/Deformation/Smooth_rotation_field.h>
#include <CGAL/Spectral_deformation/internal/Mesh/Triangle_arrays.h>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <cstddef>
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
    m_rotations.initialize(stiffness, rotation_rest);
    // Σ_j w_ij ½ R_i (v_i − v_j) = R_i b_i: the half of the right-hand side
    // that turns with the vertex's own rotation is one product per vertex.
    // The other half turns with the neighbour's rotation: the weighted rest
    // edges ½ w_ij (v_i − v_j) are stored in the order of the adjacency.
    const Cotangent_adjacency& a = m_rotations.adjacency();
    const Eigen::Index n = edge_rest.rows();
    m_own_half.setZero(3, n);
    m_half_edges.resize(3, static_cast<Eigen::Index>(a.neighbours.size()));
    for(Eigen::Index i = 0; i < n; ++i)
      for(int s = a.start[static_cast<std::size_t>(i)]; s < a.start[static_cast<std::size_t>(i) + 1]; ++s)
      {
        m_half_edges.col(s) = (0.5 * a.weights[static_cast<std::size_t>(s)]) *
                              (edge_rest.row(i) - edge_rest.row(a.neighbours[static_cast<std::size_t>(s)])).transpose();
        m_own_half.col(i) += m_half_edges.col(s);
      }
  }

  const Smooth_rotation_field& rotation_field() const { return m_rotations; }

  /// b for the rotations that carry the smooth rest mesh to `smooth_deformed`
  /// (n×3, valid until the next call).
  const Eigen::MatrixXd& evaluate(const Positions& smooth_deformed) const
  {
    m_rotations.compute(smooth_deformed, m_rotation_workspace);
    const std::vector<Eigen::Matrix3d>& R = m_rotation_workspace;
    const Cotangent_adjacency& a = m_rotations.adjacency();
    const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(m_own_half.cols());
    Eigen::MatrixXd& rhs = m_right_hand_side;
    rhs.resize(n, 3);
#ifdef _OPENMP
#pragma omp parallel for schedule(static) if(n > 20000)
#endif
    for(std::ptrdiff_t i = 0; i < n; ++i)
    {
      Eigen::Vector3d sum = R[static_cast<std::size_t>(i)] * m_own_half.col(i);
      for(int s = a.start[static_cast<std::size_t>(i)]; s < a.start[static_cast<std::size_t>(i) + 1]; ++s)
        sum.noalias() += R[static_cast<std::size_t>(a.neighbours[static_cast<std::size_t>(s)])] * m_half_edges.col(s);
      rhs.row(i) = sum.transpose();
    }
    return rhs;
  }

private:
  Smooth_rotation_field m_rotations;
  // Per vertex Σ_j ½ w_ij (v_i − v_j), per edge of the adjacency ½ w_ij (v_i − v_j).
  Eigen::Matrix<double, 3, Eigen::Dynamic> m_own_half, m_half_edges;
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

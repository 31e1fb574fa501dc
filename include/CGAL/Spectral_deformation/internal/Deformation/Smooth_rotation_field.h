// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_SMOOTH_ROTATION_FIELD_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_SMOOTH_ROTATION_FIELD_H

#include <CGAL/Spectral_deformation/internal/available_threads.h>
#include <CGAL/Spectral_deformation/internal/Mesh/Triangle_arrays.h>

#include <CGAL/Spectral_deformation/internal/Deformation/rigid_fit.h>

#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <Eigen/SparseCore>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <deque>
#include <memory>
#include <utility>
#include <vector>

namespace CGAL {
namespace Spectral_deformation {
namespace internal {
namespace Deformation {

using Mesh::Positions;

/// The edges of a triangle mesh around each vertex, with their cotangent
/// weights w_ij = ½(cot α_ij + cot β_ij), read off the cotangent stiffness
/// matrix (its off-diagonal, negated), in compressed rows: the neighbours of
/// vertex i are `neighbours[start[i] .. start[i + 1])`.
struct Cotangent_adjacency
{
  std::vector<int> start;
  std::vector<int> neighbours;
  std::vector<double> weights;

  /// `stiffness` the cotangent stiffness matrix of the mesh (`cotangent_stiffness()`).
  void initialize(const Eigen::SparseMatrix<double>& stiffness)
  {
    start.assign(1, 0);
    neighbours.clear();
    weights.clear();
    neighbours.reserve(static_cast<std::size_t>(stiffness.nonZeros()));
    weights.reserve(static_cast<std::size_t>(stiffness.nonZeros()));
    for(Eigen::Index i = 0; i < stiffness.outerSize(); ++i)
    {
      for(Eigen::SparseMatrix<double>::InnerIterator entry(stiffness, i); entry; ++entry)
        if(entry.row() != i)
        {
          neighbours.push_back(static_cast<int>(entry.row()));
          weights.push_back(-entry.value());
        }
      start.push_back(static_cast<int>(neighbours.size()));
    }
  }

  std::size_t number_of_vertices() const { return start.empty() ? 0 : start.size() - 1; }
};

/// The local rotations of a deformation of a smooth mesh, one per vertex:
/// R_i maximizes Σ_j |w_ij| (s'_j − s'_i)ᵀ R (s_j − s_i) over the edges ij of
/// the one-ring of i (the local step of as-rigid-as-possible fitting), with
/// s the smooth rest and s' the smooth deformed positions.
///
/// A band-limited smooth mesh squeezes features narrower than its shortest
/// wavelength (spikes, claws, thin tails) into near-curves. There the rest
/// moment A_i = Σ_j |w_ij| (s_j − s_i)(s_j − s_i)ᵀ has numerical rank one,
/// and the rotation about the curve is not determined by the one-ring: fitted
/// alone, it follows round-off and crumples the details. Such a vertex
/// (second eigenvalue of A_i below `rank_two_ratio` times the first) takes
/// from its one-ring only the direction of the feature: with a the principal
/// axis of A_i and u = C_i a its image under the one-ring's covariance C_i,
/// R_i maximizes uᵀ R a + ‖u‖ tr(Rᵀ R̄), R̄ the mean rotation of its
/// neighbours that are closer to a well-determined vertex, in breadth-first
/// order. The rotation of the base of a thin feature carries on into it, the
/// feature's own direction bends it, and what the squeezed one-rings say
/// about the turn around the feature, round-off, is left out: it would
/// otherwise add up over the layers, whose number grows with the resolution.
/// Well-determined vertices are not changed. The order, the neighbours and
/// the axes are fixed per rest shape.
class Smooth_rotation_field
{
public:
  /// Positions one column per vertex.
  typedef Eigen::Matrix<double, 3, Eigen::Dynamic> Vertex_major_positions;

  /// The conditioning below which a one-ring does not determine a rotation:
  /// a squared ratio of the second to the first principal extent of the
  /// smooth one-ring (0.01: extents in a ratio below 1 : 10).
  static constexpr double rank_two_ratio = 1e-2;

  /// A field initialized with `initialize(stiffness, smooth_rest)`, to be
  /// shared by the `Rotated_edges` that turn edges with it.
  static std::shared_ptr<const Smooth_rotation_field> make_shared(const Eigen::SparseMatrix<double>& stiffness,
                                                                  const Positions& smooth_rest)
  {
    auto field = std::make_shared<Smooth_rotation_field>();
    field->initialize(stiffness, smooth_rest);
    return field;
  }

  /// `stiffness` the cotangent stiffness matrix of the detailed mesh, whose
  /// weights weigh the edges; `smooth_rest` the rest positions of the smooth
  /// mesh (same connectivity).
  void initialize(const Eigen::SparseMatrix<double>& stiffness, const Positions& smooth_rest)
  {
    m_adjacency.initialize(stiffness);
    const Eigen::Index n = smooth_rest.rows();
    // A vertex's three coordinates in one cache line: the rest edges are
    // formed from them at each evaluation rather than stored per edge, which
    // would take six times the memory and as long to stream.
    m_rest_vertex_major = smooth_rest.transpose();
    std::vector<Eigen::Matrix3d> moments;
    accumulate(smooth_rest, moments);
    std::vector<char> determined(static_cast<std::size_t>(n), 0);
    for(Eigen::Index i = 0; i < n; ++i)
    {
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen;
      eigen.computeDirect(moments[static_cast<std::size_t>(i)], Eigen::EigenvaluesOnly);
      const Eigen::Vector3d lambda = eigen.eigenvalues(); // ascending
      determined[static_cast<std::size_t>(i)] = (lambda[1] > rank_two_ratio * lambda[2]) ? 1 : 0;
    }
    order_undetermined(determined);
    // The direction of the feature at each inheriting vertex: the principal
    // axis of its rest moment (any unit vector where the one-ring is a point).
    m_axes.resize(3, static_cast<Eigen::Index>(m_order.size()));
    for(std::size_t k = 0; k < m_order.size(); ++k)
    {
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen;
      eigen.computeDirect(moments[static_cast<std::size_t>(m_order[k])], Eigen::ComputeEigenvectors);
      const Eigen::Vector3d axis = eigen.eigenvectors().col(2);
      m_axes.col(static_cast<Eigen::Index>(k)) = axis.allFinite() ? axis : Eigen::Vector3d::UnitX();
    }
  }

  /// The edges and their cotangent weights.
  const Cotangent_adjacency& adjacency() const { return m_adjacency; }
  /// The smooth rest positions, one column per vertex.
  const Vertex_major_positions& rest_vertex_major() const { return m_rest_vertex_major; }

  /// Number of vertices whose rotation is carried on from their neighbours.
  std::size_t number_of_undetermined_vertices() const { return m_order.size(); }

  /// The rotations (one per vertex) that carry the smooth rest mesh to
  /// `smooth_deformed`.
  void compute(const Positions& smooth_deformed, std::vector<Eigen::Matrix3d>& rotations) const
  {
    const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(m_adjacency.number_of_vertices());
    // A neighbour's three coordinates in one cache line instead of three.
    m_vertex_major.resize(3, n);
#ifdef _OPENMP
#pragma omp parallel for schedule(static) if(n > parallel_loop_items)
#endif
    for(std::ptrdiff_t i = 0; i < n; ++i)
      m_vertex_major.col(i) = smooth_deformed.row(i).transpose();
    compute(m_vertex_major, rotations);
  }

  /// As above, with the positions one column per vertex.
  void compute(const Vertex_major_positions& smooth_deformed, std::vector<Eigen::Matrix3d>& rotations) const
  {
    const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(m_adjacency.number_of_vertices());
    rotations.resize(static_cast<std::size_t>(n));
    // Only the vertices that inherit keep their covariance (a slot each):
    // the others turn it into their rotation at once, which saves an array
    // of n matrices.
    std::vector<Eigen::Matrix3d>& C = m_covariances;
    C.resize(m_slot_count);
    // One pass: the covariance of each one-ring, and the rotation of the
    // vertices that do not inherit.
#ifdef _OPENMP
#pragma omp parallel for schedule(static) if(n > parallel_loop_items)
#endif
    for(std::ptrdiff_t i = 0; i < n; ++i)
    {
      const Eigen::Matrix3d c = covariance(smooth_deformed, static_cast<int>(i));
      const int slot = m_slot[static_cast<std::size_t>(i)];
      if(slot >= 0)
        C[static_cast<std::size_t>(slot)] = c;
      if(!m_inherits[static_cast<std::size_t>(i)])
        rotations[static_cast<std::size_t>(i)] = nearest_rotation(c);
    }
    // Layer after layer, in order: the image of the feature's direction a
    // (the rest moment's principal axis) under the one-ring's covariance C_i,
    // u = C_i a, plus the mean rotation of the neighbours of the previous
    // layer, weighed alike. The one-ring bends the feature; the rotation
    // about it comes from the base alone, whatever the number of layers.
    for(std::size_t k = 0; k < m_order.size(); ++k)
    {
      const int begin = m_parent_start[k], end = m_parent_start[k + 1];
      Eigen::Matrix3d mean_rotation = Eigen::Matrix3d::Zero();
      for(int p = begin; p < end; ++p)
        mean_rotation += rotations[static_cast<std::size_t>(m_parents[static_cast<std::size_t>(p)])];
      mean_rotation /= double(end - begin);
      const Eigen::Vector3d axis = m_axes.col(static_cast<Eigen::Index>(k));
      const Eigen::Vector3d image = C[static_cast<std::size_t>(m_order_slots[k])] * axis;
      const double weight = image.norm();
      rotations[static_cast<std::size_t>(m_order[k])] = nearest_rotation(
          weight > 0 ? Eigen::Matrix3d(image * axis.transpose() + weight * mean_rotation) : mean_rotation);
    }
  }

private:
  // covariance() of every vertex.
  void accumulate(const Positions& x, std::vector<Eigen::Matrix3d>& result) const
  {
    const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(m_adjacency.number_of_vertices());
    const Vertex_major_positions vertex_major = x.transpose();
    result.resize(static_cast<std::size_t>(n));
#ifdef _OPENMP
#pragma omp parallel for schedule(static) if(n > parallel_loop_items)
#endif
    for(std::ptrdiff_t i = 0; i < n; ++i)
      result[static_cast<std::size_t>(i)] = covariance(vertex_major, static_cast<int>(i));
  }

  // Σ_j |w_ij| (x_j − x_i)(s_j − s_i)ᵀ over the one-ring of vertex i (with
  // x = s, the rest moment); x one column per vertex.
  Eigen::Matrix3d covariance(const Vertex_major_positions& x, int i) const
  {
    const Cotangent_adjacency& a = m_adjacency;
    Eigen::Matrix3d c = Eigen::Matrix3d::Zero();
    const Eigen::Vector3d xi = x.col(i);
    const Eigen::Vector3d si = m_rest_vertex_major.col(i);
    for(int s = a.start[static_cast<std::size_t>(i)]; s < a.start[static_cast<std::size_t>(i) + 1]; ++s)
    {
      const int j = a.neighbours[static_cast<std::size_t>(s)];
      const Eigen::Vector3d d = x.col(j) - xi;
      const Eigen::Vector3d weighted_rest_edge =
          std::abs(a.weights[static_cast<std::size_t>(s)]) * (m_rest_vertex_major.col(j) - si);
      c.noalias() += d * weighted_rest_edge.transpose();
    }
    return c;
  }

  // Breadth-first layers from the determined vertices through the
  // undetermined ones; each undetermined vertex inherits from its neighbours
  // of the previous layer.
  void order_undetermined(const std::vector<char>& determined)
  {
    const Cotangent_adjacency& a = m_adjacency;
    std::vector<int> layer(determined.size(), -1);
    std::deque<int> queue;
    for(std::size_t i = 0; i < determined.size(); ++i)
      if(determined[i])
      {
        layer[i] = 0;
        queue.push_back(static_cast<int>(i));
      }
    m_order.clear();
    while(!queue.empty())
    {
      const int i = queue.front();
      queue.pop_front();
      for(int s = a.start[static_cast<std::size_t>(i)]; s < a.start[static_cast<std::size_t>(i) + 1]; ++s)
      {
        const int j = a.neighbours[static_cast<std::size_t>(s)];
        if(layer[static_cast<std::size_t>(j)] < 0)
        {
          layer[static_cast<std::size_t>(j)] = layer[static_cast<std::size_t>(i)] + 1;
          queue.push_back(j);
          m_order.push_back(j);
        }
      }
    }
    // The neighbours of each in the previous layer.
    std::vector<int> parents;
    m_parent_start.assign(1, 0);
    for(int i : m_order)
    {
      for(int s = a.start[static_cast<std::size_t>(i)]; s < a.start[static_cast<std::size_t>(i) + 1]; ++s)
      {
        const int j = a.neighbours[static_cast<std::size_t>(s)];
        if(layer[static_cast<std::size_t>(j)] == layer[static_cast<std::size_t>(i)] - 1)
          parents.push_back(j);
      }
      m_parent_start.push_back(static_cast<int>(parents.size()));
    }
    m_inherits.assign(determined.size(), 0);
    for(int i : m_order)
      m_inherits[static_cast<std::size_t>(i)] = 1;
    // A slot for every vertex whose covariance is read after the first pass.
    m_slot.assign(determined.size(), -1);
    m_slot_count = 0;
    const auto slot_of = [this](int i) {
      int& slot = m_slot[static_cast<std::size_t>(i)];
      if(slot < 0)
        slot = static_cast<int>(m_slot_count++);
      return slot;
    };
    m_order_slots.clear();
    for(int i : m_order)
      m_order_slots.push_back(slot_of(i));
    m_parents = std::move(parents);
  }

  Cotangent_adjacency m_adjacency;
  Vertex_major_positions m_rest_vertex_major; // s
  mutable Vertex_major_positions m_vertex_major;
  std::vector<int> m_order;        // undetermined vertices, breadth-first
  std::vector<char> m_inherits;    // per vertex: in m_order
  std::vector<int> m_parent_start; // offsets into m_parents, per entry of m_order
  std::vector<int> m_slot;         // per vertex: its covariance's index in m_covariances, or -1
  std::size_t m_slot_count = 0;
  std::vector<int> m_order_slots;  // the slots of m_order
  std::vector<int> m_parents;      // their neighbours in the previous layer
  Eigen::Matrix3Xd m_axes;         // per entry of m_order: the direction of the feature
  mutable std::vector<Eigen::Matrix3d> m_covariances; // by slot
};

} // namespace Deformation
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_SMOOTH_ROTATION_FIELD_H

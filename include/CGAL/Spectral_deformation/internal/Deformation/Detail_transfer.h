// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_DETAIL_TRANSFER_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_DETAIL_TRANSFER_H

#include <CGAL/Spectral_deformation/Sparse_spd_solver_traits.h>
#include <CGAL/Spectral_deformation/cotangent_operators.h>
#include <CGAL/Spectral_deformation/internal/Linear_algebra/Dirichlet_system.h>
#include <CGAL/Spectral_deformation/internal/Deformation/Rotated_edges.h>
#include <CGAL/Spectral_deformation/internal/Mesh/Triangle_arrays.h>

#include <CGAL/assertions.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Spectral_deformation {
namespace internal {
namespace Deformation {

using Linear_algebra::Dirichlet_system;
using Mesh::Positions;
using Mesh::Triangle_arrays;
using Mesh::connected_components;

/// Detail transfer: the details of the detailed mesh follow the local
/// rotations of the smooth mesh. R_i, the rotation of the smooth one-ring of
/// vertex i from the smooth rest to the smooth deformed mesh, is fitted as in
/// as-rigid-as-possible deformation (`Smooth_rotation_field`), and the
/// detailed positions Y solve the Poisson system
/// Q Y = Σ_ij w_ij ½(R_i + R_j)(v_i − v_j), Q the cotangent stiffness of the
/// detailed mesh (the global step of as-rigid-as-possible deformation with
/// the rotations of the smooth mesh). Each edge gets a rotated copy of its
/// rest vector, so the right-hand side is bounded by that of the rest shape
/// whatever the smooth mesh looks like (even where it is folded or squeezed
/// into a curve); identity rotations give back V and a rigid motion its
/// rigid image.
///
/// Botsch et al. (2006) transfer the whole deformation gradient
/// T = E′E⁻¹, E = [e1, e2, n/√|n|], of each smooth face. It divides by the
/// smooth rest face, and where a band-limited smooth mesh squeezes a thin
/// feature into a near-curve its faces are slivers whose normal, and so the
/// rotation part of T, is set by round-off: the details there crumple and
/// fold. It also carries the stretch and shrinkage of the smooth mesh into
/// the result, which rotations do not.
///
/// Two ways to fix the free translation of each connected component:
/// - soft: the vertices that never move are prescribed (and one pinned
///   vertex in a component without any, whose translation is then fitted to
///   the constrained vertices), factored once per mesh (`prepare_soft()`);
/// - exact: a Dirichlet problem with prescribed vertices, factored once per
///   set of prescribed vertices; they keep their prescribed positions exactly.
///
/// Optionally (`set_volume_preservation()`), the Poisson solution is
/// corrected to enclose the rest volume, with one more back-substitution.
template <class SparseSPDSolverTraits = Default_deformation_sparse_spd_solver_traits>
class Detail_transfer
{
public:
  /// `detailed` validated; `smooth_rest` the smooth positions of the same
  /// connectivity. Throws `Spectral_deformation_error` when `smooth_rest` is
  /// not finite.
  void initialize(const Triangle_arrays& detailed, const Positions& smooth_rest)
  {
    initialize(detailed, smooth_rest, cotangent_stiffness(detailed));
  }

  /// As above, with `stiffness` the cotangent stiffness of `detailed`
  /// (`cotangent_stiffness()`), already computed by the caller.
  void initialize(const Triangle_arrays& detailed, const Positions& smooth_rest,
                  Eigen::SparseMatrix<double> stiffness)
  {
    set_mesh(detailed, std::move(stiffness));
    set_smooth_rest(smooth_rest);
  }

  /// The first half of `initialize()`: the detailed mesh and its stiffness,
  /// all that the factorizations (`prepare_soft()`, `prepare_dirichlet()`)
  /// need; the transfers need `set_smooth_rest()` as well.
  void set_mesh(const Triangle_arrays& detailed, Eigen::SparseMatrix<double> stiffness)
  {
    m_rest = detailed.positions;
    m_triangles = detailed.triangles;
    m_rest_volume = enclosed_volume(m_rest);
    m_volume_defined = false;
    m_stiffness = std::move(stiffness);
    m_rotated_edges = Rotated_edges();
    m_component = connected_components(detailed.triangles, m_rest.rows(), m_number_of_components);
    m_soft.forget_matrix();
    m_dirichlet.forget_matrix();
    m_soft_ready = false;
    m_dirichlet_ready = false;
    m_dirichlet_prescribed.clear();
  }

  /// The second half of `initialize()`: the smooth rest positions, whose
  /// one-rings the rotations of a transfer are fitted against. Throws
  /// `Spectral_deformation_error` when `smooth_rest` is not finite.
  /// `rotations`, when not null, is a field already fitted on `smooth_rest`
  /// with the stiffness of `set_mesh()`, which the transfer then shares.
  void set_smooth_rest(const Positions& smooth_rest,
                       std::shared_ptr<const Smooth_rotation_field> rotations = nullptr)
  {
    typedef Spectral_deformation_error Error;
    if(!smooth_rest.allFinite())
      throw Error(Error::SOLVER_FAILURE, "the smooth mesh has non-finite coordinates");
    if(rotations != nullptr)
    {
      CGAL_precondition(rotations->rest_vertex_major().cols() == smooth_rest.rows());
      m_rotated_edges.initialize(std::move(rotations), &m_rest);
    }
    else
      m_rotated_edges.initialize(m_stiffness, m_rest, smooth_rest);
  }

  /// Whether a transfer keeps the volume enclosed by the surface, when it is
  /// defined: `fixed` flags the vertices that never move, and the volume is
  /// defined when every edge of the mesh's boundary joins two of them (the
  /// region is cut out of a closed surface whose other faces stay put, so
  /// the change of the signed volume of its faces is that of the volume
  /// the whole surface encloses).
  void set_volume_preservation(bool preserve, const std::vector<char>& fixed)
  {
    m_preserve_volume = preserve;
    m_volume_defined = boundary_is_fixed(fixed);
  }

  /// Whether the transfers keep the enclosed volume (set and defined).
  bool preserves_volume() const { return m_preserve_volume && m_volume_defined; }

  /// Soft policy: factor, once per mesh (later calls do nothing), the
  /// system with the vertices flagged in `anchored` prescribed (the vertices
  /// that never move), plus the first vertex of every component without an
  /// anchored vertex, whose translation is fitted afterwards. Returns false
  /// when the factorization fails.
  bool prepare_soft(const std::vector<char>& anchored)
  {
    if(m_soft_ready)
      return true;
    std::vector<char> prescribed = anchored;
    m_floating.assign(static_cast<std::size_t>(m_number_of_components), 1);
    for(std::size_t i = 0; i < anchored.size(); ++i)
      if(anchored[i])
        m_floating[static_cast<std::size_t>(m_component[i])] = 0;
    std::vector<char> pinned(static_cast<std::size_t>(m_number_of_components), 0);
    for(std::size_t i = 0; i < prescribed.size(); ++i)
    {
      const std::size_t c = static_cast<std::size_t>(m_component[i]);
      if(m_floating[c] && !pinned[c])
      {
        pinned[c] = 1;
        prescribed[i] = 1;
      }
    }
    m_soft_ready = m_soft.factor(m_stiffness, prescribed);
    return m_soft_ready;
  }

  /// Exact policy: factor the system with the vertices flagged in
  /// `prescribed` fixed (nothing to do when the last factorization had the
  /// same vertices). Returns false when a component has no prescribed
  /// vertex or the factorization fails.
  bool prepare_dirichlet(const std::vector<char>& prescribed)
  {
    if(m_dirichlet_ready && prescribed == m_dirichlet_prescribed)
      return true; // factored for these vertices already
    m_dirichlet_ready = false;
    m_dirichlet_prescribed.clear();
    std::vector<char> component_has(static_cast<std::size_t>(m_number_of_components), 0);
    for(std::size_t i = 0; i < prescribed.size(); ++i)
      if(prescribed[i])
        component_has[static_cast<std::size_t>(m_component[i])] = 1;
    for(char has : component_has)
      if(!has)
        return false;
    m_dirichlet_ready = m_dirichlet.factor(m_stiffness, prescribed);
    if(m_dirichlet_ready)
      m_dirichlet_prescribed = prescribed;
    return m_dirichlet_ready;
  }

  /// The Poisson right-hand side for the smooth deformed positions (valid
  /// until the next call); `SmoothPositions` is `Positions` (one row per
  /// vertex) or `Smooth_rotation_field::Vertex_major_positions` (one column
  /// per vertex), as for the transfers below.
  template <class SmoothPositions>
  const Eigen::MatrixXd& right_hand_side(const SmoothPositions& smooth_deformed) const
  {
    return m_rotated_edges.evaluate(smooth_deformed);
  }

  /// Soft policy: positions with the anchored vertices at
  /// `anchored_positions` (n×3, other rows ignored); a component without
  /// anchored vertex is translated by the mean offset to `targets` at its
  /// `constrained` vertices. Returns false when a solve fails (`result` is
  /// then unspecified).
  template <class SmoothPositions>
  bool transfer_soft(const SmoothPositions& smooth_deformed, const Positions& anchored_positions,
                     const std::vector<int>& constrained, const Positions& targets,
                     Positions& result) const
  {
    if(!m_soft_ready)
      return false;
    Positions& prescribed = m_soft_prescribed;
    prescribed = anchored_positions;
    for(Eigen::Index i = 0; i < m_rest.rows(); ++i)
      if(m_floating[static_cast<std::size_t>(m_component[static_cast<std::size_t>(i)])])
        prescribed.row(i).setZero(); // the pinned vertex, whichever it is
    Positions& y = result;
    if(!m_soft.solve(right_hand_side(smooth_deformed), prescribed, y))
      return false;
    Eigen::MatrixXd offset = Eigen::MatrixXd::Zero(m_number_of_components, 3);
    Eigen::VectorXd count = Eigen::VectorXd::Zero(m_number_of_components);
    for(std::size_t k = 0; k < constrained.size(); ++k)
    {
      const int c = m_component[static_cast<std::size_t>(constrained[k])];
      if(!m_floating[static_cast<std::size_t>(c)])
        continue;
      offset.row(c) += targets.row(static_cast<Eigen::Index>(k)) - y.row(constrained[k]);
      count[c] += 1;
    }
    for(int c = 0; c < m_number_of_components; ++c)
      if(count[c] > 0)
        offset.row(c) /= count[c];
    for(Eigen::Index i = 0; i < m_rest.rows(); ++i)
      result.row(i) += offset.row(m_component[static_cast<std::size_t>(i)]);
    return result.allFinite();
  }

  /// Exact policy: positions with the prescribed vertices at `prescribed_positions`
  /// (n×3, rows of other vertices ignored). Returns false when the solve
  /// fails (`result` is then unspecified).
  template <class SmoothPositions>
  bool transfer_exact(const SmoothPositions& smooth_deformed, const Positions& prescribed_positions,
                      Positions& result) const
  {
    if(!m_dirichlet_ready)
      return false;
    if(!m_dirichlet.solve(right_hand_side(smooth_deformed), prescribed_positions, result))
      return false;
    if(preserves_volume() && !keep_volume(m_dirichlet, result))
      return false;
    return result.allFinite();
  }

  /// The Dirichlet system of `prepare_dirichlet()` for another right-hand
  /// side: Q X = `rhs` with the prescribed vertices at
  /// `prescribed_positions`, the volume kept when `preserves_volume()` (the
  /// global step of the as-rigid-as-possible refinement). Returns false when
  /// the system is not factored or the solve fails.
  bool solve_dirichlet(const Eigen::MatrixXd& rhs, const Positions& prescribed_positions, Positions& result) const
  {
    if(!m_dirichlet_ready || !m_dirichlet.solve(rhs, prescribed_positions, result))
      return false;
    return !preserves_volume() || keep_volume(m_dirichlet, result);
  }

  /// Soft policy: when `preserves_volume()`, moves the unanchored vertices
  /// of `positions` so that the surface encloses the rest volume (called
  /// last, after any correction of the result). Returns false when a solve
  /// fails.
  bool keep_volume_soft(Positions& positions) const
  {
    return !preserves_volume() || keep_volume(m_soft, positions);
  }

  /// The signed volume of the faces at `positions` (Σ det(a, b, c) / 6).
  double enclosed_volume(const Positions& positions) const
  {
    double volume = 0;
    for(Eigen::Index f = 0; f < m_triangles.rows(); ++f)
      volume += corner(positions, f, 0).dot(corner(positions, f, 1).cross(corner(positions, f, 2)));
    return volume / 6;
  }

  const Eigen::SparseMatrix<double>& stiffness() const { return m_stiffness; }

private:
  Eigen::Vector3d corner(const Positions& positions, Eigen::Index face, int k) const
  {
    return positions.row(m_triangles(face, k)).transpose();
  }

  // The gradient of enclosed_volume() at `positions` (n×3).
  void volume_gradient(const Positions& positions, Eigen::MatrixXd& gradient) const
  {
    gradient.setZero(positions.rows(), 3);
    for(Eigen::Index f = 0; f < m_triangles.rows(); ++f)
    {
      const Eigen::Vector3d a = corner(positions, f, 0), b = corner(positions, f, 1), c = corner(positions, f, 2);
      gradient.row(m_triangles(f, 0)) += b.cross(c).transpose() / 6;
      gradient.row(m_triangles(f, 1)) += c.cross(a).transpose() / 6;
      gradient.row(m_triangles(f, 2)) += a.cross(b).transpose() / 6;
    }
  }

  bool boundary_is_fixed(const std::vector<char>& fixed) const
  {
    // An edge of one face only is on the boundary of the region's faces.
    std::vector<std::pair<int, int>> edges;
    edges.reserve(static_cast<std::size_t>(3 * m_triangles.rows()));
    for(Eigen::Index f = 0; f < m_triangles.rows(); ++f)
      for(int k = 0; k < 3; ++k)
      {
        const int a = m_triangles(f, k), b = m_triangles(f, (k + 1) % 3);
        edges.emplace_back((std::min)(a, b), (std::max)(a, b));
      }
    std::sort(edges.begin(), edges.end());
    for(std::size_t e = 0; e < edges.size();)
    {
      std::size_t next = e + 1;
      while(next < edges.size() && edges[next] == edges[e])
        ++next;
      if(next - e == 1 && !(fixed[static_cast<std::size_t>(edges[e].first)] &&
                            fixed[static_cast<std::size_t>(edges[e].second)]))
        return false;
      e = next;
    }
    return true;
  }

  // The Poisson solution y minimizes ½ yᵀQy − bᵀy; with the volume kept,
  // Q y = b + λ ∇V(y): y = y₀ + λ w with Q w = ∇V (prescribed rows 0), the
  // gradient taken at y₀ (one more solve), and λ the root of the cubic
  // V(y₀ + λ w) = V₀, whose coefficients one pass over the faces gives,
  // found by Newton's method from 0.
  template <class System>
  bool keep_volume(const System& system, Positions& y) const
  {
    Eigen::MatrixXd& gradient = m_volume_gradient;
    volume_gradient(y, gradient);
    Positions& w = m_volume_direction;
    if(!system.solve(gradient, Positions::Zero(y.rows(), 3), w))
      return false;
    Eigen::Vector4d cubic = Eigen::Vector4d::Zero(); // V(y₀ + λ w) = Σ_k cubic[k] λ^k
    for(Eigen::Index f = 0; f < m_triangles.rows(); ++f)
    {
      const Eigen::Vector3d a = corner(y, f, 0), b = corner(y, f, 1), c = corner(y, f, 2);
      const Eigen::Vector3d da = corner(w, f, 0), db = corner(w, f, 1), dc = corner(w, f, 2);
      cubic[0] += a.dot(b.cross(c));
      cubic[1] += da.dot(b.cross(c)) + a.dot(db.cross(c)) + a.dot(b.cross(dc));
      cubic[2] += a.dot(db.cross(dc)) + da.dot(b.cross(dc)) + da.dot(db.cross(c));
      cubic[3] += da.dot(db.cross(dc));
    }
    cubic /= 6;
    cubic[0] -= m_rest_volume;
    double lambda = 0;
    const double tolerance = 1e-12 * std::abs(m_rest_volume);
    for(int step = 0; step < 8; ++step)
    {
      const double excess = ((cubic[3] * lambda + cubic[2]) * lambda + cubic[1]) * lambda + cubic[0];
      if(std::abs(excess) <= tolerance)
        break;
      const double slope = (3 * cubic[3] * lambda + 2 * cubic[2]) * lambda + cubic[1];
      if(!(std::abs(slope) > 0))
        break; // the direction does not change the volume: keep the best so far
      lambda -= excess / slope;
    }
    y += lambda * w;
    return y.allFinite();
  }

public:

  /// Whether the sparse solvers may change process-wide state to run faster
  /// (see `SparseSPDSolverTraits`); takes effect at the next factorization.
  void set_process_wide_tuning(bool enabled)
  {
    m_soft.set_process_wide_tuning(enabled);
    m_dirichlet.set_process_wide_tuning(enabled);
  }

private:
  Positions m_rest;
  Mesh::Triangles m_triangles;
  double m_rest_volume = 0;
  bool m_preserve_volume = false, m_volume_defined = false;
  mutable Eigen::MatrixXd m_volume_gradient;
  mutable Positions m_volume_direction;
  Eigen::SparseMatrix<double> m_stiffness;
  Rotated_edges m_rotated_edges;
  // A buffer of a transfer, kept between calls: on large meshes, fresh pages
  // for it cost more than the arithmetic.
  mutable Positions m_soft_prescribed;
  std::vector<int> m_component;
  int m_number_of_components = 0;
  Dirichlet_system<SparseSPDSolverTraits> m_soft;
  std::vector<char> m_floating; // per component: no anchored vertex
  Dirichlet_system<SparseSPDSolverTraits> m_dirichlet;
  bool m_soft_ready = false;
  bool m_dirichlet_ready = false;
  std::vector<char> m_dirichlet_prescribed; // the vertices of the Dirichlet factor
};

} // namespace Deformation
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_DETAIL_TRANSFER_H

// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_CLUSTERED_ROTATIONS_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_CLUSTERED_ROTATIONS_H

#include <CGAL/Spectral_deformation/internal/available_threads.h>
#include <CGAL/Spectral_deformation/internal/Deformation/Smooth_rotation_field.h>
#include <CGAL/Spectral_deformation/internal/Deformation/rigid_fit.h>
#include <CGAL/Spectral_deformation/internal/Mesh/Dual_mesh_operator.h>
#include <CGAL/Spectral_deformation/internal/Mesh/Triangle_arrays.h>

#include <Eigen/Dense>

#ifdef _OPENMP
#include <omp.h>
#endif

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Spectral_deformation {
namespace internal {
namespace Deformation {

using Mesh::Dual_mesh_operator;
using Mesh::Positions;
using Mesh::Triangles;

/// The rows of a column-major basis (n × m, double or float) in increasing
/// order, widened to double: blocks of consecutive rows are copied to a
/// row-major buffer, so that reading a row costs one pass over short
/// contiguous pieces of the columns instead of m reads n entries apart.
template <class Basis>
class Sequential_basis_rows
{
public:
  explicit Sequential_basis_rows(const Basis& basis) : m_basis(&basis) {}

  /// Row `i` (m entries), valid until the next call. Rows read in
  /// increasing order cost one copy of their block each.
  const double* row(Eigen::Index i)
  {
    eigen_assert(i >= 0 && i < m_basis->rows());
    if(i < m_first || i >= m_first + m_block.rows())
    {
      const Eigen::Index count = (std::min)(block_rows, m_basis->rows() - i);
      // Eigen frees a buffer before it allocates the new size: emptied
      // first, the buffer is never left dangling by a failed allocation.
      if(count != m_block.rows())
        m_block.resize(0, 0);
      m_block = m_basis->middleRows(i, count).template cast<double>();
      m_first = i;
    }
    return m_block.row(i - m_first).data();
  }

private:
  static constexpr Eigen::Index block_rows = 64;
  const Basis* m_basis;
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> m_block;
  Eigen::Index m_first = 0;
};

/// The right-hand side of the reduced dual Laplacian iteration with one
/// rotation per patch of dual vertices instead of one per dual vertex.
///
/// The full iteration turns each rest coordinate l̄_r to the normal of the
/// current shape, which needs the whole shape H c at every step. Here the
/// rows of a patch C turn by one rotation R_C, so the right-hand side
/// Hᵀ (L̂F)ᵀ [l̄_r R_Cᵀ]_r is Σ_C K_C R_Cᵀ with K_C = Hᵀ (L̂F)ᵀ [l̄_r]_{r∈C}
/// (m×3, precomputed). R_C is the rotation of the patch's neighbour
/// triangles (the triangles whose planes give the normals), fitted to their
/// edges: the covariance Σ e ēᵀ of those edges is linear in the positions,
/// so it is cᵀ P_C with P_C (m×3) precomputed too. One step then costs
/// O(m × patches), independent of the size of the mesh. With one patch per
/// row, R_C takes the rest normal of the row exactly to its current one, and
/// the iteration is the full one.
///
/// The as-rigid-as-possible iteration (`initialize_arap()`) has the same
/// form. With one rotation R_C per patch C of vertices, the covariance of
/// the patch, Σ_{i∈C} Σ_j |w_ij| (x_i − x_j)(s_i − s_j)ᵀ with x = H c and s
/// the smooth rest positions, is cᵀ P_C with
/// P_C = Σ_{i∈C} Σ_j |w_ij| (H_i − H_j)ᵀ (s_i − s_j); and Hᵀ b, b the
/// right-hand side Σ_j w_ij ½(R_i + R_j)(s_i − s_j) of its global step, is
/// Σ_C K_C R_Cᵀ with K_C = Σ_{i∈C} Σ_j ½ w_ij (H_i − H_j)ᵀ (s_i − s_j). With
/// one patch per vertex, it is the full as-rigid-as-possible iteration.
class Clustered_rotation_rhs
{
public:
  /// `basis` n×m (a dense matrix of double or float), `dual` the dual mesh
  /// of the region, `weights` and `coordinates` the rest dual coordinates
  /// (rows of `dual`), `smooth_rest` the rest positions of the iteration,
  /// `patch_of_row` from `cluster_dual_rows()`.
  template <class Basis>
  void initialize(const Basis& basis, const Dual_mesh_operator& dual,
                  const Eigen::Matrix<double, Eigen::Dynamic, 3>& weights, const Positions& coordinates,
                  const Positions& smooth_rest, const std::vector<int>& patch_of_row)
  {
    const Eigen::Index m = basis.cols();
    const int patches =
        patch_of_row.empty() ? 0 : *std::max_element(patch_of_row.begin(), patch_of_row.end()) + 1;
    m_patches = patches;
    m_K.setZero(m, 3 * patches);
    m_P.setZero(m, 3 * patches);
    m_rotations.resize(3 * patches, 3);
    for(int p = 0; p < patches; ++p)
      m_rotations.middleRows<3>(3 * p).setIdentity();
    if(patches == 0)
      return;

    std::vector<int> start, rows_by_patch;
    sort_rows_by_patch(patch_of_row, patches, start, rows_by_patch);
    const std::vector<std::vector<Contribution>> gathered =
        gather_contributions(dual, weights, coordinates, smooth_rest, start, rows_by_patch, basis.rows());
    accumulate_products(basis, gathered);
  }

  /// The as-rigid-as-possible form: `basis` n×m, `adjacency` the edges and
  /// weights of the cotangent stiffness, `smooth_rest` the rest positions of
  /// the iteration, `patch_of_vertex` from `cluster_vertices()`.
  template <class Basis>
  void initialize_arap(const Basis& basis, const Cotangent_adjacency& adjacency,
                       const Positions& smooth_rest, const std::vector<int>& patch_of_vertex)
  {
    const Eigen::Index m = basis.cols();
    const int patches =
        patch_of_vertex.empty() ? 0 : *std::max_element(patch_of_vertex.begin(), patch_of_vertex.end()) + 1;
    m_patches = (std::max)(patches, 0);
    m_rotations.resize(3 * m_patches, 3);
    for(int p = 0; p < m_patches; ++p)
      m_rotations.middleRows<3>(3 * p).setIdentity();
    const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(adjacency.number_of_vertices());
    int threads = 1;
#ifdef _OPENMP
    if(n > parallel_loop_items)
      threads = omp_get_max_threads();
#endif
    // Each thread sums the rows of its share of the vertices into its own
    // copy of K and P.
    std::vector<Eigen::MatrixXd> K(static_cast<std::size_t>(threads)), P(static_cast<std::size_t>(threads));
#ifdef _OPENMP
#pragma omp parallel num_threads(threads) if(threads > 1)
#endif
    {
      int thread = 0;
#ifdef _OPENMP
      thread = omp_get_thread_num();
#endif
      Eigen::MatrixXd& my_K = K[static_cast<std::size_t>(thread)];
      Eigen::MatrixXd& my_P = P[static_cast<std::size_t>(thread)];
      my_K.setZero(m, 3 * m_patches);
      my_P.setZero(m, 3 * m_patches);
      // What vertex i puts on each patch: the patch of i and the patches of
      // its neighbours get w_ij (s_i − s_j) for every edge ij (the term of
      // the ordered pair ji has the opposite edge and the opposite sign).
      struct Load
      {
        int patch;
        Eigen::RowVector3d half, absolute;
      };
      std::vector<Load> loads;
      Sequential_basis_rows<Basis> basis_rows(basis);
      const std::ptrdiff_t first = n * thread / threads, last = n * (thread + 1) / threads;
      for(std::ptrdiff_t i = first; i < last; ++i)
      {
        const int own = patch_of_vertex[static_cast<std::size_t>(i)];
        if(own < 0)
          continue;
        loads.clear();
        auto add = [&loads](int patch, const Eigen::RowVector3d& half, const Eigen::RowVector3d& absolute) {
          for(Load& load : loads)
            if(load.patch == patch)
            {
              load.half += half;
              load.absolute += absolute;
              return;
            }
          loads.push_back(Load{patch, half, absolute});
        };
        for(int s = adjacency.start[static_cast<std::size_t>(i)]; s < adjacency.start[static_cast<std::size_t>(i) + 1];
            ++s)
        {
          const int j = adjacency.neighbours[static_cast<std::size_t>(s)];
          const double w = adjacency.weights[static_cast<std::size_t>(s)];
          const Eigen::RowVector3d edge = smooth_rest.row(i) - smooth_rest.row(j);
          add(own, 0.5 * w * edge, std::abs(w) * edge);
          add(patch_of_vertex[static_cast<std::size_t>(j)], 0.5 * w * edge, std::abs(w) * edge);
        }
        const Eigen::Map<const Eigen::VectorXd> h(basis_rows.row(i), m);
        for(const Load& load : loads)
        {
          my_K.middleCols<3>(3 * load.patch).noalias() += h * load.half;
          my_P.middleCols<3>(3 * load.patch).noalias() += h * load.absolute;
        }
      }
    }
    m_K = std::move(K[0]);
    m_P = std::move(P[0]);
    for(std::size_t t = 1; t < K.size(); ++t)
    {
      m_K += K[t];
      m_P += P[t];
    }
  }

  int number_of_patches() const { return m_patches; }

  /// `rhs` (m×3) = Σ_C K_C R_Cᵀ for the rotations of the patches at the
  /// shape H `coefficients`.
  void evaluate(const Eigen::MatrixXd& coefficients, Eigen::MatrixXd& rhs) const
  {
    rhs.setZero(m_K.rows(), 3);
    int threads = 1;
#ifdef _OPENMP
    // The two products read 6 m × patches numbers: worth a team from a few
    // hundred patches on.
    if(static_cast<double>(m_patches) * static_cast<double>(m_K.rows()) > 2e4)
      threads = (std::min)(omp_get_max_threads(), (m_patches + 63) / 64);
#endif
    m_partial.resize(static_cast<std::size_t>(threads));
    m_transposed_covariances.resize(static_cast<std::size_t>(threads));
#ifdef _OPENMP
#pragma omp parallel num_threads(threads) if(threads > 1)
#endif
    {
      int thread = 0;
#ifdef _OPENMP
      thread = omp_get_thread_num();
#endif
      const int first = static_cast<int>(static_cast<long>(m_patches) * thread / threads);
      const int last = static_cast<int>(static_cast<long>(m_patches) * (thread + 1) / threads);
      evaluate_patches(coefficients, first, last, m_partial[static_cast<std::size_t>(thread)],
                       m_transposed_covariances[static_cast<std::size_t>(thread)]);
    }
    for(const Eigen::MatrixXd& part : m_partial)
      rhs += part;
  }

private:
  // What the rows of one patch put on one vertex.
  struct Contribution
  {
    int vertex;
    int patch;
    Eigen::RowVector3d load, edge;
  };

  // The rows in the order of their patches: those of patch p are
  // rows_by_patch[start[p], start[p + 1]).
  static void sort_rows_by_patch(const std::vector<int>& patch_of_row, int patches, std::vector<int>& start,
                                 std::vector<int>& rows_by_patch)
  {
    start.assign(static_cast<std::size_t>(patches) + 1, 0);
    for(int p : patch_of_row)
      ++start[static_cast<std::size_t>(p) + 1];
    for(std::size_t i = 1; i < start.size(); ++i)
      start[i] += start[i - 1];
    rows_by_patch.resize(patch_of_row.size());
    std::vector<int> fill(start.begin(), start.end() - 1);
    for(std::size_t r = 0; r < patch_of_row.size(); ++r)
      rows_by_patch[static_cast<std::size_t>(fill[static_cast<std::size_t>(patch_of_row[r])]++)] =
          static_cast<int>(r);
  }

  // Per patch, the vertex rows of (L̂F)ᵀ [l̄_r] and of the edge covariance
  // operator, gathered sparsely (one list per thread). The products with H
  // then run over the vertices in order, because a row of the column-major
  // n×m basis is m scattered numbers: read patch by patch, the rows of a
  // large mesh missed the cache and the TLB at every number.
  static std::vector<std::vector<Contribution>>
  gather_contributions(const Dual_mesh_operator& dual, const Eigen::Matrix<double, Eigen::Dynamic, 3>& weights,
                       const Positions& coordinates, const Positions& smooth_rest, const std::vector<int>& start,
                       const std::vector<int>& rows_by_patch, Eigen::Index n)
  {
    const int patches = static_cast<int>(start.size()) - 1;
    const Triangles& triangles = dual.triangles();
    const Triangles& neighbours = dual.neighbours();
    const std::vector<int>& row_faces = dual.row_faces();
    // The rest centroids are formed where they are read, as Dual_mesh_operator::centroids() does.
    auto rest_centroid = [&](int face) -> Eigen::RowVector3d {
      return (smooth_rest.row(triangles(face, 0)) + smooth_rest.row(triangles(face, 1)) +
              smooth_rest.row(triangles(face, 2))) /
             3.0;
    };
    std::vector<std::vector<Contribution>> gathered;
#ifdef _OPENMP
#pragma omp parallel if(patches > 64)
#endif
    {
#ifdef _OPENMP
#pragma omp single
      gathered.resize(static_cast<std::size_t>(omp_get_num_threads()));
      std::vector<Contribution>& mine = gathered[static_cast<std::size_t>(omp_get_thread_num())];
#else
      gathered.resize(1);
      std::vector<Contribution>& mine = gathered[0];
#endif
      // A patch touches few vertices: each thread sums their loads and edges
      // in slots of its own, found by vertex, so that its memory is one
      // index per vertex rather than two rows of n×3 (times the threads).
      std::vector<int> slot(static_cast<std::size_t>(n), -1);
      std::vector<int> touched;
      std::vector<Eigen::RowVector3d> load, edges;
      auto add = [&](std::vector<Eigen::RowVector3d>& target, int face, const Eigen::RowVector3d& value) {
        for(int k = 0; k < 3; ++k)
        {
          const int v = triangles(face, k);
          int& s = slot[static_cast<std::size_t>(v)];
          if(s < 0)
          {
            s = static_cast<int>(touched.size());
            touched.push_back(v);
            load.emplace_back(Eigen::RowVector3d::Zero());
            edges.emplace_back(Eigen::RowVector3d::Zero());
          }
          target[static_cast<std::size_t>(s)] += value / 3.0;
        }
      };
#ifdef _OPENMP
#pragma omp for schedule(dynamic, 8)
#endif
      for(int p = 0; p < patches; ++p)
      {
        for(int s = start[static_cast<std::size_t>(p)]; s < start[static_cast<std::size_t>(p) + 1]; ++s)
        {
          const int r = rows_by_patch[static_cast<std::size_t>(s)];
          const int f = row_faces[static_cast<std::size_t>(r)];
          const Eigen::RowVector3d l = coordinates.row(r);
          // Row r of L̂F: -1/3 on the face's vertices, w_j/3 on those of its
          // neighbours (as in Dual_mesh_operator::laplacian_operator()).
          add(load, f, -l);
          for(int j = 0; j < 3; ++j)
          {
            const int a = neighbours(f, j), b = neighbours(f, (j + 1) % 3);
            add(load, a, weights(r, j) * l);
            const Eigen::RowVector3d rest_edge = rest_centroid(b) - rest_centroid(a);
            add(edges, b, rest_edge);
            add(edges, a, -rest_edge);
          }
        }
        for(std::size_t k = 0; k < touched.size(); ++k)
        {
          const int v = touched[k];
          mine.push_back(Contribution{v, p, load[k], edges[k]});
          slot[static_cast<std::size_t>(v)] = -1;
        }
        touched.clear();
        load.clear();
        edges.clear();
      }
    }
    return gathered;
  }

  // K and P: the contributions in the order of their vertices (a counting
  // sort), then one pass over the rows of H.
  template <class Basis>
  void accumulate_products(const Basis& basis, const std::vector<std::vector<Contribution>>& gathered)
  {
    const Eigen::Index n = basis.rows();
    std::vector<int> first(static_cast<std::size_t>(n) + 1, 0);
    for(const std::vector<Contribution>& part : gathered)
      for(const Contribution& c : part)
        ++first[static_cast<std::size_t>(c.vertex) + 1];
    for(std::size_t i = 1; i < first.size(); ++i)
      first[i] += first[i - 1];
    std::vector<const Contribution*> by_vertex(static_cast<std::size_t>(first.back()));
    {
      std::vector<int> fill(first.begin(), first.end() - 1);
      for(const std::vector<Contribution>& part : gathered)
        for(const Contribution& c : part)
          by_vertex[static_cast<std::size_t>(fill[static_cast<std::size_t>(c.vertex)]++)] = &c;
    }
    const Eigen::Index m = basis.cols();
    Sequential_basis_rows<Basis> basis_rows(basis);
    for(Eigen::Index v = 0; v < n; ++v)
    {
      const int begin = first[static_cast<std::size_t>(v)], end = first[static_cast<std::size_t>(v) + 1];
      if(begin == end)
        continue;
      const Eigen::Map<const Eigen::VectorXd> h(basis_rows.row(v), m);
      for(int k = begin; k < end; ++k)
      {
        const Contribution& c = *by_vertex[static_cast<std::size_t>(k)];
        m_K.middleCols<3>(3 * c.patch).noalias() += h * c.load;
        m_P.middleCols<3>(3 * c.patch).noalias() += h * c.edge;
      }
    }
  }

  // The rotations of the patches [first, last) and their share of the
  // right-hand side.
  void evaluate_patches(const Eigen::MatrixXd& coefficients, int first, int last, Eigen::MatrixXd& rhs,
                        Eigen::Matrix<double, Eigen::Dynamic, 3>& transposed_covariances) const
  {
    // Both products have three columns on one side: as general matrix
    // products, Eigen would first copy the m × 3·patches blocks of P and K
    // into its packed layout. As dot products of the columns of P with the
    // coefficients, and as rank-one updates by the columns of K, each is
    // read once, in place.
    const Eigen::Index m = m_K.rows();
    const Eigen::Index columns = 3 * (last - first);
    transposed_covariances.resize(columns, 3);
    transposed_covariances.noalias() = m_P.middleCols(3 * first, columns).transpose().lazyProduct(coefficients);
    for(int p = first; p < last; ++p)
    {
      auto rotation = m_rotations.middleRows<3>(3 * p);
      // A patch squeezed into a curve (a covariance of rank one) determines
      // no rotation: it keeps the last one.
      rotation = nearest_rotation(transposed_covariances.middleRows<3>(3 * (p - first)).transpose(),
                                  rotation.transpose())
                     .transpose();
    }
    rhs.setZero(m, 3);
    for(Eigen::Index c = 3 * first; c < 3 * last; ++c)
      rhs.noalias() += m_K.col(c) * m_rotations.row(c);
  }

  int m_patches = 0;
  Eigen::MatrixXd m_K, m_P;
  mutable std::vector<Eigen::MatrixXd> m_partial;
  // The covariances of each thread's patches, transposed.
  mutable std::vector<Eigen::Matrix<double, Eigen::Dynamic, 3>> m_transposed_covariances;
  mutable Eigen::Matrix<double, Eigen::Dynamic, 3> m_rotations;
};

} // namespace Deformation
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_CLUSTERED_ROTATIONS_H

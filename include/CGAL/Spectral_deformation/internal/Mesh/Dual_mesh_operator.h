// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_MESH_DUAL_MESH_OPERATOR_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_MESH_DUAL_MESH_OPERATOR_H

#include <CGAL/Spectral_deformation/internal/available_threads.h>
#include <CGAL/Spectral_deformation/Spectral_deformation_error.h>
#include <CGAL/Spectral_deformation/internal/Mesh/Triangle_arrays.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <Eigen/Sparse>

#include <algorithm>
#include <array>
#include <string>
#include <vector>

namespace CGAL {
namespace Spectral_deformation {
namespace internal {
namespace Mesh {

/// Dual Laplacian coordinates of a mesh at some positions, one row per dual
/// vertex that has three dual neighbours.
struct Dual_coordinates
{
  /// Barycentric weights of the projected dual vertex in its neighbour triangle.
  Eigen::Matrix<double, Eigen::Dynamic, 3> weights;
  /// Unit normals of the neighbour planes, oriented like the face.
  Positions normals;
  /// Signed distances h with l̂ = -h n̂.
  Eigen::VectorXd heights;
  /// The dual Laplacian coordinates l̂ = Σ w_j (v̂_j - v̂) = -h n̂.
  Positions coordinates;
  /// Number of rows whose neighbour triangle was degenerate.
  Eigen::Index degenerate_rows = 0;
};

/// Connectivity of the dual mesh (dual vertices are face centroids) and the
/// dual Laplacian operator of Au et al. 2006, for any positions of the
/// vertices of a fixed triangulation.
class Dual_mesh_operator
{
public:
  Dual_mesh_operator() = default;

  /// `triangles` index `number_of_vertices` vertices. Throws
  /// `Spectral_deformation_error` (INVALID_MESH) when an edge is shared by more
  /// than two faces or two faces share an edge with the same orientation.
  Dual_mesh_operator(const Triangles& triangles, Eigen::Index number_of_vertices)
    : m_triangles(triangles), m_number_of_vertices(number_of_vertices)
  {
    build_neighbours();
  }

  Eigen::Index number_of_vertices() const { return m_number_of_vertices; }
  Eigen::Index number_of_faces() const { return m_triangles.rows(); }
  /// Number of dual vertices with three dual neighbours (rows of the operator).
  Eigen::Index number_of_rows() const { return static_cast<Eigen::Index>(m_row_faces.size()); }
  /// The face of each row.
  const std::vector<int>& row_faces() const { return m_row_faces; }
  /// Per face, the faces across its edges ab, bc, ca; -1 across a border.
  const Triangles& neighbours() const { return m_neighbours; }
  const Triangles& triangles() const { return m_triangles; }

  /// Face centroids, the dual vertices (f×3).
  Positions centroids(const Positions& positions) const
  {
    Positions result(number_of_faces(), 3);
    for(Eigen::Index f = 0; f < number_of_faces(); ++f)
      result.row(f) = (positions.row(m_triangles(f, 0)) + positions.row(m_triangles(f, 1)) +
                       positions.row(m_triangles(f, 2))) / 3.0;
    return result;
  }

  /// The centroid operator F (f×n, three entries 1/3 per row).
  Eigen::SparseMatrix<double> centroid_operator() const
  {
    std::vector<Eigen::Triplet<double>> entries;
    entries.reserve(static_cast<std::size_t>(3 * number_of_faces()));
    for(Eigen::Index f = 0; f < number_of_faces(); ++f)
      for(int k = 0; k < 3; ++k)
        entries.emplace_back(static_cast<int>(f), m_triangles(f, k), 1.0 / 3.0);
    Eigen::SparseMatrix<double> F(number_of_faces(), m_number_of_vertices);
    F.setFromTriplets(entries.begin(), entries.end());
    return F;
  }

  /// Weights, normals, signed heights and coordinates at `positions`. A row
  /// whose neighbour triangle is degenerate gets uniform weights and keeps the
  /// normal of `previous` when given (the previous frame), else the direction
  /// from the neighbours' mean to the dual vertex.
  Dual_coordinates evaluate(const Positions& positions, const Positions* previous_normals = nullptr) const
  {
    const Positions c = centroids(positions);
    Dual_coordinates result;
    const Eigen::Index rows = number_of_rows();
    result.weights.resize(rows, 3);
    result.normals.resize(rows, 3);
    result.heights.resize(rows);
    result.coordinates.resize(rows, 3);
    for(Eigen::Index r = 0; r < rows; ++r)
    {
      const int f = m_row_faces[static_cast<std::size_t>(r)];
      const Eigen::Vector3d p = c.row(f).transpose();
      const Eigen::Vector3d q0 = c.row(m_neighbours(f, 0)).transpose();
      const Eigen::Vector3d q1 = c.row(m_neighbours(f, 1)).transpose();
      const Eigen::Vector3d q2 = c.row(m_neighbours(f, 2)).transpose();
      const Eigen::Vector3d normal = (q1 - q0).cross(q2 - q0);
      const double squared_norm = normal.squaredNorm();
      Eigen::Vector3d w, n;
      if(!is_degenerate(q0, q1, q2, squared_norm))
      {
        // Barycentric coordinates of the projection of p: signed areas of the
        // sub-triangles, measured along the normal (the projection drops out).
        w[0] = (q1 - p).cross(q2 - p).dot(normal) / squared_norm;
        w[1] = (q2 - p).cross(q0 - p).dot(normal) / squared_norm;
        w[2] = 1.0 - w[0] - w[1];
        n = normal / std::sqrt(squared_norm);
      }
      else
      {
        ++result.degenerate_rows;
        w.setConstant(1.0 / 3.0);
        const Eigen::Vector3d away = p - (q0 + q1 + q2) / 3.0;
        if(previous_normals != nullptr)
          n = previous_normals->row(r).transpose();
        else if(away.norm() > 0)
          n = away.normalized();
        else
          n = Eigen::Vector3d::UnitZ();
      }
      const Eigen::Vector3d l = w[0] * q0 + w[1] * q1 + w[2] * q2 - p;
      result.weights.row(r) = w.transpose();
      result.normals.row(r) = n.transpose();
      result.heights[r] = -l.dot(n);
      result.coordinates.row(r) = l.transpose();
    }
    return result;
  }

  /// The unit normals of the neighbour planes at `positions` (the `normals`
  /// of `evaluate()`), for the iterations: `normals` holds the previous
  /// normals on entry, kept for the rows whose neighbour triangle is
  /// degenerate, and the new ones on exit. `centroids` is a workspace.
  void update_normals(const Positions& positions, Positions& centroids, Positions& normals) const
  {
    const Eigen::Index f_count = number_of_faces();
    centroids.resize(f_count, 3);
#ifdef _OPENMP
#pragma omp parallel for schedule(static) if(f_count > parallel_loop_items)
#endif
    for(Eigen::Index f = 0; f < f_count; ++f)
      centroids.row(f) = (positions.row(m_triangles(f, 0)) + positions.row(m_triangles(f, 1)) +
                          positions.row(m_triangles(f, 2))) / 3.0;
    const Eigen::Index rows = number_of_rows();
#ifdef _OPENMP
#pragma omp parallel for schedule(static) if(rows > parallel_loop_items)
#endif
    for(Eigen::Index r = 0; r < rows; ++r)
    {
      const int f = m_row_faces[static_cast<std::size_t>(r)];
      const Eigen::Vector3d q0 = centroids.row(m_neighbours(f, 0)).transpose();
      const Eigen::Vector3d e1 = centroids.row(m_neighbours(f, 1)).transpose() - q0;
      const Eigen::Vector3d e2 = centroids.row(m_neighbours(f, 2)).transpose() - q0;
      const Eigen::Vector3d normal = e1.cross(e2);
      const double squared_norm = normal.squaredNorm();
      // A degenerate row keeps its normal, as in evaluate().
      if(!is_degenerate(q0, q0 + e1, q0 + e2, squared_norm))
        normals.row(r) = normal.transpose() / std::sqrt(squared_norm);
    }
  }

  /// `result` = (L̂F)ᵀ Y (n×3) for the operator of `laplacian_operator(weights)`
  /// and the rows y_r = `factors`[r] `directions`.row(r), without forming the
  /// operator: L̂F = L̂ F, so the rows are first gathered on the faces (L̂ᵀ,
  /// four updates per row), then spread on their vertices (Fᵀ). `faces` is a
  /// workspace.
  void apply_transpose(const Eigen::Matrix<double, Eigen::Dynamic, 3>& weights,
                       const Eigen::VectorXd& factors, const Positions& directions, Positions& faces,
                       Positions& result) const
  {
    faces.setZero(number_of_faces(), 3);
    for(Eigen::Index r = 0; r < number_of_rows(); ++r)
    {
      const int f = m_row_faces[static_cast<std::size_t>(r)];
      const Eigen::RowVector3d y = factors[r] * directions.row(r);
      faces.row(f) -= y;
      for(int j = 0; j < 3; ++j)
        faces.row(m_neighbours(f, j)) += weights(r, j) * y;
    }
    result.setZero(m_number_of_vertices, 3);
    for(Eigen::Index f = 0; f < number_of_faces(); ++f)
    {
      const Eigen::RowVector3d third = faces.row(f) / 3.0;
      for(int k = 0; k < 3; ++k)
        result.row(m_triangles(f, k)) += third;
    }
  }

  /// Row `r` of `laplacian_operator(weights)` applied to the vertex values
  /// `h` (one value per vertex), without forming the operator: the neighbour
  /// faces' means weighted by the row's weights, minus the face's own mean.
  template <typename Scalar>
  double apply_row(const Eigen::Matrix<double, Eigen::Dynamic, 3>& weights, Eigen::Index r,
                   const Scalar* h) const
  {
    const int f = m_row_faces[static_cast<std::size_t>(r)];
    const auto face_sum = [this, h](int g) {
      return double(h[m_triangles(g, 0)]) + double(h[m_triangles(g, 1)]) + double(h[m_triangles(g, 2)]);
    };
    double sum = -face_sum(f);
    for(int j = 0; j < 3; ++j)
      sum += weights(r, j) * face_sum(m_neighbours(f, j));
    return sum / 3.0;
  }

  /// The sparse operator L̂F (rows × n): row r maps vertex positions to the
  /// dual Laplacian coordinate Σ_j w_rj (v̂_j - v̂_r) with the given weights.
  Eigen::SparseMatrix<double> laplacian_operator(
      const Eigen::Matrix<double, Eigen::Dynamic, 3>& weights) const
  {
    std::vector<Eigen::Triplet<double>> entries;
    entries.reserve(static_cast<std::size_t>(12 * number_of_rows()));
    for(Eigen::Index r = 0; r < number_of_rows(); ++r)
    {
      const int f = m_row_faces[static_cast<std::size_t>(r)];
      for(int k = 0; k < 3; ++k)
        entries.emplace_back(static_cast<int>(r), m_triangles(f, k), -1.0 / 3.0);
      for(int j = 0; j < 3; ++j)
        for(int k = 0; k < 3; ++k)
          entries.emplace_back(static_cast<int>(r), m_triangles(m_neighbours(f, j), k),
                               weights(r, j) / 3.0);
    }
    Eigen::SparseMatrix<double> LF(number_of_rows(), m_number_of_vertices);
    LF.setFromTriplets(entries.begin(), entries.end());
    return LF;
  }

private:
  // Whether the neighbour triangle (q0, q1, q2), whose normal (q1 - q0) x
  // (q2 - q0) has the squared norm `squared_norm`, is too thin to define a
  // plane, relative to its longest edge.
  static bool is_degenerate(const Eigen::Vector3d& q0, const Eigen::Vector3d& q1,
                            const Eigen::Vector3d& q2, double squared_norm)
  {
    const double scale = (std::max)({(q1 - q0).squaredNorm(), (q2 - q1).squaredNorm(),
                                     (q0 - q2).squaredNorm()});
    return !(squared_norm > 1e-24 * scale * scale && squared_norm > 0);
  }

  void build_neighbours()
  {
    typedef Spectral_deformation_error Error;
    const Eigen::Index f_count = number_of_faces();
    // Faces incident to each vertex, in compressed rows.
    std::vector<int> start(static_cast<std::size_t>(m_number_of_vertices) + 1, 0);
    for(Eigen::Index f = 0; f < f_count; ++f)
      for(int k = 0; k < 3; ++k)
        ++start[static_cast<std::size_t>(m_triangles(f, k)) + 1];
    for(std::size_t i = 1; i < start.size(); ++i)
      start[i] += start[i - 1];
    std::vector<int> incident(static_cast<std::size_t>(start.back()));
    std::vector<int> fill(start.begin(), start.end() - 1);
    for(Eigen::Index f = 0; f < f_count; ++f)
      for(int k = 0; k < 3; ++k)
        incident[static_cast<std::size_t>(fill[static_cast<std::size_t>(m_triangles(f, k))]++)] =
            static_cast<int>(f);

    m_neighbours.setConstant(f_count, 3, -1);
    for(Eigen::Index f = 0; f < f_count; ++f)
    {
      for(int k = 0; k < 3; ++k)
      {
        const int a = m_triangles(f, k), b = m_triangles(f, (k + 1) % 3);
        int found = -1;
        for(int s = start[static_cast<std::size_t>(b)]; s < start[static_cast<std::size_t>(b) + 1]; ++s)
        {
          const int g = incident[static_cast<std::size_t>(s)];
          if(g == f)
            continue;
          for(int j = 0; j < 3; ++j)
          {
            const int ga = m_triangles(g, j), gb = m_triangles(g, (j + 1) % 3);
            if(ga == b && gb == a)
            {
              if(found != -1)
                throw Error(Error::INVALID_MESH, "edge (" + std::to_string(a) + ", " +
                                                     std::to_string(b) +
                                                     ") is shared by more than two faces");
              found = g;
            }
            else if(ga == a && gb == b)
              throw Error(Error::INVALID_MESH, "faces " + std::to_string(f) + " and " +
                                                   std::to_string(g) +
                                                   " are inconsistently oriented");
          }
        }
        m_neighbours(f, k) = found;
      }
    }
    m_row_faces.clear();
    for(Eigen::Index f = 0; f < f_count; ++f)
      if(m_neighbours(f, 0) >= 0 && m_neighbours(f, 1) >= 0 && m_neighbours(f, 2) >= 0)
        m_row_faces.push_back(static_cast<int>(f));
  }

  Triangles m_triangles;
  Eigen::Index m_number_of_vertices = 0;
  Triangles m_neighbours;
  std::vector<int> m_row_faces;
};

} // namespace Mesh
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_MESH_DUAL_MESH_OPERATOR_H

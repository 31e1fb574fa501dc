// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_COTANGENT_OPERATORS_H
#define CGAL_SPECTRAL_DEFORMATION_COTANGENT_OPERATORS_H

#include <CGAL/Spectral_deformation/internal/Memory/Large_array.h>
#include <CGAL/Spectral_deformation/internal/Mesh/Triangle_arrays.h>

#include <Eigen/Geometry>
#include <Eigen/Sparse>

#include <algorithm>
#include <vector>

namespace CGAL {
namespace Spectral_deformation {
namespace internal {

using Memory::Large_array;
using Mesh::Triangle_arrays;
using Mesh::row_vector;

typedef Eigen::SparseMatrix<double>::StorageIndex Stiffness_index;

// The cotangent stiffness matrix is assembled in compressed form directly:
// each column gathers its entries (one per incident face edge, and the
// diagonal), sorts them by row and merges the two halves of each interior
// edge. Eigen's triplet assembly moved four times as much memory.

// Where each column starts in the assembly arrays (n + 1 values): room for
// the diagonal and two entries per incident face.
inline std::vector<Stiffness_index> cotangent_column_starts(const Triangle_arrays& mesh)
{
  const Eigen::Index n = mesh.number_of_vertices();
  std::vector<Stiffness_index> start(static_cast<std::size_t>(n) + 1, 0);
  for(Eigen::Index f = 0; f < mesh.number_of_faces(); ++f)
    for(int k = 0; k < 3; ++k)
      start[static_cast<std::size_t>(mesh.triangles(f, k)) + 1] += 2;
  for(Eigen::Index j = 0; j < n; ++j)
    start[j + 1] += start[j] + 1; // + 1: the diagonal
  return start;
}

// Appends to each column its diagonal entry (0, the row sums come apart in
// `diagonal`) and the half cotangents -cot(c)/2 of the corners c opposite
// its edges, unsorted; `end` (the column starts on entry) receives the end
// of each column. With `obtuse_corners`, the obtuse corners (negative
// cotangents) count as 0 and are counted there.
inline void add_half_cotangents(const Triangle_arrays& mesh, Stiffness_index* rows,
                                double* values, std::vector<Stiffness_index>& end,
                                Eigen::VectorXd& diagonal, std::size_t* obtuse_corners = nullptr)
{
  auto add = [&](int row, int column, double value) {
    rows[end[column]] = row;
    values[end[column]++] = value;
  };
  for(Eigen::Index j = 0; j < mesh.number_of_vertices(); ++j)
    add(static_cast<int>(j), static_cast<int>(j), 0.0);
  for(Eigen::Index f = 0; f < mesh.number_of_faces(); ++f)
  {
    for(int k = 0; k < 3; ++k)
    {
      // The corner at vertex k is opposite to the edge (i, j).
      const int c = mesh.triangles(f, k);
      const int i = mesh.triangles(f, (k + 1) % 3);
      const int j = mesh.triangles(f, (k + 2) % 3);
      const Eigen::Vector3d u = row_vector(mesh.positions, i) - row_vector(mesh.positions, c);
      const Eigen::Vector3d v = row_vector(mesh.positions, j) - row_vector(mesh.positions, c);
      double half_cot = 0.5 * u.dot(v) / u.cross(v).norm();
      if(obtuse_corners != nullptr && half_cot < 0)
      {
        half_cot = 0;
        ++*obtuse_corners;
      }
      add(i, j, -half_cot);
      add(j, i, -half_cot);
      diagonal[i] += half_cot;
      diagonal[j] += half_cot;
    }
  }
}

// Sorts the entries [first, last) of a column by row (a dozen entries:
// insertion sort) and merges duplicates in place. Returns the end of the
// merged column.
inline Stiffness_index sort_and_merge_column(Stiffness_index* rows, double* values,
                                             Stiffness_index first, Stiffness_index last)
{
  for(Stiffness_index a = first + 1; a < last; ++a)
  {
    const Stiffness_index row = rows[a];
    const double value = values[a];
    Stiffness_index b = a;
    for(; b > first && rows[b - 1] > row; --b)
    {
      rows[b] = rows[b - 1];
      values[b] = values[b - 1];
    }
    rows[b] = row;
    values[b] = value;
  }
  Stiffness_index merged = first;
  for(Stiffness_index a = first; a < last; ++a)
  {
    if(a > first && rows[a] == rows[merged - 1])
      values[merged - 1] += values[a];
    else
    {
      rows[merged] = rows[a];
      values[merged++] = values[a];
    }
  }
  return merged;
}

// The n × n matrix of the merged columns [start[j], end[j]), `nonzeros`
// entries in all, with `diagonal` added to the diagonal entries.
inline Eigen::SparseMatrix<double>
compress_columns(Eigen::Index n, const std::vector<Stiffness_index>& start,
                 const std::vector<Stiffness_index>& end, const Stiffness_index* rows,
                 const double* values, const Eigen::VectorXd& diagonal, Stiffness_index nonzeros)
{
  Eigen::SparseMatrix<double> stiffness(n, n);
  stiffness.resizeNonZeros(nonzeros);
  Stiffness_index* outer = stiffness.outerIndexPtr();
  outer[0] = 0;
  for(Eigen::Index j = 0; j < n; ++j)
  {
    const Stiffness_index count = end[j] - start[j];
    std::copy(rows + start[j], rows + end[j], stiffness.innerIndexPtr() + outer[j]);
    double* column = stiffness.valuePtr() + outer[j];
    std::copy(values + start[j], values + end[j], column);
    for(Stiffness_index a = 0; a < count; ++a)
      if(stiffness.innerIndexPtr()[outer[j] + a] == j)
        column[a] += diagonal[j];
    outer[j + 1] = outer[j] + count;
  }
  return stiffness;
}

/// Cotangent stiffness matrix: Q_ij = -(cot a_ij + cot b_ij)/2 for an edge ij
/// with opposite angles a_ij and b_ij, Q_ii = -sum_j Q_ij. Symmetric, positive
/// semi-definite, rows summing to zero. The arrays must have been validated
/// (no degenerate face), which keeps every cotangent finite. With
/// `huge_pages`, the temporaries of the assembly are mapped in huge pages
/// (see Large_array): only when a traits object was asked for process-wide
/// tuning. With `obtuse_corners`, the cotangent of every obtuse corner is
/// taken as 0 (the weights stay positive: CGAL's `ORIGINAL_ARAP` clamps so)
/// and the number of such corners is written there.
inline Eigen::SparseMatrix<double> cotangent_stiffness(const Triangle_arrays& mesh,
                                                       bool huge_pages = false,
                                                       std::size_t* obtuse_corners = nullptr)
{
  const Eigen::Index n = mesh.number_of_vertices();
  const std::vector<Stiffness_index> start = cotangent_column_starts(mesh);
  // Large_array: these temporaries are tens of MiB, uninitialized; page
  // faults dominated the assembly unless they are in huge pages.
  Large_array<Stiffness_index> row_storage(static_cast<std::size_t>(start[n]), huge_pages);
  Large_array<double> value_storage(static_cast<std::size_t>(start[n]), huge_pages);
  Stiffness_index* rows = row_storage.data();
  double* values = value_storage.data();
  std::vector<Stiffness_index> end(start.begin(), start.end() - 1);
  Eigen::VectorXd diagonal = Eigen::VectorXd::Zero(n);
  if(obtuse_corners != nullptr)
    *obtuse_corners = 0;
  add_half_cotangents(mesh, rows, values, end, diagonal, obtuse_corners);
  Stiffness_index nonzeros = 0;
  for(Eigen::Index j = 0; j < n; ++j)
  {
    end[j] = sort_and_merge_column(rows, values, start[j], end[j]);
    nonzeros += end[j] - start[j];
  }
  return compress_columns(n, start, end, rows, values, diagonal, nonzeros);
}

/// Lumped (barycentric) mass: one third of the area of every incident face.
inline Eigen::VectorXd lumped_mass(const Triangle_arrays& mesh)
{
  Eigen::VectorXd mass = Eigen::VectorXd::Zero(mesh.number_of_vertices());
  for(Eigen::Index f = 0; f < mesh.number_of_faces(); ++f)
  {
    const Eigen::Vector3i t = mesh.triangles.row(f).transpose();
    const Eigen::Vector3d a = row_vector(mesh.positions, t[0]);
    const Eigen::Vector3d b = row_vector(mesh.positions, t[1]);
    const Eigen::Vector3d c = row_vector(mesh.positions, t[2]);
    const double third_area = (b - a).cross(c - a).norm() / 6.0;
    for(int k = 0; k < 3; ++k)
      mass[t[k]] += third_area;
  }
  return mass;
}

} // namespace internal
} // namespace Spectral_deformation

/// \ingroup PkgSpectralSurfaceMeshDeformationOperators
/// Returns the cotangent stiffness matrix `Q` of a triangle mesh: for an edge
/// `ij` with opposite angles `a` and `b`, `Q(i,j) = -(cot a + cot b)/2`, and
/// `Q(i,i) = -sum_j Q(i,j)`. `Q` is symmetric positive semi-definite and its
/// rows sum to zero. Row `i` corresponds to the vertex of index `i` in the
/// vertex index map.
///
/// \tparam TriangleMesh a model of `FaceListGraph`, triangulated
/// \tparam NamedParameters a sequence of CGAL named parameters
///
/// \param tm the mesh
/// \param np optional named parameters among: `vertex_point_map` (default
///        `get(CGAL::vertex_point, tm)`), `vertex_index_map` (default: an
///        initialized vertex index map of `tm`)
///
/// \throws Spectral_deformation_error (`INVALID_MESH`) when the mesh is not
///         triangulated, is empty, has a degenerate face, an isolated vertex or a
///         non-finite coordinate.
template <class TriangleMesh, class NamedParameters = parameters::Default_named_parameters>
Eigen::SparseMatrix<double>
cotangent_stiffness_matrix(const TriangleMesh& tm,
                           const NamedParameters& np = parameters::default_values())
{
  return Spectral_deformation::internal::cotangent_stiffness(
      Spectral_deformation::internal::Mesh::extract_triangle_arrays(tm, np));
}

/// \ingroup PkgSpectralSurfaceMeshDeformationOperators
/// Returns the lumped (barycentric) mass matrix `M` of a triangle mesh, a
/// diagonal matrix whose entry `i` is one third of the total area of the faces
/// incident to the vertex of index `i`.
///
/// \tparam TriangleMesh a model of `FaceListGraph`, triangulated
/// \tparam NamedParameters a sequence of CGAL named parameters
///
/// \param tm the mesh
/// \param np optional named parameters, as for `cotangent_stiffness_matrix()`
///
/// \throws Spectral_deformation_error (`INVALID_MESH`) as `cotangent_stiffness_matrix()`.
template <class TriangleMesh, class NamedParameters = parameters::Default_named_parameters>
Eigen::SparseMatrix<double>
lumped_mass_matrix(const TriangleMesh& tm,
                   const NamedParameters& np = parameters::default_values())
{
  const Eigen::VectorXd mass = Spectral_deformation::internal::lumped_mass(
      Spectral_deformation::internal::Mesh::extract_triangle_arrays(tm, np));
  Eigen::SparseMatrix<double> matrix(mass.size(), mass.size());
  matrix.reserve(Eigen::VectorXi::Ones(mass.size()));
  for(Eigen::Index i = 0; i < mass.size(); ++i)
    matrix.insert(i, i) = mass[i];
  matrix.makeCompressed();
  return matrix;
}

} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_COTANGENT_OPERATORS_H

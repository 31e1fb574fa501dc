// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_DUAL_MESH_LAPLACIAN_H
#define CGAL_DUAL_MESH_LAPLACIAN_H

#include <CGAL/Spectral_deformation/internal/Mesh/Dual_mesh_operator.h>
#include <CGAL/Spectral_deformation/internal/Mesh/Triangle_arrays.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/iterator.h>

#include <array>
#include <vector>

namespace CGAL {

/// \ingroup PkgSpectralSurfaceMeshDeformationRef
/// The dual mesh of a triangle mesh and its dual Laplacian (Au et al.\ 2006).
///
/// The dual vertex of a face is its centroid; the dual neighbours of a face
/// `(a, b, c)` are the faces across its edges `ab`, `bc` and `ca`, in that
/// order, which keeps the orientation of the face in the triangle they form.
/// For a dual vertex `v̂` with neighbours `v̂_1, v̂_2, v̂_3`, the dual Laplacian
/// weights `w_j` are the barycentric coordinates of the projection of `v̂` onto
/// the plane of its neighbours: they sum to one, and the dual Laplacian
/// coordinate `l̂ = Σ_j w_j (v̂_j - v̂) = -h n̂` is along the unit normal `n̂` of
/// that plane, with a signed height `h`.
///
/// Only faces with three dual neighbours get a coordinate (a *row*); faces
/// along a border have none. A row whose neighbour triangle is degenerate
/// (its area is negligible against its longest edge) gets uniform weights
/// and keeps a previous normal when one is given (see `evaluate()`).
///
/// Weights, normals, heights and coordinates can be evaluated at any vertex
/// positions (the original mesh, a smoothed or a deformed one) without
/// rebuilding the connectivity, and the sparse operator `L̂F` that maps vertex
/// positions to dual Laplacian coordinates is available for solvers.
///
/// Vertex positions are given as `n × 3` matrices whose row `i` is the vertex
/// of index `i` in the vertex index map given at construction; faces are
/// numbered in the order of `faces(tm)`.
///
/// \tparam TriangleMesh a model of `FaceListGraph`, triangulated.
template <class TriangleMesh>
class Dual_mesh_laplacian
{
public:
  /// Vertex positions or per-row vectors, `k × 3`.
  typedef Eigen::Matrix<double, Eigen::Dynamic, 3> Positions;
  /// Per-row barycentric weights, `rows × 3`.
  typedef Eigen::Matrix<double, Eigen::Dynamic, 3> Weights;
  /// Weights, normals, heights and coordinates at some positions, one row
  /// per row of the dual mesh. Its public members are `weights` (`rows × 3`,
  /// the barycentric weights of the neighbours across `ab`, `bc`, `ca`),
  /// `normals` (`rows × 3`, the unit normals of the neighbour planes, oriented
  /// like the face), `heights` (a vector of `rows` signed heights `h`),
  /// `coordinates` (`rows × 3`, `l̂ = -h n̂`) and `degenerate_rows` (the
  /// number of rows whose neighbour triangle was degenerate).
  typedef Spectral_deformation::internal::Mesh::Dual_coordinates Coordinates;
  /// Face descriptor of the mesh.
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;

  /// Builds the dual mesh of `tm` and evaluates its coordinates at the
  /// positions of `tm`.
  ///
  /// \tparam NamedParameters a sequence of CGAL named parameters
  /// \param tm the mesh, triangulated, with no degenerate face and no isolated vertex
  /// \param np optional named parameters among `vertex_point_map` (default
  ///        `get(CGAL::vertex_point, tm)`) and `vertex_index_map` (default: an
  ///        initialized vertex index map of `tm`)
  /// \throws Spectral_deformation_error (`INVALID_MESH`) for a mesh that is
  ///         empty or not triangulated, has degenerate faces, isolated
  ///         vertices, non-finite coordinates, edges shared by more than two
  ///         faces or inconsistently oriented faces, or a vertex index map
  ///         that is not a bijection onto `[0, num_vertices(tm))`.
  template <class NamedParameters = parameters::Default_named_parameters>
  explicit Dual_mesh_laplacian(const TriangleMesh& tm,
                               const NamedParameters& np = parameters::default_values())
  {
    const Spectral_deformation::internal::Mesh::Triangle_arrays arrays =
        Spectral_deformation::internal::Mesh::extract_triangle_arrays(tm, np);
    m_operator = Spectral_deformation::internal::Mesh::Dual_mesh_operator(
        arrays.triangles, arrays.number_of_vertices());
    m_positions = arrays.positions;
    m_rest = m_operator.evaluate(m_positions);
    m_faces.assign(faces(tm).begin(), faces(tm).end());
  }

  /// The number of vertices `n`.
  Eigen::Index number_of_vertices() const { return m_operator.number_of_vertices(); }
  /// The number of dual vertices (faces) `f`.
  Eigen::Index number_of_dual_vertices() const { return m_operator.number_of_faces(); }
  /// The number of dual vertices with three dual neighbours, which carry a coordinate.
  Eigen::Index number_of_rows() const { return m_operator.number_of_rows(); }
  /// The face index (in the order of `faces(tm)`) of row `r`.
  int face_index_of_row(Eigen::Index r) const
  {
    return m_operator.row_faces()[static_cast<std::size_t>(r)];
  }
  /// The face of row `r`.
  face_descriptor face_of_row(Eigen::Index r) const
  {
    return m_faces[static_cast<std::size_t>(face_index_of_row(r))];
  }
  /// The dual neighbours of the face of index `f`, across its edges `ab`,
  /// `bc`, `ca`; -1 across a border.
  std::array<int, 3> dual_neighbours(Eigen::Index f) const
  {
    const auto& nb = m_operator.neighbours();
    return {nb(f, 0), nb(f, 1), nb(f, 2)};
  }

  /// The vertex positions of the mesh at construction (`n × 3`).
  const Positions& positions() const { return m_positions; }
  /// The dual vertices (face centroids) at `positions` (`f × 3`).
  Positions dual_vertices(const Positions& positions) const { return m_operator.centroids(positions); }
  /// The coordinates at the positions of the mesh at construction.
  const Coordinates& rest_coordinates() const { return m_rest; }
  /// Weights, unit normals, signed heights and coordinates at `positions`
  /// (`n × 3`). A row with a degenerate neighbour triangle gets the weights
  /// 1/3 and keeps the normal of the same row in `previous_normals`
  /// (`rows × 3`) when it is given, for instance the normals of the previous
  /// iteration; otherwise its normal points from the centroid of its
  /// neighbours to its dual vertex.
  Coordinates evaluate(const Positions& positions, const Positions* previous_normals = nullptr) const
  {
    return m_operator.evaluate(positions, previous_normals);
  }

  /// The centroid operator `F` (`f × n`, entries 1/3).
  Eigen::SparseMatrix<double> centroid_operator() const { return m_operator.centroid_operator(); }
  /// The operator `L̂F` (`rows × n`) for the given weights (`rows × 3`):
  /// `L̂F X` are the dual Laplacian coordinates of positions `X` measured with
  /// these weights. Row `r` has the entry -1/3 at the vertices of its face
  /// and `w_j/3` at the vertices of its neighbour `j`, summed at the vertices
  /// they share.
  Eigen::SparseMatrix<double> laplacian_operator(const Weights& weights) const
  {
    return m_operator.laplacian_operator(weights);
  }
  /// `L̂F` with the weights of the mesh at construction.
  Eigen::SparseMatrix<double> laplacian_operator() const
  {
    return m_operator.laplacian_operator(m_rest.weights);
  }

private:
  Spectral_deformation::internal::Mesh::Dual_mesh_operator m_operator;
  Positions m_positions;
  Coordinates m_rest;
  std::vector<face_descriptor> m_faces;
};

} // namespace CGAL

#endif // CGAL_DUAL_MESH_LAPLACIAN_H

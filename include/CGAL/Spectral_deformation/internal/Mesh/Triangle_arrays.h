// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_MESH_TRIANGLE_ARRAYS_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_MESH_TRIANGLE_ARRAYS_H

#include <CGAL/Spectral_deformation/Spectral_deformation_error.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace CGAL {
namespace Spectral_deformation {
namespace internal {
namespace Mesh {

typedef Eigen::Matrix<double, Eigen::Dynamic, 3> Positions;
typedef Eigen::Matrix<int, Eigen::Dynamic, 3> Triangles;

/// A triangle mesh as plain arrays: row i of `positions` is the vertex of
/// index i, each row of `triangles` holds the indices of one face, in the
/// orientation of the face. All numerics of the package work on this form,
/// so that every FaceGraph model gives the same numbers.
struct Triangle_arrays
{
  Positions positions;
  Triangles triangles;

  Eigen::Index number_of_vertices() const { return positions.rows(); }
  Eigen::Index number_of_faces() const { return triangles.rows(); }
};

inline Eigen::Vector3d row_vector(const Positions& positions, int i)
{
  return positions.row(i).transpose();
}

/// Twice the area of triangle `t`, and its longest squared edge length.
inline void triangle_size(const Positions& positions, const Eigen::Vector3i& t,
                          double& twice_area, double& longest_squared_edge)
{
  const Eigen::Vector3d a = row_vector(positions, t[0]);
  const Eigen::Vector3d b = row_vector(positions, t[1]);
  const Eigen::Vector3d c = row_vector(positions, t[2]);
  twice_area = (b - a).cross(c - a).norm();
  longest_squared_edge =
      (std::max)({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()});
}

/// A face is degenerate when its area is negligible against its longest
/// edge: such a face has no well-defined cotangent weights. The threshold is
/// scale invariant.
inline bool is_degenerate_triangle(double twice_area, double longest_squared_edge)
{
  return !(twice_area > 1e-12 * longest_squared_edge);
}

/// Throws `Spectral_deformation_error` (INVALID_MESH) unless the arrays
/// describe a mesh the package can process: at least one face, finite
/// coordinates, no degenerate face, no vertex without an incident face.
inline void validate_triangle_arrays(const Triangle_arrays& mesh)
{
  typedef Spectral_deformation_error Error;
  const Eigen::Index n = mesh.number_of_vertices();
  if(n == 0 || mesh.number_of_faces() == 0)
    throw Error(Error::INVALID_MESH, "the mesh is empty: it has no vertex or no face");

  for(Eigen::Index i = 0; i < n; ++i)
    if(!mesh.positions.row(i).allFinite())
      throw Error(Error::INVALID_MESH,
                  "vertex " + std::to_string(i) + " has a non-finite coordinate");

  std::vector<char> referenced(static_cast<std::size_t>(n), 0);
  for(Eigen::Index f = 0; f < mesh.number_of_faces(); ++f)
  {
    const Eigen::Vector3i t = mesh.triangles.row(f).transpose();
    for(int k = 0; k < 3; ++k)
    {
      if(t[k] < 0 || t[k] >= n)
        throw Error(Error::INVALID_MESH, "face " + std::to_string(f) +
                                             " refers to a vertex index out of range");
      referenced[static_cast<std::size_t>(t[k])] = 1;
    }
    if(t[0] == t[1] || t[1] == t[2] || t[2] == t[0])
      throw Error(Error::INVALID_MESH,
                  "face " + std::to_string(f) + " uses the same vertex twice");
    double twice_area, longest;
    triangle_size(mesh.positions, t, twice_area, longest);
    if(is_degenerate_triangle(twice_area, longest))
      throw Error(Error::INVALID_MESH,
                  "face " + std::to_string(f) + " is degenerate (zero or negligible area)");
  }
  for(Eigen::Index i = 0; i < n; ++i)
    if(!referenced[static_cast<std::size_t>(i)])
      throw Error(Error::INVALID_MESH, "vertex " + std::to_string(i) +
                                           " is isolated (no incident face)");
}

/// Reads a FaceGraph through its vertex point map and vertex index map into
/// plain arrays, then validates them. Throws `Spectral_deformation_error`.
template <class TriangleMesh, class VertexPointMap, class VertexIndexMap>
Triangle_arrays extract_triangle_arrays(const TriangleMesh& tm, VertexPointMap vpm,
                                        VertexIndexMap vim)
{
  typedef Spectral_deformation_error Error;
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;

  Triangle_arrays arrays;
  const std::size_t n = static_cast<std::size_t>(num_vertices(tm));
  arrays.positions.resize(static_cast<Eigen::Index>(n), 3);
  std::vector<char> seen(n, 0);
  for(auto v : vertices(tm))
  {
    const std::size_t i = static_cast<std::size_t>(get(vim, v));
    if(i >= n || seen[i])
      throw Error(Error::INVALID_MESH,
                  "the vertex index map is not a bijection onto [0, number of vertices)");
    seen[i] = 1;
    // By index, as CGAL's RawPoint_3 concept reads points: OpenMesh's own
    // points (OpenMesh::Vec3d with CGAL_USE_OM_POINTS) have no x().
    const auto& p = get(vpm, v);
    arrays.positions.row(static_cast<Eigen::Index>(i))
        << CGAL::to_double(p[0]), CGAL::to_double(p[1]), CGAL::to_double(p[2]);
  }

  arrays.triangles.resize(static_cast<Eigen::Index>(num_faces(tm)), 3);
  Eigen::Index f = 0;
  for(auto face : faces(tm))
  {
    int k = 0;
    for(halfedge_descriptor h : halfedges_around_face(halfedge(face, tm), tm))
    {
      if(k == 3)
        throw Error(Error::INVALID_MESH, "face " + std::to_string(f) +
                                             " is not a triangle: the mesh must be triangulated");
      arrays.triangles(f, k++) = static_cast<int>(get(vim, target(h, tm)));
    }
    if(k != 3)
      throw Error(Error::INVALID_MESH, "face " + std::to_string(f) +
                                           " has fewer than three vertices");
    ++f;
  }
  validate_triangle_arrays(arrays);
  return arrays;
}

/// The same, with the maps taken from CGAL named parameters
/// (`vertex_point_map`, `vertex_index_map`).
template <class TriangleMesh, class NamedParameters>
Triangle_arrays extract_triangle_arrays(const TriangleMesh& tm, const NamedParameters& np)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  auto vpm = choose_parameter(get_parameter(np, internal_np::vertex_point),
                              get_const_property_map(vertex_point, tm));
  auto vim = CGAL::get_initialized_vertex_index_map(tm, np);
  return extract_triangle_arrays(tm, vpm, vim);
}

/// The connected component of every vertex (components numbered from 0 in
/// the order of their first vertex), and their number.
inline std::vector<int> connected_components(const Triangles& triangles, Eigen::Index n,
                                             int& number_of_components)
{
  std::vector<int> parent(static_cast<std::size_t>(n));
  for(std::size_t i = 0; i < parent.size(); ++i)
    parent[i] = static_cast<int>(i);
  auto find = [&parent](int i) {
    while(parent[static_cast<std::size_t>(i)] != i)
    {
      parent[static_cast<std::size_t>(i)] =
          parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(i)])];
      i = parent[static_cast<std::size_t>(i)];
    }
    return i;
  };
  for(Eigen::Index f = 0; f < triangles.rows(); ++f)
    for(int k = 1; k < 3; ++k)
    {
      const int a = find(triangles(f, 0)), b = find(triangles(f, k));
      if(a != b)
        parent[static_cast<std::size_t>((std::max)(a, b))] = (std::min)(a, b);
    }
  std::vector<int> component(static_cast<std::size_t>(n), -1);
  std::vector<int> label_of_root(static_cast<std::size_t>(n), -1);
  number_of_components = 0;
  for(Eigen::Index i = 0; i < n; ++i)
  {
    const int root = find(static_cast<int>(i));
    int& label = label_of_root[static_cast<std::size_t>(root)];
    if(label < 0)
      label = number_of_components++;
    component[static_cast<std::size_t>(i)] = label;
  }
  return component;
}

/// A 64-bit FNV-1a digest of the connectivity and the exact coordinates: it
/// identifies the mesh a stored basis belongs to.
inline std::uint64_t fingerprint(const Triangle_arrays& mesh)
{
  std::uint64_t hash = 1469598103934665603ull;
  auto add_bytes = [&hash](const void* data, std::size_t size) {
    const unsigned char* bytes = static_cast<const unsigned char*>(data);
    for(std::size_t i = 0; i < size; ++i)
    {
      hash ^= bytes[i];
      hash *= 1099511628211ull;
    }
  };
  const std::int64_t counts[2] = {static_cast<std::int64_t>(mesh.number_of_vertices()),
                                  static_cast<std::int64_t>(mesh.number_of_faces())};
  add_bytes(counts, sizeof(counts));
  for(Eigen::Index f = 0; f < mesh.number_of_faces(); ++f)
    for(int k = 0; k < 3; ++k)
    {
      const std::int32_t index = mesh.triangles(f, k);
      add_bytes(&index, sizeof(index));
    }
  for(Eigen::Index i = 0; i < mesh.number_of_vertices(); ++i)
    for(int k = 0; k < 3; ++k)
    {
      const double x = mesh.positions(i, k) + 0.0; // maps -0.0 to +0.0
      add_bytes(&x, sizeof(x));
    }
  return hash;
}

} // namespace Mesh
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_MESH_TRIANGLE_ARRAYS_H

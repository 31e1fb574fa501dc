// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_MESH_REGION_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_MESH_REGION_H

#include <CGAL/Spectral_deformation/Spectral_deformation_error.h>
#include <CGAL/Spectral_deformation/internal/Mesh/Triangle_arrays.h>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Spatial_sort_traits_adapter_3.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/hilbert_sort.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Spectral_deformation {
namespace internal {
namespace Mesh {

/// The part of a mesh a deformation works on: the faces incident to a vertex
/// of the region of interest, with local vertex indices, and what the
/// solvers need to know about it.
struct Region_geometry
{
  std::vector<char> is_fixed; ///< per local vertex: in the region, outside the ROI
  Triangle_arrays arrays;     ///< positions at rest and triangles, local indices
  double diagonal = 0;        ///< bounding-box diagonal of the rest positions
  std::vector<int> component; ///< per local vertex: its connected component
  int number_of_components = 0;
  /// The local index of the k-th region vertex in the order of the mesh's
  /// vertex indices, and the row in `arrays.triangles` of the k-th face in
  /// the mesh's traversal order (see `in_mesh_order()`).
  std::vector<int> vertex_from_mesh_order;
  std::vector<int> face_from_mesh_order;

  Eigen::Index number_of_vertices() const { return arrays.number_of_vertices(); }
};

/// The arrays of `region` with its vertices in the order of the mesh's
/// vertex indices and its faces in the mesh's traversal order: the arrays a
/// basis of the whole mesh is computed on (`CGAL::Manifold_harmonics_basis`),
/// and those of the regions of version 0.1, whose basis files name them.
inline Triangle_arrays in_mesh_order(const Region_geometry& region)
{
  Triangle_arrays result;
  const std::vector<int>& vertex = region.vertex_from_mesh_order;
  std::vector<int> mesh_order(vertex.size());
  result.positions.resize(static_cast<Eigen::Index>(vertex.size()), 3);
  for(std::size_t k = 0; k < vertex.size(); ++k)
  {
    mesh_order[static_cast<std::size_t>(vertex[k])] = static_cast<int>(k);
    result.positions.row(static_cast<Eigen::Index>(k)) = region.arrays.positions.row(vertex[k]);
  }
  result.triangles.resize(static_cast<Eigen::Index>(region.face_from_mesh_order.size()), 3);
  for(std::size_t f = 0; f < region.face_from_mesh_order.size(); ++f)
    for(int c = 0; c < 3; ++c)
      result.triangles(static_cast<Eigen::Index>(f), c) =
          mesh_order[static_cast<std::size_t>(region.arrays.triangles(region.face_from_mesh_order[f], c))];
  return result;
}

/// A `Region_geometry` and the vertices of the mesh it was cut from.
template <class VertexDescriptor>
struct Region : Region_geometry
{
  std::vector<VertexDescriptor> vertices; ///< local index -> vertex
  std::vector<int> local;                 ///< vertex index -> local index, or -1
};

/// The order of `positions` (n×3) along a Hilbert curve (CGAL's
/// `hilbert_sort()`, median policy, which is deterministic): neighbours on
/// the surface get nearby indices. Every pass over the region gathers the
/// rows of its neighbours (one-rings, faces, sparse rows), and meshes often
/// number their vertices with little locality (Loop subdivision appends the
/// new vertices at the end), which leaves most of those gathers to miss the
/// cache.
inline std::vector<std::size_t> spatial_order(const Positions& positions)
{
  typedef CGAL::Simple_cartesian<double> Kernel;
  typedef Kernel::Point_3 Point_3;
  std::vector<Point_3> points;
  points.reserve(static_cast<std::size_t>(positions.rows()));
  for(Eigen::Index i = 0; i < positions.rows(); ++i)
    points.emplace_back(positions(i, 0), positions(i, 1), positions(i, 2));
  std::vector<std::size_t> order(points.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  typedef CGAL::Pointer_property_map<Point_3>::type Point_map;
  CGAL::hilbert_sort(order.begin(), order.end(),
                     CGAL::Spatial_sort_traits_adapter_3<Kernel, Point_map>(CGAL::make_property_map(points)),
                     CGAL::Hilbert_sort_median_policy());
  return order;
}

/// Cuts the region of the vertices flagged in `is_roi` (indexed by `id`) out
/// of `tm`, with the rest positions `rest` (indexed likewise), local vertices
/// in the order of `spatial_order()` and faces by their lowest local vertex,
/// and validates it. Throws
/// `Spectral_deformation_error` (`INVALID_MESH`) when a face touching the ROI
/// is not a triangle, no face touches the ROI, or the region is not a valid
/// triangle mesh.
template <class TriangleMesh, class VertexIndex, class Point>
Region<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>
extract_region(const TriangleMesh& tm, const VertexIndex& id, const std::vector<char>& is_roi,
               const std::vector<Point>& rest)
{
  typedef Spectral_deformation_error Error;
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  const std::size_t n = is_roi.size();
  std::vector<char> in_region(n, 0);
  std::vector<std::array<std::size_t, 3>> faces_of_region;
  for(auto f : faces(tm))
  {
    std::array<std::size_t, 3> t;
    int k = 0;
    bool touches_roi = false;
    for(auto h : halfedges_around_face(halfedge(f, tm), tm))
    {
      if(k == 3)
        throw Error(Error::INVALID_MESH, "the mesh is not triangulated");
      t[static_cast<std::size_t>(k)] = id(target(h, tm));
      touches_roi = touches_roi || is_roi[t[static_cast<std::size_t>(k)]];
      ++k;
    }
    if(k != 3)
      throw Error(Error::INVALID_MESH, "the mesh has a face with fewer than three vertices");
    if(!touches_roi)
      continue;
    faces_of_region.push_back(t);
    for(std::size_t i : t)
      in_region[i] = 1;
  }
  if(faces_of_region.empty())
    throw Error(Error::INVALID_MESH, "no face is incident to the region of interest");

  Region<vertex_descriptor> region;
  std::vector<vertex_descriptor> by_index(n);
  for(vertex_descriptor vd : vertices(tm))
    by_index[id(vd)] = vd;
  std::vector<std::size_t> members;
  for(std::size_t i = 0; i < n; ++i)
    if(in_region[i])
      members.push_back(i);
  const Eigen::Index region_size = static_cast<Eigen::Index>(members.size());
  Positions by_member(region_size, 3);
  for(Eigen::Index r = 0; r < region_size; ++r)
  {
    const Point& p = rest[members[static_cast<std::size_t>(r)]];
    by_member.row(r) << CGAL::to_double(p[0]), CGAL::to_double(p[1]), CGAL::to_double(p[2]);
  }
  // A non-finite coordinate has no place on the curve (and would break the
  // sort's ordering): such a region keeps the mesh's order, and
  // validate_triangle_arrays() below names the vertex.
  std::vector<std::size_t> order(members.size());
  if(by_member.allFinite())
    order = spatial_order(by_member);
  else
    std::iota(order.begin(), order.end(), std::size_t(0));
  region.vertex_from_mesh_order.resize(order.size());
  for(std::size_t r = 0; r < order.size(); ++r)
    region.vertex_from_mesh_order[order[r]] = static_cast<int>(r);
  region.local.assign(n, -1);
  region.vertices.reserve(members.size());
  region.is_fixed.reserve(members.size());
  region.arrays.positions.resize(region_size, 3);
  for(std::size_t r = 0; r < order.size(); ++r)
  {
    const std::size_t i = members[order[r]];
    region.local[i] = static_cast<int>(r);
    region.vertices.push_back(by_index[i]);
    region.is_fixed.push_back(is_roi[i] ? 0 : 1);
    region.arrays.positions.row(static_cast<Eigen::Index>(r)) = by_member.row(static_cast<Eigen::Index>(order[r]));
  }
  // Faces by their lowest local vertex (a counting sort, stable): the faces
  // around a vertex then lie near each other too.
  const auto lowest = [&region](const std::array<std::size_t, 3>& t) {
    return static_cast<std::size_t>((std::min)({region.local[t[0]], region.local[t[1]], region.local[t[2]]}));
  };
  std::vector<int> first_face(static_cast<std::size_t>(region_size) + 1, 0);
  for(const std::array<std::size_t, 3>& t : faces_of_region)
    ++first_face[lowest(t) + 1];
  std::partial_sum(first_face.begin(), first_face.end(), first_face.begin());
  region.arrays.triangles.resize(static_cast<Eigen::Index>(faces_of_region.size()), 3);
  region.face_from_mesh_order.reserve(faces_of_region.size());
  for(const std::array<std::size_t, 3>& t : faces_of_region)
  {
    const int f = first_face[lowest(t)]++;
    region.face_from_mesh_order.push_back(f);
    for(int k = 0; k < 3; ++k)
      region.arrays.triangles(f, k) = region.local[t[static_cast<std::size_t>(k)]];
  }
  validate_triangle_arrays(region.arrays);
  region.component =
      connected_components(region.arrays.triangles, region.arrays.number_of_vertices(), region.number_of_components);
  region.diagonal =
      (region.arrays.positions.colwise().maxCoeff() - region.arrays.positions.colwise().minCoeff()).norm();
  return region;
}

} // namespace Mesh
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_MESH_REGION_H

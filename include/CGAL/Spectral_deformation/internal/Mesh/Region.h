// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_MESH_REGION_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_MESH_REGION_H

#include <CGAL/Spectral_deformation/Spectral_deformation_error.h>
#include <CGAL/Spectral_deformation/internal/Mesh/Triangle_arrays.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <array>
#include <cstddef>
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

  Eigen::Index number_of_vertices() const { return arrays.number_of_vertices(); }
};

/// A `Region_geometry` and the vertices of the mesh it was cut from.
template <class VertexDescriptor>
struct Region : Region_geometry
{
  std::vector<VertexDescriptor> vertices; ///< local index -> vertex
  std::vector<int> local;                 ///< vertex index -> local index, or -1
};

/// Cuts the region of the vertices flagged in `is_roi` (indexed by `id`) out
/// of `tm`, with the rest positions `rest` (indexed likewise), local vertices
/// in the order of their indices, and validates it. Throws
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
  region.local.assign(n, -1);
  for(std::size_t i = 0; i < n; ++i)
    if(in_region[i])
    {
      region.local[i] = static_cast<int>(region.vertices.size());
      region.vertices.push_back(by_index[i]);
      region.is_fixed.push_back(is_roi[i] ? 0 : 1);
    }
  const Eigen::Index region_size = static_cast<Eigen::Index>(region.vertices.size());
  region.arrays.positions.resize(region_size, 3);
  for(Eigen::Index r = 0; r < region_size; ++r)
  {
    const Point& p = rest[id(region.vertices[static_cast<std::size_t>(r)])];
    region.arrays.positions.row(r) << CGAL::to_double(p[0]), CGAL::to_double(p[1]), CGAL::to_double(p[2]);
  }
  region.arrays.triangles.resize(static_cast<Eigen::Index>(faces_of_region.size()), 3);
  for(std::size_t f = 0; f < faces_of_region.size(); ++f)
    for(int k = 0; k < 3; ++k)
      region.arrays.triangles(static_cast<Eigen::Index>(f), k) =
          region.local[faces_of_region[f][static_cast<std::size_t>(k)]];
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

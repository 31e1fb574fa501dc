// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_VERTEX_SELECTION_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_VERTEX_SELECTION_H

#include <CGAL/Spectral_deformation/Spectral_deformation_error.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Spectral_deformation {
namespace internal {
namespace Deformation {

/// What the user selected on a mesh, indexed by the vertex index map: the
/// region of interest, the control vertices and their targets, and the
/// initial positions. It checks the vertices it is handed and knows nothing
/// of the computation.
template <class TriangleMesh, class VertexIndexMap, class VertexPointMap>
class Vertex_selection
{
public:
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  typedef typename boost::property_traits<VertexPointMap>::value_type Point;

  /// Reads the initial positions. Throws `INVALID_MESH` when the vertex
  /// index map is not a bijection onto [0, number of vertices).
  Vertex_selection(TriangleMesh& tm, VertexIndexMap vim, VertexPointMap vpm) : m_tm(tm), m_vim(vim), m_vpm(vpm)
  {
    const std::size_t n = static_cast<std::size_t>(num_vertices(m_tm));
    m_is_roi.assign(n, 0);
    m_is_control.assign(n, 0);
    m_original.resize(n);
    std::vector<char> seen(n, 0);
    for(vertex_descriptor vd : vertices(m_tm))
    {
      const std::size_t i = id(vd);
      if(i >= n || seen[i])
        throw Spectral_deformation_error(
            Spectral_deformation_error::INVALID_MESH,
            "the vertex index map is not a bijection onto [0, number of vertices) "
            "(for a Surface_mesh with removed elements, call collect_garbage() first)");
      seen[i] = 1;
      m_original[i] = get(m_vpm, vd);
    }
    m_target = m_original;
    m_is_vertex.swap(seen); // removed, not collected, vertices are not vertices
  }

  TriangleMesh& mesh() const { return m_tm; }
  const VertexIndexMap& vertex_index_map() const { return m_vim; }

  std::size_t id(vertex_descriptor vd) const { return static_cast<std::size_t>(get(m_vim, vd)); }

  /// Whether `vd` is a vertex of the mesh as it was at construction.
  bool has_index(vertex_descriptor vd) const
  {
    return vd != boost::graph_traits<TriangleMesh>::null_vertex() && id(vd) < m_is_roi.size() &&
           m_is_vertex[id(vd)] != 0;
  }

  /// The index of `vd`; throws `INVALID_ARGUMENT` when it is not a vertex.
  std::size_t checked_id(vertex_descriptor vd) const
  {
    if(!has_index(vd))
      throw Spectral_deformation_error(Spectral_deformation_error::INVALID_ARGUMENT,
                                       "the vertex is not a vertex of the mesh");
    return id(vd);
  }

  bool mesh_size_changed() const { return static_cast<std::size_t>(num_vertices(m_tm)) != m_is_roi.size(); }

  const std::vector<vertex_descriptor>& roi() const { return m_roi; }
  bool is_roi(vertex_descriptor vd) const { return has_index(vd) && m_is_roi[id(vd)] != 0; }
  bool is_control(vertex_descriptor vd) const { return has_index(vd) && m_is_control[id(vd)] != 0; }
  /// Whether the vertex of index `i` is a control vertex.
  bool is_control_index(std::size_t i) const { return m_is_control[i] != 0; }
  std::size_t number_of_indices() const { return m_is_control.size(); }

  /// Returns whether the ROI changed.
  bool insert_roi(vertex_descriptor vd)
  {
    if(is_roi(vd))
      return false;
    m_is_roi[checked_id(vd)] = 1;
    m_roi.push_back(vd);
    return true;
  }

  /// Erases `vd` from the ROI and from the control vertices; returns whether
  /// the ROI changed.
  bool erase_roi(vertex_descriptor vd)
  {
    if(!is_roi(vd))
      return false;
    m_is_control[id(vd)] = 0;
    m_is_roi[id(vd)] = 0;
    m_roi.erase(std::find(m_roi.begin(), m_roi.end(), vd));
    return true;
  }

  void clear_roi()
  {
    m_roi.clear();
    std::fill(m_is_roi.begin(), m_is_roi.end(), 0);
    clear_controls();
  }

  /// Makes `vd`, already in the ROI, a control vertex whose target is its
  /// current position; returns whether it was not one.
  bool insert_control(vertex_descriptor vd)
  {
    CGAL_precondition(is_roi(vd));
    if(is_control(vd))
      return false;
    m_is_control[id(vd)] = 1;
    m_target[id(vd)] = get(m_vpm, vd);
    return true;
  }

  bool erase_control(vertex_descriptor vd)
  {
    if(!is_control(vd))
      return false;
    m_is_control[id(vd)] = 0;
    return true;
  }

  void clear_controls() { std::fill(m_is_control.begin(), m_is_control.end(), 0); }

  const Point& target(vertex_descriptor vd) const { return m_target[checked_id(vd)]; }

  /// Throws `INVALID_ARGUMENT`, the target unchanged, when `p` is not finite.
  void set_target(vertex_descriptor vd, const Point& p)
  {
    if(!(std::isfinite(CGAL::to_double(p[0])) && std::isfinite(CGAL::to_double(p[1])) &&
         std::isfinite(CGAL::to_double(p[2]))))
      throw Spectral_deformation_error(Spectral_deformation_error::INVALID_ARGUMENT,
                                       "a target position is not finite");
    m_target[checked_id(vd)] = p;
  }

  const Point& original(vertex_descriptor vd) const { return m_original[id(vd)]; }
  const std::vector<Point>& originals() const { return m_original; }
  const std::vector<char>& roi_flags() const { return m_is_roi; }

  void put_position(vertex_descriptor vd, const Point& p) const { put(m_vpm, vd, p); }
  Point position(vertex_descriptor vd) const { return get(m_vpm, vd); }

  /// The ROI vertices and the targets of the control vertices back at their
  /// initial positions.
  void reset_to_original()
  {
    for(vertex_descriptor vd : m_roi)
    {
      put(m_vpm, vd, m_original[id(vd)]);
      if(is_control(vd))
        m_target[id(vd)] = m_original[id(vd)];
    }
  }

  /// The current positions of the ROI vertices become their initial ones.
  void overwrite_original()
  {
    for(vertex_descriptor vd : m_roi)
      m_original[id(vd)] = get(m_vpm, vd);
  }

private:
  TriangleMesh& m_tm;
  VertexIndexMap m_vim;
  VertexPointMap m_vpm;

  std::vector<Point> m_original;
  std::vector<Point> m_target;
  std::vector<vertex_descriptor> m_roi;
  std::vector<char> m_is_roi;
  std::vector<char> m_is_control;
  std::vector<char> m_is_vertex;
};

} // namespace Deformation
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_VERTEX_SELECTION_H

// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_ROI_AND_CONTROL_VERTICES_H
#define CGAL_SPECTRAL_DEFORMATION_ROI_AND_CONTROL_VERTICES_H

#include <CGAL/Spectral_deformation/Spectral_parameters.h>

#include <CGAL/assertions.h>

namespace CGAL {
namespace Spectral_deformation {

/// \ingroup PkgSpectralSurfaceMeshDeformationRef
/// The region of interest, the control vertices and their targets, with the
/// semantics of CGAL's `Surface_mesh_deformation`: a public base of
/// `Spectral_surface_mesh_deformation`, whose functions they are. Its own
/// public base `Spectral_parameters` holds the parameters of the spectral
/// algorithms. It holds no data: the selection and the computation are the
/// deformation class's, reached through it (the curiously recurring template
/// pattern).
///
/// \tparam Deformation the deformation class, `Spectral_surface_mesh_deformation`
/// \tparam TM the mesh type of the deformation
/// \tparam EigensolverTraits the eigensolver traits of the deformation
/// \tparam Computation the computation on the region behind the deformation
///         class (not documented: an implementation detail)
/// \tparam Selection the vertices selected on the mesh, their targets and
///         initial positions (not documented: an implementation detail)
template <class Deformation, class TM, class EigensolverTraits, class Computation, class Selection>
class Roi_and_control_vertices : public Spectral_parameters<Deformation, TM, EigensolverTraits, Computation>
{
  typedef typename Selection::vertex_descriptor vertex_descriptor;
  typedef typename Selection::Point Point;

public:
  /// \name Region of interest and control vertices
  /// @{

  /// Erases all the vertices from the region of interest (control vertices included).
  void clear_roi_vertices()
  {
    selection().clear_roi();
    computation().roi_changed();
  }

  /// Erases all the vertices from the set of control vertices.
  void clear_control_vertices()
  {
    selection().clear_controls();
    computation().constraints_changed();
  }

  /// Inserts `vd` in the set of control vertices, and in the ROI if needed
  /// (which changes the region). Its target is its current position. Returns
  /// `true` if `vd` was not a control vertex.
  /// \throws Spectral_deformation_error (`INVALID_ARGUMENT`) when `vd` is not
  ///         a vertex of the mesh (null, removed, or an index out of range).
  bool insert_control_vertex(vertex_descriptor vd)
  {
    if(selection().is_control(vd))
      return false;
    insert_roi_vertex(vd);
    selection().insert_control(vd);
    computation().constraints_changed();
    return true;
  }

  /// Inserts the vertices of `[begin, end)` in the set of control vertices.
  /// \tparam InputIterator an input iterator with `vertex_descriptor` as value type
  template <class InputIterator>
  void insert_control_vertices(InputIterator begin, InputIterator end)
  {
    for(; begin != end; ++begin)
      insert_control_vertex(*begin);
  }

  /// Erases `vd` from the set of control vertices (it stays in the ROI).
  /// Returns `true` if `vd` was a control vertex.
  bool erase_control_vertex(vertex_descriptor vd)
  {
    if(!selection().erase_control(vd))
      return false;
    computation().constraints_changed();
    return true;
  }

  /// Inserts the vertices of `[begin, end)` in the ROI.
  /// \tparam InputIterator an input iterator with `vertex_descriptor` as value type
  template <class InputIterator>
  void insert_roi_vertices(InputIterator begin, InputIterator end)
  {
    for(; begin != end; ++begin)
      insert_roi_vertex(*begin);
  }

  /// Inserts `vd` in the ROI. Returns `true` if it was not in it; the region
  /// is then rebuilt, basis included, by the next `preprocess()`.
  /// \throws Spectral_deformation_error (`INVALID_ARGUMENT`) when `vd` is not
  ///         a vertex of the mesh (null, removed, or an index out of range).
  bool insert_roi_vertex(vertex_descriptor vd)
  {
    if(!selection().insert_roi(vd))
      return false;
    computation().roi_changed();
    return true;
  }

  /// Erases `vd` from the ROI and from the control vertices. At the next
  /// `preprocess()`, a vertex no longer in the ROI is put back at its initial
  /// position. Returns `true` if `vd` was in the ROI.
  bool erase_roi_vertex(vertex_descriptor vd)
  {
    if(!selection().erase_roi(vd))
      return false;
    computation().roi_changed();
    return true;
  }

  /// Prepares `deform()` for the current ROI and control vertices; called by
  /// `deform()` when needed. Builds the region (basis, reduced matrices,
  /// detail transfer) when the ROI, the initial geometry or the number of
  /// frequencies changed, then factors the systems of the constraint set.
  /// Returns at once when nothing changed since its last success.
  ///
  /// Returns `false`, with the reason in `preprocess_report().message`, when
  /// the ROI is empty, there is no constraint at all, a connected part of the
  /// region has no constrained vertex, the region is not a valid triangle
  /// mesh (degenerate faces, non-manifold edges, ...), or a numerical step
  /// fails. The mesh is never modified by `preprocess()`, except that
  /// vertices erased from the ROI return to their initial positions.
  bool preprocess() { return computation().preprocess(selection()); }

  /// @}

  /// \name Targets
  /// @{

  /// Sets the target position of the control vertex `vd`; does nothing when
  /// `vd` is not a control vertex.
  /// \throws Spectral_deformation_error (`INVALID_ARGUMENT`) when
  ///         `target_position` is not finite (the target is then unchanged).
  void set_target_position(vertex_descriptor vd, const Point& target_position)
  {
    if(selection().is_control(vd))
      selection().set_target(vd, target_position);
  }

  /// Translates the target of the control vertex `vd` by `t`; does nothing
  /// when `vd` is not a control vertex.
  /// \tparam Vect a 3D vector with `operator[](int)` and a constructor from three coordinates
  /// \throws Spectral_deformation_error (`INVALID_ARGUMENT`) when the new
  ///         target is not finite.
  template <class Vect>
  void translate(vertex_descriptor vd, const Vect& t)
  {
    if(!selection().is_control(vd))
      return;
    const Point& p = selection().target(vd);
    set_target_position(vd, Point(p[0] + t[0], p[1] + t[1], p[2] + t[2]));
  }

  /// Translates the targets of the control vertices of `[begin, end)` by `t`
  /// (see the single-vertex overload).
  template <class InputIterator, class Vect>
  void translate(InputIterator begin, InputIterator end, const Vect& t)
  {
    for(; begin != end; ++begin)
      translate(*begin, t);
  }

  /// Rotates the target of the control vertex `vd` by `quat` around the
  /// point at `to_rotation_center` from the origin (cumulative, as in CGAL);
  /// does nothing when `vd` is not a control vertex.
  /// \tparam Quaternion a quaternion with `Vect operator*(Quaternion, Vect)`
  /// \tparam Vect a 3D vector with `operator[](int)` and a constructor from three coordinates
  /// \throws Spectral_deformation_error (`INVALID_ARGUMENT`) when the new
  ///         target is not finite.
  template <typename Quaternion, typename Vect>
  void rotate(vertex_descriptor vd, const Vect& to_rotation_center, const Quaternion& quat)
  {
    if(!selection().is_control(vd))
      return;
    const Point& p = selection().target(vd);
    const Vect relative(p[0] - to_rotation_center[0], p[1] - to_rotation_center[1],
                        p[2] - to_rotation_center[2]);
    const Vect v = quat * relative;
    set_target_position(vd, Point(to_rotation_center[0] + v[0], to_rotation_center[1] + v[1],
                                  to_rotation_center[2] + v[2]));
  }

  /// Rotates the targets of the control vertices of `[begin, end)` (see the
  /// single-vertex overload).
  template <typename InputIterator, typename Vect, typename Quaternion>
  void rotate(InputIterator begin, InputIterator end, const Vect& to_rotation_center,
              const Quaternion& quat)
  {
    for(; begin != end; ++begin)
      rotate(*begin, to_rotation_center, quat);
  }

  /// The target position of the control vertex `vd`.
  /// \pre `vd` is a control vertex (as in CGAL).
  const Point& target_position(vertex_descriptor vd)
  {
    CGAL_precondition(selection().is_control(vd));
    return selection().target(vd);
  }

  /// @}

protected:
  Roi_and_control_vertices() = default;
  ~Roi_and_control_vertices() = default;
  Roi_and_control_vertices(const Roi_and_control_vertices&) = delete;
  Roi_and_control_vertices& operator=(const Roi_and_control_vertices&) = delete;

private:
  Computation& computation() { return static_cast<Deformation&>(*this).m_computation; }
  Selection& selection() { return static_cast<Deformation&>(*this).m_selection; }
  const Selection& selection() const { return static_cast<const Deformation&>(*this).m_selection; }
};

} // namespace Spectral_deformation
} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_ROI_AND_CONTROL_VERTICES_H

// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_SURFACE_MESH_DEFORMATION_H
#define CGAL_SPECTRAL_SURFACE_MESH_DEFORMATION_H

#include <CGAL/Manifold_harmonics_basis.h>
#include <CGAL/Spectral_deformation/Spectral_deformation_error.h>
#include <CGAL/Spectral_deformation/Sparse_spd_solver_traits.h>
#include <CGAL/Spectral_deformation/Block_lanczos_eigensolver_traits.h>
#include <CGAL/Spectral_deformation/Spectra_eigensolver_traits.h>
#include <CGAL/Spectral_deformation/internal/Deformation/Detail_transfer.h>
#include <CGAL/Spectral_deformation/internal/Deformation/Spatial_dual_laplacian_solver.h>
#include <CGAL/Spectral_deformation/internal/Deformation/Spectral_dual_laplacian_solver.h>
#include <CGAL/Spectral_deformation/internal/Mesh/Triangle_arrays.h>
#include <CGAL/Spectral_deformation/internal/Basis/basis_io.h>
#include <CGAL/Spectral_deformation/internal/Deformation/rigid_fit.h>

#include <CGAL/Default.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/boost/graph/properties.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <istream>
#include <limits>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

namespace CGAL {

/// \ingroup PkgSpectralSurfaceMeshDeformationRef
/// The algorithms of `Spectral_surface_mesh_deformation`, its template
/// parameter `TAG`.
enum Spectral_deformation_algorithm_tag {
  /// The paper's algorithm (the default): dual Laplacian editing in the space
  /// of the first `m` manifold harmonics, iterated so that the dual Laplacian
  /// coordinates follow the local rotations, then detail transfer.
  SPECTRAL_DUAL_LAPLACIAN,
  /// The same reduced system solved once with the dual Laplacian coordinates
  /// of the rest shape, then detail transfer: the linear spectral solution
  /// the paper compares against, which cannot follow large rotations.
  /// Every `deform()` starts again from the rest shape, and the number of
  /// iterations is not used.
  SPECTRAL_LINEAR,
  /// Dual Laplacian editing of Au et al.\ 2006 on the detailed region, the
  /// paper's spatial baseline: a sparse system of the size of the region,
  /// factored once per constraint set, with the constrained vertices
  /// eliminated (they land exactly on their targets). There is no basis and
  /// no detail transfer; the constraint weight and the constraint policy are
  /// not used.
  SPATIAL_DUAL_LAPLACIAN
};

/// \ingroup PkgSpectralSurfaceMeshDeformationRef
/// How the spectral algorithms of `Spectral_surface_mesh_deformation` meet
/// the constraints (`SPATIAL_DUAL_LAPLACIAN` always meets them exactly).
///
/// In both policies the reduced solve meets the constraints of the smooth
/// mesh in the least-squares sense, and the vertices outside the region of
/// interest are never moved; the policies differ in the detail transfer.
enum Spectral_constraint_policy {
  /// CGAL's semantics (the default): control vertices land exactly on their
  /// targets and the region of interest joins the fixed vertices around it.
  /// The detail transfer is a Poisson problem in which the control vertices
  /// and the fixed vertices are prescribed; `preprocess()` factors it once
  /// per constraint set, a sparse factorization of the size of the region.
  EXACT_CONSTRAINTS,
  /// The paper's formulation: the control vertices are met in the least
  /// squares sense only. The detail transfer prescribes the fixed vertices
  /// around the region of interest, which only change with the region, so it
  /// is factored once per region and a new constraint set costs no sparse
  /// factorization at all (only the `m × m` one); in a connected part of the
  /// region without fixed vertices, the translation that best matches the
  /// control vertices is fitted. Control vertices land near their targets
  /// (the residuals are in `Spectral_deformation_report`); the region joins
  /// the fixed vertices as with the exact policy.
  SOFT_CONSTRAINTS
};

/// \ingroup PkgSpectralSurfaceMeshDeformationRef
/// What the last `preprocess()` of a `Spectral_surface_mesh_deformation` did.
///
/// When `preprocess()` finds nothing to do (neither the region nor the
/// constraint set changed since its last success), the report is kept, with
/// `region_rebuilt` and `basis_computed` set to `false` and the times to 0.
/// Times are wall-clock seconds.
struct Spectral_preprocess_report
{
  bool success = false;                     ///< whether the deformation can run
  std::string message;                      ///< why not, when `success` is `false`
  bool region_rebuilt = false;              ///< the region (and its basis) had to be built
  bool basis_computed = false;              ///< the eigensolver ran (not reused, handed in or loaded)
  std::size_t number_of_region_vertices = 0;///< vertices of the region of interest and their fixed ring
  std::size_t number_of_frequencies = 0;    ///< basis functions in use (spectral algorithms; 0 with `SPATIAL_DUAL_LAPLACIAN`)
  std::size_t number_of_constrained_vertices = 0; ///< control vertices and fixed ring vertices
  double region_seconds = 0;                ///< region extraction, validation, basis, per-region matrices and factorizations
  double basis_seconds = 0;                 ///< of which the eigensolve
  double factorization_seconds = 0;         ///< per constraint set: the reduced factorization, plus the sparse one of the exact policy or of `SPATIAL_DUAL_LAPLACIAN`
};

/// \ingroup PkgSpectralSurfaceMeshDeformationRef
/// What the last `deform()` of a `Spectral_surface_mesh_deformation` did.
///
/// The residuals are measured on the positions written to the mesh: they are
/// 0 up to round-off with `EXACT_CONSTRAINTS` and with
/// `SPATIAL_DUAL_LAPLACIAN`. Times are wall-clock seconds.
struct Spectral_deformation_report
{
  bool success = false;             ///< whether the mesh was updated
  std::string message;              ///< why not, when `success` is `false`
  unsigned int iterations = 0;      ///< solves of the (reduced or spatial) system
  double last_step = 0;             ///< last relative step (see `set_tolerance()`)
  bool converged = false;           ///< the last step fell below the tolerance
  double max_control_residual = 0;  ///< largest distance of a control vertex to its target, relative to the bounding-box diagonal of the region
  double rms_control_residual = 0;  ///< root mean square of the same distances, relative likewise
  double solve_seconds = 0;         ///< rigid fits and iterations
  double detail_transfer_seconds = 0; ///< deformation transfer (spectral algorithms; 0 with `SPATIAL_DUAL_LAPLACIAN`)
  double total_seconds = 0;         ///< the whole `deform()` call, preprocessing excluded
};

/// \ingroup PkgSpectralSurfaceMeshDeformationRef
/// Deforms a triangle mesh with the spectral dual Laplacian editing of
/// *Spectral Surface Deformation with Dual Mesh*, behind the API of
/// `CGAL::Surface_mesh_deformation`.
///
/// A program written for CGAL's class with its default template arguments
/// compiles when only the class name and the include change, and keeps the
/// semantics of the region of interest, the control vertices and their
/// targets. What has no counterpart: CGAL's algorithm tags, weight
/// calculator, closest rotation traits and `set_sre_arap_alpha()`. What
/// differs: the default number of iterations (10 instead of 5) and the
/// meaning of the tolerance (see `set_tolerance()`).
///
/// As with CGAL's class, the user selects a region of interest (ROI) and, in
/// it, control vertices whose target positions are set with
/// `set_target_position()`, `translate()` or `rotate()`; `deform()` moves
/// the vertices of the ROI. Vertices outside the ROI never move; those
/// adjacent to the ROI (the *fixed* vertices) hold it in place. Control
/// vertices are also ROI vertices.
///
/// **Per region.** The work is done on the faces incident to the ROI
/// vertices (the *region*: the ROI and the fixed vertices), so that its cost
/// follows the size of the ROI; `n` below is the number of vertices of the
/// region. Per region, `preprocess()` computes the manifold harmonics basis
/// of the region (the dominant cost, see `Manifold_harmonics_basis`), its
/// smooth rest shape, the reduced dual Laplacian matrix and the detail
/// transfer system; they are kept as long as the ROI, the initial geometry
/// and the number of frequencies do not change, and are reused by `reset()`,
/// by constraint changes and by target changes. The basis can also be handed
/// in (`set_basis()`) or read from a cache (`load_basis()`).
///
/// **Per constraint set** (`preprocess()` after the control vertices, the
/// constraint weight or the policy changed): the `m × m` reduced matrix is
/// updated and factored, plus, for the exact policy, a sparse factorization
/// of the detail transfer system.
///
/// **Per target change** (`deform()`): a rigid motion is fitted to every group
/// of constrained vertices (the fixed vertices; each connected set of control
/// vertices) and carries the smooth rest shape to its targets; the reduced
/// system is iterated with `O(n m)` work per iteration; the details are
/// transferred back with one back-substitution.
///
/// **Defaults**: 100 frequencies, constraint weight 1, at most 10 iterations,
/// tolerance 1e-4 on the relative step, `EXACT_CONSTRAINTS` (the semantics of
/// CGAL's class, which a drop-in replacement must keep).
///
/// **Errors**: `preprocess()` and `deform()` do not throw
/// `Spectral_deformation_error`: they report a failure in
/// `preprocess_report()` and `deform_report()`, and a failed `deform()`
/// leaves the mesh unchanged. The functions that set a target throw when it
/// is not finite, and so do the parameter setters for invalid values.
///
/// \tparam TM a model of `HalfedgeListGraph` and `FaceListGraph`, triangulated
/// \tparam VIM a model of `ReadablePropertyMap` with `vertex_descriptor` as key
///         and an unsigned integer as value, giving each vertex a unique index in
///         `[0, num_vertices(tm))`; `Default` means an initialized vertex index map
/// \tparam HIM a halfedge index map, accepted for compatibility with CGAL's
///         class and not used; `Default` as in CGAL
/// \tparam TAG the algorithm, a `Spectral_deformation_algorithm_tag`
/// \tparam ET a model of `ManifoldHarmonicsEigensolverTraits`; `Default` means
///         `Block_lanczos_eigensolver_traits<>`
/// \tparam ST a model of `SparseSPDSolverTraits` for the detail transfer and
///         the spatial solver; `Default` means
///         `Default_deformation_sparse_spd_solver_traits` for the detail
///         transfer and `Default_sparse_spd_solver_traits` for the spatial
///         solver
/// \tparam Reserved not used; it keeps `VPM` at the position it has in CGAL's class
/// \tparam VPM a model of `ReadWritePropertyMap` with `vertex_descriptor` as key and
///         a 3D point as value; `Default` means `boost::property_map<TM, vertex_point_t>::%type`
template <class TM,
          class VIM = Default,
          class HIM = Default,
          Spectral_deformation_algorithm_tag TAG = SPECTRAL_DUAL_LAPLACIAN,
          class ET = Default,
          class ST = Default,
          class Reserved = Default,
          class VPM = Default>
class Spectral_surface_mesh_deformation
{
public:
  /// \name Types
  /// @{

  /// The mesh type.
  typedef TM Triangle_mesh;
  /// The vertex index map type.
  typedef typename Default::Get<VIM, typename GetInitializedVertexIndexMap<TM>::type>::type
      Vertex_index_map;
  /// The halfedge index map type (unused).
  typedef typename Default::Get<HIM, typename GetInitializedHalfedgeIndexMap<TM>::type>::type
      Hedge_index_map;
  /// The vertex point map type.
  typedef typename Default::Get<VPM, typename boost::property_map<TM, vertex_point_t>::type>::type
      Vertex_point_map;
  /// The eigensolver traits type.
  typedef typename Default::Get<ET, Block_lanczos_eigensolver_traits<>>::type Eigensolver_traits;
  /// The sparse solver traits type of the detail transfer.
  typedef typename Default::Get<ST, Default_deformation_sparse_spd_solver_traits>::type Sparse_solver_traits;
  /// The sparse solver traits type of the spatial solver.
  // The spatial solver's system couples two rings of neighbours: there the
  // supernodal factor was measured faster (1.22 s against 2.30 s at 104k).
  typedef typename Default::Get<ST, Default_sparse_spd_solver_traits>::type Spatial_solver_traits;
  /// The point type.
  typedef typename boost::property_traits<Vertex_point_map>::value_type Point;
  /// The vertex descriptor type.
  typedef typename boost::graph_traits<TM>::vertex_descriptor vertex_descriptor;
  /// The range of ROI vertices.
  typedef std::vector<vertex_descriptor> Roi_vertex_range;

  /// @}

private:
  typedef Spectral_deformation::internal::Positions Positions;
  typedef Spectral_deformation::internal::Triangle_arrays Triangle_arrays;
  typedef Spectral_deformation_error Error;

  /// \cond SKIP_IN_MANUAL
  // Everything that depends only on the ROI and the initial geometry.
  struct Region
  {
    std::vector<vertex_descriptor> vertices; // local index -> vertex
    std::vector<int> local;                  // vertex index -> local index, or -1
    std::vector<char> is_fixed;              // local: in the region, outside the ROI
    Triangle_arrays arrays;
    double diagonal = 0;
    std::vector<int> component; // local index -> connected component
    int number_of_components = 0;
    Spectral_deformation::internal::Basis_data basis;
    Spectral_deformation::internal::Spectral_dual_laplacian_solver spectral;
    Spectral_deformation::internal::Detail_transfer<Sparse_solver_traits> detail;
    std::unique_ptr<Spectral_deformation::internal::Spatial_dual_laplacian_solver<Spatial_solver_traits>> spatial;
  };
  /// \endcond

  static constexpr bool is_spectral = (TAG != SPATIAL_DUAL_LAPLACIAN);

public:
  /// \name Construction
  /// @{

  /// Creates a deformation object for `triangle_mesh`, with an empty ROI.
  /// The initial geometry is the current one. As in CGAL, the last arguments
  /// can be omitted (see the other constructors).
  ///
  /// \param triangle_mesh the triangulated mesh to deform, which must outlive
  ///        this object; its connectivity must not change while it is used
  /// \param vertex_index_map unique vertex indices in `[0, num_vertices(triangle_mesh))`
  /// \param hedge_index_map unused, for compatibility
  /// \param vertex_point_map the positions, read and written
  /// \throws Spectral_deformation_error (`INVALID_MESH`) when the vertex
  ///         index map is not a bijection onto `[0, num_vertices(triangle_mesh))`
  ///         (a `Surface_mesh` with removed, not yet collected, elements).
  Spectral_surface_mesh_deformation(Triangle_mesh& triangle_mesh,
                                    Vertex_index_map vertex_index_map,
                                    Hedge_index_map hedge_index_map,
                                    Vertex_point_map vertex_point_map)
    : m_tm(triangle_mesh), m_vim(vertex_index_map), m_him(hedge_index_map), m_vpm(vertex_point_map)
  {
    init();
  }

  /// Creates a deformation object for `triangle_mesh` with an initialized
  /// vertex index map, an initialized halfedge index map and the internal
  /// vertex point map `get(vertex_point, triangle_mesh)`.
  explicit Spectral_surface_mesh_deformation(Triangle_mesh& triangle_mesh)
    : Spectral_surface_mesh_deformation(triangle_mesh,
                                        CGAL::get_initialized_vertex_index_map(triangle_mesh))
  {}

  /// Creates a deformation object for `triangle_mesh` with the given vertex
  /// index map, an initialized halfedge index map and the internal vertex
  /// point map.
  Spectral_surface_mesh_deformation(Triangle_mesh& triangle_mesh, Vertex_index_map vertex_index_map)
    : Spectral_surface_mesh_deformation(triangle_mesh, vertex_index_map,
                                        CGAL::get_initialized_halfedge_index_map(triangle_mesh))
  {}

  /// Creates a deformation object for `triangle_mesh` with the given index
  /// maps and the internal vertex point map.
  Spectral_surface_mesh_deformation(Triangle_mesh& triangle_mesh, Vertex_index_map vertex_index_map,
                                    Hedge_index_map hedge_index_map)
    : Spectral_surface_mesh_deformation(triangle_mesh, vertex_index_map, hedge_index_map,
                                        get(vertex_point, triangle_mesh))
  {}

  /// Not copyable, as in CGAL: the object refers to the mesh it deforms.
  Spectral_surface_mesh_deformation(const Spectral_surface_mesh_deformation&) = delete;
  /// Not assignable, as in CGAL.
  Spectral_surface_mesh_deformation& operator=(const Spectral_surface_mesh_deformation&) = delete;

  /// @}

  /// \name Region of interest and control vertices
  /// @{

  /// Erases all the vertices from the region of interest (control vertices included).
  void clear_roi_vertices()
  {
    m_roi.clear();
    std::fill(m_is_roi.begin(), m_is_roi.end(), 0);
    std::fill(m_is_control.begin(), m_is_control.end(), 0);
    roi_changed();
  }

  /// Erases all the vertices from the set of control vertices.
  void clear_control_vertices()
  {
    std::fill(m_is_control.begin(), m_is_control.end(), 0);
    m_constraints_valid = false;
  }

  /// Inserts `vd` in the set of control vertices, and in the ROI if needed
  /// (which changes the region). Its target is its current position. Returns
  /// `true` if `vd` was not a control vertex.
  /// \throws Spectral_deformation_error (`INVALID_ARGUMENT`) when `vd` is not
  ///         a vertex of the mesh (null, removed, or an index out of range).
  bool insert_control_vertex(vertex_descriptor vd)
  {
    if(is_control_vertex(vd))
      return false;
    checked_id(vd);
    insert_roi_vertex(vd);
    m_is_control[id(vd)] = 1;
    m_target[id(vd)] = get(m_vpm, vd);
    m_constraints_valid = false;
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
    if(!is_control_vertex(vd))
      return false;
    m_is_control[id(vd)] = 0;
    m_constraints_valid = false;
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
    if(is_roi_vertex(vd))
      return false;
    m_is_roi[checked_id(vd)] = 1;
    m_roi.push_back(vd);
    roi_changed();
    return true;
  }

  /// Erases `vd` from the ROI and from the control vertices. At the next
  /// `preprocess()`, a vertex no longer in the ROI is put back at its initial
  /// position. Returns `true` if `vd` was in the ROI.
  bool erase_roi_vertex(vertex_descriptor vd)
  {
    if(!is_roi_vertex(vd))
      return false;
    erase_control_vertex(vd);
    m_is_roi[id(vd)] = 0;
    m_roi.erase(std::find(m_roi.begin(), m_roi.end(), vd));
    roi_changed();
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
  bool preprocess()
  {
    if(m_region && m_constraints_valid && m_preprocess_report.success)
    {
      // Nothing to do: the report says so.
      m_preprocess_report.region_rebuilt = false;
      m_preprocess_report.basis_computed = false;
      m_preprocess_report.region_seconds = 0;
      m_preprocess_report.basis_seconds = 0;
      m_preprocess_report.factorization_seconds = 0;
      return true;
    }
    m_preprocess_report = Spectral_preprocess_report();
    try
    {
      preprocess_or_throw();
      m_preprocess_report.success = true;
    }
    catch(const Error& e)
    {
      m_preprocess_report.success = false;
      m_preprocess_report.message = e.what();
      m_constraints_valid = false;
    }
    return m_preprocess_report.success;
  }

  /// @}

  /// \name Targets
  /// @{

  /// Sets the target position of the control vertex `vd`; does nothing when
  /// `vd` is not a control vertex.
  /// \throws Spectral_deformation_error (`INVALID_ARGUMENT`) when
  ///         `target_position` is not finite (the target is then unchanged).
  void set_target_position(vertex_descriptor vd, const Point& target_position)
  {
    if(!is_control_vertex(vd))
      return;
    check_finite(target_position);
    m_target[id(vd)] = target_position;
  }

  /// Translates the target of the control vertex `vd` by `t`; does nothing
  /// when `vd` is not a control vertex.
  /// \tparam Vect a 3D vector with `operator[](int)` and a constructor from three coordinates
  /// \throws Spectral_deformation_error (`INVALID_ARGUMENT`) when the new
  ///         target is not finite.
  template <class Vect>
  void translate(vertex_descriptor vd, const Vect& t)
  {
    if(!is_control_vertex(vd))
      return;
    const Point& p = m_target[id(vd)];
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
    if(!is_control_vertex(vd))
      return;
    const Point& p = m_target[id(vd)];
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

  /// The target position of the control vertex `vd` (`vd` must be a control
  /// vertex, as in CGAL).
  const Point& target_position(vertex_descriptor vd) { return m_target[checked_id(vd)]; }

  /// @}

  /// \name Deformation
  /// @{

  /// Deforms with the number of iterations and the tolerance set by
  /// `set_iterations()` and `set_tolerance()`.
  void deform() { deform(m_iterations, m_tolerance); }

  /// Deforms the ROI towards the targets of the control vertices with at most
  /// `iterations` solves (0 counts as 1); stops earlier when the relative
  /// step falls below `tolerance`. A second call continues from the previous
  /// result (the iteration goes on), as in CGAL, except with
  /// `SPECTRAL_LINEAR`. Nothing happens when `preprocess()` fails; the reason
  /// and the statistics are in `deform_report()`. The positions of the ROI
  /// vertices are only written when the deformation succeeds; a numerical
  /// failure (non-finite values, a diverging iteration, a degenerate face of
  /// the smooth deformed mesh) leaves the mesh unchanged.
  void deform(unsigned int iterations, double tolerance)
  {
    const auto start = std::chrono::steady_clock::now();
    m_deform_report = Spectral_deformation_report();
    if(!preprocess())
    {
      m_deform_report.message = "preprocess() failed: " + m_preprocess_report.message;
      return;
    }
    try
    {
      Positions result;
      Eigen::MatrixXd coefficients;
      if(is_spectral)
        deform_spectral(std::max(1u, iterations), tolerance, result, coefficients);
      else
        deform_spatial(std::max(1u, iterations), tolerance, result);
      write_result(result);
      // The iteration state changes only with the mesh.
      if(is_spectral)
        m_coefficients.swap(coefficients);
      else
        m_spatial_solution = result;
      m_has_solution = true;
      m_deform_report.success = true;
    }
    catch(const Error& e)
    {
      m_deform_report.success = false;
      m_deform_report.message = e.what();
    }
    m_deform_report.total_seconds = seconds_since(start);
  }

  /// Puts the vertices of the ROI back at their initial positions, resets the
  /// targets of the control vertices to them, and restarts the iteration.
  /// The region (and its basis) is kept.
  void reset()
  {
    for(vertex_descriptor vd : m_roi)
    {
      put(m_vpm, vd, m_original[id(vd)]);
      if(is_control_vertex(vd))
        m_target[id(vd)] = m_original[id(vd)];
    }
    m_has_solution = false;
  }

  /// Makes the current positions of the ROI vertices their initial
  /// positions, as if a new object had been built on the current mesh with
  /// the same ROI and control vertices. The region, its basis included, is
  /// rebuilt by the next `preprocess()`.
  void overwrite_initial_geometry()
  {
    for(vertex_descriptor vd : m_roi)
      m_original[id(vd)] = get(m_vpm, vd);
    m_region.reset();
    m_has_solution = false;
    m_constraints_valid = false;
  }

  /// @}

  /// \name Parameters
  /// @{

  /// The maximal number of solves of `deform()` (default 10).
  unsigned int iterations() { return m_iterations; }
  /// The tolerance of `deform()` (default 1e-4).
  double tolerance() { return m_tolerance; }
  /// Sets the maximal number of solves run by `deform()`; 0 counts as 1.
  void set_iterations(unsigned int iterations) { m_iterations = iterations; }
  /// Sets the tolerance: the iteration stops when the relative step falls
  /// below it; 0 runs all iterations. The relative step is the change of the
  /// positions of the region between two solves, measured in the \f$ L^2 \f$
  /// norm of the surface (the \f$ M \f$-norm) and divided by the square root
  /// of the area and by the bounding-box diagonal of the region; with
  /// `SPATIAL_DUAL_LAPLACIAN`, it is the root mean square of the vertex
  /// displacements divided by the diagonal. (CGAL's tolerance is on the
  /// relative change of the ARAP energy instead.)
  void set_tolerance(double tolerance) { m_tolerance = tolerance; }

  /// The number of frequencies `m` of the basis (default 100).
  std::size_t number_of_frequencies() const { return m_frequencies; }
  /// Sets the number of frequencies; a region with fewer vertices uses all of
  /// them. A different value makes the next `preprocess()` rebuild the
  /// region, basis included. Not used by `SPATIAL_DUAL_LAPLACIAN`.
  /// \throws Spectral_deformation_error (`INVALID_ARGUMENT`) when `m` is 0.
  void set_number_of_frequencies(std::size_t m)
  {
    if(m == 0)
      throw Error(Error::INVALID_ARGUMENT, "the number of frequencies must be positive");
    if(m != m_frequencies)
    {
      m_frequencies = m;
      m_region.reset();
      m_constraints_valid = false;
    }
  }
  /// The weight `w` of the constraints in the reduced least squares system (default 1).
  double constraint_weight() const { return m_weight; }
  /// Sets the constraint weight, a change of the constraint set. Larger
  /// weights meet the constraints of the smooth mesh more closely but the
  /// truncated basis cannot form sharp transitions, which degrades the
  /// result; smaller weights loosen the constraints. Not used by
  /// `SPATIAL_DUAL_LAPLACIAN`.
  /// \throws Spectral_deformation_error (`INVALID_ARGUMENT`) unless `w` is positive and finite.
  void set_constraint_weight(double w)
  {
    if(!(w > 0 && std::isfinite(w)))
      throw Error(Error::INVALID_ARGUMENT, "the constraint weight must be positive and finite");
    m_weight = w;
    m_constraints_valid = false;
  }
  /// The constraint policy (default `EXACT_CONSTRAINTS`).
  Spectral_constraint_policy constraint_policy() const { return m_policy; }
  /// Sets the constraint policy; a different policy is a change of the
  /// constraint set. Not used by `SPATIAL_DUAL_LAPLACIAN`.
  void set_constraint_policy(Spectral_constraint_policy policy)
  {
    if(policy != m_policy)
    {
      m_policy = policy;
      m_constraints_valid = false;
    }
  }
  /// Sets the eigensolver used when a basis is next computed; a basis already
  /// computed is kept.
  void set_eigensolver_traits(const Eigensolver_traits& traits) { m_eigensolver = traits; }
  /// Whether `deform()` reads its copy of the basis in single precision
  /// (default `false`).
  bool single_precision_basis() const { return m_single_precision_basis; }
  /// Stores the copy of the basis that every iteration of `deform()` reads
  /// in float (4 n m bytes instead of 8 n m); the arithmetic stays in double.
  /// Not the default: the reduced systems amplify the rounding of the copy,
  /// and the armadillo arm (104k vertices, m = 100) deformed 1.1e-4 of the
  /// bounding-box diagonal away from the double precision result, above the
  /// 1e-6 a default must meet (see the manual's benchmark). Takes effect at
  /// once, the basis is kept. Not used by `SPATIAL_DUAL_LAPLACIAN`.
  void set_single_precision_basis(bool single)
  {
    m_single_precision_basis = single;
    if(m_region)
      m_region->spectral.set_single_precision(single);
  }

  /// @}

  /// \name Basis cache
  /// @{

  /// Hands in a precomputed basis. It is used instead of computing one when
  /// the region is the mesh on which `basis` was computed: every face has a
  /// vertex in the ROI (for instance, the ROI is the whole mesh), the
  /// vertices are indexed alike and the initial geometry is the one `basis`
  /// was computed with. Its number of frequencies then prevails. Otherwise
  /// it is ignored and `preprocess_report().basis_computed` tells. Not used
  /// by `SPATIAL_DUAL_LAPLACIAN`.
  template <class EigensolverTraits>
  void set_basis(const Manifold_harmonics_basis<TM, EigensolverTraits>& basis)
  {
    m_supplied_basis = basis.data();
    if(m_region && !m_region->basis.empty() &&
       m_supplied_basis.fingerprint != m_region->basis.fingerprint)
    {
      m_region.reset();
      m_constraints_valid = false;
    }
  }

  /// Writes the basis of the current region in the format of
  /// `Manifold_harmonics_basis::save()`.
  /// \throws Spectral_deformation_error (`IO_ERROR`) when there is no basis
  ///         yet (call `preprocess()` first) or the stream fails.
  void save_basis(std::ostream& os) const
  {
    if(!m_region || m_region->basis.empty())
      throw Error(Error::IO_ERROR, "save_basis: no basis yet, call preprocess() first");
    Spectral_deformation::internal::write_basis(os, m_region->basis);
  }

  /// Reads a basis written by `save_basis()` (or by
  /// `Manifold_harmonics_basis::save()`) and uses it for the current region
  /// instead of computing one: the region is rebuilt by the next
  /// `preprocess()`, with this basis. The basis is checked against the
  /// region of the current ROI and initial geometry.
  /// \throws Spectral_deformation_error with code `IO_ERROR` (unreadable or
  ///         corrupted stream), `MESH_MISMATCH` (the basis belongs to another
  ///         region or geometry) or `INVALID_MESH`; nothing changes then.
  void load_basis(std::istream& is)
  {
    Spectral_deformation::internal::Basis_data data = Spectral_deformation::internal::read_basis(is);
    std::unique_ptr<Region> region = build_region_connectivity();
    Spectral_deformation::internal::check_basis_matches(data, region->arrays);
    m_supplied_basis = std::move(data);
    m_region.reset();
    m_constraints_valid = false;
  }

  /// @}

  /// \name Reports and intermediate shapes
  /// @{

  /// What the last `preprocess()` did.
  const Spectral_preprocess_report& preprocess_report() const { return m_preprocess_report; }
  /// What the last `deform()` did.
  const Spectral_deformation_report& deform_report() const { return m_deform_report; }

  /// The smooth rest position of `vd`, the second shape of the paper's
  /// pipeline figure: its low-pass reconstruction \f$ H H^\top M V \f$ with
  /// the basis of the region. It is the initial position when `vd` is not in
  /// the region, when no region is built, or with `SPATIAL_DUAL_LAPLACIAN`.
  Point smoothed_rest_point(vertex_descriptor vd) const
  {
    const int i = local_index(vd);
    if(i < 0 || !is_spectral)
      return m_original[id(vd)];
    return to_point(m_region->spectral.smooth_rest().row(i));
  }

  /// The smooth deformed position of `vd` after the last successful
  /// `deform()`, the third shape of the paper's pipeline figure; the smooth
  /// rest position before any deformation or after `reset()`. It is the
  /// initial position when `vd` is not in the region, when no region is
  /// built, or with `SPATIAL_DUAL_LAPLACIAN`.
  Point smoothed_deformed_point(vertex_descriptor vd) const
  {
    const int i = local_index(vd);
    if(i < 0 || !is_spectral)
      return m_original[id(vd)];
    if(!m_has_solution)
      return smoothed_rest_point(vd);
    return to_point((m_region->basis.basis.row(i) * m_coefficients).eval());
  }

  /// @}

  /// \name Access
  /// @{

  /// The vertices of the ROI.
  const Roi_vertex_range& roi_vertices() const { return m_roi; }
  /// Whether `vd` is in the ROI.
  bool is_roi_vertex(vertex_descriptor vd) const { return has_index(vd) && m_is_roi[id(vd)] != 0; }
  /// Whether `vd` is a control vertex.
  bool is_control_vertex(vertex_descriptor vd) const
  {
    return has_index(vd) && m_is_control[id(vd)] != 0;
  }
  /// The mesh being deformed.
  const Triangle_mesh& triangle_mesh() const { return m_tm; }
  /// The vertex index map.
  const Vertex_index_map& vertex_index_map() const { return m_vim; }
  /// The halfedge index map (not used by the deformation).
  Hedge_index_map hedge_index_map() const { return m_him; }

  /// @}

private:
  void init()
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
        throw Error(Error::INVALID_MESH,
                    "the vertex index map is not a bijection onto [0, number of vertices) "
                    "(for a Surface_mesh with removed elements, call collect_garbage() first)");
      seen[i] = 1;
      m_original[i] = get(m_vpm, vd);
    }
    m_target = m_original;
    m_is_vertex.swap(seen); // removed, not collected, vertices are not vertices
  }

  // The index of `vd`, or an exception when `vd` is not a vertex of the mesh
  // as it was at construction.
  std::size_t checked_id(vertex_descriptor vd) const
  {
    if(!has_index(vd))
      throw Error(Error::INVALID_ARGUMENT, "the vertex is not a vertex of the mesh");
    return id(vd);
  }

  bool has_index(vertex_descriptor vd) const
  {
    return vd != boost::graph_traits<TM>::null_vertex() && id(vd) < m_is_roi.size() &&
           m_is_vertex[id(vd)] != 0;
  }

  std::size_t id(vertex_descriptor vd) const { return static_cast<std::size_t>(get(m_vim, vd)); }

  int local_index(vertex_descriptor vd) const
  {
    return m_region ? m_region->local[id(vd)] : -1;
  }

  static Point to_point(const Eigen::RowVector3d& x) { return Point(x[0], x[1], x[2]); }

  static void check_finite(const Point& p)
  {
    if(!(std::isfinite(CGAL::to_double(p[0])) && std::isfinite(CGAL::to_double(p[1])) &&
         std::isfinite(CGAL::to_double(p[2]))))
      throw Error(Error::INVALID_ARGUMENT, "a target position is not finite");
  }

  static double seconds_since(std::chrono::steady_clock::time_point start)
  {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }

  void roi_changed()
  {
    if(m_region)
      m_previous_region_vertices = m_region->vertices;
    m_region.reset();
    m_constraints_valid = false;
    m_has_solution = false;
  }

  // The faces incident to ROI vertices, with local vertex indices in the
  // order of the vertex index map; validated.
  std::unique_ptr<Region> build_region_connectivity() const
  {
    std::unique_ptr<Region> region(new Region());
    const std::size_t n = m_is_roi.size();
    std::vector<char> in_region(n, 0);
    std::vector<std::array<std::size_t, 3>> faces_of_region;
    for(auto f : faces(m_tm))
    {
      std::array<std::size_t, 3> t;
      int k = 0;
      bool touches_roi = false;
      for(auto h : halfedges_around_face(halfedge(f, m_tm), m_tm))
      {
        if(k == 3)
          throw Error(Error::INVALID_MESH, "the mesh is not triangulated");
        t[k] = id(target(h, m_tm));
        touches_roi = touches_roi || m_is_roi[t[k]];
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

    std::vector<vertex_descriptor> by_index(n);
    for(vertex_descriptor vd : vertices(m_tm))
      by_index[id(vd)] = vd;
    region->local.assign(n, -1);
    for(std::size_t i = 0; i < n; ++i)
      if(in_region[i])
      {
        region->local[i] = static_cast<int>(region->vertices.size());
        region->vertices.push_back(by_index[i]);
        region->is_fixed.push_back(m_is_roi[i] ? 0 : 1);
      }
    const Eigen::Index region_size = static_cast<Eigen::Index>(region->vertices.size());
    region->arrays.positions.resize(region_size, 3);
    for(Eigen::Index r = 0; r < region_size; ++r)
    {
      const Point& p = m_original[id(region->vertices[static_cast<std::size_t>(r)])];
      region->arrays.positions.row(r) << CGAL::to_double(p[0]), CGAL::to_double(p[1]),
          CGAL::to_double(p[2]);
    }
    region->arrays.triangles.resize(static_cast<Eigen::Index>(faces_of_region.size()), 3);
    for(std::size_t f = 0; f < faces_of_region.size(); ++f)
      for(int k = 0; k < 3; ++k)
        region->arrays.triangles(static_cast<Eigen::Index>(f), k) = region->local[faces_of_region[f][k]];
    Spectral_deformation::internal::validate_triangle_arrays(region->arrays);
    region->component = Spectral_deformation::internal::connected_components(
        region->arrays.triangles, region->arrays.number_of_vertices(), region->number_of_components);
    region->diagonal = (region->arrays.positions.colwise().maxCoeff() -
                        region->arrays.positions.colwise().minCoeff())
                           .norm();
    return region;
  }

  void build_region()
  {
    const auto start = std::chrono::steady_clock::now();
    std::unique_ptr<Region> region = build_region_connectivity();
    if(is_spectral)
    {
      const std::uint64_t fingerprint = Spectral_deformation::internal::fingerprint(region->arrays);
      if(!m_supplied_basis.empty() && m_supplied_basis.fingerprint == fingerprint &&
         m_supplied_basis.basis.rows() == region->arrays.number_of_vertices())
        region->basis = m_supplied_basis;
      else
      {
        const auto basis_start = std::chrono::steady_clock::now();
        const Eigen::Index m = std::min<Eigen::Index>(static_cast<Eigen::Index>(m_frequencies),
                                                      region->arrays.number_of_vertices());
        Eigensolver_traits eigensolver = m_eigensolver;
        Spectral_deformation::internal::compute_manifold_harmonics(
            region->arrays, m, eigensolver, region->basis.eigenvalues, region->basis.basis,
            region->basis.mass);
        region->basis.number_of_faces = static_cast<std::uint64_t>(region->arrays.number_of_faces());
        region->basis.fingerprint = fingerprint;
        m_preprocess_report.basis_computed = true;
        m_preprocess_report.basis_seconds = seconds_since(basis_start);
      }
      region->spectral.set_single_precision(m_single_precision_basis);
      region->spectral.initialize(region->basis.basis, region->basis.mass, region->arrays);
      region->detail.initialize(region->arrays, region->spectral.smooth_rest());
    }
    else
    {
      region->spatial.reset(
          new Spectral_deformation::internal::Spatial_dual_laplacian_solver<Spatial_solver_traits>(
              region->arrays));
    }
    m_region = std::move(region);
    m_has_solution = false;
    m_preprocess_report.region_rebuilt = true;
    m_preprocess_report.region_seconds = seconds_since(start);
  }

  void preprocess_or_throw()
  {
    if(static_cast<std::size_t>(num_vertices(m_tm)) != m_is_roi.size())
      throw Error(Error::INVALID_MESH, "the number of vertices of the mesh changed since the "
                                       "construction of the deformation object");
    if(m_roi.empty())
      throw Error(Error::INVALID_ARGUMENT, "the region of interest is empty");
    if(!m_region)
    {
      // Vertices that left the ROI go back to their initial positions.
      for(vertex_descriptor vd : m_previous_region_vertices)
        if(!is_roi_vertex(vd))
          put(m_vpm, vd, m_original[id(vd)]);
      m_previous_region_vertices.clear();
      build_region();
    }
    Region& region = *m_region;
    m_preprocess_report.number_of_region_vertices = region.vertices.size();
    m_preprocess_report.number_of_frequencies = static_cast<std::size_t>(region.basis.basis.cols());

    // Constrained vertices: the fixed ring first, then the control vertices.
    m_constrained.clear();
    for(std::size_t i = 0; i < region.vertices.size(); ++i)
      if(region.is_fixed[i])
        m_constrained.push_back(static_cast<int>(i));
    const std::size_t fixed_count = m_constrained.size();
    for(std::size_t i = 0; i < region.vertices.size(); ++i)
      if(!region.is_fixed[i] && is_control_vertex(region.vertices[i]))
        m_constrained.push_back(static_cast<int>(i));
    if(m_constrained.empty())
      throw Error(Error::INVALID_ARGUMENT,
                  "no constraint: the region of interest is the whole mesh and has no control vertex");
    m_preprocess_report.number_of_constrained_vertices = m_constrained.size();

    std::vector<char> has_constraint(static_cast<std::size_t>(region.number_of_components), 0);
    for(int i : m_constrained)
      has_constraint[static_cast<std::size_t>(region.component[static_cast<std::size_t>(i)])] = 1;
    for(char c : has_constraint)
      if(!c)
        throw Error(Error::INVALID_ARGUMENT,
                    "a connected part of the region of interest has neither a control vertex "
                    "nor a fixed neighbour: its position would be undetermined");

    build_groups(fixed_count);

    const auto start = std::chrono::steady_clock::now();
    if(is_spectral)
    {
      if(!region.spectral.preprocess(m_constrained, m_weight))
        throw Error(Error::SOLVER_FAILURE, "the reduced system is not positive definite");
      if(m_policy == EXACT_CONSTRAINTS)
      {
        std::vector<char> prescribed(region.vertices.size(), 0);
        for(int i : m_constrained)
          prescribed[static_cast<std::size_t>(i)] = 1;
        if(!region.detail.prepare_dirichlet(prescribed))
          throw Error(Error::SOLVER_FAILURE, "the factorization of the detail transfer failed");
      }
      else if(!region.detail.prepare_soft(region.is_fixed))
        throw Error(Error::SOLVER_FAILURE, "the factorization of the detail transfer failed");
    }
    else if(!region.spatial->preprocess(m_constrained, 0.0))
      throw Error(Error::SOLVER_FAILURE, region.spatial->error_message());
    m_preprocess_report.factorization_seconds = seconds_since(start);
    m_constraints_valid = true;
  }

  // Groups of constrained vertices fitted by one rigid motion each: the fixed
  // ring, and every connected set of control vertices (positions in
  // m_constrained).
  void build_groups(std::size_t fixed_count)
  {
    m_groups.clear();
    if(fixed_count > 0)
    {
      m_groups.emplace_back();
      for(std::size_t k = 0; k < fixed_count; ++k)
        m_groups.back().push_back(static_cast<int>(k));
    }
    const Region& region = *m_region;
    std::vector<int> position(region.vertices.size(), -1);
    for(std::size_t k = fixed_count; k < m_constrained.size(); ++k)
      position[static_cast<std::size_t>(m_constrained[k])] = static_cast<int>(k);
    // Union-find over edges joining two control vertices.
    std::vector<int> parent(m_constrained.size());
    for(std::size_t k = 0; k < parent.size(); ++k)
      parent[k] = static_cast<int>(k);
    auto find = [&parent](int k) {
      while(parent[static_cast<std::size_t>(k)] != k)
        k = parent[static_cast<std::size_t>(k)] = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(k)])];
      return k;
    };
    const auto& T = region.arrays.triangles;
    for(Eigen::Index f = 0; f < T.rows(); ++f)
      for(int e = 0; e < 3; ++e)
      {
        const int a = position[static_cast<std::size_t>(T(f, e))];
        const int b = position[static_cast<std::size_t>(T(f, (e + 1) % 3))];
        if(a >= 0 && b >= 0)
          parent[static_cast<std::size_t>(find(a))] = find(b);
      }
    std::vector<int> group_of_root(m_constrained.size(), -1);
    for(std::size_t k = fixed_count; k < m_constrained.size(); ++k)
    {
      const int root = find(static_cast<int>(k));
      if(group_of_root[static_cast<std::size_t>(root)] < 0)
      {
        group_of_root[static_cast<std::size_t>(root)] = static_cast<int>(m_groups.size());
        m_groups.emplace_back();
      }
      m_groups[static_cast<std::size_t>(group_of_root[static_cast<std::size_t>(root)])].push_back(
          static_cast<int>(k));
    }
  }

  // Targets of the constrained vertices (k×3): initial positions for the
  // fixed ring, the user's targets for the control vertices.
  Positions constrained_targets() const
  {
    const Region& region = *m_region;
    Positions targets(static_cast<Eigen::Index>(m_constrained.size()), 3);
    for(std::size_t k = 0; k < m_constrained.size(); ++k)
    {
      const vertex_descriptor vd = region.vertices[static_cast<std::size_t>(m_constrained[k])];
      const Point& p = region.is_fixed[static_cast<std::size_t>(m_constrained[k])] ? m_original[id(vd)]
                                                                                  : m_target[id(vd)];
      targets.row(static_cast<Eigen::Index>(k)) << CGAL::to_double(p[0]), CGAL::to_double(p[1]),
          CGAL::to_double(p[2]);
    }
    if(!targets.allFinite())
      throw Error(Error::INVALID_ARGUMENT, "a target position is not finite");
    return targets;
  }

  void deform_spectral(unsigned int iterations, double tolerance, Positions& result,
                       Eigen::MatrixXd& coefficients)
  {
    Region& region = *m_region;
    const Positions targets = constrained_targets();
    const auto start = std::chrono::steady_clock::now();

    // Smooth targets: the rigid motion of each group carries the smooth rest
    // positions, plus the non-rigid part of the detailed targets.
    const Positions& rest = region.arrays.positions;
    const Positions& smooth = region.spectral.smooth_rest();
    Positions smooth_targets(targets.rows(), 3);
    for(const std::vector<int>& group : m_groups)
    {
      Positions from(static_cast<Eigen::Index>(group.size()), 3), to(from.rows(), 3);
      for(std::size_t g = 0; g < group.size(); ++g)
      {
        from.row(static_cast<Eigen::Index>(g)) = rest.row(m_constrained[static_cast<std::size_t>(group[g])]);
        to.row(static_cast<Eigen::Index>(g)) = targets.row(group[g]);
      }
      const Spectral_deformation::internal::Rigid_motion motion =
          Spectral_deformation::internal::fit_rigid_motion(from, to);
      for(std::size_t g = 0; g < group.size(); ++g)
      {
        const int i = m_constrained[static_cast<std::size_t>(group[g])];
        const Eigen::RowVector3d residual =
            to.row(static_cast<Eigen::Index>(g)) - motion.apply(rest.row(i));
        smooth_targets.row(group[g]) = motion.apply(smooth.row(i)) + residual;
      }
    }

    const bool linear = (TAG == SPECTRAL_LINEAR);
    coefficients = (m_has_solution && !linear) ? m_coefficients : region.spectral.rest_coefficients();
    const Spectral_deformation::internal::Iteration_report report = region.spectral.solve(
        smooth_targets, coefficients, linear ? 0 : static_cast<int>(iterations) - 1, tolerance);
    if(!report.success)
      throw Error(Error::SOLVER_FAILURE, report.message);
    m_deform_report.iterations = static_cast<unsigned int>(report.iterations + 1);
    m_deform_report.last_step = report.last_step;
    m_deform_report.converged = report.converged;
    m_deform_report.solve_seconds = seconds_since(start);

    const auto transfer_start = std::chrono::steady_clock::now();
    const Positions smooth_deformed = region.spectral.shape(coefficients);
    bool transferred = false;
    if(m_policy == EXACT_CONSTRAINTS)
    {
      Positions prescribed(rest.rows(), 3);
      for(std::size_t k = 0; k < m_constrained.size(); ++k)
        prescribed.row(m_constrained[k]) = targets.row(static_cast<Eigen::Index>(k));
      transferred = region.detail.transfer_exact(smooth_deformed, prescribed, result);
    }
    else
    {
      // The fixed vertices around the ROI are anchored: only the control
      // vertices are soft.
      Positions anchored(rest.rows(), 3);
      for(std::size_t i = 0; i < region.is_fixed.size(); ++i)
        if(region.is_fixed[i])
          anchored.row(static_cast<Eigen::Index>(i)) = rest.row(static_cast<Eigen::Index>(i));
      transferred = region.detail.transfer_soft(smooth_deformed, anchored, m_constrained, targets, result);
      if(transferred)
        meet_soft_constraints(targets, result);
    }
    if(!transferred)
      throw Error(Error::SOLVER_FAILURE, "the detail transfer failed (a face of the smooth "
                                         "deformed mesh is degenerate)");
    m_deform_report.detail_transfer_seconds = seconds_since(transfer_start);
    report_residuals(result, targets);
  }

  // Soft policy: the detail transfer carries the rotations of the smooth
  // mesh, not its stretch, so the control vertices end farther from their
  // targets than the smooth mesh did. The residuals are met as the reduced
  // system meets its targets, by a smooth field of the basis added to the
  // region (not to the fixed vertices, which stay where they are).
  void meet_soft_constraints(const Positions& targets, Positions& result) const
  {
    const Region& region = *m_region;
    Positions residuals(targets.rows(), 3);
    for(std::size_t k = 0; k < m_constrained.size(); ++k)
      residuals.row(static_cast<Eigen::Index>(k)) =
          targets.row(static_cast<Eigen::Index>(k)) - result.row(m_constrained[k]);
    const Positions correction = region.spectral.shape(region.spectral.fit_constraints(residuals));
    if(!correction.allFinite())
      throw Error(Error::SOLVER_FAILURE, "the iteration produced non-finite values");
    for(std::size_t i = 0; i < region.is_fixed.size(); ++i)
      if(!region.is_fixed[i])
        result.row(static_cast<Eigen::Index>(i)) += correction.row(static_cast<Eigen::Index>(i));
  }

  void deform_spatial(unsigned int iterations, double tolerance, Positions& result)
  {
    Region& region = *m_region;
    const Positions targets = constrained_targets();
    const auto start = std::chrono::steady_clock::now();
    const Positions& from = m_has_solution ? m_spatial_solution : region.arrays.positions;
    const Spectral_deformation::internal::Iteration_report report =
        region.spatial->solve(targets, from, result, static_cast<int>(iterations) - 1, tolerance);
    if(!report.success)
      throw Error(Error::SOLVER_FAILURE, report.message);
    m_deform_report.iterations = static_cast<unsigned int>(report.iterations + 1);
    m_deform_report.last_step = report.last_step;
    m_deform_report.converged = report.converged;
    m_deform_report.solve_seconds = seconds_since(start);
    report_residuals(result, targets);
  }

  void report_residuals(const Positions& result, const Positions& targets)
  {
    double max_residual = 0, sum = 0;
    std::size_t count = 0;
    for(std::size_t k = 0; k < m_constrained.size(); ++k)
    {
      const int i = m_constrained[k];
      if(m_region->is_fixed[static_cast<std::size_t>(i)])
        continue;
      const double d = (result.row(i) - targets.row(static_cast<Eigen::Index>(k))).norm();
      max_residual = std::max(max_residual, d);
      sum += d * d;
      ++count;
    }
    const double diagonal = m_region->diagonal > 0 ? m_region->diagonal : 1.0;
    m_deform_report.max_control_residual = max_residual / diagonal;
    m_deform_report.rms_control_residual = count ? std::sqrt(sum / double(count)) / diagonal : 0.0;
  }

  // Only ROI vertices are written; the fixed ring never moves.
  void write_result(const Positions& result)
  {
    if(!result.allFinite())
      throw Error(Error::SOLVER_FAILURE, "the deformation produced non-finite positions");
    const Region& region = *m_region;
    for(std::size_t i = 0; i < region.vertices.size(); ++i)
      if(!region.is_fixed[i])
        put(m_vpm, region.vertices[i], to_point(result.row(static_cast<Eigen::Index>(i))));
  }

  Triangle_mesh& m_tm;
  Vertex_index_map m_vim;
  Hedge_index_map m_him;
  Vertex_point_map m_vpm;

  std::vector<Point> m_original;
  std::vector<Point> m_target;
  Roi_vertex_range m_roi;
  std::vector<char> m_is_roi;
  std::vector<char> m_is_control;
  std::vector<char> m_is_vertex;
  std::vector<vertex_descriptor> m_previous_region_vertices;

  unsigned int m_iterations = 10;
  double m_tolerance = 1e-4;
  std::size_t m_frequencies = 100;
  bool m_single_precision_basis = false;
  double m_weight = 1.0;
  Spectral_constraint_policy m_policy = EXACT_CONSTRAINTS;
  Eigensolver_traits m_eigensolver;
  Spectral_deformation::internal::Basis_data m_supplied_basis;

  std::unique_ptr<Region> m_region;
  bool m_constraints_valid = false;
  std::vector<int> m_constrained;
  std::vector<std::vector<int>> m_groups;
  bool m_has_solution = false;
  Eigen::MatrixXd m_coefficients;
  Positions m_spatial_solution;

  Spectral_preprocess_report m_preprocess_report;
  Spectral_deformation_report m_deform_report;
};

} // namespace CGAL

#endif // CGAL_SPECTRAL_SURFACE_MESH_DEFORMATION_H

// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_SURFACE_MESH_DEFORMATION_H
#define CGAL_SPECTRAL_SURFACE_MESH_DEFORMATION_H

#include <CGAL/Manifold_harmonics_basis.h>
#include <CGAL/Spectral_deformation/Block_lanczos_eigensolver_traits.h>
#include <CGAL/Spectral_deformation/Deformation_options.h>
#include <CGAL/Spectral_deformation/Deformation_reports.h>
#include <CGAL/Spectral_deformation/Roi_and_control_vertices.h>
#include <CGAL/Spectral_deformation/Sparse_spd_solver_traits.h>
#include <CGAL/Spectral_deformation/Spectral_deformation_error.h>
#include <CGAL/Spectral_deformation/Spectral_parameters.h>
#include <CGAL/Spectral_deformation/version.h>
#include <CGAL/Spectral_deformation/internal/Deformation/Deformation_class_types.h>
#include <CGAL/Spectral_deformation/internal/Deformation/Template_arguments.h>

#include <CGAL/assertions.h>
#include <CGAL/Default.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/boost/graph/properties.h>

#include <istream>
#include <type_traits>
#include <vector>

namespace CGAL {

/// \ingroup PkgSpectralSurfaceMeshDeformationRef
/// Deforms a triangle mesh with the spectral dual Laplacian editing of
/// *Spectral Surface Deformation with Dual Mesh*, behind the API of
/// `CGAL::Surface_mesh_deformation`.
///
/// A program written for CGAL's class compiles when only the class name and
/// the include change, and keeps the semantics of the region of interest,
/// the control vertices and their targets. CGAL's algorithm tags are
/// accepted as `TAG` and select `SPECTRAL_DUAL_LAPLACIAN`; a weight calculator
/// of CGAL's class is accepted at the position of `ET` (and in the
/// constructor) and is not used, and so are CGAL's sparse solver traits at
/// the position of `ST`. What has no counterpart: CGAL's weight
/// calculators, sparse solver traits, closest rotation traits and SRE-ARAP's `alpha`
/// (`set_sre_arap_alpha()` is accepted and does nothing). What
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
/// **Costs.** The work is done on the faces incident to the ROI vertices
/// (the *region*: the ROI and the fixed vertices), so that it follows the
/// size of the ROI. `preprocess()` computes, per region, the manifold
/// harmonics basis (the dominant cost, see `Manifold_harmonics_basis`; it
/// can also be handed in or read from a cache) and, per constraint set, the
/// `m × m` factorization; `deform()` costs `O(n m)` per iteration and one
/// back-substitution, for `n` vertices of the region and `m` frequencies (see
/// the manual's section "What is computed when").
///
/// **Parameters** that only the spectral algorithms have, and the basis
/// cache, are the functions of the base `Spectral_deformation::Spectral_parameters`.
/// The functions of the ROI, the control vertices and their targets are
/// those of the base `Spectral_deformation::Roi_and_control_vertices`.
///
/// **Defaults**: 100 frequencies, constraint weight 1, at most 10 iterations,
/// tolerance 1e-4 on the relative step, `EXACT_CONSTRAINTS` (the semantics of
/// CGAL's class, which a drop-in replacement must keep), and the basis of
/// `Partition_of_unity_eigensolver_traits<>`: eigenvectors approximated in a
/// space of sampled functions on large regions, several times cheaper than
/// the exact ones and measured to give deformations as good; exact
/// eigenvectors on small regions. `Block_lanczos_eigensolver_traits<>` as `ET`
/// computes the exact basis at every size.
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
/// \tparam TAG the algorithm, a value of `Spectral_deformation_algorithm_tag`,
///         or, for programs written for CGAL's class, a value of CGAL's
///         `Deformation_algorithm_tag` (`ORIGINAL_ARAP`, `SPOKES_AND_RIMS`,
///         `SRE_ARAP`), which all select `SPECTRAL_DUAL_LAPLACIAN` (see
///         `algorithm`); any other value does not compile
/// \tparam ET a model of `ManifoldHarmonicsEigensolverTraits`; `Default` means
///         `Partition_of_unity_eigensolver_traits<>`, and so does a weight
///         calculator of CGAL's class (a model of `SurfaceMeshDeformationWeights`,
///         the parameter at this position in CGAL), which is not used: the
///         method's operators are the cotangent Laplacian of the manifold
///         harmonics and the dual mesh Laplacian, whose weights are fixed by
///         the method
/// \tparam ST a model of `SparseSPDSolverTraits` for the detail transfer and
///         the spatial solver; `Default` means
///         `Default_deformation_sparse_spd_solver_traits` for the detail
///         transfer and `Default_sparse_spd_solver_traits` for the spatial
///         solver, and so do CGAL's sparse solver traits (a model of
///         `SparseLinearAlgebraWithFactorTraits_d` such as `Eigen_solver_traits`,
///         the parameter at this position in CGAL), which are not used: the
///         systems here are symmetric positive definite and are factored
///         through the package's own concept
/// \tparam Reserved not used, whatever it is (CGAL's closest rotation traits
///         in programs written for CGAL's class); it keeps `VPM` at the
///         position it has in CGAL's class
/// \tparam VPM a model of `ReadWritePropertyMap` with `vertex_descriptor` as key and
///         a 3D point as value; `Default` means `boost::property_map<TM, vertex_point_t>::%type`
template <class TM,
          class VIM = Default,
          class HIM = Default,
          auto TAG = SPECTRAL_DUAL_LAPLACIAN,
          class ET = Default,
          class ST = Default,
          class Reserved = Default,
          class VPM = Default>
class Spectral_surface_mesh_deformation
  : public Spectral_deformation::Roi_and_control_vertices<
        Spectral_surface_mesh_deformation<TM, VIM, HIM, TAG, ET, ST, Reserved, VPM>,
        TM,
        typename Spectral_deformation::internal::Deformation::Deformation_class_types<TM, VIM, HIM, TAG, ET, ST,
                                                                                     VPM>::Eigensolver_traits,
        typename Spectral_deformation::internal::Deformation::Deformation_class_types<TM, VIM, HIM, TAG, ET, ST,
                                                                                     VPM>::Computation,
        typename Spectral_deformation::internal::Deformation::Deformation_class_types<TM, VIM, HIM, TAG, ET, ST,
                                                                                     VPM>::Selection>
{
  typedef Spectral_deformation::internal::Deformation::Deformation_class_types<TM, VIM, HIM, TAG, ET, ST, VPM> Types;
  typedef typename Types::Computation Computation;
  typedef typename Types::Selection Selection;
  typedef Spectral_deformation::Roi_and_control_vertices<Spectral_surface_mesh_deformation,
                                                         TM, typename Types::Eigensolver_traits, Computation,
                                                         Selection>
      Base;
  typedef Spectral_deformation::Spectral_parameters<Spectral_surface_mesh_deformation, TM,
                                                    typename Types::Eigensolver_traits, Computation>
      Parameters_base;
  // The bases hold no data: they reach the selection and the computation,
  // the one home of the settings, through this class.
  friend Base;
  friend Parameters_base;
  static constexpr bool is_spectral = Computation::is_spectral;

public:
  /// \name Types
  /// @{

  /// The mesh type.
  typedef TM Triangle_mesh;
  /// The vertex index map type.
  typedef typename Types::Vertex_index_map Vertex_index_map;
  /// The halfedge index map type (unused).
  typedef typename Types::Hedge_index_map Hedge_index_map;
  /// The vertex point map type.
  typedef typename Types::Vertex_point_map Vertex_point_map;
  /// The eigensolver traits type: `ET`, or `Partition_of_unity_eigensolver_traits<>`
  /// when `ET` is `Default` or a weight calculator.
  typedef typename Types::Eigensolver_traits Eigensolver_traits;
  /// The sparse solver traits type of the detail transfer.
  typedef typename Types::Sparse_solver_traits Sparse_solver_traits;
  /// The sparse solver traits type of the spatial solver.
  typedef typename Types::Spatial_solver_traits Spatial_solver_traits;
  /// The point type.
  typedef typename boost::property_traits<Vertex_point_map>::value_type Point;
  /// The vertex descriptor type.
  typedef typename boost::graph_traits<TM>::vertex_descriptor vertex_descriptor;
  /// The range of ROI vertices.
  typedef std::vector<vertex_descriptor> Roi_vertex_range;

  /// @}

  /// The algorithm that `TAG` selects: `TAG` itself when it is a
  /// `Spectral_deformation_algorithm_tag`, `SPECTRAL_DUAL_LAPLACIAN` when it
  /// is one of CGAL's tags.
  static constexpr Spectral_deformation_algorithm_tag algorithm = Types::Algorithm::value;
  /// Whether `TAG` is one of CGAL's `Deformation_algorithm_tag` values.
  static constexpr bool is_cgal_algorithm_tag = Types::Algorithm::is_cgal_tag;
  /// Whether `ET` is a weight calculator of CGAL's class, accepted and not used.
  static constexpr bool has_unused_weight_calculator = Types::Eigensolver::is_weight_calculator;

  /// Whether the algorithm `TAG` works in a basis of manifold harmonics
  /// (`SPECTRAL_DUAL_LAPLACIAN`, `SPECTRAL_LINEAR`). The options of the basis
  /// and of the reduced system (`set_number_of_frequencies()`,
  /// `set_constraint_weight()`, `set_constraint_policy()`, the basis cache,
  /// ...) do not compile for an algorithm without basis.
  static constexpr bool has_basis = is_spectral;

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
    : m_selection(triangle_mesh, vertex_index_map, vertex_point_map), m_him(hedge_index_map)
  {}

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

  /// Creates a deformation object as the constructor with four arguments does,
  /// for programs written for CGAL's class, whose constructor takes a weight
  /// calculator last: `weight_calculator` is not used (see `ET`).
  /// \tparam WeightCalculator a model of CGAL's `SurfaceMeshDeformationWeights`
  /// \param triangle_mesh the triangulated mesh to deform (see the constructor with four arguments)
  /// \param vertex_index_map unique vertex indices in `[0, num_vertices(triangle_mesh))`
  /// \param hedge_index_map unused, for compatibility
  /// \param vertex_point_map the positions, read and written
  /// \param weight_calculator not used
  template <class WeightCalculator,
            std::enable_if_t<Spectral_deformation::internal::Deformation::Is_weight_calculator<WeightCalculator, TM>::value,
                             int> = 0>
  Spectral_surface_mesh_deformation(Triangle_mesh& triangle_mesh,
                                    Vertex_index_map vertex_index_map,
                                    Hedge_index_map hedge_index_map,
                                    Vertex_point_map vertex_point_map,
                                    const WeightCalculator& weight_calculator)
    : Spectral_surface_mesh_deformation(triangle_mesh, vertex_index_map, hedge_index_map, vertex_point_map)
  {
    CGAL_USE(weight_calculator);
  }

  /// Not copyable, as in CGAL: the object refers to the mesh it deforms.
  Spectral_surface_mesh_deformation(const Spectral_surface_mesh_deformation&) = delete;
  /// Not assignable, as in CGAL.
  Spectral_surface_mesh_deformation& operator=(const Spectral_surface_mesh_deformation&) = delete;

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
  void deform(unsigned int iterations, double tolerance) { m_computation.deform(m_selection, iterations, tolerance); }

  /// Refines the current positions of the ROI towards the optimum of the
  /// as-rigid-as-possible energy (Sorkine and Alexa 2007) for the current
  /// targets: the iteration of CGAL's `Surface_mesh_deformation` with
  /// `ORIGINAL_ARAP`, on the detailed mesh, with the control vertices on
  /// their targets and the vertices outside the ROI fixed, started from what
  /// the mesh holds (usually the result of `deform()`, a far better start
  /// than the rest shape). Each iteration fits a rotation per vertex one-ring
  /// and back-substitutes with a sparse factorization of the region's
  /// cotangent Laplacian, its negative weights clamped at 0 as in CGAL: with
  /// `EXACT_CONSTRAINTS` and no negative weight the one `preprocess()` made
  /// for the detail transfer; otherwise the first `refine()` of a constraint
  /// set makes it. With `set_volume_preservation()`, each
  /// iteration keeps the enclosed volume (as-rigid-as-possible deformation
  /// alone lets a twisted tube collapse as its energy falls).
  ///
  /// Runs at most `max_iterations` iterations; stops earlier when one lowers
  /// the energy by less than `tolerance` times its value. Returns whether the
  /// mesh was updated; the energies, iterations and times are in
  /// `refine_report()`. A failure (of `preprocess()`, a numerical one, a
  /// negative or NaN `tolerance`) leaves the mesh unchanged. The next
  /// `deform()` goes on from its own iteration, not from the refined shape.
  bool refine(unsigned int max_iterations = 100, double tolerance = 1e-5)
  {
    return m_computation.refine(m_selection, max_iterations, tolerance);
  }

  /// Puts the vertices of the ROI back at their initial positions, resets the
  /// targets of the control vertices to them, and restarts the iteration.
  /// The region (and its basis) is kept.
  void reset()
  {
    m_selection.reset_to_original();
    m_computation.restart();
  }

  /// Makes the current positions of the ROI vertices their initial
  /// positions, as if a new object had been built on the current mesh with
  /// the same ROI and control vertices. The region, its basis included, is
  /// rebuilt by the next `preprocess()`.
  void overwrite_initial_geometry()
  {
    m_selection.overwrite_original();
    m_computation.drop_region();
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

  /// Accepted for programs written for CGAL's class with `SRE_ARAP`, and
  /// not used: the method has no bending term to weight; the iteration on the
  /// smooth mesh already makes neighbouring rotations alike.
  void set_sre_arap_alpha(double alpha) { CGAL_USE(alpha); }

  /// Whether the solvers of this object may change state of the whole
  /// process to run faster (default `false`): the thread count of OpenBLAS,
  /// huge pages, SuiteSparse's allocator during a factorization (see
  /// `Block_lanczos_eigensolver_traits::set_process_wide_tuning()` and
  /// `Cholmod_llt_solver_traits::set_process_wide_tuning()`). With the
  /// spectral algorithms it is the setting of the eigensolver traits.
  bool process_wide_tuning() const { return m_computation.process_wide_tuning(); }
  /// Sets `process_wide_tuning()`, for programs that own their process; it
  /// applies to the eigensolver traits (when they have the option) and to the
  /// sparse solvers of the detail transfer or of the spatial solver, from
  /// their next factorization or basis; the region, its basis and its
  /// factorizations are kept.
  void set_process_wide_tuning(bool enabled) { m_computation.set_process_wide_tuning(enabled); }

  /// @}

  /// \name Basis cache
  /// @{

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
    static_assert(is_spectral, "load_basis(): SPATIAL_DUAL_LAPLACIAN has no basis");
    m_computation.load_basis(is, m_selection);
  }

  /// @}

  /// \name Reports and intermediate shapes
  /// @{

  /// What the last `preprocess()` did.
  const Spectral_preprocess_report& preprocess_report() const { return m_computation.preprocess_report(); }
  /// What the last `deform()` did.
  const Spectral_deformation_report& deform_report() const { return m_computation.deform_report(); }
  /// What the last `refine()` did.
  const Spectral_refinement_report& refine_report() const { return m_computation.refine_report(); }

  /// The smooth rest position of `vd`, the second shape of the paper's
  /// pipeline figure: its low-pass reconstruction \f$ H H^\top M V \f$ with
  /// the basis of the region. It is the initial position when `vd` is not in
  /// the region, when no region is built, or with `SPATIAL_DUAL_LAPLACIAN`.
  Point smoothed_rest_point(vertex_descriptor vd) const
  {
    const int i = m_computation.local_index(m_selection, vd);
    if constexpr(is_spectral)
      if(i >= 0)
        return to_point(m_computation.pipeline().smooth_rest(i));
    return m_selection.original(vd);
  }

  /// The smooth deformed position of `vd` after the last successful
  /// `deform()`, the third shape of the paper's pipeline figure; the smooth
  /// rest position before any deformation or after `reset()`. It is the
  /// initial position when `vd` is not in the region, when no region is
  /// built, or with `SPATIAL_DUAL_LAPLACIAN`.
  Point smoothed_deformed_point(vertex_descriptor vd) const
  {
    const int i = m_computation.local_index(m_selection, vd);
    if constexpr(is_spectral)
      if(i >= 0)
        return to_point(m_computation.pipeline().smooth_deformed(i));
    return m_selection.original(vd);
  }

  /// @}

  /// \name Access
  /// @{

  /// The vertices of the ROI.
  const Roi_vertex_range& roi_vertices() const { return m_selection.roi(); }
  /// Whether `vd` is in the ROI.
  bool is_roi_vertex(vertex_descriptor vd) const { return m_selection.is_roi(vd); }
  /// Whether `vd` is a control vertex.
  bool is_control_vertex(vertex_descriptor vd) const { return m_selection.is_control(vd); }
  /// The mesh being deformed.
  const Triangle_mesh& triangle_mesh() const { return m_selection.mesh(); }
  /// The vertex index map.
  const Vertex_index_map& vertex_index_map() const { return m_selection.vertex_index_map(); }
  /// The halfedge index map (not used by the deformation).
  Hedge_index_map hedge_index_map() const { return m_him; }

  /// @}

private:
  static Point to_point(const Eigen::RowVector3d& x) { return Point(x[0], x[1], x[2]); }

  /// What the user selected on the mesh: the ROI, the control vertices,
  /// their targets and the initial positions.
  Selection m_selection;
  /// The computation on the region, owner of the settings (one object,
  /// handed down by const reference to the pipeline and the solvers).
  Computation m_computation;
  Hedge_index_map m_him;
  unsigned int m_iterations = 10;
  double m_tolerance = 1e-4;
};

} // namespace CGAL

#endif // CGAL_SPECTRAL_SURFACE_MESH_DEFORMATION_H
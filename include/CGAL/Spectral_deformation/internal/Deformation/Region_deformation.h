// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_REGION_DEFORMATION_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_REGION_DEFORMATION_H

#include <CGAL/Spectral_deformation/Deformation_reports.h>
#include <CGAL/Spectral_deformation/Spectral_deformation_error.h>
#include <CGAL/Spectral_deformation/internal/Basis/basis_in_region_order.h>
#include <CGAL/Spectral_deformation/internal/Basis/basis_io.h>
#include <CGAL/Spectral_deformation/internal/Deformation/Constraint_set.h>
#include <CGAL/Spectral_deformation/internal/Deformation/Iteration_report.h>
#include <CGAL/Spectral_deformation/internal/Deformation/Spectral_settings.h>
#include <CGAL/Spectral_deformation/internal/Memory/Process_wide_tuning.h>
#include <CGAL/Spectral_deformation/internal/Mesh/Region.h>
#include <CGAL/Spectral_deformation/internal/available_threads.h>

#include <CGAL/number_utils.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <istream>
#include <memory>
#include <new>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Spectral_deformation {
namespace internal {
namespace Deformation {

using Basis::Basis_data;
using Mesh::Positions;

/// The computation behind `Spectral_surface_mesh_deformation` for the
/// vertices a `Vertex_selection` holds: the region cut from the mesh, its
/// pipeline (built per region, prepared per constraint set, run per target
/// change), the settings, a basis handed in, and the reports. `preprocess()`
/// and `deform()` never throw `Spectral_deformation_error`: they put the
/// reason in their report.
template <class VertexSelection, class Pipeline, class EigensolverTraits, bool IsSpectral>
class Region_deformation
{
public:
  /// Whether `Pipeline` works in a basis of manifold harmonics.
  static constexpr bool is_spectral = IsSpectral;

private:
  typedef typename VertexSelection::vertex_descriptor vertex_descriptor;
  typedef typename VertexSelection::Point Point;
  typedef Spectral_deformation_error Error;

  // Everything that depends only on the ROI and the initial geometry.
  struct Region : Mesh::Region<vertex_descriptor>
  {
    Pipeline pipeline;
  };

  static constexpr const char* out_of_memory = "not enough memory (an allocation failed); nothing was changed";

public:
  Spectral_settings& settings() { return m_settings; }
  const Spectral_settings& settings() const { return m_settings; }
  EigensolverTraits& eigensolver() { return m_eigensolver; }

  /// Whether the solvers may change process-wide state: the spectral
  /// pipelines follow the eigensolver traits (which hand the choice on to the
  /// detail transfer), the spatial one this flag.
  bool process_wide_tuning() const
  {
    if constexpr(is_spectral)
      return Memory::process_wide_tuning_of(m_eigensolver);
    else
      return m_process_wide_tuning;
  }

  /// Takes effect at the next factorization and, for the eigensolver, at
  /// the next basis (the spectral pipelines: when the eigensolver traits
  /// support the option). The region, its basis and its factorizations are
  /// kept: the setting changes how fast they are made, not what they are.
  void set_process_wide_tuning(bool enabled)
  {
    Memory::set_process_wide_tuning_if_supported(m_eigensolver, enabled);
    m_process_wide_tuning = enabled;
    if(m_region)
      m_region->pipeline.set_process_wide_tuning(process_wide_tuning());
  }

  const Spectral_preprocess_report& preprocess_report() const { return m_preprocess_report; }
  const Spectral_deformation_report& deform_report() const { return m_deform_report; }
  const Spectral_refinement_report& refine_report() const { return m_refine_report; }

  /// The ROI changed: the region is cut again by the next `preprocess()`,
  /// which puts the vertices that left it back at their initial positions.
  void roi_changed()
  {
    if(m_region)
      m_previous_region_vertices = m_region->vertices;
    drop_region();
  }

  /// The initial geometry or the number of frequencies changed.
  void drop_region()
  {
    m_region.reset();
    m_result = Positions();
    m_constraints_valid = false;
  }

  void constraints_changed() { m_constraints_valid = false; }

  /// The iteration starts again from the rest shape.
  void restart()
  {
    if(m_region)
      m_region->pipeline.restart();
  }

  void set_rotation_patches(std::size_t count)
  {
    m_settings.rotation_patches = count;
    if(m_region)
      m_region->pipeline.set_rotation_patches(count);
  }

  /// Takes effect at the next `deform()`.
  void set_stage_angle(double radians) { m_settings.stage_angle = radians; }

  /// Takes effect at the next `deform()`.
  void set_volume_preservation(bool preserve)
  {
    m_settings.preserve_volume = preserve;
    if(m_region)
      m_region->pipeline.set_volume_preservation(preserve, *m_region);
  }

  void set_smooth_energy(Spectral_smooth_energy energy)
  {
    if(energy == m_settings.smooth_energy)
      return;
    m_settings.smooth_energy = energy;
    if(m_region)
    {
      m_region->pipeline.set_smooth_energy(energy, *m_region);
      m_constraints_valid = false;
    }
  }

  /// A basis to use for a region on the mesh it was computed on; a region
  /// built with another basis is built again.
  void supply_basis(Basis_data data)
  {
    m_supplied_basis = std::move(data);
    if(m_region && m_region->pipeline.has_basis() &&
       m_supplied_basis.fingerprint != m_region->pipeline.basis_fingerprint())
      drop_region();
  }

  void save_basis(std::ostream& os) const
  {
    if(!m_region || !m_region->pipeline.has_basis())
      throw Error(Error::IO_ERROR, "save_basis: no basis yet, call preprocess() first");
    m_region->pipeline.write_basis(os);
  }

  /// Reads a basis and checks it against the region of the current ROI.
  void load_basis(std::istream& is, const VertexSelection& selection)
  {
    Basis_data data = Basis::read_basis(is);
    const Mesh::Region<vertex_descriptor> region = extract_region(selection);
    const std::uint64_t region_fingerprint = Mesh::fingerprint(region.arrays);
    const Basis::Basis_match match = Basis::basis_match(data, region, region_fingerprint);
    if(match == Basis::Basis_match::NONE)
    {
      // Throws with the sizes, or the fingerprint, that differ.
      Basis::check_basis_matches(data, region.arrays);
      throw Error(Error::MESH_MISMATCH, "load: the basis was computed on a different mesh");
    }
    m_supplied_basis = Basis::in_region_order(data, region, match, region_fingerprint);
    drop_region();
  }

  /// The local index of `vd` in the region, or -1.
  int local_index(const VertexSelection& selection, vertex_descriptor vd) const
  {
    return m_region ? m_region->local[selection.id(vd)] : -1;
  }

  const Pipeline& pipeline() const { return m_region->pipeline; }

  bool preprocess(VertexSelection& selection)
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
    const bool serial = selection.roi().size() < serial_preparation_vertices;
    const One_thread_scope threads(serial);
    m_preprocess_report = Spectral_preprocess_report();
    m_preprocess_report.success = reported(m_preprocess_report, [&] { preprocess_or_throw(selection); });
    m_blas_threads_may_spin = serial && m_preprocess_report.basis_computed;
    if(!m_preprocess_report.success)
      m_constraints_valid = false;
    return m_preprocess_report.success;
  }

  void deform(VertexSelection& selection, unsigned int iterations, double tolerance)
  {
    const auto start = std::chrono::steady_clock::now();
    m_deform_report = Spectral_deformation_report();
    if(!preprocess(selection))
    {
      m_deform_report.message = "preprocess() failed: " + m_preprocess_report.message;
      return;
    }
    // Right after the basis of a small region the BLAS threads still wait
    // for work spinning, and a team of OpenMP threads beside them took ten
    // times as long (80 ms instead of 6-12 ms on 2,174 region vertices).
    const One_thread_scope threads(selection.roi().size() < serial_deformation_vertices ||
                                   std::exchange(m_blas_threads_may_spin, false));
    m_deform_report.success = reported(m_deform_report, [&] {
      Region& region = *m_region;
      const Positions targets = constrained_targets(selection);
      Positions& result = m_result;
      region.pipeline.deform(region, m_constraints, targets, std::max(1u, iterations), tolerance,
                             m_settings.stage_angle, result, m_deform_report);
      report_residuals(result, targets);
      write_result(selection, result);
      // The iteration state changes only with the mesh.
      region.pipeline.accept();
    });
    m_deform_report.total_seconds = seconds_since(start);
  }

  /// As-rigid-as-possible iterations from the current positions of the
  /// region in the mesh, with the control vertices on their targets and the
  /// fixed ring at rest; written to the mesh only when they succeed.
  bool refine(VertexSelection& selection, unsigned int max_iterations, double tolerance)
  {
    const auto start = std::chrono::steady_clock::now();
    const One_thread_scope threads(selection.roi().size() < serial_deformation_vertices);
    m_refine_report = Spectral_refinement_report();
    if(!(tolerance >= 0))
    {
      m_refine_report.message = "refine(): the tolerance must be a number, 0 or more";
      return false;
    }
    if(!preprocess(selection))
    {
      m_refine_report.message = "preprocess() failed: " + m_preprocess_report.message;
      return false;
    }
    m_refine_report.success = reported(m_refine_report, [&] {
      Region& region = *m_region;
      const Positions targets = constrained_targets(selection);
      Positions positions(static_cast<Eigen::Index>(region.vertices.size()), 3);
      for(std::size_t i = 0; i < region.vertices.size(); ++i)
      {
        const Point p = selection.position(region.vertices[i]);
        positions.row(static_cast<Eigen::Index>(i)) << CGAL::to_double(p[0]), CGAL::to_double(p[1]),
            CGAL::to_double(p[2]);
      }
      if(!positions.allFinite())
        throw Error(Error::INVALID_MESH, "refine(): a vertex of the region has a non-finite position");
      region.pipeline.refine(region, m_constraints, targets, max_iterations, tolerance, positions,
                             m_refine_report);
      write_result(selection, positions);
    });
    m_refine_report.total_seconds = seconds_since(start);
    return m_refine_report.success;
  }

private:
  // Runs `step`; returns false with the reason in `report.message` when it
  // fails with a `Spectral_deformation_error` or runs out of memory.
  template <class Report, class Step>
  static bool reported(Report& report, const Step& step)
  {
    try
    {
      step();
      return true;
    }
    catch(const Error& e)
    {
      report.message = e.what();
    }
    catch(const std::bad_alloc&)
    {
      report.message = out_of_memory;
    }
    return false;
  }

  // The faces incident to ROI vertices, with local vertex indices along the
  // surface (Mesh::extract_region()); validated.
  static Mesh::Region<vertex_descriptor> extract_region(const VertexSelection& selection)
  {
    return Mesh::extract_region(
        selection.mesh(), [&selection](vertex_descriptor vd) { return selection.id(vd); }, selection.roi_flags(),
        selection.originals());
  }

  // The fixed ring around the region and the control vertices of `selection`.
  static Constraint_set selection_constraints(const VertexSelection& selection, const Region& region)
  {
    return make_constraint_set(
        region, [&selection, &region](std::size_t i) { return selection.is_control(region.vertices[i]); });
  }

  void build_region(const VertexSelection& selection)
  {
    const auto start = std::chrono::steady_clock::now();
    std::unique_ptr<Region> region(new Region());
    static_cast<Mesh::Region<vertex_descriptor>&>(*region) = extract_region(selection);
    if constexpr(is_spectral)
    {
      // The constraint set that preprocess() prepares next: its factorization
      // may start while the basis is computed. An invalid one is reported
      // by preprocess() after the region is built, as without the overlap.
      Constraint_set first_set;
      bool valid = true;
      try
      {
        first_set = selection_constraints(selection, *region);
      }
      catch(const Error&)
      {
        valid = false;
      }
      region->pipeline.build(*region, m_supplied_basis, m_settings, m_eigensolver, m_preprocess_report,
                             valid ? &first_set : nullptr);
    }
    else
      region->pipeline.build(*region, m_process_wide_tuning);
    m_region = std::move(region);
    m_preprocess_report.region_rebuilt = true;
    m_preprocess_report.region_seconds = seconds_since(start);
  }

  void preprocess_or_throw(VertexSelection& selection)
  {
    if(selection.mesh_size_changed())
      throw Error(Error::INVALID_MESH, "the number of vertices of the mesh changed since the "
                                       "construction of the deformation object");
    if(selection.roi().empty())
      throw Error(Error::INVALID_ARGUMENT, "the region of interest is empty");
    if(!m_region)
    {
      // Vertices that left the ROI go back to their initial positions.
      for(vertex_descriptor vd : m_previous_region_vertices)
        if(!selection.is_roi(vd))
          selection.put_position(vd, selection.original(vd));
      m_previous_region_vertices.clear();
      build_region(selection);
    }
    Region& region = *m_region;
    // A control vertex of no face is not in the region: its target could not
    // be met. (An isolated ROI vertex without a target just stays put.)
    for(std::size_t i = 0; i < selection.number_of_indices(); ++i)
      if(selection.is_control_index(i) && region.local[i] < 0)
        throw Error(Error::INVALID_MESH, "control vertex " + std::to_string(i) + " belongs to no face");
    m_preprocess_report.number_of_region_vertices = region.vertices.size();
    if constexpr(is_spectral)
    {
      m_preprocess_report.number_of_frequencies = region.pipeline.number_of_frequencies();
      m_preprocess_report.single_precision_basis = region.pipeline.single_precision_basis();
    }

    m_constraints = selection_constraints(selection, region);
    m_preprocess_report.number_of_constrained_vertices = m_constraints.size();

    const auto start = std::chrono::steady_clock::now();
    if constexpr(is_spectral)
      region.pipeline.prepare(region, m_constraints, m_settings);
    else
      region.pipeline.prepare(region, m_constraints);
    m_preprocess_report.factorization_seconds = seconds_since(start);
    m_constraints_valid = true;
  }

  // Targets of the constrained vertices (k×3): initial positions for the
  // fixed ring, the user's targets for the control vertices.
  Positions constrained_targets(const VertexSelection& selection) const
  {
    const Region& region = *m_region;
    const std::vector<int>& constrained = m_constraints.constrained;
    Positions targets(static_cast<Eigen::Index>(constrained.size()), 3);
    for(std::size_t k = 0; k < constrained.size(); ++k)
    {
      const std::size_t i = static_cast<std::size_t>(constrained[k]);
      const vertex_descriptor vd = region.vertices[i];
      const Point& p = region.is_fixed[i] ? selection.original(vd) : selection.target(vd);
      targets.row(static_cast<Eigen::Index>(k)) << CGAL::to_double(p[0]), CGAL::to_double(p[1]),
          CGAL::to_double(p[2]);
    }
    if(!targets.allFinite())
      throw Error(Error::INVALID_ARGUMENT, "a target position is not finite");
    return targets;
  }

  void report_residuals(const Positions& result, const Positions& targets)
  {
    double max_residual = 0, sum = 0;
    std::size_t count = 0;
    for(std::size_t k = 0; k < m_constraints.size(); ++k)
    {
      const int i = m_constraints.constrained[k];
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
  void write_result(const VertexSelection& selection, const Positions& result) const
  {
    if(!result.allFinite())
      throw Error(Error::SOLVER_FAILURE, "the deformation produced non-finite positions");
    const Region& region = *m_region;
    for(std::size_t i = 0; i < region.vertices.size(); ++i)
      if(!region.is_fixed[i])
      {
        const auto x = result.row(static_cast<Eigen::Index>(i));
        selection.put_position(region.vertices[i], Point(x[0], x[1], x[2]));
      }
  }

  Spectral_settings m_settings;
  EigensolverTraits m_eigensolver;
  Basis_data m_supplied_basis;
  std::vector<vertex_descriptor> m_previous_region_vertices;
  bool m_process_wide_tuning = false;

  std::unique_ptr<Region> m_region;
  Positions m_result; // of the last drag, its storage kept for the next one
  bool m_constraints_valid = false;
  // The last preprocess() computed a small region's basis on one OpenMP
  // thread beside the BLAS threads (serial_preparation_vertices).
  bool m_blas_threads_may_spin = false;
  Constraint_set m_constraints;

  Spectral_preprocess_report m_preprocess_report;
  Spectral_deformation_report m_deform_report;
  Spectral_refinement_report m_refine_report;
};

} // namespace Deformation
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_REGION_DEFORMATION_H

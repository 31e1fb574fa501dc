// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The compiled core of the package (internal/compiled_core.h): the
// pipelines of the three algorithms with the default traits, compiled once
// for the programs that link the package's CMake targets.

// The functions of the eigensolvers that are not templates are defined here,
// once, for the programs that link the core (internal/compiled_core.h).
#define CGAL_SSMD_COMPILING_CORE
#include <CGAL/Spectral_deformation/Sparse_spd_solver_traits.h>
#include <CGAL/Spectral_deformation/internal/Deformation/Compiled_spectral_pipeline.h>
#include <CGAL/Spectral_deformation/internal/Deformation/Spatial_pipeline.h>
#include <CGAL/Spectral_deformation/internal/Deformation/Spectral_pipeline.h>

#if !defined(CGAL_SSMD_COMPILED_CORE) || CGAL_SSMD_COMPILED_CORE != CGAL_SSMD_CONFIGURATION
#error "the compiled core must be compiled with CGAL_SSMD_COMPILED_CORE set to its CGAL_SSMD_CONFIGURATION"
#endif

namespace CGAL {
namespace Spectral_deformation {
namespace internal {
namespace Deformation {

template <bool Iterated>
class Compiled_spectral_pipeline<Iterated>::Implementation
    : public Spectral_pipeline<Default_deformation_sparse_spd_solver_traits, Iterated>
{
};

template <bool Iterated>
Compiled_spectral_pipeline<Iterated>::Compiled_spectral_pipeline() : m_implementation(new Implementation())
{
}
template <bool Iterated>
Compiled_spectral_pipeline<Iterated>::~Compiled_spectral_pipeline() = default;

template <bool Iterated>
void Compiled_spectral_pipeline<Iterated>::build(const Mesh::Region_geometry& region, const Basis::Basis_data& supplied,
                                       const Spectral_settings& settings, const Approximate_eigensolver& eigensolver,
                                       Spectral_preprocess_report& report, const Constraint_set* first_set)
{
  m_implementation->build(region, supplied, settings, eigensolver, report, first_set);
}

template <bool Iterated>
void Compiled_spectral_pipeline<Iterated>::build(const Mesh::Region_geometry& region, const Basis::Basis_data& supplied,
                                       const Spectral_settings& settings, const Exact_eigensolver& eigensolver,
                                       Spectral_preprocess_report& report, const Constraint_set* first_set)
{
  m_implementation->build(region, supplied, settings, eigensolver, report, first_set);
}

template <bool Iterated>
void Compiled_spectral_pipeline<Iterated>::prepare(const Mesh::Region_geometry& region, const Constraint_set& set,
                                         const Spectral_settings& settings)
{
  m_implementation->prepare(region, set, settings);
}

template <bool Iterated>
void Compiled_spectral_pipeline<Iterated>::deform(const Mesh::Region_geometry& region, const Constraint_set& set,
                                        const Mesh::Positions& targets, unsigned int iterations, double tolerance,
                                        double stage_angle, Mesh::Positions& result,
                                        Spectral_deformation_report& report)
{
  m_implementation->deform(region, set, targets, iterations, tolerance, stage_angle, result, report);
}

template <bool Iterated>
void Compiled_spectral_pipeline<Iterated>::refine(const Mesh::Region_geometry& region, const Constraint_set& set,
                                        const Mesh::Positions& targets, unsigned int max_iterations,
                                        double tolerance, Mesh::Positions& positions,
                                        Spectral_refinement_report& report)
{
  m_implementation->refine(region, set, targets, max_iterations, tolerance, positions, report);
}

template <bool Iterated>
void Compiled_spectral_pipeline<Iterated>::accept() { m_implementation->accept(); }
template <bool Iterated>
void Compiled_spectral_pipeline<Iterated>::restart() { m_implementation->restart(); }
template <bool Iterated>
void Compiled_spectral_pipeline<Iterated>::set_process_wide_tuning(bool enabled)
{
  m_implementation->set_process_wide_tuning(enabled);
}
template <bool Iterated>
void Compiled_spectral_pipeline<Iterated>::set_rotation_patches(std::size_t count)
{
  m_implementation->set_rotation_patches(count);
}
template <bool Iterated>
void Compiled_spectral_pipeline<Iterated>::set_volume_preservation(bool preserve, const Mesh::Region_geometry& region)
{
  m_implementation->set_volume_preservation(preserve, region);
}
template <bool Iterated>
bool Compiled_spectral_pipeline<Iterated>::preserves_volume() const { return m_implementation->preserves_volume(); }
template <bool Iterated>
void Compiled_spectral_pipeline<Iterated>::set_smooth_energy(Spectral_smooth_energy energy, const Mesh::Region_geometry& region)
{
  m_implementation->set_smooth_energy(energy, region);
}
template <bool Iterated>
bool Compiled_spectral_pipeline<Iterated>::has_basis() const { return m_implementation->has_basis(); }
template <bool Iterated>
std::uint64_t Compiled_spectral_pipeline<Iterated>::basis_fingerprint() const { return m_implementation->basis_fingerprint(); }
template <bool Iterated>
bool Compiled_spectral_pipeline<Iterated>::single_precision_basis() const { return m_implementation->single_precision_basis(); }
template <bool Iterated>
void Compiled_spectral_pipeline<Iterated>::write_basis(std::ostream& os) const { m_implementation->write_basis(os); }
template <bool Iterated>
std::size_t Compiled_spectral_pipeline<Iterated>::number_of_frequencies() const
{
  return m_implementation->number_of_frequencies();
}
template <bool Iterated>
Eigen::RowVector3d Compiled_spectral_pipeline<Iterated>::smooth_rest(Eigen::Index i) const
{
  return m_implementation->smooth_rest(i);
}
template <bool Iterated>
Eigen::RowVector3d Compiled_spectral_pipeline<Iterated>::smooth_deformed(Eigen::Index i) const
{
  return m_implementation->smooth_deformed(i);
}

template class Compiled_spectral_pipeline<true>;
template class Compiled_spectral_pipeline<false>;

class Compiled_spatial_pipeline::Implementation : public Spatial_pipeline<Default_sparse_spd_solver_traits>
{
};

Compiled_spatial_pipeline::Compiled_spatial_pipeline() : m_implementation(new Implementation()) {}
Compiled_spatial_pipeline::~Compiled_spatial_pipeline() = default;
void Compiled_spatial_pipeline::build(const Mesh::Region_geometry& region, bool process_wide_tuning)
{
  m_implementation->build(region, process_wide_tuning);
}
void Compiled_spatial_pipeline::set_process_wide_tuning(bool enabled)
{
  m_implementation->set_process_wide_tuning(enabled);
}
void Compiled_spatial_pipeline::prepare(const Mesh::Region_geometry& region, const Constraint_set& set)
{
  m_implementation->prepare(region, set);
}
void Compiled_spatial_pipeline::deform(const Mesh::Region_geometry& region, const Constraint_set& set,
                                       const Mesh::Positions& targets, unsigned int iterations, double tolerance,
                                       double stage_angle, Mesh::Positions& result,
                                       Spectral_deformation_report& report)
{
  m_implementation->deform(region, set, targets, iterations, tolerance, stage_angle, result, report);
}
void Compiled_spatial_pipeline::refine(const Mesh::Region_geometry& region, const Constraint_set& set,
                                       const Mesh::Positions& targets, unsigned int max_iterations,
                                       double tolerance, Mesh::Positions& positions,
                                       Spectral_refinement_report& report)
{
  m_implementation->refine(region, set, targets, max_iterations, tolerance, positions, report);
}
void Compiled_spatial_pipeline::accept() { m_implementation->accept(); }
void Compiled_spatial_pipeline::restart() { m_implementation->restart(); }

} // namespace Deformation
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

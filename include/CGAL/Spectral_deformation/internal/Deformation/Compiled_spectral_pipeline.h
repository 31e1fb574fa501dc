// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_COMPILED_SPECTRAL_PIPELINE_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_COMPILED_SPECTRAL_PIPELINE_H

#include <CGAL/Spectral_deformation/Block_lanczos_eigensolver_traits.h>
#include <CGAL/Spectral_deformation/Deformation_reports.h>
#include <CGAL/Spectral_deformation/Partition_of_unity_eigensolver_traits.h>
#include <CGAL/Spectral_deformation/internal/Basis/basis_io.h>
#include <CGAL/Spectral_deformation/internal/Deformation/Constraint_set.h>
#include <CGAL/Spectral_deformation/internal/Deformation/Spectral_settings.h>
#include <CGAL/Spectral_deformation/internal/Mesh/Region.h>
#include <CGAL/Spectral_deformation/internal/compiled_core.h>

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <ostream>

namespace CGAL {
namespace Spectral_deformation {
namespace internal {
namespace Deformation {

/// `Spectral_pipeline<Default_deformation_sparse_spd_solver_traits, Iterated>`
/// (the pipeline of `SPECTRAL_DUAL_LAPLACIAN`, and of `SPECTRAL_LINEAR`
/// without iterations) behind a class whose functions are defined only in
/// the package's compiled core (`compiled_core.h`), for both values of
/// `Iterated`, so that a program that deforms does not compile them. Same
/// functions, same results; `build()` takes the two eigensolver traits whose
/// defaults the core compiles.
template <bool Iterated>
class Compiled_spectral_pipeline
{
public:
  typedef Partition_of_unity_eigensolver_traits<> Approximate_eigensolver;
  typedef Block_lanczos_eigensolver_traits<> Exact_eigensolver;

  Compiled_spectral_pipeline();
  ~Compiled_spectral_pipeline();
  Compiled_spectral_pipeline(const Compiled_spectral_pipeline&) = delete;
  Compiled_spectral_pipeline& operator=(const Compiled_spectral_pipeline&) = delete;

  void build(const Mesh::Region_geometry& region, const Basis::Basis_data& supplied,
             const Spectral_settings& settings, const Approximate_eigensolver& eigensolver,
             Spectral_preprocess_report& report, const Constraint_set* first_set = nullptr);
  void build(const Mesh::Region_geometry& region, const Basis::Basis_data& supplied,
             const Spectral_settings& settings, const Exact_eigensolver& eigensolver,
             Spectral_preprocess_report& report, const Constraint_set* first_set = nullptr);
  void prepare(const Mesh::Region_geometry& region, const Constraint_set& set, const Spectral_settings& settings);
  void deform(const Mesh::Region_geometry& region, const Constraint_set& set, const Mesh::Positions& targets,
              unsigned int iterations, double tolerance, double stage_angle, Mesh::Positions& result,
              Spectral_deformation_report& report);
  void refine(const Mesh::Region_geometry& region, const Constraint_set& set, const Mesh::Positions& targets,
              unsigned int max_iterations, double tolerance, Mesh::Positions& positions,
              Spectral_refinement_report& report);
  void accept();
  void restart();

  void set_process_wide_tuning(bool enabled);
  void set_rotation_patches(std::size_t count);
  void set_volume_preservation(bool preserve, const Mesh::Region_geometry& region);
  bool preserves_volume() const;
  void set_smooth_energy(Spectral_smooth_energy energy, const Mesh::Region_geometry& region);
  bool has_basis() const;
  std::uint64_t basis_fingerprint() const;
  bool single_precision_basis() const;
  void write_basis(std::ostream& os) const;
  std::size_t number_of_frequencies() const;
  Eigen::RowVector3d smooth_rest(Eigen::Index i) const;
  Eigen::RowVector3d smooth_deformed(Eigen::Index i) const;

private:
  class Implementation;
  std::unique_ptr<Implementation> m_implementation;
};

/// `Spatial_pipeline<Default_sparse_spd_solver_traits>` (the pipeline of
/// `SPATIAL_DUAL_LAPLACIAN`) behind a class whose functions are defined only
/// in the compiled core.
class Compiled_spatial_pipeline
{
public:
  Compiled_spatial_pipeline();
  ~Compiled_spatial_pipeline();
  Compiled_spatial_pipeline(const Compiled_spatial_pipeline&) = delete;
  Compiled_spatial_pipeline& operator=(const Compiled_spatial_pipeline&) = delete;

  void build(const Mesh::Region_geometry& region, bool process_wide_tuning);
  void set_process_wide_tuning(bool enabled);
  void prepare(const Mesh::Region_geometry& region, const Constraint_set& set);
  void deform(const Mesh::Region_geometry& region, const Constraint_set& set, const Mesh::Positions& targets,
              unsigned int iterations, double tolerance, double stage_angle, Mesh::Positions& result,
              Spectral_deformation_report& report);
  void refine(const Mesh::Region_geometry& region, const Constraint_set& set, const Mesh::Positions& targets,
              unsigned int max_iterations, double tolerance, Mesh::Positions& positions,
              Spectral_refinement_report& report);
  void accept();
  void restart();

private:
  class Implementation;
  std::unique_ptr<Implementation> m_implementation;
};

} // namespace Deformation
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_COMPILED_SPECTRAL_PIPELINE_H

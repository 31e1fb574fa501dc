// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_SPECTRAL_PARAMETERS_H
#define CGAL_SPECTRAL_DEFORMATION_SPECTRAL_PARAMETERS_H

#include <CGAL/Manifold_harmonics_basis.h>
#include <CGAL/Spectral_deformation/Deformation_options.h>
#include <CGAL/Spectral_deformation/Spectral_deformation_error.h>

#include <cmath>
#include <cstddef>
#include <ostream>

namespace CGAL {
namespace Spectral_deformation {

/// \ingroup PkgSpectralSurfaceMeshDeformationRef
/// The parameters that only the spectral algorithms have (the basis, the
/// reduced system, the iteration in the basis) and the basis cache: a public
/// base of `Spectral_surface_mesh_deformation`, whose functions they are.
/// With `SPATIAL_DUAL_LAPLACIAN`, which has no basis, they do not compile;
/// the getters return the defaults.
///
/// The settings have one home, the computation that the deformation class
/// owns (privately); this base reaches it through the deformation class
/// (the curiously recurring template pattern), and holds no data.
///
/// \tparam Deformation the deformation class, `Spectral_surface_mesh_deformation`
/// \tparam TM the mesh type of the deformation
/// \tparam EigensolverTraits the eigensolver traits of the deformation
/// \tparam Computation the computation on the region behind the deformation
///         class (not documented: an implementation detail)
template <class Deformation, class TM, class EigensolverTraits, class Computation>
class Spectral_parameters
{
  static constexpr bool is_spectral = Computation::is_spectral;
  typedef Spectral_deformation_error Error;

public:
  /// \name Parameters of the spectral algorithms
  /// @{

  /// The number of frequencies `m` of the basis (default 100).
  std::size_t number_of_frequencies() const { return computation().settings().frequencies; }
  /// Sets the number of frequencies; a region with fewer vertices uses all of
  /// them. A different value makes the next `preprocess()` rebuild the
  /// region, basis included.
  /// \throws Spectral_deformation_error (`INVALID_ARGUMENT`) when `m` is 0.
  void set_number_of_frequencies(std::size_t m)
  {
    static_assert(is_spectral, "set_number_of_frequencies(): SPATIAL_DUAL_LAPLACIAN has no basis");
    if(m == 0)
      throw Error(Error::INVALID_ARGUMENT, "the number of frequencies must be positive");
    if(m != computation().settings().frequencies)
    {
      computation().settings().frequencies = m;
      computation().drop_region();
    }
  }

  /// The weight `w` of the constraints in the reduced least squares system (default 1).
  double constraint_weight() const { return computation().settings().weight; }
  /// Sets the constraint weight, a change of the constraint set. Larger
  /// weights meet the constraints of the smooth mesh more closely but the
  /// truncated basis cannot form sharp transitions, which degrades the
  /// result; smaller weights loosen the constraints.
  /// \throws Spectral_deformation_error (`INVALID_ARGUMENT`) unless `w` is positive and finite.
  void set_constraint_weight(double w)
  {
    static_assert(is_spectral, "set_constraint_weight(): SPATIAL_DUAL_LAPLACIAN has no constraint weight");
    if(!(w > 0 && std::isfinite(w)))
      throw Error(Error::INVALID_ARGUMENT, "the constraint weight must be positive and finite");
    computation().settings().weight = w;
    computation().constraints_changed();
  }

  /// The constraint policy (default `EXACT_CONSTRAINTS`).
  Spectral_constraint_policy constraint_policy() const { return computation().settings().policy; }
  /// Sets the constraint policy; a different policy is a change of the
  /// constraint set.
  void set_constraint_policy(Spectral_constraint_policy policy)
  {
    static_assert(is_spectral, "set_constraint_policy(): SPATIAL_DUAL_LAPLACIAN always meets the constraints exactly");
    if(policy != computation().settings().policy)
    {
      computation().settings().policy = policy;
      computation().constraints_changed();
    }
  }

  /// Sets the eigensolver used when a basis is next computed; a basis already
  /// computed is kept.
  void set_eigensolver_traits(const EigensolverTraits& traits)
  {
    static_assert(is_spectral, "set_eigensolver_traits(): SPATIAL_DUAL_LAPLACIAN has no basis");
    computation().eigensolver() = traits;
  }

  /// The number of vertices from which a region keeps its basis in single
  /// precision (default 20,000).
  std::size_t single_precision_basis_threshold() const
  {
    return computation().settings().single_precision_basis_threshold;
  }
  /// Regions of at least `vertices` vertices keep their basis in float: 4 n m
  /// bytes instead of 8 n m (0.6 GiB instead of 1.2 GiB for 1.6 million
  /// vertices and m = 100). Everything the deformation derives from the basis
  /// is computed from the stored values in double, so results move by
  /// \f$ 10^{-8} \f$ to \f$ 10^{-5} \f$ of the bounding-box diagonal and
  /// the deformation measures of the manual's quality benchmark do not
  /// change (see the manual, *Memory*). 0 keeps every
  /// basis in float, `std::numeric_limits<std::size_t>::max()` none. Takes
  /// effect when a basis is next computed or loaded; `save_basis()` writes a
  /// float basis widened to double.
  void set_single_precision_basis_threshold(std::size_t vertices)
  {
    static_assert(is_spectral, "set_single_precision_basis_threshold(): SPATIAL_DUAL_LAPLACIAN has no basis");
    computation().settings().single_precision_basis_threshold = vertices;
  }

  /// The number of rotation patches of the iteration (default 1000; 0: one
  /// rotation per dual vertex, the full iteration of the paper).
  std::size_t rotation_patches() const { return computation().settings().rotation_patches; }
  /// Groups the dual vertices of the region into about `count` patches of
  /// neighbouring faces that turn by one rotation each in the iterations of
  /// `deform()`. Each iteration then costs O(m × count) instead of two
  /// products with the n×m basis, whatever the size of the mesh; only the
  /// detail transfer and the output stay O(n). On the manual's quality
  /// sweep the default's ARAP energies are within a few per cent of the
  /// full iteration's. 0 restores the full iteration, and so does a region
  /// with fewer than four faces per patch (about 2,000 vertices with the
  /// default), where the full iteration is both cheaper and more accurate.
  /// Takes effect at once, the basis and the factorization are kept.
  void set_rotation_patches(std::size_t count)
  {
    static_assert(is_spectral, "set_rotation_patches(): SPATIAL_DUAL_LAPLACIAN has no basis");
    computation().set_rotation_patches(count);
  }

  /// The energy the iteration of `deform()` minimizes in the space of the
  /// basis (default `DUAL_LAPLACIAN_AND_ARAP_ENERGY`; `DUAL_LAPLACIAN_ENERGY`
  /// is the paper's).
  Spectral_smooth_energy smooth_energy() const { return computation().settings().smooth_energy; }
  /// Sets the energy the iteration minimizes. `ARAP_ENERGY` and
  /// `DUAL_LAPLACIAN_AND_ARAP_ENERGY` keep twisted tubes round where dual
  /// Laplacian editing pinches them, and with stages (`set_stage_angle()`)
  /// large bends do not fold; `DUAL_LAPLACIAN_ENERGY` bends open sheets with
  /// the least stretch (see the manual's section on the energy of the
  /// iteration). All work with rotation patches. A change recomputes the
  /// reduced matrices, not the basis,
  /// and the next `deform()` starts from the rest shape; it is a change of
  /// the constraint set. `SPECTRAL_LINEAR` does not iterate and ignores it.
  /// \throws Spectral_deformation_error (`INVALID_ARGUMENT`) when `energy`
  /// is not one of the enumerators.
  void set_smooth_energy(Spectral_smooth_energy energy)
  {
    static_assert(is_spectral, "set_smooth_energy(): SPATIAL_DUAL_LAPLACIAN has no basis");
    if(energy != DUAL_LAPLACIAN_ENERGY && energy != ARAP_ENERGY && energy != DUAL_LAPLACIAN_AND_ARAP_ENERGY)
      throw Error(Error::INVALID_ARGUMENT, "unknown smooth energy");
    computation().set_smooth_energy(energy);
  }

  /// The largest angle, in degrees, by which one stage of `deform()` turns a
  /// group of control vertices (default 30; 0: the targets are reached in
  /// one stage, the paper's iteration).
  double stage_angle() const { return computation().settings().stage_angle * 180 / 3.14159265358979323846; }
  /// Sets stage_angle(). When the targets turn a connected group of control
  /// vertices by more than this angle from where the smooth mesh holds it,
  /// `deform()` moves them there in stages along the group's rigid path
  /// (each stage but the last iterated three times, then the iterations
  /// asked for at the targets): one jump from the rest shape to a large
  /// bend or twist makes the first solve squash the region, and the
  /// iteration can settle in a folded shape near it. With
  /// `DUAL_LAPLACIAN_AND_ARAP_ENERGY`, 30 removes the folds of large bends
  /// (see the manual's section on stages); with the dual Laplacian energy
  /// alone the results of large bends depend on the number of stages, and
  /// 0 may suit it better. Small target changes, such as the steps of a drag,
  /// are not staged. An angle below one degree still makes at most 180
  /// stages. `SPECTRAL_LINEAR` does not iterate and ignores it.
  /// Takes effect at the next `deform()`.
  /// \throws Spectral_deformation_error (`INVALID_ARGUMENT`) when `degrees`
  /// is negative or not finite.
  void set_stage_angle(double degrees)
  {
    static_assert(is_spectral, "set_stage_angle(): SPATIAL_DUAL_LAPLACIAN has no basis");
    if(!(degrees >= 0) || !std::isfinite(degrees))
      throw Error(Error::INVALID_ARGUMENT, "the stage angle must be a finite angle of at least 0 degrees");
    computation().set_stage_angle(degrees * 3.14159265358979323846 / 180);
  }

  /// Whether the detail transfer keeps the volume the surface encloses
  /// (default `false`).
  bool volume_preservation() const { return computation().settings().preserve_volume; }
  /// Makes the detail transfer of `deform()` keep the volume enclosed by
  /// the surface: the least-squares positions of the detail transfer are
  /// corrected along the direction that changes the volume at the least
  /// cost in the same energy (one more back-substitution, with the gradient
  /// of the volume as right-hand side), by the amount that restores the
  /// volume of the rest shape. A twist, which turns a tube without changing
  /// its volume, then keeps the tube's section (see the manual's section on
  /// tubes). The volume is that of the whole surface when the region is cut
  /// out of a closed surface: every boundary edge of the faces of the region
  /// joins two fixed vertices. Otherwise (an open sheet, a boundary inside the
  /// ROI) it is not defined and the setting has no effect. With several
  /// connected components, their total volume is kept. Takes effect at the
  /// next `deform()`. `SPECTRAL_LINEAR` keeps the volume too.
  void set_volume_preservation(bool preserve)
  {
    static_assert(is_spectral, "set_volume_preservation(): SPATIAL_DUAL_LAPLACIAN has no detail transfer");
    computation().set_volume_preservation(preserve);
  }

  /// @}

  /// \name Basis cache
  /// @{

  /// Hands in a precomputed basis. It is used instead of computing one when
  /// the region is the mesh on which `basis` was computed: every face has a
  /// vertex in the ROI (for instance, the ROI is the whole mesh), the
  /// vertices are indexed alike and the initial geometry is the one `basis`
  /// was computed with. Its number of frequencies then prevails. Otherwise
  /// it is ignored and `preprocess_report().basis_computed` tells.
  /// \tparam BasisEigensolverTraits the eigensolver traits `basis` was computed with
  template <class BasisEigensolverTraits>
  void set_basis(const Manifold_harmonics_basis<TM, BasisEigensolverTraits>& basis)
  {
    static_assert(is_spectral, "set_basis(): SPATIAL_DUAL_LAPLACIAN has no basis");
    computation().supply_basis(basis.data());
  }

  /// Writes the basis of the current region in the format of
  /// `Manifold_harmonics_basis::save()`.
  /// \throws Spectral_deformation_error (`IO_ERROR`) when there is no basis
  ///         yet (call `preprocess()` first) or the stream fails.
  void save_basis(std::ostream& os) const
  {
    static_assert(is_spectral, "save_basis(): SPATIAL_DUAL_LAPLACIAN has no basis");
    computation().save_basis(os);
  }

  /// @}

protected:
  Spectral_parameters() = default;
  ~Spectral_parameters() = default;
  Spectral_parameters(const Spectral_parameters&) = delete;
  Spectral_parameters& operator=(const Spectral_parameters&) = delete;

private:
  Computation& computation() { return static_cast<Deformation&>(*this).m_computation; }
  const Computation& computation() const { return static_cast<const Deformation&>(*this).m_computation; }
};

} // namespace Spectral_deformation
} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_SPECTRAL_PARAMETERS_H

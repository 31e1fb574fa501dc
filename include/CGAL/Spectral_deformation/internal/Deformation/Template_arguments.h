// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_TEMPLATE_ARGUMENTS_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_TEMPLATE_ARGUMENTS_H

#include <CGAL/Spectral_deformation/Deformation_options.h>
#include <CGAL/Spectral_deformation/internal/Traits_requirements.h>

// A program written for CGAL's class names CGAL::ORIGINAL_ARAP,
// CGAL::SPOKES_AND_RIMS or CGAL::SRE_ARAP; after the switch it no longer
// includes CGAL's header, so this one must declare them, and CGAL's
// enumeration cannot be declared a second time.
#include <CGAL/Surface_mesh_deformation.h>

#include <CGAL/Default.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/boost/graph/properties.h>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <string>
#include <type_traits>
#include <utility>

namespace CGAL {
namespace Spectral_deformation {
namespace internal {
namespace Deformation {

/// The algorithm selected by a value of the template parameter `TAG` of
/// `Spectral_surface_mesh_deformation`, by the type of the value: `valid`
/// is false for a type that is neither the package's tag nor CGAL's.
template <class Tag>
struct Algorithm_tag_traits
{
  static constexpr bool valid = false;
  static constexpr bool is_cgal_tag = false;
  // The class reports the error with a static_assert; a valid algorithm here
  // keeps the compiler from piling further errors on that message.
  static constexpr Spectral_deformation_algorithm_tag algorithm(Tag) { return SPECTRAL_DUAL_LAPLACIAN; }
};

template <>
struct Algorithm_tag_traits<Spectral_deformation_algorithm_tag>
{
  static constexpr bool valid = true;
  static constexpr bool is_cgal_tag = false;
  static constexpr Spectral_deformation_algorithm_tag algorithm(Spectral_deformation_algorithm_tag tag)
  {
    return tag;
  }
};

// CGAL's three tags name variants of ARAP, a nonlinear method that follows the
// local rotations of the surface: the iterated spectral method is the one that
// does the same, and it is the package's default, as SPOKES_AND_RIMS is CGAL's.
template <>
struct Algorithm_tag_traits<Deformation_algorithm_tag>
{
  static constexpr bool valid = true;
  static constexpr bool is_cgal_tag = true;
  static constexpr Spectral_deformation_algorithm_tag algorithm(Deformation_algorithm_tag)
  {
    return SPECTRAL_DUAL_LAPLACIAN;
  }
};

template <auto TAG>
struct Algorithm_of
{
  typedef Algorithm_tag_traits<std::decay_t<decltype(TAG)>> Traits;
  static constexpr bool valid = Traits::valid;
  static constexpr bool is_cgal_tag = Traits::is_cgal_tag;
  static constexpr Spectral_deformation_algorithm_tag value = Traits::algorithm(TAG);
};

// ManifoldHarmonicsEigensolverTraits: compute() and error_message() with
// the signatures of the concept.
template <class T>
struct Is_eigensolver_traits
  : std::conjunction<Members::Compute<T>, Members::Error_message<T>>
{};

// The point map that CGAL's class hands to its weight calculator: points of
// Simple_cartesian<double>, read on the fly from the vertex point map. Only
// its type is used, to recognize a weight calculator.
template <class TM>
struct Weight_calculator_point_map
{
  typedef boost::readable_property_map_tag category;
  typedef typename boost::graph_traits<TM>::vertex_descriptor key_type;
  typedef Simple_cartesian<double>::Point_3 value_type;
  typedef value_type reference;

  friend value_type get(const Weight_calculator_point_map&, key_type) { return value_type(0, 0, 0); }
};

// A model of CGAL's SurfaceMeshDeformationWeights: called as CGAL's class
// calls it, with a halfedge, the mesh and a point map, and returns a number.
template <class T, class TM, class = void>
struct Is_weight_calculator : std::false_type
{};

template <class T, class TM>
struct Is_weight_calculator<
    T, TM,
    std::enable_if_t<std::is_convertible<
        decltype(std::declval<T&>()(std::declval<typename boost::graph_traits<TM>::halfedge_descriptor>(),
                                    std::declval<TM&>(), std::declval<Weight_calculator_point_map<TM>>())),
        double>::value>> : std::true_type
{};

/// The fifth template argument of `Spectral_surface_mesh_deformation`, at
/// the position of CGAL's weight calculator: `Default`, eigensolver traits,
/// or one of CGAL's weight calculators, which is not used (see the manual).
/// `type` is the eigensolver traits to use.
template <class ET, class TM, class DefaultTraits>
struct Eigensolver_argument
{
  static constexpr bool is_default = std::is_same<ET, Default>::value;
  static constexpr bool is_eigensolver_traits = !is_default && Is_eigensolver_traits<ET>::value;
  static constexpr bool is_weight_calculator =
      std::conjunction<std::bool_constant<!is_default && !is_eigensolver_traits>,
                       Is_weight_calculator<ET, TM>>::value;
  static constexpr bool valid = is_default || is_eigensolver_traits || is_weight_calculator;
  // Anything else falls back on the default: the static_assert of
  // Deformation_class_types is then the only error.
  typedef std::conditional_t<is_eigensolver_traits, ET, DefaultTraits> type;
};

// SparseSPDSolverTraits: factor() and a const solve() with the signatures of the concept.
template <class T>
struct Is_sparse_spd_solver_traits : std::conjunction<Members::Factor<T>, Members::Const_solve<T>>
{};

// CGAL's SparseLinearAlgebraWithFactorTraits_d (the sparse solver of CGAL's
// class, such as CGAL::Eigen_solver_traits): factor(A, D) on its own matrix type.
template <class T, class = void>
struct Is_cgal_sparse_solver_traits : std::false_type
{};

template <class T>
struct Is_cgal_sparse_solver_traits<
    T, std::void_t<typename T::Matrix, typename T::Vector, typename T::NT,
                   decltype(std::declval<T&>().factor(std::declval<const typename T::Matrix&>(),
                                                      std::declval<typename T::NT&>()))>> : std::true_type
{};

/// The sixth template argument of `Spectral_surface_mesh_deformation`, at
/// the position of CGAL's sparse solver traits: `Default`, a model of
/// `SparseSPDSolverTraits`, or CGAL's solver traits, which are not used.
/// `type` is the argument with CGAL's solver traits replaced by `Default`.
template <class ST>
struct Sparse_solver_argument
{
  static constexpr bool is_default = std::is_same<ST, Default>::value;
  static constexpr bool is_sparse_spd_solver_traits = !is_default && Is_sparse_spd_solver_traits<ST>::value;
  static constexpr bool is_cgal_solver_traits =
      std::conjunction<std::bool_constant<!is_default && !is_sparse_spd_solver_traits>,
                       Is_cgal_sparse_solver_traits<ST>>::value;
  static constexpr bool valid = is_default || is_sparse_spd_solver_traits || is_cgal_solver_traits;
  typedef std::conditional_t<is_sparse_spd_solver_traits, ST, Default> type;
};

// `Requirements<T>::met`, checked unless `skip` (an argument that is not
// meant as a traits class of the concept): a traits class that misses a
// member of the concept then fails with the name of that member.
template <bool skip, class T, template <class> class Requirements>
struct Requirements_unless
{
  static constexpr bool met = true;
};

template <class T, template <class> class Requirements>
struct Requirements_unless<false, T, Requirements>
{
  static constexpr bool met = Requirements<T>::met;
};

} // namespace Deformation
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_TEMPLATE_ARGUMENTS_H

// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_TRAITS_REQUIREMENTS_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_TRAITS_REQUIREMENTS_H

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Spectral_deformation {
namespace internal {

// The requirements of the concepts SparseSPDSolverTraits and
// ManifoldHarmonicsEigensolverTraits, checked where a traits class is
// taken: a missing required member is a compile error that names it.
//
// The optional members come in groups, each declared by a tag of the model
// (`typedef CGAL::Tag_true Supports_row_updates;`). The package uses a group
// exactly when its tag says so, and a model that declares a tag without the
// members, or with other signatures, is a compile error too: a member with a
// slightly wrong signature cannot silently go unused.

// The value of the tag `T::Tag`, false when T declares none.
#define CGAL_SSMD_DECLARED_TAG(Tag)                                                                  \
  template <class T, class = void>                                                                 \
  struct Declares_##Tag : std::false_type                                                          \
  {};                                                                                              \
  template <class T>                                                                               \
  struct Declares_##Tag<T, std::void_t<typename T::Tag>> : std::bool_constant<bool(T::Tag::value)> \
  {};
CGAL_SSMD_DECLARED_TAG(Supports_process_wide_tuning)
CGAL_SSMD_DECLARED_TAG(Supports_fill_reducing_ordering)
CGAL_SSMD_DECLARED_TAG(Supports_row_updates)
CGAL_SSMD_DECLARED_TAG(Uses_vertex_positions)
CGAL_SSMD_DECLARED_TAG(Supports_single_precision_eigenvectors)
#undef CGAL_SSMD_DECLARED_TAG

namespace Members {

template <class T, class = void>
struct Factor : std::false_type
{};
template <class T>
struct Factor<T, std::void_t<decltype(bool(std::declval<T&>().factor(std::declval<const Eigen::SparseMatrix<double>&>())))>>
  : std::true_type
{};

template <class T, class = void>
struct Const_solve : std::false_type
{};
template <class T>
struct Const_solve<T, std::void_t<decltype(bool(std::declval<const T&>().solve(
                          std::declval<const Eigen::MatrixXd&>(), std::declval<Eigen::MatrixXd&>())))>>
  : std::true_type
{};

template <class T, class = void>
struct Process_wide_tuning : std::false_type
{};
template <class T>
struct Process_wide_tuning<T, std::void_t<decltype(bool(std::declval<const T&>().process_wide_tuning())),
                                          decltype(std::declval<T&>().set_process_wide_tuning(true))>>
  : std::true_type
{};

template <class T, class = void>
struct Fill_reducing_ordering : std::false_type
{};
template <class T>
struct Fill_reducing_ordering<
    T, std::void_t<decltype(std::vector<int>(
                       std::declval<T&>().fill_reducing_ordering(std::declval<const Eigen::SparseMatrix<double>&>()))),
                   decltype(std::declval<T&>().set_fill_reducing_ordering(std::vector<int>()))>> : std::true_type
{};

template <class T, class = void>
struct Refactor_rows : std::false_type
{};
template <class T>
struct Refactor_rows<T, std::void_t<decltype(bool(std::declval<T&>().refactor_rows(
                            std::declval<const Eigen::SparseMatrix<double>&>(), std::declval<const std::vector<int>&>())))>>
  : std::true_type
{};

template <class T, class = void>
struct Compute : std::false_type
{};
template <class T>
struct Compute<T, std::void_t<decltype(bool(std::declval<T&>().compute(
                      std::declval<const Eigen::SparseMatrix<double>&>(), std::declval<const Eigen::VectorXd&>(),
                      std::declval<Eigen::Index>(), std::declval<Eigen::VectorXd&>(),
                      std::declval<Eigen::MatrixXd&>())))>> : std::true_type
{};

template <class T, class = void>
struct Compute_single_precision : std::false_type
{};
template <class T>
struct Compute_single_precision<T, std::void_t<decltype(bool(std::declval<T&>().compute(
                                       std::declval<const Eigen::SparseMatrix<double>&>(),
                                       std::declval<const Eigen::VectorXd&>(), std::declval<Eigen::Index>(),
                                       std::declval<Eigen::VectorXd&>(), std::declval<Eigen::MatrixXf&>())))>>
  : std::true_type
{};

template <class T, class = void>
struct Error_message : std::false_type
{};
template <class T>
struct Error_message<T, std::void_t<decltype(std::string(std::declval<const T&>().error_message()))>>
  : std::true_type
{};

template <class T, class = void>
struct Set_vertex_positions : std::false_type
{};
template <class T>
struct Set_vertex_positions<T, std::void_t<decltype(std::declval<T&>().set_vertex_positions(
                                   std::declval<const Eigen::Matrix<double, Eigen::Dynamic, 3>&>()))>>
  : std::true_type
{};

} // namespace Members

// The optional groups of members both concepts share.
template <class T>
struct Process_wide_tuning_requirements
{
  static_assert(!Declares_Supports_process_wide_tuning<T>::value || Members::Process_wide_tuning<T>::value,
                "the traits class declares Supports_process_wide_tuning but lacks the members "
                "bool process_wide_tuning() const and void set_process_wide_tuning(bool)");
  static constexpr bool met = true;
};

/// Checks a model of SparseSPDSolverTraits: `met` is true, or the
/// compilation stops with the member that is missing.
template <class T>
struct Sparse_spd_solver_requirements
{
  static_assert(Members::Factor<T>::value,
                "SparseSPDSolverTraits: the traits class lacks the required member "
                "bool factor(const Eigen::SparseMatrix<double>& A)");
  static_assert(Members::Const_solve<T>::value,
                "SparseSPDSolverTraits: the traits class lacks the required member "
                "bool solve(const Eigen::MatrixXd& B, Eigen::MatrixXd& X) const");
  static_assert(!Declares_Supports_fill_reducing_ordering<T>::value || Members::Fill_reducing_ordering<T>::value,
                "SparseSPDSolverTraits: the traits class declares Supports_fill_reducing_ordering but lacks "
                "the members std::vector<int> fill_reducing_ordering(const Eigen::SparseMatrix<double>&) and "
                "void set_fill_reducing_ordering(std::vector<int>)");
  static_assert(!Declares_Supports_row_updates<T>::value || Members::Refactor_rows<T>::value,
                "SparseSPDSolverTraits: the traits class declares Supports_row_updates but lacks the member "
                "bool refactor_rows(const Eigen::SparseMatrix<double>& A, const std::vector<int>& rows)");
  static constexpr bool met = Process_wide_tuning_requirements<T>::met;
};

/// Checks a model of ManifoldHarmonicsEigensolverTraits, as
/// `Sparse_spd_solver_requirements` does.
template <class T>
struct Eigensolver_requirements
{
  static_assert(Members::Compute<T>::value,
                "ManifoldHarmonicsEigensolverTraits: the traits class lacks the required member "
                "bool compute(const Eigen::SparseMatrix<double>& stiffness, const Eigen::VectorXd& mass, "
                "Eigen::Index m, Eigen::VectorXd& eigenvalues, Eigen::MatrixXd& eigenvectors)");
  static_assert(Members::Error_message<T>::value,
                "ManifoldHarmonicsEigensolverTraits: the traits class lacks the required member "
                "std::string error_message() const");
  static_assert(!Declares_Uses_vertex_positions<T>::value || Members::Set_vertex_positions<T>::value,
                "ManifoldHarmonicsEigensolverTraits: the traits class declares Uses_vertex_positions but lacks "
                "the member void set_vertex_positions(const Eigen::Matrix<double, Eigen::Dynamic, 3>&)");
  static_assert(!Declares_Supports_single_precision_eigenvectors<T>::value || Members::Compute_single_precision<T>::value,
                "ManifoldHarmonicsEigensolverTraits: the traits class declares Supports_single_precision_eigenvectors "
                "but lacks the member bool compute(const Eigen::SparseMatrix<double>& stiffness, "
                "const Eigen::VectorXd& mass, Eigen::Index m, Eigen::VectorXd& eigenvalues, Eigen::MatrixXf& eigenvectors)");
  static constexpr bool met = Process_wide_tuning_requirements<T>::met;
};

} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_TRAITS_REQUIREMENTS_H

// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_MANIFOLD_HARMONICS_BASIS_H
#define CGAL_MANIFOLD_HARMONICS_BASIS_H

#include <CGAL/Spectral_deformation/Spectral_deformation_error.h>
#include <CGAL/Spectral_deformation/Block_lanczos_eigensolver_traits.h>
#include <CGAL/Spectral_deformation/cotangent_operators.h>
#include <CGAL/Spectral_deformation/internal/Basis/basis_io.h>
#include <CGAL/Spectral_deformation/internal/Memory/Process_wide_tuning.h>
#include <CGAL/Spectral_deformation/internal/Mesh/Triangle_arrays.h>

#include <CGAL/Default.h>
#include <CGAL/Named_function_parameters.h>

#include <Eigen/Dense>

#include <cstdint>
#include <istream>
#include <ostream>
#include <string>
#include <type_traits>
#include <utility>

namespace CGAL {
namespace Spectral_deformation {
namespace internal {

using Memory::process_wide_tuning_of;
using Mesh::Triangle_arrays;

/// Makes the sign of every column deterministic: its entry of largest
/// magnitude (first one on ties) is positive.
template <typename Scalar>
void normalize_signs(Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>& eigenvectors)
{
  for(Eigen::Index k = 0; k < eigenvectors.cols(); ++k)
  {
    Eigen::Index largest = 0;
    eigenvectors.col(k).cwiseAbs().maxCoeff(&largest);
    if(eigenvectors(largest, k) < 0)
      eigenvectors.col(k) = -eigenvectors.col(k);
  }
}

/// The m smallest generalized eigenpairs of `stiffness`, the cotangent
/// stiffness of `mesh` (validated arrays), against its lumped mass. Throws
/// `Spectral_deformation_error`. The eigenvectors are in double or in float
/// (`Scalar`); float ones come straight from an eigensolver that
/// `Supports_single_precision_eigenvectors`, else rounded from double ones.
template <class EigensolverTraits, typename Scalar>
void compute_manifold_harmonics(const Triangle_arrays& mesh, const Eigen::SparseMatrix<double>& stiffness,
                                Eigen::Index m, EigensolverTraits& eigensolver, Eigen::VectorXd& eigenvalues,
                                Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>& eigenvectors,
                                Eigen::VectorXd& mass)
{
  typedef Spectral_deformation_error Error;
  const Eigen::Index n = mesh.number_of_vertices();
  if(m < 1 || m > n)
    throw Error(Error::INVALID_ARGUMENT,
                "the number of frequencies must be between 1 and the number of vertices (" +
                    std::to_string(n) + "), got " + std::to_string(m));
  CGAL_precondition(stiffness.rows() == n && stiffness.cols() == n);
  mass = lumped_mass(mesh);
  if constexpr(Declares_Uses_vertex_positions<EigensolverTraits>::value)
    eigensolver.set_vertex_positions(mesh.positions);
  bool computed = false;
  if constexpr(std::is_same_v<Scalar, double> ||
               Declares_Supports_single_precision_eigenvectors<EigensolverTraits>::value)
    computed = eigensolver.compute(stiffness, mass, m, eigenvalues, eigenvectors);
  else
  {
    // The signs fixed in double, as for a double basis, then rounded.
    Eigen::MatrixXd in_double;
    computed = eigensolver.compute(stiffness, mass, m, eigenvalues, in_double);
    if(computed && in_double.allFinite())
      normalize_signs(in_double);
    if(computed)
      eigenvectors = in_double.cast<Scalar>();
  }
  if(!computed)
    throw Error(Error::SOLVER_FAILURE,
                "the manifold harmonics eigensolver failed: " + eigensolver.error_message());
  if(eigenvalues.size() != m || eigenvectors.rows() != n || eigenvectors.cols() != m ||
     !eigenvalues.allFinite() || !eigenvectors.allFinite())
    throw Error(Error::SOLVER_FAILURE,
                "the manifold harmonics eigensolver returned an incomplete or non-finite result");
  // Float eigenvectors from the eigensolver have their signs fixed on the
  // rounded values: a column whose two largest entries of opposite signs
  // round to the same float may take the other sign than in double, which
  // changes no deformation (its coefficients change sign with it).
  if constexpr(std::is_same_v<Scalar, double> ||
               Declares_Supports_single_precision_eigenvectors<EigensolverTraits>::value)
    normalize_signs(eigenvectors);
}

/// The same, with the cotangent stiffness assembled here (in huge pages when
/// the eigensolver was asked for process-wide tuning).
template <class EigensolverTraits>
void compute_manifold_harmonics(const Triangle_arrays& mesh, Eigen::Index m,
                                EigensolverTraits& eigensolver, Eigen::VectorXd& eigenvalues,
                                Eigen::MatrixXd& eigenvectors, Eigen::VectorXd& mass)
{
  const Eigen::SparseMatrix<double> stiffness =
      cotangent_stiffness(mesh, process_wide_tuning_of(eigensolver));
  compute_manifold_harmonics(mesh, stiffness, m, eigensolver, eigenvalues, eigenvectors, mass);
}

} // namespace internal
} // namespace Spectral_deformation

/// \ingroup PkgSpectralSurfaceMeshDeformationRef
/// The manifold harmonics basis (Vallet and Lévy 2008) of a triangle mesh: the
/// `m` eigenfunctions of the cotangent Laplace-Beltrami operator of lowest
/// frequency.
///
/// The basis is the solution of the generalized eigenproblem `Q h = lambda M h`
/// with `Q` the cotangent stiffness matrix (`cotangent_stiffness_matrix()`) and
/// `M` the lumped mass matrix (`lumped_mass_matrix()`): the `m` smallest
/// eigenvalues in ascending order and the matching eigenvectors, stored as the
/// columns of an `n × m` matrix `H` with `Hᵀ M H = I`. The sign of each column
/// is fixed so that its entry of largest magnitude is positive.
///
/// The manifold harmonic transform of per-vertex data `x` (`n × d`) is
/// `Hᵀ M x`, its inverse `H x̃`; `H Hᵀ M x` is the low-pass reconstruction,
/// the M-orthogonal projection onto the basis.
///
/// Row `i` of every per-vertex matrix corresponds to the vertex of index `i` in
/// the vertex index map given at construction.
///
/// Meshes with boundaries and with several connected components are
/// supported (a component contributes its own constant function of
/// eigenvalue 0).
///
/// \tparam TriangleMesh a model of `FaceListGraph`, triangulated.
/// By default, computing a basis changes no state of the process. A program
/// that owns its process can let the eigensolver tune settings of the whole
/// process (OpenBLAS threads, SuiteSparse's allocator, huge pages) by
/// passing eigensolver traits with `set_process_wide_tuning(true)`; see
/// `Block_lanczos_eigensolver_traits::set_process_wide_tuning()`.
///
/// \tparam EigensolverTraits a model of `ManifoldHarmonicsEigensolverTraits`;
///         `CGAL::Default` means `Block_lanczos_eigensolver_traits<>`;
///         `Spectra_eigensolver_traits<>` is the reference solver (its
///         header, `<CGAL/Spectral_deformation/Spectra_eigensolver_traits.h>`,
///         is not included by this one).
template <class TriangleMesh, class EigensolverTraits = CGAL::Default>
class Manifold_harmonics_basis
{
public:
  /// The eigensolver traits type.
  typedef typename CGAL::Default::Get<EigensolverTraits, Block_lanczos_eigensolver_traits<>>::type
      Eigensolver_traits;
#ifndef DOXYGEN_RUNNING
  static_assert(Spectral_deformation::internal::Eigensolver_requirements<Eigensolver_traits>::met);
#endif
  /// Dense matrix type of bases and per-vertex data.
  typedef Eigen::MatrixXd Matrix;
  /// Dense vector type of eigenvalues and masses.
  typedef Eigen::VectorXd Vector;

  /// Creates an empty basis, to be filled by `compute()` or `load()`.
  Manifold_harmonics_basis() = default;

  /// Computes the basis of `number_of_frequencies` functions of `tm`; see `compute()`.
  template <class NamedParameters = parameters::Default_named_parameters>
  Manifold_harmonics_basis(const TriangleMesh& tm, std::size_t number_of_frequencies,
                           const NamedParameters& np = parameters::default_values(),
                           Eigensolver_traits eigensolver = Eigensolver_traits())
  {
    compute(tm, number_of_frequencies, np, eigensolver);
  }

  /// Computes the basis of `number_of_frequencies` functions of `tm`,
  /// replacing the current content.
  ///
  /// \tparam NamedParameters a sequence of CGAL named parameters
  /// \param tm the mesh, triangulated, with no degenerate face and no isolated vertex
  /// \param number_of_frequencies `m`, between 1 and the number of vertices
  /// \param np optional named parameters among `vertex_point_map` (default
  ///        `get(CGAL::vertex_point, tm)`) and `vertex_index_map` (default: an
  ///        initialized vertex index map of `tm`)
  /// \param eigensolver the eigensolver to use
  ///
  /// \throws Spectral_deformation_error with code `INVALID_MESH` (not a
  ///         triangle mesh, empty, degenerate face, isolated vertex, non-finite
  ///         coordinate), `INVALID_ARGUMENT` (`m` out of range) or
  ///         `SOLVER_FAILURE` (the eigensolver failed or did not converge). The
  ///         basis is unchanged when an exception is thrown.
  template <class NamedParameters = parameters::Default_named_parameters>
  void compute(const TriangleMesh& tm, std::size_t number_of_frequencies,
               const NamedParameters& np = parameters::default_values(),
               Eigensolver_traits eigensolver = Eigensolver_traits())
  {
    const Spectral_deformation::internal::Mesh::Triangle_arrays arrays =
        Spectral_deformation::internal::Mesh::extract_triangle_arrays(tm, np);
    Vector eigenvalues, mass;
    Matrix eigenvectors;
    Spectral_deformation::internal::compute_manifold_harmonics(
        arrays, static_cast<Eigen::Index>(number_of_frequencies), eigensolver, eigenvalues,
        eigenvectors, mass);
    m_data.eigenvalues.swap(eigenvalues);
    m_data.basis.swap(eigenvectors);
    m_data.mass.swap(mass);
    m_data.number_of_faces = static_cast<std::uint64_t>(arrays.number_of_faces());
    m_data.fingerprint = Spectral_deformation::internal::Mesh::fingerprint(arrays);
  }

  /// \name Accessors
  /// @{

  /// `true` when no basis has been computed or loaded.
  bool empty() const { return m_data.basis.size() == 0; }
  /// The number of vertices `n` of the mesh.
  std::size_t number_of_vertices() const { return static_cast<std::size_t>(m_data.basis.rows()); }
  /// The number of basis functions `m`.
  std::size_t number_of_frequencies() const { return static_cast<std::size_t>(m_data.basis.cols()); }
  /// The eigenvalues, ascending (`m`).
  const Vector& eigenvalues() const { return m_data.eigenvalues; }
  /// The basis `H` (`n × m`), M-orthonormal.
  const Matrix& basis() const { return m_data.basis; }
  /// The diagonal of the lumped mass matrix `M` (`n`).
  const Vector& mass() const { return m_data.mass; }
  /// A digest of the connectivity and coordinates of the mesh the basis was
  /// computed on; `load()` compares it with the mesh it is given.
  std::uint64_t mesh_fingerprint() const { return m_data.fingerprint; }

  /// \cond SKIP_IN_MANUAL
  const Spectral_deformation::internal::Basis::Basis_data& data() const { return m_data; }
  /// \endcond

  /// @}

  /// \name Transforms
  /// @{

  /// The manifold harmonic transform `Hᵀ M x` of per-vertex data `x` (`n × d`),
  /// an `m × d` matrix of coefficients.
  /// \throws Spectral_deformation_error (`INVALID_ARGUMENT`) when `x` does not have `n` rows.
  Matrix transform(const Matrix& x) const
  {
    check_rows(x, m_data.basis.rows(), "transform");
    return m_data.basis.transpose() * (m_data.mass.asDiagonal() * x);
  }

  /// The inverse transform `H_k x̃` of `k × d` coefficients, `k ≤ m` (the
  /// first `k` frequencies are used), an `n × d` matrix.
  /// \throws Spectral_deformation_error (`INVALID_ARGUMENT`) when `k > m` or
  ///         when the basis is empty.
  Matrix inverse_transform(const Matrix& coefficients) const
  {
    if(coefficients.rows() > m_data.basis.cols() || empty())
      throw Spectral_deformation_error(
          Spectral_deformation_error::INVALID_ARGUMENT,
          "inverse_transform: more coefficients than basis functions");
    return m_data.basis.leftCols(coefficients.rows()) * coefficients;
  }

  /// The low-pass reconstruction of per-vertex data `x` (`n × d`) with the
  /// first `k` frequencies (`1 ≤ k ≤ m`; `k = 0` means all `m`): the
  /// M-orthogonal projection `H_k H_kᵀ M x`.
  /// \throws Spectral_deformation_error (`INVALID_ARGUMENT`) on a size mismatch.
  Matrix low_pass(const Matrix& x, std::size_t k = 0) const
  {
    check_rows(x, m_data.basis.rows(), "low_pass");
    const Eigen::Index used = (k == 0) ? m_data.basis.cols() : static_cast<Eigen::Index>(k);
    if(used > m_data.basis.cols())
      throw Spectral_deformation_error(Spectral_deformation_error::INVALID_ARGUMENT,
                                       "low_pass: more frequencies requested than computed");
    const auto Hk = m_data.basis.leftCols(used);
    return Hk * (Hk.transpose() * (m_data.mass.asDiagonal() * x));
  }

  /// @}

  /// \name Storage
  /// @{

  /// Writes the basis to a binary stream: a header (format tag and version,
  /// number of vertices, faces and frequencies, the mesh fingerprint), the
  /// eigenvalues, the mass, the basis, and a checksum of all of it.
  /// \throws Spectral_deformation_error (`IO_ERROR`) when the basis is empty or
  ///         the stream fails.
  void save(std::ostream& os) const
  {
    if(empty())
      throw Spectral_deformation_error(Spectral_deformation_error::IO_ERROR,
                                       "save: the basis is empty");
    Spectral_deformation::internal::Basis::write_basis(os, m_data);
  }

  /// Reads a basis written by `save()` and checks that it belongs to `tm`
  /// (same numbers of vertices and faces, same fingerprint of connectivity and
  /// coordinates, read through the same kind of named parameters as in
  /// `compute()`).
  /// \throws Spectral_deformation_error with code `IO_ERROR` (unreadable,
  ///         truncated or corrupted stream, not a basis file), `MESH_MISMATCH`
  ///         (the basis belongs to another mesh) or `INVALID_MESH`. The basis is
  ///         unchanged when an exception is thrown.
  template <class NamedParameters = parameters::Default_named_parameters>
  void load(std::istream& is, const TriangleMesh& tm,
            const NamedParameters& np = parameters::default_values())
  {
    Spectral_deformation::internal::Basis::Basis_data data = Spectral_deformation::internal::Basis::read_basis(is);
    Spectral_deformation::internal::Basis::check_basis_matches(
        data, Spectral_deformation::internal::Mesh::extract_triangle_arrays(tm, np));
    m_data = std::move(data);
  }

  /// @}

private:
  static void check_rows(const Matrix& x, Eigen::Index n, const char* what)
  {
    if(x.rows() != n || n == 0)
      throw Spectral_deformation_error(
          Spectral_deformation_error::INVALID_ARGUMENT,
          std::string(what) + ": the data must have one row per vertex of the basis");
  }

  Spectral_deformation::internal::Basis::Basis_data m_data;
};

} // namespace CGAL

#endif // CGAL_MANIFOLD_HARMONICS_BASIS_H

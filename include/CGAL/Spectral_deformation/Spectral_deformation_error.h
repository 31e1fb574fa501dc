// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_SPECTRAL_DEFORMATION_ERROR_H
#define CGAL_SPECTRAL_DEFORMATION_SPECTRAL_DEFORMATION_ERROR_H

#include <stdexcept>
#include <string>

namespace CGAL {

/// \ingroup PkgSpectralSurfaceMeshDeformationRef
/// The exception thrown by the package when its input cannot be processed or
/// when a numerical step fails.
///
/// The `what()` message names the offending element (a face or vertex index,
/// a parameter value, ...); `code()` classifies the failure so that a caller
/// can react programmatically. When an operation throws, nothing that the
/// caller passed in has been modified.
class Spectral_deformation_error : public std::runtime_error
{
public:
  /// The kinds of failure.
  enum Code {
    INVALID_MESH,      ///< the mesh is not a valid input (not triangulated, degenerate faces, isolated vertices, non-finite coordinates, ...)
    INVALID_ARGUMENT,  ///< a parameter is out of range (number of frequencies, non-finite target, ...)
    SOLVER_FAILURE,    ///< a factorization or an eigensolver failed or did not converge
    IO_ERROR,          ///< a stream could not be read or written, or its content is corrupted
    MESH_MISMATCH      ///< stored data belongs to another mesh than the one it is used with
  };

  /// Creates an exception of kind `code` with the message `what`.
  Spectral_deformation_error(Code code, const std::string& what)
    : std::runtime_error(what), m_code(code)
  {}

  /// The kind of failure.
  Code code() const noexcept { return m_code; }

private:
  Code m_code;
};

} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_SPECTRAL_DEFORMATION_ERROR_H

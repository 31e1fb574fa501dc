// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_BLOCK_LANCZOS_STATE_IMPL_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_BLOCK_LANCZOS_STATE_IMPL_H

// The definitions of the functions declared in Block_lanczos_state.h (see
// internal/compiled_core.h: the compiled core holds them).

#include <CGAL/Spectral_deformation/internal/Eigensolvers/Block_lanczos_state.h>

namespace CGAL {
namespace Spectral_deformation {
namespace internal {
namespace Eigensolvers {

CGAL_SSMD_CORE_FUNCTION Eigen::Index round_up(Eigen::Index value, Eigen::Index multiple)
{
  return ((value + multiple - 1) / multiple) * multiple;
}

} // namespace Eigensolvers
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_BLOCK_LANCZOS_STATE_IMPL_H

// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_MEMORY_PROCESS_WIDE_TUNING_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_MEMORY_PROCESS_WIDE_TUNING_H

#include <CGAL/Spectral_deformation/internal/Traits_requirements.h>

namespace CGAL {
namespace Spectral_deformation {
namespace internal {
namespace Memory {

// The opt-in to the tuning that changes state of the whole process.
//
// Some of the speed of the eigensolver comes from settings that belong to
// the whole process, not to the object that makes them:
// - the number of OpenBLAS threads (`openblas_set_num_threads()`,
//   Dense_products.h);
// - SuiteSparse's allocator, global to the process
//   (Cholmod_huge_page_allocator.h);
// - transparent huge pages on large blocks and their pages mapped ahead
//   (Page_mapping.h, Large_array.h): the advice stays on the address range
//   after the block is freed.
// Including a header or using a traits object with its defaults changes
// none of them. A traits class that can use them declares the tag
// `Supports_process_wide_tuning` and has the members `process_wide_tuning()`
// and `set_process_wide_tuning(bool)` (default `false`; see
// Traits_requirements.h); the traits that create other traits objects (the
// eigensolvers create their sparse solver) hand the choice on with the
// helpers below, which do nothing for a traits class without the tag.

// `traits.process_wide_tuning()`, or `false` for traits without the option.
template <class Traits>
bool process_wide_tuning_of(const Traits& traits)
{
  if constexpr(Declares_Supports_process_wide_tuning<Traits>::value)
    return traits.process_wide_tuning();
  else
  {
    (void)traits;
    return false;
  }
}

// `traits.set_process_wide_tuning(enabled)`, nothing for traits without the
// option.
template <class Traits>
void set_process_wide_tuning_if_supported(Traits& traits, bool enabled)
{
  if constexpr(Declares_Supports_process_wide_tuning<Traits>::value)
    traits.set_process_wide_tuning(enabled);
  else
  {
    (void)traits;
    (void)enabled;
  }
}

} // namespace Memory
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_MEMORY_PROCESS_WIDE_TUNING_H

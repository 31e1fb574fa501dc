// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_PARALLEL_EXCEPTION_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_PARALLEL_EXCEPTION_H

#include <atomic>
#include <exception>
#include <mutex>

namespace CGAL {
namespace Spectral_deformation {
namespace internal {
namespace Eigensolvers {

// The first exception thrown in the loop bodies of an OpenMP region, which
// must not leave the region: the bodies after it are skipped, and
// `rethrow()` throws it again once the region is over.
class Parallel_exception
{
public:
  template <class Body>
  void run(Body&& body) noexcept
  {
    if(m_failed.load(std::memory_order_relaxed))
      return;
    try
    {
      body();
    }
    catch(...)
    {
      std::lock_guard<std::mutex> lock(m_mutex);
      if(!m_error)
        m_error = std::current_exception();
      m_failed.store(true, std::memory_order_relaxed);
    }
  }

  void rethrow() const
  {
    if(m_error)
      std::rethrow_exception(m_error);
  }

private:
  std::atomic<bool> m_failed{false};
  std::mutex m_mutex;
  std::exception_ptr m_error;
};

} // namespace Eigensolvers
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_PARALLEL_EXCEPTION_H

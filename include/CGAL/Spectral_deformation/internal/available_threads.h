// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_AVAILABLE_THREADS_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_AVAILABLE_THREADS_H

#ifdef _OPENMP
#include <omp.h>
#endif

#include <atomic>
#include <cstddef>
#include <exception>

namespace CGAL {
namespace Spectral_deformation {
namespace internal {

/// The threads a step may use from here: OpenMP's count outside a parallel
/// region, one inside it, and one in a program built without OpenMP.
inline int available_threads()
{
#ifdef _OPENMP
  return omp_in_parallel() ? 1 : omp_get_max_threads();
#else
  return 1;
#endif
}

/// Loops over the vertices or faces of a region run on all threads from this
/// many items: a few tens of nanoseconds of work per item, so that below it
/// the loop is shorter than starting and joining a team of threads.
constexpr std::ptrdiff_t parallel_loop_items = 20000;
/// Kernels over the rows of the basis (n rows, m columns) run on all threads
/// from this many entries, for the same reason.
constexpr std::ptrdiff_t parallel_basis_entries = 100000;
/// Products of the reduced operators, rows × m, from this many entries (each
/// row's product is longer than a row of the basis alone).
constexpr std::ptrdiff_t parallel_operator_entries = 200000;
/// Products of a sparse matrix by the basis, non-zeros × m, from this many
/// multiply-adds (a few nanoseconds each).
constexpr std::ptrdiff_t parallel_sparse_products = 1000000;
/// Triangular solves with a sparse factor of this many non-zeros, for
/// several columns, run on all threads, a block of columns each (the
/// eigenvectors of the approximate basis's reduced problem: 100 columns, a
/// factor of about 450,000 non-zeros for m = 100).
constexpr std::ptrdiff_t parallel_sparse_solve_entries = 100000;

/// Regions of interest with fewer vertices are prepared (`preprocess()`:
/// the region, its basis, the first factorizations) with the calling
/// thread's OpenMP teams on one thread. Their steps are too short for a
/// team: the idle threads of the team and those of a threaded BLAS wait for
/// work by spinning and took the cores from the threads doing it. Measured
/// on two cores with the reference harness: 550 region vertices prepared in
/// 0.05 s instead of 0.08-0.16 s, 2,174 in 0.25 s instead of 0.30 s, 3,433 in
/// 0.33 s instead of 0.38-0.42 s; 13,552 in 0.80 s instead of 0.71 s, so
/// larger regions keep all threads.
constexpr std::size_t serial_preparation_vertices = 5000;
/// Regions of interest with fewer vertices are deformed (`deform()`,
/// `refine()`) with the calling thread's OpenMP teams on one thread, for the
/// same reason: a drag on 550 region vertices took 2.4 ms instead of 2.6-2.8
/// ms (and the first one 3 ms instead of 23-29 ms, beside the BLAS threads
/// still spinning after the basis), while one on 2,174 took 12.5 ms instead
/// of 6.5 ms.
constexpr std::size_t serial_deformation_vertices = 1000;

/// While it lives, the OpenMP teams that the calling thread starts run on
/// one thread when `serial` is true (outside a parallel region). Only the
/// calling thread's setting changes (`nthreads-var` is a per-thread setting
/// of OpenMP); the destructor restores it.
class One_thread_scope
{
public:
  explicit One_thread_scope(bool serial)
  {
#ifdef _OPENMP
    if(serial && !omp_in_parallel() && omp_get_max_threads() > 1)
    {
      m_threads = omp_get_max_threads();
      omp_set_num_threads(1);
    }
#else
    (void)serial;
#endif
  }
  ~One_thread_scope()
  {
#ifdef _OPENMP
    if(m_threads > 0)
      omp_set_num_threads(m_threads);
#endif
  }
  One_thread_scope(const One_thread_scope&) = delete;
  One_thread_scope& operator=(const One_thread_scope&) = delete;

private:
  int m_threads = 0;
};

#ifdef _OPENMP
/// Runs `work()` on the first thread of a team of two OpenMP threads and
/// `beside(done)` on the second, `done` (a `const std::atomic<bool>&`)
/// turning true once `work()` has returned; an exception of `work()` is
/// thrown again once the team has ended. Inside the team, the OpenMP loops
/// of `work()` are nested: they run on its thread alone when nested
/// parallelism is off (OpenMP's default), whatever their own thread counts.
/// Two is the smallest active team: with one thread, the loops of `work()`
/// would form the active level instead.
template <class Work, class Beside>
void run_beside_a_second_thread(Work&& work, Beside&& beside)
{
  std::atomic<bool> done{false};
  std::exception_ptr error;
  constexpr int smallest_active_team = 2;
#pragma omp parallel num_threads(smallest_active_team)
  {
    if(omp_get_thread_num() == 0)
    {
      try
      {
        work();
      }
      catch(...)
      {
        error = std::current_exception();
      }
      done.store(true, std::memory_order_relaxed);
    }
    else
      beside(static_cast<const std::atomic<bool>&>(done));
  }
  if(error)
    std::rethrow_exception(error);
}
#endif

} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_AVAILABLE_THREADS_H

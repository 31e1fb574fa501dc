// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_ITERATION_REPORT_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_ITERATION_REPORT_H

#include <CGAL/Spectral_deformation/Spectral_deformation_error.h>

#include <chrono>

namespace CGAL {
namespace Spectral_deformation {
namespace internal {
namespace Deformation {

/// Wall-clock seconds since `start`, for the times of the reports.
inline double seconds_since(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// What an iterative solve did: rotation updates performed after the linear
/// solve, the last relative step, and whether it converged. A solve that
/// fails throws `Spectral_deformation_error` instead.
struct Iteration_report
{
  int iterations = 0;
  double last_step = 0;
  bool converged = false;

  /// Records the relative step of solve number `iteration` (from 0) and tells
  /// whether to stop (step below `tolerance`). Throws when the iteration
  /// diverges: a step above half the scale after the third solve.
  bool stop_after(int iteration, double step, double tolerance)
  {
    iterations = iteration;
    last_step = step;
    if(iteration > 2 && step > 0.5)
      throw Spectral_deformation_error(Spectral_deformation_error::SOLVER_FAILURE, "the iteration diverges");
    converged = (step < tolerance);
    return converged;
  }
};

} // namespace Deformation
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_ITERATION_REPORT_H

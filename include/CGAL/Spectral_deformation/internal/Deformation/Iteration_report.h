// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_ITERATION_REPORT_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_ITERATION_REPORT_H

#include <string>

namespace CGAL {
namespace Spectral_deformation {
namespace internal {

/// What an iterative solve did: rotation updates performed after the linear
/// solve, the last relative RMS step, and whether it converged or failed.
struct Iteration_report
{
  int iterations = 0;
  double last_step = 0;
  bool converged = false;
  bool success = true;
  std::string message;

  Iteration_report& failed(const std::string& why)
  {
    success = false;
    message = why;
    return *this;
  }

  /// Records the relative step of solve number `iteration` (from 0) and tells
  /// whether to stop: converged (step below `tolerance`), or diverging (a
  /// step above half the scale after the third solve; `success` is then false).
  bool stop_after(int iteration, double step, double tolerance)
  {
    iterations = iteration;
    last_step = step;
    if(iteration > 2 && step > 0.5)
    {
      failed("the iteration diverges");
      return true;
    }
    converged = (step < tolerance);
    return converged;
  }
};

} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_DEFORMATION_ITERATION_REPORT_H

// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// A progress bar for the eigensolve of the manifold harmonics basis, driven
// by the progress callback of CGAL::Block_lanczos_eigensolver_traits.

#ifndef SSMD_TOOLS_BASIS_PROGRESS_BAR_H
#define SSMD_TOOLS_BASIS_PROGRESS_BAR_H

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <ostream>
#include <sstream>
#include <string>

namespace Deformation_tool {

/// Draws, on a terminal, one line that is redrawn in place:
///
///     basis [==========>           ]  47%  solves 290/~620  elapsed 1.3 s  left ~1.5 s
///
/// The block Lanczos iteration does not know in advance how many solves it
/// needs: the estimate is `typical_dimension_per_eigenpair` solves per
/// wanted eigenpair (it converged at 3.0 to 3.8 m on the armadillo meshes
/// with m = 100 and 200), raised by a tenth whenever the iteration passes it.
///
/// The time of a block grows with its position `k` in the subspace (the new
/// block is orthogonalized against the previous ones), so the time of the
/// first `k` solves is modelled as `a k + b k^2`, fitted by least squares to
/// the times observed so far; the remaining time is the sum of the modelled
/// times of the remaining solves.
///
/// `Progress` is `CGAL::Block_lanczos_eigensolver_traits<...>::Progress`.
template <class Progress>
class Basis_progress_bar
{
public:
  typedef std::chrono::steady_clock Clock;

  /// Solves per wanted eigenpair that the first estimate assumes.
  static constexpr double typical_dimension_per_eigenpair = 4;

  /// Draws on `os` when `interactive` (a terminal); otherwise only counts.
  Basis_progress_bar(std::ostream& os, bool interactive)
    : m_os(os), m_interactive(interactive), m_start(Clock::now()), m_last_draw(m_start)
  {}

  /// The progress callback.
  void operator()(const Progress& progress)
  {
    const Clock::time_point now = Clock::now();
    if(progress.stage == Progress::ITERATION && m_solves == 0)
      m_iteration_start = now;
    m_solves = progress.solves;
    if(progress.stage == Progress::ITERATION && progress.solves > 1)
      m_step_times.add(static_cast<double>(progress.solves - 1),
                       std::chrono::duration<double>(now - m_iteration_start).count());
    m_dense = m_dense || progress.stage == Progress::DENSE_SOLVE;
    if(!m_interactive)
      return;
    // At most ten redraws per second, but every change of stage is shown.
    const bool stage_changed = progress.stage != m_last_stage;
    m_last_stage = progress.stage;
    if(!stage_changed && now - m_last_draw < std::chrono::milliseconds(100))
      return;
    m_last_draw = now;
    draw(progress, now);
  }

  /// Erases the line of the bar.
  void finish()
  {
    if(m_interactive && m_drawn_width > 0)
    {
      m_os << '\r' << std::string(m_drawn_width, ' ') << '\r' << std::flush;
      m_drawn_width = 0;
    }
  }

  /// The number of solves of the Lanczos iteration (0 with the dense solver).
  std::size_t solves() const { return m_solves; }
  /// Whether the dense solver was used.
  bool dense() const { return m_dense; }

private:
  static std::string seconds(double s)
  {
    std::ostringstream out;
    if(s < 10)
      out << std::fixed << std::setprecision(1) << s << " s";
    else if(s < 600)
      out << static_cast<long>(std::lround(s)) << " s";
    else
      out << static_cast<long>(s / 60) << " min " << static_cast<long>(std::fmod(s, 60.0)) << " s";
    return out.str();
  }

  // Least squares fit of t = a k + b k^2 (time t after k steps).
  struct Quadratic_fit
  {
    double s2 = 0, s3 = 0, s4 = 0, ts = 0, ts2 = 0;
    std::size_t count = 0;

    void add(double k, double t)
    {
      s2 += k * k;
      s3 += k * k * k;
      s4 += k * k * k * k;
      ts += t * k;
      ts2 += t * k * k;
      ++count;
    }

    // The coefficients; a linear fit when the quadratic term comes out
    // negative (noise on short runs).
    void coefficients(double& a, double& b) const
    {
      const double determinant = s2 * s4 - s3 * s3;
      b = determinant > 0 ? (s2 * ts2 - s3 * ts) / determinant : 0.0;
      a = determinant > 0 ? (s4 * ts - s3 * ts2) / determinant : 0.0;
      if(b < 0 || a < 0)
      {
        b = 0;
        a = s2 > 0 ? ts / s2 : 0.0;
      }
    }
  };

  // The modelled time of the solves after `progress.solves` up to `expected`.
  double remaining_seconds(const Progress& progress, std::size_t expected) const
  {
    double a = 0, b = 0;
    m_step_times.coefficients(a, b);
    double total = 0;
    for(std::size_t k = progress.solves + 1; k <= expected; ++k)
      total += a + b * (2.0 * static_cast<double>(k) - 1.0);
    return total;
  }

  void draw(const Progress& progress, Clock::time_point now)
  {
    const double elapsed = std::chrono::duration<double>(now - m_start).count();
    std::ostringstream line;
    line << "basis (" << progress.number_of_vertices << " vertices, m = "
         << progress.number_of_eigenpairs << ") ";
    switch(progress.stage)
    {
    case Progress::FACTORIZATION:
      line << "factoring the shifted stiffness matrix  elapsed " << seconds(elapsed);
      break;
    case Progress::DENSE_SOLVE:
      line << "dense eigensolve  elapsed " << seconds(elapsed);
      break;
    case Progress::REFERENCE_SOLVE:
      line << "reference Lanczos solver, solves " << progress.solves << "  elapsed "
           << seconds(elapsed);
      break;
    case Progress::ITERATION:
    {
      double expected =
          typical_dimension_per_eigenpair * static_cast<double>(progress.number_of_eigenpairs);
      const double done = static_cast<double>(progress.solves);
      while(expected < done + 1)
        expected = std::ceil(1.1 * expected);
      const double fraction = done / expected;
      const int width = 24;
      const int filled = static_cast<int>(fraction * width);
      line << "[" << std::string(static_cast<std::size_t>(filled), '=') << ">"
           << std::string(static_cast<std::size_t>(width - filled), ' ') << "] " << std::setw(3)
           << static_cast<int>(100 * fraction) << "%  solves " << progress.solves << "/~"
           << static_cast<long>(expected) << "  elapsed " << seconds(elapsed);
      if(m_step_times.count >= 10)
        line << "  left ~"
             << seconds(remaining_seconds(progress, static_cast<std::size_t>(expected)));
      break;
    }
    case Progress::FINISHED:
      line << "done  elapsed " << seconds(elapsed);
      break;
    }
    const std::string text = line.str();
    m_os << '\r' << text;
    if(text.size() < m_drawn_width)
      m_os << std::string(m_drawn_width - text.size(), ' ');
    m_os << std::flush;
    m_drawn_width = std::max(m_drawn_width, text.size());
  }

  std::ostream& m_os;
  bool m_interactive;
  Clock::time_point m_start, m_last_draw, m_iteration_start;
  typename Progress::Stage m_last_stage = Progress::FINISHED;
  std::size_t m_solves = 0;
  Quadratic_fit m_step_times;
  std::size_t m_drawn_width = 0;
  bool m_dense = false;
};

} // namespace Deformation_tool

#endif // SSMD_TOOLS_BASIS_PROGRESS_BAR_H

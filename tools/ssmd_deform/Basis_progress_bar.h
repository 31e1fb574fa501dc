// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The progress of the eigensolve of the manifold harmonics basis, driven by
// the progress callback of CGAL::Block_lanczos_eigensolver_traits.
//
// It is written here rather than taken from a library: Debian 12 packages no
// C++ progress-bar library (indicators, tqdm-cpp, ... are not packaged), and
// what the tool needs beyond drawing a bar is its own: an estimate of the
// number of solves, which the iteration does not know in advance, and a
// model of the time of the remaining ones.

#ifndef SSMD_TOOLS_BASIS_PROGRESS_BAR_H
#define SSMD_TOOLS_BASIS_PROGRESS_BAR_H

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iomanip>
#include <ostream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <sys/ioctl.h>
#include <unistd.h>

namespace Deformation_tool {

/// The number of columns of the terminal on `fd`: its window size, else
/// `$COLUMNS`, else 80.
inline std::size_t terminal_width(int fd)
{
  struct winsize size;
  if(::ioctl(fd, TIOCGWINSZ, &size) == 0 && size.ws_col > 0)
    return size.ws_col;
  if(const char* columns = std::getenv("COLUMNS"))
  {
    char* end = nullptr;
    const long value = std::strtol(columns, &end, 10);
    if(end != columns && *end == '\0' && value > 0 && value < 10000)
      return static_cast<std::size_t>(value);
  }
  return 80;
}

/// How the progress is shown.
enum class Progress_display {
  NONE,     ///< not at all (`--quiet`)
  TERMINAL, ///< one line redrawn in place, as wide as the terminal
  LOG       ///< plain lines, for a pipe or a log file
};

/// On a terminal, one line redrawn in place that never reaches the last
/// column of the terminal (so it cannot wrap), for instance at 100 columns:
///
///     basis (2281 vertices, m = 200) [=====>      ]  47%  solves 290/~620  elapsed 1.3 s  left ~1.5 s
///
/// and with less on narrower terminals: the vertex count, the remaining
/// time, the elapsed time and the number of solves are left out in this
/// order, and the bar takes the room that is left, 10 to 40 columns. Every redraw starts
/// with a carriage return and ends with "clear to the end of the line", so
/// a shorter line leaves nothing of a longer one.
///
/// Elsewhere (a pipe, a log file), plain lines, one whenever the work passes
/// another tenth of the estimate or a few seconds after the previous one:
///
///     basis: 2281 vertices, 200 frequencies: factoring the shifted stiffness matrix
///     basis: 10% (64 of ~800 solves), 0.1 s
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
  /// The longest interval between two lines of the LOG display.
  static constexpr double log_interval_seconds = 5;

  /// Shows the progress on `os` as `display` says; `terminal_fd` is the
  /// file descriptor of `os`, whose width the TERMINAL display follows.
  Basis_progress_bar(std::ostream& os, Progress_display display, int terminal_fd = STDERR_FILENO)
    : m_os(os), m_display(display), m_terminal_fd(terminal_fd), m_start(Clock::now()),
      m_last_draw(m_start)
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
    m_approximate = m_approximate || progress.stage == Progress::APPROXIMATION;
    const bool stage_changed = progress.stage != m_last_stage;
    m_last_stage = progress.stage;
    if(m_display == Progress_display::TERMINAL)
    {
      // At most ten redraws per second, but every change of stage is shown.
      if(!stage_changed && now - m_last_draw < std::chrono::milliseconds(100))
        return;
      m_last_draw = now;
      draw(progress, now);
    }
    else if(m_display == Progress_display::LOG)
      log(progress, now, stage_changed);
  }

  /// Erases the line of the bar.
  void finish()
  {
    if(m_display == Progress_display::TERMINAL && m_drawn)
    {
      m_os << "\r\x1b[K" << std::flush;
      m_drawn = false;
    }
  }

  /// The number of solves of the Lanczos iteration (0 with the dense solver).
  std::size_t solves() const { return m_solves; }
  /// Whether the dense solver was used.
  bool dense() const { return m_dense; }
  /// Whether the basis was approximated in a space of sampled functions.
  bool approximate() const { return m_approximate; }

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

  // The estimated total number of solves: never below the solves done.
  static std::size_t expected_solves(const Progress& progress)
  {
    double expected =
        typical_dimension_per_eigenpair * static_cast<double>(progress.number_of_eigenpairs);
    const double done = static_cast<double>(progress.solves);
    while(expected < done + 1)
      expected = std::ceil(1.1 * expected) + 1;
    return static_cast<std::size_t>(expected);
  }

  static std::string stage_description(const Progress& progress)
  {
    switch(progress.stage)
    {
    case Progress::FACTORIZATION:
      return "factoring the shifted stiffness matrix";
    case Progress::DENSE_SOLVE:
      return "dense eigensolve";
    case Progress::APPROXIMATION:
      return "approximation in a space of sampled functions";
    case Progress::REFERENCE_SOLVE:
      return "single-vector Lanczos solver, " + std::to_string(progress.solves) + " solves";
    case Progress::ITERATION:
      return "Lanczos iteration";
    case Progress::FINISHED:
      break;
    }
    return "done";
  }

  struct Field
  {
    std::string text;
    std::size_t reserved;
  };

  // The line of the TERMINAL display, in at most `width` characters: the
  // richest variant that fits, the bar taking the room that is left.
  std::string line(const Progress& progress, Clock::time_point now, std::size_t width) const
  {
    const double elapsed = std::chrono::duration<double>(now - m_start).count();
    const std::string long_prefix = "basis (" + std::to_string(progress.number_of_vertices) +
                                    " vertices, m = " +
                                    std::to_string(progress.number_of_eigenpairs) + ")";
    const std::string short_prefix = "basis";
    const std::string elapsed_text = "elapsed " + seconds(elapsed);

    std::vector<std::string> variants;
    if(progress.stage != Progress::ITERATION)
    {
      const std::string stage = stage_description(progress);
      variants = {long_prefix + " " + stage + "  " + elapsed_text,
                  short_prefix + " " + stage + "  " + elapsed_text,
                  short_prefix + " " + stage, short_prefix + "  " + elapsed_text};
      for(const std::string& variant : variants)
        if(variant.size() <= width)
          return variant;
      return variants.back().substr(0, width);
    }

    const std::size_t expected = expected_solves(progress);
    const double fraction = static_cast<double>(progress.solves) / static_cast<double>(expected);
    std::ostringstream percent;
    percent << std::setw(3) << static_cast<int>(100 * fraction) << "%";
    // Each field reserves the room of its widest likely text, so that the
    // layout, and the length of the bar, stay put from one redraw to the
    // next; the remaining time reserves its room before it is known.
    const std::string expected_text = std::to_string(expected);
    const Field fields[] = {
        {percent.str(), 4},
        {"solves " + std::to_string(progress.solves) + "/~" + expected_text,
         7 + 2 * expected_text.size() + 2},
        {elapsed_text, 13},
        {m_step_times.count >= 10 ? "left ~" + seconds(remaining_seconds(progress, expected))
                                  : std::string(),
         11}};
    // The variants, richest first: the prefix, and how many of the fields.
    const std::pair<const std::string*, std::size_t> variants_of_bar[] = {
        {&long_prefix, 4}, {&short_prefix, 4}, {&short_prefix, 3}, {&short_prefix, 2},
        {&short_prefix, 1}};
    const std::size_t minimum_bar = 10, maximum_bar = 40;
    for(const auto& variant : variants_of_bar)
    {
      std::string text;
      std::size_t reserved = 0;
      for(std::size_t i = 0; i < variant.second; ++i)
      {
        reserved += (i == 0 ? 0 : 2) + std::max(fields[i].reserved, fields[i].text.size());
        if(!fields[i].text.empty())
          text += (text.empty() ? "" : "  ") + fields[i].text;
      }
      // prefix, " [", bar, "] ", fields
      const std::size_t fixed = variant.first->size() + 4 + reserved;
      if(fixed + minimum_bar > width)
        continue;
      const std::size_t bar = std::min(maximum_bar, width - fixed);
      const std::size_t filled =
          std::min(bar - 1, static_cast<std::size_t>(fraction * static_cast<double>(bar - 1)));
      return *variant.first + " [" + std::string(filled, '=') + ">" +
             std::string(bar - 1 - filled, ' ') + "] " + text;
    }
    return (short_prefix + " " + fields[0].text).substr(0, width);
  }

  void draw(const Progress& progress, Clock::time_point now)
  {
    // One column less than the terminal: a character in the last column
    // makes some terminals wrap at once.
    const std::size_t columns = terminal_width(m_terminal_fd);
    const std::size_t width = columns > 1 ? columns - 1 : 1;
    m_os << '\r' << line(progress, now, width) << "\x1b[K" << std::flush;
    m_drawn = true;
  }

  void log(const Progress& progress, Clock::time_point now, bool stage_changed)
  {
    const double elapsed = std::chrono::duration<double>(now - m_start).count();
    const bool overdue =
        std::chrono::duration<double>(now - m_last_draw).count() >= log_interval_seconds;
    std::ostringstream out;
    switch(progress.stage)
    {
    case Progress::FACTORIZATION:
    case Progress::DENSE_SOLVE:
    case Progress::APPROXIMATION:
      if(!stage_changed)
        return;
      out << "basis: " << progress.number_of_vertices << " vertices, "
          << progress.number_of_eigenpairs << " frequencies: " << stage_description(progress);
      break;
    case Progress::REFERENCE_SOLVE:
      if(!stage_changed && !overdue)
        return;
      out << "basis: " << stage_description(progress) << ", " << seconds(elapsed);
      break;
    case Progress::ITERATION:
    {
      const std::size_t expected = expected_solves(progress);
      const int tenth = static_cast<int>(10 * progress.solves / expected);
      if(tenth <= m_logged_tenth && !overdue)
        return;
      m_logged_tenth = std::max(m_logged_tenth, tenth);
      out << "basis: " << (100 * progress.solves / expected) << "% (" << progress.solves
          << " of ~" << expected << " solves), " << seconds(elapsed);
      break;
    }
    case Progress::FINISHED:
      out << "basis: done";
      if(m_solves > 0)
        out << " (" << m_solves << " solves)";
      out << ", " << seconds(elapsed);
      break;
    }
    m_last_draw = now;
    m_os << out.str() << '\n' << std::flush;
  }

  std::ostream& m_os;
  Progress_display m_display;
  int m_terminal_fd;
  Clock::time_point m_start, m_last_draw, m_iteration_start;
  typename Progress::Stage m_last_stage = Progress::FINISHED;
  std::size_t m_solves = 0;
  Quadratic_fit m_step_times;
  int m_logged_tenth = 0;
  bool m_drawn = false;
  bool m_dense = false;
  bool m_approximate = false;
};

} // namespace Deformation_tool

#endif // SSMD_TOOLS_BASIS_PROGRESS_BAR_H

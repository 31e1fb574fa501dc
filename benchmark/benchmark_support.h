// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This file is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.
//
// What the benchmark programs share about the machine and the process: /proc
// fields, peak memory, the BLAS and sparse solver in use, the compiler, the
// time, and the pipe through which a forked run sends its results.

#ifndef SSMD_BENCHMARK_SUPPORT_H
#define SSMD_BENCHMARK_SUPPORT_H

#include <CGAL/Spectral_deformation/Sparse_spd_solver_traits.h>

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <limits>
#include <set>
#include <string>
#include <vector>

namespace ssmd_benchmark {

/// The median of `values` (the mean of the two middle ones for an even
/// count), NaN when there is none.
inline double median(std::vector<double> values)
{
  if(values.empty())
    return std::numeric_limits<double>::quiet_NaN();
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

/// The value in KiB of the line `key:   1234 kB` of a /proc file, -1 if absent.
inline long proc_field_kib(const std::string& file, const std::string& key)
{
  std::ifstream in(file);
  std::string line;
  while(std::getline(in, line))
    if(line.compare(0, key.size() + 1, key + ":") == 0)
      return std::strtol(line.c_str() + key.size() + 1, nullptr, 10);
  return -1;
}

/// Resets VmHWM to the current resident size (Linux >= 4.0).
inline bool reset_peak_resident_size()
{
  std::ofstream clear_refs("/proc/self/clear_refs");
  clear_refs << "5";
  clear_refs.close();
  return !clear_refs.fail();
}

/// The BLAS and LAPACK libraries mapped into this process.
inline std::string loaded_blas()
{
  std::ifstream maps("/proc/self/maps");
  std::set<std::string> libraries;
  std::string line;
  while(std::getline(maps, line))
  {
    const std::size_t slash = line.find('/');
    if(slash == std::string::npos)
      continue;
    const std::string path = line.substr(slash);
    const std::string file = path.substr(path.rfind('/') + 1);
    if(file.find("blas") != std::string::npos || file.find("lapack") != std::string::npos)
      libraries.insert(path);
  }
  std::string text;
  for(const std::string& library : libraries)
    text += (text.empty() ? "" : ", ") + library;
  return text.empty() ? "none" : text;
}

inline std::string sparse_solver()
{
#ifdef CGAL_SSMD_USE_CHOLMOD
  return "CHOLMOD " + std::to_string(CHOLMOD_MAIN_VERSION) + "." +
         std::to_string(CHOLMOD_SUB_VERSION) + "." + std::to_string(CHOLMOD_SUBSUB_VERSION) +
         " supernodal LLᵀ (`CGAL_SSMD_USE_CHOLMOD` defined)";
#else
  return "Eigen `SimplicialLDLT` (`CGAL_SSMD_USE_CHOLMOD` not defined)";
#endif
}

inline void write_all(int fd, const std::string& text)
{
  std::size_t written = 0;
  while(written < text.size())
  {
    const ssize_t count = ::write(fd, text.data() + written, text.size() - written);
    if(count < 0 && errno == EINTR)
      continue;
    if(count <= 0)
      return;
    written += static_cast<std::size_t>(count);
  }
}

inline std::string read_all(int fd)
{
  std::string text;
  char buffer[4096];
  for(;;)
  {
    const ssize_t count = ::read(fd, buffer, sizeof(buffer));
    if(count < 0 && errno == EINTR)
      continue;
    if(count <= 0)
      return text;
    text.append(buffer, static_cast<std::size_t>(count));
  }
}

inline std::string first_line_value(const std::string& file, const std::string& key)
{
  std::ifstream in(file);
  std::string line;
  while(std::getline(in, line))
    if(line.compare(0, key.size(), key) == 0)
    {
      const std::size_t colon = line.find(':');
      if(colon != std::string::npos)
      {
        const std::size_t start = line.find_first_not_of(" \t", colon + 1);
        return start == std::string::npos ? std::string() : line.substr(start);
      }
    }
  return "unknown";
}

inline std::string compiler()
{
#if defined(__clang__)
  return "Clang " __clang_version__;
#elif defined(__GNUC__)
  return "GCC " __VERSION__;
#else
  return "unknown";
#endif
}

inline std::string utc_time(std::time_t time)
{
  char buffer[64];
  std::strftime(buffer, sizeof(buffer), "%Y-%m-%d %H:%M UTC", std::gmtime(&time));
  return buffer;
}

} // namespace ssmd_benchmark

#endif // SSMD_BENCHMARK_SUPPORT_H

// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Pictures of a mesh before and after the deformation, rendered off screen
// by f3d under xvfb-run. Both pictures use the same camera, framed on the
// union of the two shapes, so that they can be compared side by side.

#ifndef SSMD_TOOLS_RENDERING_H
#define SSMD_TOOLS_RENDERING_H

#include <Eigen/Dense>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

namespace Deformation_tool {

/// A failure of the renderer.
class Rendering_error : public std::runtime_error
{
public:
  explicit Rendering_error(const std::string& what) : std::runtime_error(what) {}
};

/// The full path of `program` found in `PATH`, or an empty string.
inline std::string find_in_path(const std::string& program)
{
  const char* path = std::getenv("PATH");
  if(path == nullptr)
    return std::string();
  std::istringstream directories(path);
  for(std::string directory; std::getline(directories, directory, ':');)
  {
    const std::string candidate = (directory.empty() ? std::string(".") : directory) + "/" + program;
    if(::access(candidate.c_str(), X_OK) == 0 && std::filesystem::is_regular_file(candidate))
      return candidate;
  }
  return std::string();
}

/// Throws `Rendering_error` unless xvfb-run and f3d are in `PATH`; checked
/// before any work so that a missing renderer does not cost a deformation.
inline void check_renderer_available()
{
  std::string missing;
  for(const char* program : {"xvfb-run", "f3d"})
    if(find_in_path(program).empty())
      missing += (missing.empty() ? "" : " and ") + std::string(program);
  if(!missing.empty())
    throw Rendering_error("--render needs " + missing +
                          " in PATH (on Debian: apt-get install f3d xvfb)");
}

/// Runs `arguments` (the program is searched in `PATH`) with its output
/// appended to `log_file`; returns its exit status, or -1 when it could not
/// be started or did not exit normally. No shell is involved, so file names
/// need no quoting.
inline int run_program(const std::vector<std::string>& arguments, const std::string& log_file)
{
  std::vector<char*> argv;
  for(const std::string& argument : arguments)
    argv.push_back(const_cast<char*>(argument.c_str()));
  argv.push_back(nullptr);
  const pid_t child = ::fork();
  if(child < 0)
    return -1;
  if(child == 0)
  {
    const int log = ::open(log_file.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
    const int null_input = ::open("/dev/null", O_RDONLY);
    if(log >= 0)
    {
      ::dup2(log, STDOUT_FILENO);
      ::dup2(log, STDERR_FILENO);
    }
    if(null_input >= 0)
      ::dup2(null_input, STDIN_FILENO);
    ::execvp(argv[0], argv.data());
    ::_exit(127);
  }
  int status = 0;
  while(::waitpid(child, &status, 0) < 0)
    if(errno != EINTR)
      return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

/// Renders the mesh files `before_mesh` and `after_mesh` (formats f3d reads,
/// e.g. PLY) into `before_png` and `after_png` with one camera looking along
/// -z at the box [`low`, `high`] (the union of both shapes), y up.
/// Throws `Rendering_error` with the renderer's output on failure; no
/// picture is left behind then.
inline void render_before_after(const std::string& before_mesh, const std::string& after_mesh,
                                const std::string& before_png, const std::string& after_png,
                                const Eigen::Vector3d& low, const Eigen::Vector3d& high,
                                const std::string& log_file)
{
  const Eigen::Vector3d center = 0.5 * (low + high);
  const double radius = std::max(0.5 * (high - low).norm(), 1e-12);
  // f3d's default view angle is 30 degrees: at this distance the bounding
  // sphere fills the picture with a small margin.
  const double distance = 1.1 * radius / std::sin(15.0 * 3.14159265358979323846 / 180.0);
  auto triple = [](const Eigen::Vector3d& p) {
    std::ostringstream out;
    out.precision(17);
    out << p[0] << "," << p[1] << "," << p[2];
    return out.str();
  };
  const std::vector<std::pair<std::string, std::string>> jobs = {{before_mesh, before_png},
                                                                 {after_mesh, after_png}};
  for(const auto& job : jobs)
  {
    const int status = run_program(
        {"xvfb-run", "-a", "f3d", job.first, "--output=" + job.second, "--resolution=800,800",
         "--camera-position=" + triple(center + Eigen::Vector3d(0, 0, distance)),
         "--camera-focal-point=" + triple(center), "--camera-view-up=0,1,0",
         "--color=0.85,0.8,0.7", "--fxaa", "--bg-color=1,1,1"},
        log_file);
    if(status != 0 || !std::filesystem::exists(job.second))
    {
      std::ifstream log(log_file);
      std::stringstream output;
      output << log.rdbuf();
      std::error_code ignored;
      std::filesystem::remove(before_png, ignored);
      std::filesystem::remove(after_png, ignored);
      throw Rendering_error("f3d could not render " + job.first + " (exit status " +
                            std::to_string(status) + "):\n" + output.str());
    }
  }
}

} // namespace Deformation_tool

#endif // SSMD_TOOLS_RENDERING_H

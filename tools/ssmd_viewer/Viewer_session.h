// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The deformation side of the viewer: loads the mesh and runs one
// deformation session per WebSocket connection. Kept free of Boost.Beast so
// that the protocol can be driven without a network, and so that the
// CGAL-heavy and the Beast-heavy translation units compile separately.

#ifndef SSMD_VIEWER_VIEWER_SESSION_H
#define SSMD_VIEWER_VIEWER_SESSION_H

#include <cstddef>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>

namespace ssmd_viewer {

struct Loaded_mesh;

struct Mesh_error : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

// Reads any format CGAL reads, triangulates polygons and applies `subdivide`
// rounds of Loop subdivision. Throws Mesh_error.
std::shared_ptr<const Loaded_mesh> load_mesh(const std::string& file, unsigned int subdivide);
std::size_t number_of_vertices(const Loaded_mesh& mesh);
std::size_t number_of_faces(const Loaded_mesh& mesh);

struct Session_options
{
  std::size_t frequencies = 100;
  // Solves per drag: deform() continues the iteration of the previous drag,
  // so a few solves per update converge while the handle moves.
  unsigned int iterations_per_drag = 2;
  // Rotation patches of the iteration (0: one rotation per dual vertex);
  // see set_rotation_patches() of the deformation class.
  std::size_t rotation_patches = 1000;
  // The "refine" command: as-rigid-as-possible iterations per command (the
  // page asks for one chunk after the other and shows each), the most run
  // since the last drag, and the tolerance of refine() (an iteration that
  // lowers the energy by less than this fraction of it ends the refinement).
  unsigned int refine_iterations = 5;
  unsigned int refine_max_iterations = 500;
  double refine_tolerance = 1e-5;
};

// A message to the page: JSON text, or binary data announced by the JSON
// message sent just before it.
struct Outgoing
{
  bool binary = false;
  std::string payload;
};

class Session
{
public:
  typedef std::function<void(const Outgoing&)> Sender;

  Session(std::shared_ptr<const Loaded_mesh> mesh, const Session_options& options, Sender send);
  ~Session();
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;

  // Sends the mesh: {"type":"mesh",...} then its positions and faces.
  void start();
  // Handles one command; every failure is answered with {"type":"error"}
  // and leaves the session usable.
  void on_text(const std::string& text);
  void on_binary(std::size_t bytes);
  void on_oversized(std::size_t bytes, std::size_t limit);

private:
  struct Impl;
  std::unique_ptr<Impl> m_impl;
};

} // namespace ssmd_viewer

#endif // SSMD_VIEWER_VIEWER_SESSION_H

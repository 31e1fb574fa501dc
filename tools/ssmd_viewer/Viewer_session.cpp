// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include "Viewer_session.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Spectral_surface_mesh_deformation.h>
#include <CGAL/Subdivision_method_3/subdivision_methods_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <sstream>
#include <vector>

namespace ssmd_viewer {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef Mesh::Vertex_index Vertex_index;
typedef CGAL::Spectral_surface_mesh_deformation<Mesh> Deformation;
typedef Deformation::Eigensolver_traits Eigensolver_traits;
typedef nlohmann::json Json;
typedef std::chrono::steady_clock Clock;

struct Loaded_mesh
{
  Mesh mesh;
  std::string name;
};

std::shared_ptr<const Loaded_mesh> load_mesh(const std::string& file, unsigned int subdivide)
{
  auto loaded = std::make_shared<Loaded_mesh>();
  Mesh& mesh = loaded->mesh;
  if(!CGAL::IO::read_polygon_mesh(file, mesh) || mesh.is_empty())
    throw Mesh_error("cannot read a polygon mesh from " + file);
  if(!CGAL::is_triangle_mesh(mesh) && !CGAL::Polygon_mesh_processing::triangulate_faces(mesh))
    throw Mesh_error("cannot triangulate the faces of " + file);
  if(subdivide > 0)
    CGAL::Subdivision_method_3::Loop_subdivision(mesh, CGAL::parameters::number_of_iterations(subdivide));
  // The page addresses vertices by index: they must be 0 .. n-1.
  mesh.collect_garbage();
  loaded->name = std::filesystem::path(file).stem().string();
  return loaded;
}

std::size_t number_of_vertices(const Loaded_mesh& mesh) { return mesh.mesh.number_of_vertices(); }
std::size_t number_of_faces(const Loaded_mesh& mesh) { return mesh.mesh.number_of_faces(); }

namespace {

double seconds_since(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// A command the page got wrong: answered with an error, the session goes on.
struct Request_error : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

template <std::size_t N>
std::array<double, N> finite_numbers(const Json& command, const char* key, const std::array<double, N>& fallback)
{
  auto it = command.find(key);
  if(it == command.end())
    return fallback;
  if(!it->is_array() || it->size() != N)
    throw Request_error(std::string("\"") + key + "\" must be an array of " + std::to_string(N) + " numbers");
  std::array<double, N> values;
  for(std::size_t i = 0; i < N; ++i)
  {
    const Json& x = (*it)[i];
    if(!x.is_number())
      throw Request_error(std::string("\"") + key + "\" must be an array of " + std::to_string(N) + " numbers");
    values[i] = x.get<double>();
    if(!std::isfinite(values[i]))
      throw Request_error(std::string("\"") + key + "\" has a value that is not finite");
  }
  return values;
}

const char* stage_name(Eigensolver_traits::Progress::Stage stage)
{
  switch(stage)
  {
  case Eigensolver_traits::Progress::FACTORIZATION: return "factorization";
  case Eigensolver_traits::Progress::ITERATION: return "iteration";
  case Eigensolver_traits::Progress::REFERENCE_SOLVE: return "reference solve";
  case Eigensolver_traits::Progress::DENSE_SOLVE: return "dense solve";
  case Eigensolver_traits::Progress::APPROXIMATION: return "approximation";
  case Eigensolver_traits::Progress::FINISHED: return "finished";
  }
  return "";
}

} // namespace

struct Session::Impl
{
  std::shared_ptr<const Loaded_mesh> loaded;
  Session_options options;
  Sender send;

  Mesh mesh; // this connection's copy, deformed in place
  std::unique_ptr<Deformation> deformation;
  std::vector<std::uint32_t> region; // vertices whose positions the replies carry, ascending
  std::vector<std::uint32_t> handle;
  std::vector<char> in_region;
  std::array<double, 3> handle_centroid{};
  Clock::time_point last_progress;
  // The refinement since the last drag, selection or reset: iterations run
  // and the energy before the first of them.
  unsigned int refined_iterations = 0;
  double refine_energy_start = 0;

  Impl(std::shared_ptr<const Loaded_mesh> m, const Session_options& o, Sender s)
    : loaded(std::move(m)), options(o), send(std::move(s)), mesh(loaded->mesh)
  {
  }

  const Mesh& rest() const { return loaded->mesh; }

  void send_json(const Json& message) { send(Outgoing{false, message.dump()}); }
  void send_binary(std::string data) { send(Outgoing{true, std::move(data)}); }

  void send_error(const std::string& request, const std::string& message)
  {
    send_json({{"type", "error"}, {"request", request}, {"message", message}});
  }

  void start()
  {
    const std::size_t n = mesh.number_of_vertices(), f = mesh.number_of_faces();
    std::string data(4 * (3 * n + 3 * f), '\0');
    std::vector<float> positions(3 * n);
    for(Vertex_index v : mesh.vertices())
      for(int k = 0; k < 3; ++k)
        positions[3 * v.idx() + k] = static_cast<float>(mesh.point(v)[k]);
    std::vector<std::uint32_t> faces;
    faces.reserve(3 * f);
    for(auto face : mesh.faces())
      for(Vertex_index v : CGAL::vertices_around_face(mesh.halfedge(face), mesh))
        faces.push_back(static_cast<std::uint32_t>(v.idx()));
    std::memcpy(&data[0], positions.data(), 4 * positions.size());
    std::memcpy(&data[4 * positions.size()], faces.data(), 4 * faces.size());
    send_json({{"type", "mesh"},
               {"name", loaded->name},
               {"vertices", n},
               {"faces", f},
               {"frequencies", options.frequencies},
               {"iterations_per_drag", options.iterations_per_drag},
               {"rotation_patches", options.rotation_patches},
               {"refine_iterations", options.refine_iterations},
               {"refine_max_iterations", options.refine_max_iterations}});
    send_binary(std::move(data));
  }

  std::vector<std::uint32_t> indices(const Json& command, const char* key) const
  {
    auto it = command.find(key);
    if(it == command.end())
      return {};
    if(!it->is_array())
      throw Request_error(std::string("\"") + key + "\" must be an array of vertex indices");
    const std::size_t n = mesh.number_of_vertices();
    std::vector<std::uint32_t> result;
    result.reserve(it->size());
    for(const Json& x : *it)
    {
      if(!x.is_number_integer() || x.get<long long>() < 0 || static_cast<unsigned long long>(x.get<long long>()) >= n)
        throw Request_error(std::string("\"") + key + "\" has an entry that is not a vertex index in [0, " +
                            std::to_string(n) + ")");
      result.push_back(static_cast<std::uint32_t>(x.get<long long>()));
    }
    std::sort(result.begin(), result.end());
    result.erase(std::unique(result.begin(), result.end()), result.end());
    return result;
  }

  void report_progress(const Eigensolver_traits::Progress& progress)
  {
    const bool last = progress.stage == Eigensolver_traits::Progress::FINISHED;
    // One message per block solve would flood a slow page on small meshes.
    if(!last && progress.stage == Eigensolver_traits::Progress::ITERATION &&
       Clock::now() - last_progress < std::chrono::milliseconds(50))
      return;
    last_progress = Clock::now();
    const double wanted = static_cast<double>(std::max<std::size_t>(progress.number_of_eigenpairs, 1));
    // The subspace typically grows to about four columns per wanted pair;
    // the converged count only moves near the end.
    double fraction = std::max(static_cast<double>(progress.converged_eigenpairs) / wanted,
                               static_cast<double>(progress.solves) / (4 * wanted));
    fraction = last ? 1.0 : std::min(fraction, 0.99);
    send_json({{"type", "progress"},
               {"stage", stage_name(progress.stage)},
               {"solves", progress.solves},
               {"converged", progress.converged_eigenpairs},
               {"wanted", progress.number_of_eigenpairs},
               {"fraction", fraction}});
  }

  void select(const Json& command)
  {
    const Clock::time_point start = Clock::now();
    const std::vector<std::uint32_t> roi = indices(command, "roi");
    const std::vector<std::uint32_t> fixed = indices(command, "fixed");
    std::vector<std::uint32_t> new_handle = indices(command, "handle");
    if(new_handle.empty())
      throw Request_error("the handle is empty");
    std::vector<char> flags(mesh.number_of_vertices(), 0);
    const std::vector<std::uint32_t>* parts[] = {&roi, &fixed, &new_handle};
    for(const std::vector<std::uint32_t>* part : parts)
      for(std::uint32_t i : *part)
        flags[i] = 1;

    // The mesh goes back to its rest shape: a new selection starts a new edit.
    if(deformation)
      deformation->reset();
    refined_iterations = 0;
    const bool same_region = deformation && flags == in_region;
    if(!same_region)
    {
      deformation.reset(new Deformation(mesh));
      deformation->set_number_of_frequencies(options.frequencies);
      deformation->set_rotation_patches(options.rotation_patches);
      Eigensolver_traits eigensolver;
      eigensolver.set_progress_callback([this](const Eigensolver_traits::Progress& p) { report_progress(p); });
      deformation->set_eigensolver_traits(eigensolver);
      for(Vertex_index v : mesh.vertices())
        if(flags[v.idx()])
          deformation->insert_roi_vertex(v);
      in_region = flags;
      region.clear();
      for(std::size_t i = 0; i < flags.size(); ++i)
        if(flags[i])
          region.push_back(static_cast<std::uint32_t>(i));
    }
    else
      deformation->clear_control_vertices();
    // Fixed vertices are control vertices that keep their rest position.
    for(std::uint32_t i : fixed)
      deformation->insert_control_vertex(Vertex_index(i));
    for(std::uint32_t i : new_handle)
      deformation->insert_control_vertex(Vertex_index(i));
    handle = std::move(new_handle);
    handle_centroid = {0, 0, 0};
    for(std::uint32_t i : handle)
      for(int k = 0; k < 3; ++k)
        handle_centroid[k] += rest().point(Vertex_index(i))[k] / static_cast<double>(handle.size());

    if(!deformation->preprocess())
    {
      const std::string reason = deformation->preprocess_report().message;
      deformation.reset();
      in_region.clear();
      region.clear();
      throw Request_error("the selection cannot be deformed: " + reason);
    }
    const CGAL::Spectral_preprocess_report& report = deformation->preprocess_report();
    send_json({{"type", "ready"},
               {"region", region},
               {"handle", handle},
               {"fixed", fixed},
               {"center", handle_centroid},
               {"basis_computed", report.basis_computed},
               {"basis_seconds", report.basis_seconds},
               {"preprocess_seconds", seconds_since(start)}});
  }

  // Sends `header` with the region's count and the server's time, then the
  // positions of the region.
  void send_region_positions(Json header, const Clock::time_point& start)
  {
    std::vector<float> positions(3 * region.size());
    for(std::size_t j = 0; j < region.size(); ++j)
    {
      const Point& p = mesh.point(Vertex_index(region[j]));
      for(int k = 0; k < 3; ++k)
        positions[3 * j + k] = static_cast<float>(p[k]);
    }
    std::string data(4 * positions.size(), '\0');
    if(!positions.empty())
      std::memcpy(&data[0], positions.data(), data.size());
    header["indices"] = "region";
    header["count"] = region.size();
    header["server_seconds"] = seconds_since(start);
    send_json(header);
    send_binary(std::move(data));
  }

  static Json deformed_header(unsigned int iterations, double deform_seconds)
  {
    return {{"type", "deformed"}, {"iterations", iterations}, {"deform_seconds", deform_seconds}};
  }

  // An optional integer of a command in [1, `max`].
  static unsigned int count_in_range(const Json& command, const char* key, unsigned int fallback, long long max)
  {
    auto it = command.find(key);
    if(it == command.end())
      return fallback;
    if(!it->is_number_integer() || it->get<long long>() < 1 || it->get<long long>() > max)
      throw Request_error(std::string("\"") + key + "\" must be an integer in [1, " + std::to_string(max) + "]");
    return static_cast<unsigned int>(it->get<long long>());
  }

  void drag(const Json& command)
  {
    const Clock::time_point start = Clock::now();
    if(!deformation)
      throw Request_error("no selection: send \"select\" first");
    const std::array<double, 3> t = finite_numbers<3>(command, "translation", {0, 0, 0});
    std::array<double, 4> q = finite_numbers<4>(command, "rotation", {1, 0, 0, 0});
    const std::array<double, 3> c = finite_numbers<3>(command, "center", handle_centroid);
    const unsigned int iterations = count_in_range(command, "iterations", options.iterations_per_drag, 100);
    const double norm = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    if(!(norm > 1e-12) || !std::isfinite(norm))
      throw Request_error("\"rotation\" must be a nonzero quaternion [w, x, y, z]");
    for(double& x : q)
      x /= norm;
    const double w = q[0], x = q[1], y = q[2], z = q[3];
    const double R[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
                            {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
                            {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}};
    for(std::uint32_t i : handle)
    {
      const Point& p = rest().point(Vertex_index(i));
      const double d[3] = {p.x() - c[0], p.y() - c[1], p.z() - c[2]};
      double target[3];
      for(int r = 0; r < 3; ++r)
        target[r] = c[r] + R[r][0] * d[0] + R[r][1] * d[1] + R[r][2] * d[2] + t[r];
      deformation->set_target_position(Vertex_index(i), Point(target[0], target[1], target[2]));
    }
    // New targets: a refinement starts again from the deformation.
    refined_iterations = 0;
    deformation->deform(iterations, 0.0);
    const CGAL::Spectral_deformation_report& report = deformation->deform_report();
    if(!report.success)
      throw Request_error("the deformation failed: " + report.message);
    send_region_positions(deformed_header(report.iterations, report.total_seconds), start);
  }

  // One chunk of as-rigid-as-possible iterations from the positions the mesh
  // holds (the last drag's result or the previous chunk's), at most
  // `refine_max_iterations` since the last drag; the page sends the next
  // chunk's command when the answer says the refinement is not done.
  void refine(const Json& command)
  {
    const Clock::time_point start = Clock::now();
    if(!deformation)
      throw Request_error("no selection: send \"select\" first");
    const unsigned int chunk = count_in_range(command, "iterations", options.refine_iterations, 100);
    double tolerance = options.refine_tolerance;
    if(auto it = command.find("tolerance"); it != command.end())
    {
      if(!it->is_number() || !(it->get<double>() >= 0) || !std::isfinite(it->get<double>()))
        throw Request_error("\"tolerance\" must be a finite number, 0 or more");
      tolerance = it->get<double>();
    }
    const unsigned int left =
        options.refine_max_iterations > refined_iterations ? options.refine_max_iterations - refined_iterations : 0;
    if(!deformation->refine(std::min(chunk, left), tolerance))
      throw Request_error("the refinement failed: " + deformation->refine_report().message);
    const CGAL::Spectral_refinement_report& report = deformation->refine_report();
    if(refined_iterations == 0)
      refine_energy_start = report.energy_before;
    refined_iterations += report.iterations;
    const bool done = report.converged || refined_iterations >= options.refine_max_iterations;
    send_region_positions({{"type", "refined"},
                           {"iterations", report.iterations},
                           {"total_iterations", refined_iterations},
                           {"max_iterations", options.refine_max_iterations},
                           {"energy_start", refine_energy_start},
                           {"energy_before", report.energy_before},
                           {"energy_after", report.energy_after},
                           {"converged", report.converged},
                           {"done", done},
                           {"refine_seconds", report.total_seconds}},
                          start);
  }

  void reset()
  {
    const Clock::time_point start = Clock::now();
    if(!deformation)
      throw Request_error("no selection: nothing to reset");
    deformation->reset();
    refined_iterations = 0;
    send_region_positions(deformed_header(0, 0), start);
  }

  void save()
  {
    std::ostringstream off;
    off.precision(9);
    if(!CGAL::IO::write_OFF(off, mesh))
      throw Request_error("cannot write the mesh");
    const std::string text = off.str();
    send_json({{"type", "off"}, {"name", loaded->name + "_deformed.off"}, {"bytes", text.size()}});
    send_binary(text);
  }

  void on_text(const std::string& text)
  {
    const Json command = Json::parse(text, nullptr, false);
    if(command.is_discarded())
    {
      send_error("", "the message is not valid JSON");
      return;
    }
    std::string type;
    if(command.is_object())
    {
      auto it = command.find("type");
      if(it != command.end() && it->is_string())
        type = it->get<std::string>();
    }
    try
    {
      if(type == "select")
        select(command);
      else if(type == "drag")
        drag(command);
      else if(type == "refine")
        refine(command);
      else if(type == "reset")
        reset();
      else if(type == "save")
        save();
      else if(type.empty())
        send_error(type, "a command is a JSON object with a string \"type\"");
      else
        send_error(type, "unknown command type \"" + type + "\"");
    }
    catch(const Request_error& e)
    {
      send_error(type, e.what());
    }
    catch(const CGAL::Spectral_deformation_error& e)
    {
      send_error(type, e.what());
    }
    catch(const std::bad_alloc&)
    {
      send_error(type, "out of memory");
    }
  }
};

Session::Session(std::shared_ptr<const Loaded_mesh> mesh, const Session_options& options, Sender send)
  : m_impl(new Impl(std::move(mesh), options, std::move(send)))
{
}

Session::~Session() = default;

void Session::start() { m_impl->start(); }

void Session::on_text(const std::string& text) { m_impl->on_text(text); }

void Session::on_binary(std::size_t bytes)
{
  m_impl->send_error("", "binary messages are not commands (" + std::to_string(bytes) + " bytes ignored)");
}

void Session::on_oversized(std::size_t bytes, std::size_t limit)
{
  m_impl->send_error("", "the message is too large (" + std::to_string(bytes) + " bytes read, limit " +
                             std::to_string(limit) + "): ignored");
}

} // namespace ssmd_viewer

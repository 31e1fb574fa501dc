// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This file is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.
//
// What the deformation benchmarks share (quality/quality_report.cpp and
// benchmark_deformation.cpp): the cases (the Botsch & Sorkine 2008 files and
// the *.case files of quality/cases, optionally on a Loop-subdivided mesh),
// the measures of the quality of a result, the formatting of numbers and the
// description of the machine.

#ifndef SSMD_BENCHMARK_DEFORMATION_CASES_H
#define SSMD_BENCHMARK_DEFORMATION_CASES_H

#include "benchmark_support.h"

#include <CGAL/Spectral_deformation/IO/deformation_selection.h>
#include <CGAL/Spectral_deformation/arap_energy.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <boost/property_map/function_property_map.hpp>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/subdivision_method_3.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <limits>
#include <numeric>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace ssmd_benchmark {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
typedef Eigen::Matrix<double, Eigen::Dynamic, 3> Positions;
typedef CGAL::IO::Deformation_vertex_status Status;
typedef std::chrono::steady_clock Clock;

constexpr double pi = 3.14159265358979323846;
const double not_a_number = std::numeric_limits<double>::quiet_NaN();

inline double seconds_since(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// ----------------------------------------------------------------------------
// Cases

struct Deformation_case
{
  std::string name;
  std::string title;   // one line
  std::string source;  // the files it was read from
  Mesh mesh;
  std::vector<Status> status; // per vertex index
  Eigen::Matrix4d transformation = Eigen::Matrix4d::Identity(); // applied to the handle
  // Derived by finish_case():
  std::vector<vertex_descriptor> roi;     // status ROI_VERTEX or HANDLE_VERTEX
  std::vector<vertex_descriptor> handles; // status HANDLE_VERTEX
  std::vector<Point> targets;             // of the handles
};

inline Positions positions_of(const Mesh& mesh)
{
  Positions x(static_cast<Eigen::Index>(num_vertices(mesh)), 3);
  for(vertex_descriptor v : vertices(mesh))
  {
    const Point& p = mesh.point(v);
    x.row(static_cast<Eigen::Index>(v.idx())) << p.x(), p.y(), p.z();
  }
  return x;
}

inline Eigen::Vector3d vector_of(const Point& p) { return Eigen::Vector3d(p.x(), p.y(), p.z()); }

inline Mesh read_mesh(const std::string& filename)
{
  Mesh mesh;
  std::ifstream in(filename);
  if(!in)
    throw std::runtime_error("cannot open " + filename);
  // Surface_mesh's OFF reader keeps the vertex order of the file, which the
  // .sel files rely on.
  if(!CGAL::IO::read_OFF(in, mesh) || num_vertices(mesh) == 0)
    throw std::runtime_error("cannot read the OFF mesh " + filename);
  if(!CGAL::is_triangle_mesh(mesh))
    throw std::runtime_error(filename + " is not a triangle mesh");
  if(mesh.has_garbage() || mesh.number_of_removed_vertices() > 0)
    throw std::runtime_error(filename + ": unexpected removed elements after reading");
  return mesh;
}

inline void finish_case(Deformation_case& c)
{
  c.roi.clear();
  c.handles.clear();
  c.targets.clear();
  for(vertex_descriptor v : vertices(c.mesh))
  {
    const Status s = c.status[v.idx()];
    if(s != CGAL::IO::FIXED_VERTEX)
      c.roi.push_back(v);
    if(s == CGAL::IO::HANDLE_VERTEX)
    {
      c.handles.push_back(v);
      const Eigen::Vector4d p = c.transformation * vector_of(c.mesh.point(v)).homogeneous();
      c.targets.push_back(Point(p[0], p[1], p[2]));
    }
  }
  if(c.handles.empty())
    throw std::runtime_error("case " + c.name + ": no handle vertex");
}

/// Refines `c.mesh` by `levels` steps of Loop subdivision and extends the
/// per-vertex status: CGAL's Loop subdivision keeps the old vertices first,
/// each new vertex is on an old edge, adjacent to its two old endpoints; it
/// takes their status when they agree and is a free ROI vertex otherwise.
inline void subdivide_case(Deformation_case& c, unsigned int levels)
{
  for(unsigned int level = 0; level < levels; ++level)
  {
    const std::size_t old_count = num_vertices(c.mesh);
    CGAL::Subdivision_method_3::Loop_subdivision(c.mesh, CGAL::parameters::number_of_iterations(1));
    std::vector<Status> status(num_vertices(c.mesh), CGAL::IO::ROI_VERTEX);
    std::copy(c.status.begin(), c.status.end(), status.begin());
    for(vertex_descriptor v : vertices(c.mesh))
    {
      if(v.idx() < old_count)
        continue;
      std::vector<Status> ends;
      for(vertex_descriptor w : CGAL::vertices_around_target(v, c.mesh))
        if(w.idx() < old_count)
          ends.push_back(c.status[w.idx()]);
      if(ends.size() != 2)
        throw std::runtime_error("case " + c.name + ": unexpected Loop subdivision vertex order");
      status[v.idx()] = ends[0] == ends[1] ? ends[0] : CGAL::IO::ROI_VERTEX;
    }
    c.status = std::move(status);
  }
  if(levels > 0)
    c.source += ", Loop-subdivided " + std::to_string(levels) + (levels == 1 ? " time" : " times");
}

/// The Botsch and Sorkine 2008 case `name`, or false when one of its files
/// is missing; with `subdivision_levels` > 0 on its mesh refined by
/// `subdivide_case()`.
inline bool read_botsch08_case(const std::string& directory, const std::string& name,
                        Deformation_case& c, std::string& why_not,
                        unsigned int subdivision_levels = 0)
{
  const std::string base = directory + "/" + name;
  for(const char* extension : {".off", ".sel", ".def"})
    if(!std::filesystem::exists(base + extension))
    {
      why_not = base + extension + " not found";
      return false;
    }
  c.name = name;
  c.title = name + " (Botsch & Sorkine 2008)";
  c.source = "`" + name + ".off`, `" + name + ".sel`, `" + name + ".def` of the Botsch & Sorkine 2008 benchmark";
  c.mesh = read_mesh(base + ".off");
  c.status = CGAL::IO::read_selection(base + ".sel", num_vertices(c.mesh));
  c.transformation = CGAL::IO::read_handle_transformation(base + ".def");
  subdivide_case(c, subdivision_levels);
  finish_case(c);
  return true;
}

// A region of space selecting vertices in a case file.
struct Shape
{
  bool is_sphere = true;
  Eigen::Vector3d a = Eigen::Vector3d::Zero(); // center, or lower corner
  Eigen::Vector3d b = Eigen::Vector3d::Zero(); // upper corner
  double radius = 0;

  bool contains(const Eigen::Vector3d& p) const
  {
    if(is_sphere)
      return (p - a).squaredNorm() <= radius * radius;
    return (p.array() >= a.array()).all() && (p.array() <= b.array()).all();
  }
};

/// Reads a case file. The format, one statement per line, `#` starts a
/// comment, numbers are in the coordinates of the mesh:
///
///     name         NAME                 (default: the file name without .case)
///     title        free text            (one line, shown in the report)
///     mesh         FILE                 (an OFF file, relative to the mesh directory)
///     handle       SHAPE                (repeatable: the control vertices)
///     fixed        SHAPE                (repeatable: vertices outside the ROI)
///     roi          all | SHAPE          (repeatable; default all)
///     rotation     AX AY AZ DEGREES CX CY CZ   (axis, angle, center; default none)
///     translation  TX TY TZ             (applied after the rotation; default none)
///
/// where SHAPE is `sphere CX CY CZ R` or `box XMIN YMIN ZMIN XMAX YMAX ZMAX`.
/// A vertex is fixed (outside the ROI) when it lies in a `fixed` shape, or
/// when `roi` shapes are given and it lies in none of them; it is a handle
/// when it lies in a `handle` shape; it is in the ROI and free otherwise. A
/// vertex in both a `handle` and a `fixed` shape is an error. The handle
/// targets are x' = R (x - c) + c + t.
///
/// With `subdivision_levels` > 0 the mesh is refined by as many steps of Loop
/// subdivision before the shapes select the vertices (the same case on a
/// finer mesh: about 4^levels times as many vertices).
inline Deformation_case read_case_file(const std::string& filename, const std::string& mesh_directory,
                                       unsigned int subdivision_levels = 0)
{
  std::ifstream in(filename);
  if(!in)
    throw std::runtime_error("cannot open " + filename);
  Deformation_case c;
  c.name = std::filesystem::path(filename).stem().string();
  std::string mesh_file;
  std::vector<Shape> handle, fixed, roi;
  bool roi_all = false;
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ(), center = Eigen::Vector3d::Zero(),
                  translation = Eigen::Vector3d::Zero();
  double degrees = 0;

  std::string line;
  int line_number = 0;
  while(std::getline(in, line))
  {
    ++line_number;
    const std::string where = filename + ":" + std::to_string(line_number) + ": ";
    line = line.substr(0, line.find('#'));
    std::istringstream words(line);
    std::string keyword;
    if(!(words >> keyword))
      continue;
    auto numbers = [&](int count) {
      std::vector<double> values(static_cast<std::size_t>(count));
      for(double& value : values)
        if(!(words >> value) || !std::isfinite(value))
          throw std::runtime_error(where + "expected " + std::to_string(count) + " numbers after '" +
                                   keyword + "'");
      return values;
    };
    auto shape = [&]() {
      std::string kind;
      words >> kind;
      Shape s;
      if(kind == "sphere")
      {
        const std::vector<double> v = numbers(4);
        s.a = Eigen::Vector3d(v[0], v[1], v[2]);
        s.radius = v[3];
        if(!(s.radius > 0))
          throw std::runtime_error(where + "the radius must be positive");
      }
      else if(kind == "box")
      {
        const std::vector<double> v = numbers(6);
        s.is_sphere = false;
        s.a = Eigen::Vector3d(v[0], v[1], v[2]);
        s.b = Eigen::Vector3d(v[3], v[4], v[5]);
        if(!(s.a.array() <= s.b.array()).all())
          throw std::runtime_error(where + "the box corners must be min then max");
      }
      else
        throw std::runtime_error(where + "expected 'sphere' or 'box', got '" + kind + "'");
      return s;
    };
    if(keyword == "name")
      words >> c.name;
    else if(keyword == "title")
    {
      std::getline(words >> std::ws, c.title);
      words.clear();
    }
    else if(keyword == "mesh")
      words >> mesh_file;
    else if(keyword == "handle")
      handle.push_back(shape());
    else if(keyword == "fixed")
      fixed.push_back(shape());
    else if(keyword == "roi")
    {
      std::string next;
      const std::streampos position = words.tellg();
      if(words >> next && next == "all")
        roi_all = true;
      else
      {
        words.clear();
        words.seekg(position);
        roi.push_back(shape());
      }
    }
    else if(keyword == "rotation")
    {
      const std::vector<double> v = numbers(7);
      axis = Eigen::Vector3d(v[0], v[1], v[2]);
      degrees = v[3];
      center = Eigen::Vector3d(v[4], v[5], v[6]);
      if(axis.norm() == 0)
        throw std::runtime_error(where + "the rotation axis is zero");
    }
    else if(keyword == "translation")
    {
      const std::vector<double> v = numbers(3);
      translation = Eigen::Vector3d(v[0], v[1], v[2]);
    }
    else
      throw std::runtime_error(where + "unknown keyword '" + keyword + "'");
    std::string extra;
    if(words >> extra)
      throw std::runtime_error(where + "unexpected '" + extra + "'");
  }
  if(mesh_file.empty())
    throw std::runtime_error(filename + ": no 'mesh'");
  if(handle.empty())
    throw std::runtime_error(filename + ": no 'handle'");
  if(roi_all && !roi.empty())
    throw std::runtime_error(filename + ": 'roi all' and 'roi' shapes exclude each other");
  if(c.title.empty())
    c.title = c.name;
  c.source = "`" + std::filesystem::path(filename).filename().string() + "` on `" + mesh_file + "`";
  c.mesh = read_mesh(mesh_directory + "/" + mesh_file);
  if(subdivision_levels > 0)
  {
    CGAL::Subdivision_method_3::Loop_subdivision(
        c.mesh, CGAL::parameters::number_of_iterations(static_cast<int>(subdivision_levels)));
    c.source += ", Loop-subdivided " + std::to_string(subdivision_levels) +
                (subdivision_levels == 1 ? " time" : " times");
  }

  const Eigen::Matrix3d R = Eigen::AngleAxisd(degrees * pi / 180, axis.normalized()).toRotationMatrix();
  c.transformation.setIdentity();
  c.transformation.topLeftCorner<3, 3>() = R;
  c.transformation.topRightCorner<3, 1>() = center - R * center + translation;

  auto inside = [](const std::vector<Shape>& shapes, const Eigen::Vector3d& p) {
    return std::any_of(shapes.begin(), shapes.end(), [&p](const Shape& s) { return s.contains(p); });
  };
  c.status.assign(num_vertices(c.mesh), CGAL::IO::ROI_VERTEX);
  for(vertex_descriptor v : vertices(c.mesh))
  {
    const Eigen::Vector3d p = vector_of(c.mesh.point(v));
    const bool is_handle = inside(handle, p);
    const bool is_fixed = inside(fixed, p) || (!roi.empty() && !inside(roi, p));
    if(is_handle && is_fixed)
      throw std::runtime_error(filename + ": vertex " + std::to_string(v.idx()) +
                               " is both a handle and fixed");
    c.status[v.idx()] = is_handle ? CGAL::IO::HANDLE_VERTEX
                                  : (is_fixed ? CGAL::IO::FIXED_VERTEX : CGAL::IO::ROI_VERTEX);
  }
  finish_case(c);
  return c;
}

// ----------------------------------------------------------------------------
// Measures

/// What is needed to measure a result of a case: the rest shape and its
/// connectivity.
struct Case_geometry
{
  Positions rest;
  double diagonal = 0;
  Mesh mesh;               // the rest shape, for the ARAP energy
  std::string energy_error; // why the ARAP energy cannot be measured
  std::vector<std::array<int, 3>> faces;
  // Adjacent faces whose normals make an angle below 90° − fold_margin_degrees at rest.
  std::vector<std::pair<int, int>> flat_face_pairs;
  std::size_t interior_edges = 0;
  bool closed = false;       // no border edge: the volume is measured
  double volume = 0;         // enclosed by the rest shape (closed meshes)
  std::vector<std::pair<int, int>> moving_edges;     // with at least one ROI vertex
  std::vector<double> moving_edge_lengths;
  std::vector<std::size_t> border_edges;             // in moving_edges, with one vertex outside the ROI
  std::vector<int> handle_indices, outside_indices;
  Positions targets;
};

inline Eigen::Vector3d face_normal(const Positions& x, const std::array<int, 3>& t)
{
  const Eigen::Vector3d a = x.row(t[0]).transpose();
  return (Eigen::Vector3d(x.row(t[1]).transpose()) - a).cross(Eigen::Vector3d(x.row(t[2]).transpose()) - a);
}

/// How far below 90° the angle between the normals of two adjacent faces
/// must be at rest for the pair to be a candidate fold. Right-angled creases
/// of the input (the edges of a box, whose normals make 89.94-89.99° in the
/// Botsch-Sorkine bar's file) cross 90° by hundredths of a degree under any
/// deformation; they are not folds.
constexpr double fold_margin_degrees = 1.0;

/// The signed volume enclosed by the faces at `x` (meaningful for closed meshes).
inline double enclosed_volume(const Positions& x, const std::vector<std::array<int, 3>>& faces)
{
  double six_volume = 0;
  for(const auto& t : faces)
    six_volume += Eigen::Vector3d(x.row(t[0]).transpose())
                      .dot(Eigen::Vector3d(x.row(t[1]).transpose()).cross(Eigen::Vector3d(x.row(t[2]).transpose())));
  return six_volume / 6.0;
}

inline Case_geometry case_geometry(const Deformation_case& c)
{
  Case_geometry g;
  const Mesh& mesh = c.mesh;
  g.rest = positions_of(mesh);
  g.diagonal = (g.rest.colwise().maxCoeff() - g.rest.colwise().minCoeff()).norm();
  try
  {
    g.mesh = mesh;
    CGAL::arap_energy(g.mesh, get(CGAL::vertex_point, g.mesh)); // throws for a mesh it cannot measure
  }
  catch(const std::exception& e)
  {
    g.energy_error = e.what();
  }
  g.faces.resize(num_faces(mesh));
  for(auto f : faces(mesh))
  {
    int k = 0;
    for(vertex_descriptor v : vertices_around_face(halfedge(f, mesh), mesh))
      g.faces[f.idx()][static_cast<std::size_t>(k++)] = static_cast<int>(v.idx());
  }
  for(auto e : edges(mesh))
  {
    const auto h = halfedge(e, mesh);
    const int a = static_cast<int>(source(h, mesh).idx()), b = static_cast<int>(target(h, mesh).idx());
    const bool a_fixed = c.status[static_cast<std::size_t>(a)] == CGAL::IO::FIXED_VERTEX;
    const bool b_fixed = c.status[static_cast<std::size_t>(b)] == CGAL::IO::FIXED_VERTEX;
    if(!a_fixed || !b_fixed)
    {
      if(a_fixed || b_fixed)
        g.border_edges.push_back(g.moving_edges.size());
      g.moving_edges.emplace_back(a, b);
      g.moving_edge_lengths.push_back((g.rest.row(a) - g.rest.row(b)).norm());
    }
    if(is_border_edge(h, mesh))
      continue;
    ++g.interior_edges;
    const int f1 = static_cast<int>(face(h, mesh).idx());
    const int f2 = static_cast<int>(face(opposite(h, mesh), mesh).idx());
    const Eigen::Vector3d n1 = face_normal(g.rest, g.faces[static_cast<std::size_t>(f1)]).normalized();
    const Eigen::Vector3d n2 = face_normal(g.rest, g.faces[static_cast<std::size_t>(f2)]).normalized();
    if(n1.dot(n2) > std::sin(fold_margin_degrees * CGAL_PI / 180.0))
      g.flat_face_pairs.emplace_back(f1, f2);
  }
  g.closed = (g.interior_edges == num_edges(mesh));
  if(g.closed)
    g.volume = enclosed_volume(g.rest, g.faces);
  g.targets.resize(static_cast<Eigen::Index>(c.handles.size()), 3);
  for(std::size_t k = 0; k < c.handles.size(); ++k)
  {
    g.handle_indices.push_back(static_cast<int>(c.handles[k].idx()));
    g.targets.row(static_cast<Eigen::Index>(k)) = vector_of(c.targets[k]).transpose();
  }
  for(std::size_t i = 0; i < c.status.size(); ++i)
    if(c.status[i] == CGAL::IO::FIXED_VERTEX)
      g.outside_indices.push_back(static_cast<int>(i));
  return g;
}

struct Quality
{
  std::size_t non_finite = 0;             // coordinates
  double max_residual = not_a_number;     // relative to the diagonal
  double rms_residual = not_a_number;
  double max_outside_displacement = not_a_number; // relative to the diagonal
  double arap_energy = not_a_number;
  double mean_edge_change = not_a_number;
  double max_edge_change = not_a_number;
  double max_border_edge_change = not_a_number;
  std::size_t folded_pairs = 0;
  double volume_change = not_a_number; // relative, closed meshes only
};

inline Quality measure(const Case_geometry& g, const Positions& x)
{
  Quality q;
  for(Eigen::Index i = 0; i < x.size(); ++i)
    if(!std::isfinite(x.data()[i]))
      ++q.non_finite;
  if(q.non_finite > 0)
    return q;

  double max_residual = 0, sum = 0;
  for(std::size_t k = 0; k < g.handle_indices.size(); ++k)
  {
    const double d = (x.row(g.handle_indices[k]) - g.targets.row(static_cast<Eigen::Index>(k))).norm();
    max_residual = std::max(max_residual, d);
    sum += d * d;
  }
  q.max_residual = max_residual / g.diagonal;
  q.rms_residual = std::sqrt(sum / static_cast<double>(g.handle_indices.size())) / g.diagonal;

  double outside = 0;
  for(int i : g.outside_indices)
    outside = std::max(outside, (x.row(i) - g.rest.row(i)).norm());
  q.max_outside_displacement = outside / g.diagonal;

  if(g.energy_error.empty())
    q.arap_energy = CGAL::arap_energy(g.mesh, boost::make_function_property_map<vertex_descriptor>(
                                                  [&x](vertex_descriptor v) {
                                                    const Eigen::Index i = static_cast<Eigen::Index>(v.idx());
                                                    return Point(x(i, 0), x(i, 1), x(i, 2));
                                                  }));

  std::vector<double> change(g.moving_edges.size());
  for(std::size_t k = 0; k < g.moving_edges.size(); ++k)
  {
    const double length = (x.row(g.moving_edges[k].first) - x.row(g.moving_edges[k].second)).norm();
    change[k] = std::abs(length - g.moving_edge_lengths[k]) / g.moving_edge_lengths[k];
  }
  if(!change.empty())
  {
    q.mean_edge_change = std::accumulate(change.begin(), change.end(), 0.0) / static_cast<double>(change.size());
    q.max_edge_change = *std::max_element(change.begin(), change.end());
  }
  if(!g.border_edges.empty())
  {
    q.max_border_edge_change = 0;
    for(std::size_t k : g.border_edges)
      q.max_border_edge_change = std::max(q.max_border_edge_change, change[k]);
  }

  if(g.closed && g.volume != 0)
    q.volume_change = enclosed_volume(x, g.faces) / g.volume - 1.0;

  for(const auto& pair : g.flat_face_pairs)
    if(face_normal(x, g.faces[static_cast<std::size_t>(pair.first)])
           .dot(face_normal(x, g.faces[static_cast<std::size_t>(pair.second)])) < 0)
      ++q.folded_pairs;
  return q;
}

// ----------------------------------------------------------------------------
// Formatting

inline std::string format(const char* pattern, double value)
{
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), pattern, value);
  return buffer;
}

/// Two significant digits, `1.2e-3` (`1e-3` for `1.0e-3`); exact zeros as `0`.
inline std::string scientific(double value)
{
  if(std::isnan(value))
    return "n/a";
  if(value == 0)
    return "0";
  std::string text = format("%.1e", value);
  const std::size_t e = text.find('e');
  std::string exponent = text.substr(e + 1);
  const bool negative = exponent[0] == '-';
  exponent = exponent.substr(1);
  exponent.erase(0, std::min(exponent.find_first_not_of('0'), exponent.size() - 1));
  std::string mantissa = text.substr(0, e);
  if(mantissa.size() > 2 && mantissa.compare(mantissa.size() - 2, 2, ".0") == 0)
    mantissa.erase(mantissa.size() - 2);
  return mantissa + "e" + (negative ? "-" : "") + exponent;
}

inline std::string percent(double value)
{
  if(std::isnan(value))
    return "n/a";
  if(value == 0)
    return "0";
  const double p = 100 * value;
  return (p >= 10 ? format("%.0f", p) : p >= 1 ? format("%.1f", p) : format("%.2g", p)) + " %";
}

inline std::string duration(double seconds)
{
  if(std::isnan(seconds))
    return "n/a";
  if(seconds < 0.01)
    return format("%.1f ms", 1000 * seconds);
  if(seconds < 1)
    return format("%.0f ms", 1000 * seconds);
  return format("%.2f s", seconds);
}

inline std::string fixed(double value, int digits)
{
  std::ostringstream out;
  out.setf(std::ios::fixed);
  out.precision(digits);
  out << value;
  return out.str();
}

inline std::string describe_transformation(const Deformation_case& c, const Case_geometry& g)
{
  const Eigen::Matrix3d A = c.transformation.topLeftCorner<3, 3>();
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for(int i : g.handle_indices)
    centroid += g.rest.row(i).transpose();
  centroid /= static_cast<double>(g.handle_indices.size());
  const Eigen::Vector3d moved = A * centroid + c.transformation.topRightCorner<3, 1>();
  std::ostringstream text;
  if((A.transpose() * A - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() < 1e-4 &&
     A.determinant() > 0)
  {
    const Eigen::AngleAxisd rotation(A);
    if(rotation.angle() < 1e-9)
      text << "translation";
    else
    {
      const Eigen::Vector3d axis = rotation.axis();
      text << "rotation by " << fixed(rotation.angle() * 180 / pi, 1) << "° about the axis ("
           << fixed(axis.x(), 3) << ", " << fixed(axis.y(), 3) << ", " << fixed(axis.z(), 3) << ")";
    }
  }
  else
    text << "affine map (not a rigid motion)";
  text << "; the handle centroid moves by " << fixed((moved - centroid).norm() / g.diagonal, 3)
       << " of the bounding-box diagonal";
  return text.str();
}

inline double load_average()
{
  std::ifstream in("/proc/loadavg");
  double load = not_a_number;
  in >> load;
  return load;
}

inline double memory_gib()
{
  std::ifstream in("/proc/meminfo");
  std::string key;
  double kib = not_a_number;
  while(in >> key)
    if(key == "MemTotal:")
    {
      in >> kib;
      break;
    }
  return kib / (1024.0 * 1024.0);
}

} // namespace ssmd_benchmark

#endif // SSMD_BENCHMARK_DEFORMATION_CASES_H

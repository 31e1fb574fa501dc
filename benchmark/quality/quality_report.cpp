// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// This program is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.
//
// Compares the quality of the deformations computed by
// CGAL::Surface_mesh_deformation (as-rigid-as-possible, both energies) and by
// the algorithms of CGAL::Spectral_surface_mesh_deformation on the same
// cases, and writes a markdown report.
//
// Cases:
//   - the four cases of Botsch and Sorkine 2008 (bar, cactus, cylinder,
//     plane: NAME.off, NAME.sel, NAME.def) when their directory is given with
//     --botsch08 (skipped otherwise);
//   - every file *.case of the case directory (see read_case_file() for the
//     format), on meshes of the mesh directory.
//
// Every algorithm deforms its own copy of the input mesh with the same region
// of interest, control vertices and targets; the result is measured on the
// whole mesh (see write_definitions() for the exact definitions).
//
// Usage: quality_report --output FILE [options], see print_usage().

#include <CGAL/Spectral_surface_mesh_deformation.h>
#include <CGAL/Spectral_surface_mesh_deformation/IO/deformation_selection.h>
#include <CGAL/Spectral_surface_mesh_deformation/Sparse_spd_solver_traits.h>
#include <CGAL/Spectral_surface_mesh_deformation/internal/Triangle_arrays.h>
#include <CGAL/Spectral_surface_mesh_deformation/internal/arap_energy.h>
#include <CGAL/Surface_mesh_deformation.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/version.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <Spectra/Util/Version.h>

#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <numeric>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#ifndef SSMD_QUALITY_BUILD_TYPE
#define SSMD_QUALITY_BUILD_TYPE "unknown"
#endif
#ifndef SSMD_QUALITY_CXX_FLAGS_BUILD_TYPE
#define SSMD_QUALITY_CXX_FLAGS_BUILD_TYPE "unknown"
#endif
#ifndef SSMD_QUALITY_CXX_FLAGS
#define SSMD_QUALITY_CXX_FLAGS ""
#endif
#ifndef SSMD_QUALITY_COMPILE_OPTIONS
#define SSMD_QUALITY_COMPILE_OPTIONS ""
#endif
#ifndef SSMD_QUALITY_DEFAULT_MESH_DIR
#define SSMD_QUALITY_DEFAULT_MESH_DIR "data/meshes"
#endif
#ifndef SSMD_QUALITY_DEFAULT_CASE_DIR
#define SSMD_QUALITY_DEFAULT_CASE_DIR "cases"
#endif

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
typedef CGAL::Spectral_deformation::internal::Positions Positions;
typedef CGAL::Spectral_deformation::internal::Triangle_arrays Triangle_arrays;
typedef CGAL::IO::Deformation_vertex_status Status;
typedef std::chrono::steady_clock Clock;

const double pi = 3.14159265358979323846;
const double not_a_number = std::numeric_limits<double>::quiet_NaN();

double seconds_since(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// ----------------------------------------------------------------------------
// Command line

struct Options
{
  std::string output;
  std::string botsch08_directory; // empty: the Botsch & Sorkine cases are skipped
  std::string mesh_directory = SSMD_QUALITY_DEFAULT_MESH_DIR;
  std::string case_directory = SSMD_QUALITY_DEFAULT_CASE_DIR;
  std::string mesh_output_directory; // empty: no mesh is written
  std::vector<std::string> only;     // names of the cases to run; empty: all
  std::size_t frequencies = 100;
  unsigned int long_iterations = 1000;      // of the additional runs
  unsigned int arap_large_iterations = 200; // of the additional CGAL runs on large ROIs
  std::size_t large_roi = 20000;
  std::vector<std::string> notes;
  bool selection_only = false; // write the selections and stop
};

void print_usage(const char* program)
{
  std::cerr
      << "Usage: " << program << " --output FILE [options]\n"
      << "  --output FILE                 the markdown report\n"
      << "  --botsch08 DIR                directory of the Botsch & Sorkine 2008 cases\n"
      << "                                (NAME.off, NAME.sel, NAME.def for bar, cactus,\n"
      << "                                cylinder, plane); skipped when not given or absent\n"
      << "  --meshes DIR                  meshes named by the case files\n"
      << "                                (default " SSMD_QUALITY_DEFAULT_MESH_DIR ")\n"
      << "  --cases DIR                   the *.case files (default " SSMD_QUALITY_DEFAULT_CASE_DIR
         ")\n"
      << "  --only a,b,...                run only the cases of these names\n"
      << "  --frequencies m               basis size of the spectral algorithms (default 100)\n"
      << "  --long-iterations N           iteration cap of the additional runs made when the\n"
      << "                                default deform() does not converge (default 1000)\n"
      << "  --large-roi N                 ROIs with more vertices are large (default 20000)\n"
      << "  --arap-large-iterations N     cap of the additional CGAL runs on large ROIs\n"
      << "                                (default 200)\n"
      << "  --mesh-output DIR             write the input, the selection (.vtk, scalar\n"
      << "                                'status') and every result (.off) there\n"
      << "  --selection-only              with --mesh-output: write the inputs and selections,\n"
      << "                                print their sizes and run nothing (to check the\n"
      << "                                shapes of a case file)\n"
      << "  --note TEXT                   a line added to the notes of the report\n";
}

std::vector<std::string> split(const std::string& text, char separator)
{
  std::vector<std::string> parts;
  std::istringstream in(text);
  std::string part;
  while(std::getline(in, part, separator))
    if(!part.empty())
      parts.push_back(part);
  return parts;
}

unsigned int to_positive_int(const std::string& text, const std::string& option)
{
  char* end = nullptr;
  const long value = std::strtol(text.c_str(), &end, 10);
  if(end == text.c_str() || *end != '\0' || value < 1 || value > 1000000000L)
    throw std::invalid_argument(option + " expects a positive integer, got '" + text + "'");
  return static_cast<unsigned int>(value);
}

Options parse_options(int argc, char** argv)
{
  Options options;
  for(int i = 1; i < argc; ++i)
  {
    const std::string argument = argv[i];
    auto value = [&]() -> std::string {
      if(i + 1 >= argc)
        throw std::invalid_argument(argument + " expects a value");
      return argv[++i];
    };
    if(argument == "--help" || argument == "-h")
    {
      print_usage(argv[0]);
      std::exit(EXIT_SUCCESS);
    }
    else if(argument == "--output")
      options.output = value();
    else if(argument == "--botsch08")
      options.botsch08_directory = value();
    else if(argument == "--meshes")
      options.mesh_directory = value();
    else if(argument == "--cases")
      options.case_directory = value();
    else if(argument == "--only")
      options.only = split(value(), ',');
    else if(argument == "--frequencies")
      options.frequencies = to_positive_int(value(), argument);
    else if(argument == "--long-iterations")
      options.long_iterations = to_positive_int(value(), argument);
    else if(argument == "--large-roi")
      options.large_roi = to_positive_int(value(), argument);
    else if(argument == "--arap-large-iterations")
      options.arap_large_iterations = to_positive_int(value(), argument);
    else if(argument == "--mesh-output")
      options.mesh_output_directory = value();
    else if(argument == "--note")
      options.notes.push_back(value());
    else if(argument == "--selection-only")
      options.selection_only = true;
    else
      throw std::invalid_argument("unknown argument '" + argument + "'");
  }
  if(options.selection_only && options.mesh_output_directory.empty())
    throw std::invalid_argument("--selection-only needs --mesh-output");
  if(options.output.empty() && !options.selection_only)
    throw std::invalid_argument("--output is required");
  return options;
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

Positions positions_of(const Mesh& mesh)
{
  Positions x(static_cast<Eigen::Index>(num_vertices(mesh)), 3);
  for(vertex_descriptor v : vertices(mesh))
  {
    const Point& p = mesh.point(v);
    x.row(static_cast<Eigen::Index>(v.idx())) << p.x(), p.y(), p.z();
  }
  return x;
}

Eigen::Vector3d vector_of(const Point& p) { return Eigen::Vector3d(p.x(), p.y(), p.z()); }

Mesh read_mesh(const std::string& filename)
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

void finish_case(Deformation_case& c)
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

/// The Botsch and Sorkine 2008 case `name`, or false when one of its files
/// is missing.
bool read_botsch08_case(const std::string& directory, const std::string& name,
                        Deformation_case& c, std::string& why_not)
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
Deformation_case read_case_file(const std::string& filename, const std::string& mesh_directory)
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
  Triangle_arrays arrays; // for the ARAP energy
  std::string arrays_error;
  std::vector<std::array<int, 3>> faces;
  std::vector<std::pair<int, int>> flat_face_pairs;  // adjacent faces, normals' dot > 0 at rest
  std::size_t interior_edges = 0;
  std::vector<std::pair<int, int>> moving_edges;     // with at least one ROI vertex
  std::vector<double> moving_edge_lengths;
  std::vector<std::size_t> border_edges;             // in moving_edges, with one vertex outside the ROI
  std::vector<int> handle_indices, outside_indices;
  Positions targets;
};

Eigen::Vector3d face_normal(const Positions& x, const std::array<int, 3>& t)
{
  const Eigen::Vector3d a = x.row(t[0]).transpose();
  return (Eigen::Vector3d(x.row(t[1]).transpose()) - a).cross(Eigen::Vector3d(x.row(t[2]).transpose()) - a);
}

Case_geometry case_geometry(const Deformation_case& c)
{
  Case_geometry g;
  const Mesh& mesh = c.mesh;
  g.rest = positions_of(mesh);
  g.diagonal = (g.rest.colwise().maxCoeff() - g.rest.colwise().minCoeff()).norm();
  try
  {
    g.arrays = CGAL::Spectral_deformation::internal::extract_triangle_arrays(
        mesh, CGAL::parameters::default_values());
  }
  catch(const std::exception& e)
  {
    g.arrays_error = e.what();
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
    if(face_normal(g.rest, g.faces[static_cast<std::size_t>(f1)])
           .dot(face_normal(g.rest, g.faces[static_cast<std::size_t>(f2)])) > 0)
      g.flat_face_pairs.emplace_back(f1, f2);
  }
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
};

Quality measure(const Case_geometry& g, const Positions& x)
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

  if(g.arrays_error.empty())
    q.arap_energy = CGAL::Spectral_deformation::internal::arap_energy(g.arrays, x);

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

  for(const auto& pair : g.flat_face_pairs)
    if(face_normal(x, g.faces[static_cast<std::size_t>(pair.first)])
           .dot(face_normal(x, g.faces[static_cast<std::size_t>(pair.second)])) < 0)
      ++q.folded_pairs;
  return q;
}

// ----------------------------------------------------------------------------
// Runs

struct Run_result
{
  std::string label; // as shown in the report
  std::string key;   // in the names of the written meshes
  bool success = false;
  std::string message; // why not
  double preprocess_seconds = not_a_number;
  bool preprocess_reused = false;
  double deform_seconds = not_a_number;
  std::string iterations;
  Positions after;
  Quality quality;
};

template <class Deformation>
void select_vertices(Deformation& deformation, const Deformation_case& c)
{
  deformation.insert_roi_vertices(c.roi.begin(), c.roi.end());
  deformation.insert_control_vertices(c.handles.begin(), c.handles.end());
}

template <class Deformation>
void set_targets(Deformation& deformation, const Deformation_case& c)
{
  for(std::size_t k = 0; k < c.handles.size(); ++k)
    deformation.set_target_position(c.handles[k], c.targets[k]);
}

template <CGAL::Deformation_algorithm_tag TAG>
using Cgal_deformation = CGAL::Surface_mesh_deformation<Mesh, CGAL::Default, CGAL::Default, TAG>;

/// The number of iterations a call `deform(cap, tolerance)` of CGAL's class
/// performed (the class does not tell): a new object repeats `deform(1, 0)`,
/// which performs the same operations one iteration at a time, until its
/// result is bitwise equal to `result`. 0 if it never is.
template <CGAL::Deformation_algorithm_tag TAG>
unsigned int count_cgal_iterations(const Deformation_case& c, const Positions& result, unsigned int cap)
{
  Mesh mesh = c.mesh;
  Cgal_deformation<TAG> deformation(mesh);
  select_vertices(deformation, c);
  if(!deformation.preprocess())
    return 0;
  set_targets(deformation, c);
  for(unsigned int k = 1; k <= cap; ++k)
  {
    deformation.deform(1, 0.0);
    if(positions_of(mesh) == result)
      return k;
  }
  return 0;
}

/// What a run of CGAL's class did: the iterations it performed (0 when
/// unknown), its cap and its tolerance.
struct Cgal_iterations
{
  unsigned int performed = 0;
  unsigned int cap = 0;
  double tolerance = 0;
};

/// CGAL's `deform(iterations, tolerance)` on a new object with the tolerance
/// of the class; `iterations == 0` means `deform()` with the defaults of the
/// class.
template <CGAL::Deformation_algorithm_tag TAG>
Cgal_iterations run_cgal(const Deformation_case& c, unsigned int iterations, Run_result& result)
{
  Mesh mesh = c.mesh;
  Cgal_deformation<TAG> deformation(mesh);
  select_vertices(deformation, c);
  Cgal_iterations run;
  run.cap = iterations == 0 ? deformation.iterations() : iterations;
  run.tolerance = deformation.tolerance();
  const Clock::time_point start = Clock::now();
  const bool preprocessed = deformation.preprocess();
  result.preprocess_seconds = seconds_since(start);
  if(!preprocessed)
  {
    result.message = "preprocess() failed";
    result.iterations = "failed";
    return run;
  }
  set_targets(deformation, c);
  const Clock::time_point deform_start = Clock::now();
  if(iterations == 0)
    deformation.deform();
  else
    deformation.deform(iterations, run.tolerance);
  result.deform_seconds = seconds_since(deform_start);
  result.after = positions_of(mesh);
  result.success = true;
  run.performed = count_cgal_iterations<TAG>(c, result.after, run.cap);
  std::ostringstream text;
  if(run.performed == 0)
    text << "? (cap " << run.cap << ")";
  else if(run.performed < run.cap)
    text << run.performed << ", tolerance reached";
  else
    text << run.performed << " (cap), tolerance not reached";
  result.iterations = text.str();
  return run;
}

template <CGAL::Spectral_deformation_algorithm_tag TAG>
using Spectral_deformation =
    CGAL::Spectral_surface_mesh_deformation<Mesh, CGAL::Default, CGAL::Default, TAG>;

// ----------------------------------------------------------------------------
// Formatting

std::string format(const char* pattern, double value)
{
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), pattern, value);
  return buffer;
}

/// Two significant digits, `1.2e-3` (`1e-3` for `1.0e-3`); exact zeros as `0`.
std::string scientific(double value)
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

std::string percent(double value)
{
  if(std::isnan(value))
    return "n/a";
  if(value == 0)
    return "0";
  const double p = 100 * value;
  return (p >= 10 ? format("%.0f", p) : p >= 1 ? format("%.1f", p) : format("%.2g", p)) + " %";
}

std::string duration(double seconds)
{
  if(std::isnan(seconds))
    return "n/a";
  if(seconds < 0.01)
    return format("%.1f ms", 1000 * seconds);
  if(seconds < 1)
    return format("%.0f ms", 1000 * seconds);
  return format("%.2f s", seconds);
}

std::string fixed(double value, int digits)
{
  std::ostringstream out;
  out.setf(std::ios::fixed);
  out.precision(digits);
  out << value;
  return out.str();
}

// ----------------------------------------------------------------------------
// Runs of the package's algorithms

std::string spectral_iterations(const CGAL::Spectral_deformation_report& report, bool linear)
{
  if(!report.success)
    return "failed";
  std::ostringstream text;
  text << report.iterations;
  if(linear)
    text << " (no iteration)";
  else if(report.converged)
    text << ", converged";
  else
    text << " (cap), last step " << scientific(report.last_step);
  return text.str();
}

template <class Deformation>
void record_deformation(const Deformation& deformation, bool linear, double seconds, const Mesh& mesh,
                        Run_result& result)
{
  const CGAL::Spectral_deformation_report& report = deformation.deform_report();
  result.deform_seconds = seconds;
  result.success = report.success;
  result.message = report.message;
  result.iterations = spectral_iterations(report, linear);
  result.after = positions_of(mesh);
}

/// Runs `deform()` with the defaults of the class and, when it stops at its
/// iteration cap, `deform(long_iterations, tolerance)` after `reset()` (same
/// region, basis and factorizations).
template <CGAL::Spectral_deformation_algorithm_tag TAG>
void run_package_algorithm(const Deformation_case& c, const Options& options,
                           CGAL::Spectral_constraint_policy policy, const std::string& label,
                           const std::string& key, std::vector<Run_result>& results)
{
  const bool linear = (TAG == CGAL::SPECTRAL_LINEAR);
  Mesh mesh = c.mesh;
  Spectral_deformation<TAG> deformation(mesh);
  select_vertices(deformation, c);
  deformation.set_number_of_frequencies(options.frequencies);
  deformation.set_constraint_policy(policy);

  Run_result first;
  first.label = label + ", `deform()`";
  first.key = key;
  const Clock::time_point start = Clock::now();
  const bool preprocessed = deformation.preprocess();
  first.preprocess_seconds = seconds_since(start);
  if(!preprocessed)
  {
    first.message = "preprocess() failed: " + deformation.preprocess_report().message;
    first.iterations = "failed";
    results.push_back(first);
    return;
  }
  set_targets(deformation, c);
  const Clock::time_point deform_start = Clock::now();
  deformation.deform();
  record_deformation(deformation, linear, seconds_since(deform_start), mesh, first);
  results.push_back(first);

  const CGAL::Spectral_deformation_report& report = deformation.deform_report();
  if(linear || !report.success || report.converged ||
     options.long_iterations <= deformation.iterations())
    return;
  Run_result second;
  second.label = label + ", `deform(" + std::to_string(options.long_iterations) + ", " +
                 scientific(deformation.tolerance()) + ")`";
  second.key = key + "_long";
  second.preprocess_reused = true;
  deformation.reset();
  set_targets(deformation, c);
  const Clock::time_point long_start = Clock::now();
  deformation.deform(options.long_iterations, deformation.tolerance());
  record_deformation(deformation, linear, seconds_since(long_start), mesh, second);
  results.push_back(second);
}

/// Runs CGAL's `deform()` with the defaults of the class and, when it stops
/// at its iteration cap, `deform(long_iterations, tolerance)` on a new object.
template <CGAL::Deformation_algorithm_tag TAG>
void run_cgal_algorithm(const Deformation_case& c, unsigned int long_iterations,
                        const std::string& label, const std::string& key,
                        std::vector<Run_result>& results)
{
  Run_result first;
  first.label = label + ", `deform()`";
  first.key = key;
  const Cgal_iterations run = run_cgal<TAG>(c, 0, first);
  results.push_back(first);
  if(!first.success || (run.performed != 0 && run.performed < run.cap) || long_iterations <= run.cap)
    return;
  Run_result second;
  second.label = label + ", `deform(" + std::to_string(long_iterations) + ", " +
                 scientific(run.tolerance) + ")`";
  second.key = key + "_long";
  run_cgal<TAG>(c, long_iterations, second);
  results.push_back(second);
}

// ----------------------------------------------------------------------------
// Output of meshes

void write_off(const std::string& filename, const Mesh& mesh, const Positions& x)
{
  Mesh copy = mesh;
  for(vertex_descriptor v : vertices(copy))
  {
    const Eigen::Index i = static_cast<Eigen::Index>(v.idx());
    copy.point(v) = Point(x(i, 0), x(i, 1), x(i, 2));
  }
  std::ofstream out(filename);
  out.precision(17);
  if(!CGAL::IO::write_OFF(out, copy))
    throw std::runtime_error("cannot write " + filename);
}

/// The mesh with the status of every vertex as point data `status`
/// (0 fixed, 1 ROI, 2 handle), in the legacy VTK format.
void write_selection(const std::string& filename, const Deformation_case& c, const Case_geometry& g)
{
  std::ofstream out(filename);
  out.precision(17);
  out << "# vtk DataFile Version 3.0\n" << c.name << " selection\nASCII\nDATASET POLYDATA\n"
      << "POINTS " << g.rest.rows() << " double\n";
  for(Eigen::Index i = 0; i < g.rest.rows(); ++i)
    out << g.rest(i, 0) << ' ' << g.rest(i, 1) << ' ' << g.rest(i, 2) << '\n';
  out << "POLYGONS " << g.faces.size() << ' ' << 4 * g.faces.size() << '\n';
  for(const auto& t : g.faces)
    out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
  out << "POINT_DATA " << g.rest.rows() << "\nSCALARS status int 1\nLOOKUP_TABLE default\n";
  for(Status s : c.status)
    out << static_cast<int>(s) << '\n';
  if(!out)
    throw std::runtime_error("cannot write " + filename);
}

// ----------------------------------------------------------------------------
// Report

struct Case_report
{
  std::string name, title, source;
  std::string skipped; // why the case did not run; empty when it ran
  std::size_t vertices = 0, faces = 0, roi = 0, handles = 0, fixed = 0;
  std::size_t interior_edges = 0, flat_pairs = 0;
  double diagonal = 0;
  std::string transformation;
  unsigned int cgal_long_iterations = 0;
  double seconds = 0;
  std::vector<Run_result> results;
};

std::string describe_transformation(const Deformation_case& c, const Case_geometry& g)
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

std::string first_line_value(const std::string& file, const std::string& key)
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

double load_average()
{
  std::ifstream in("/proc/loadavg");
  double load = not_a_number;
  in >> load;
  return load;
}

double memory_gib()
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

std::string compiler()
{
#if defined(__clang__)
  return "Clang " __clang_version__;
#elif defined(__GNUC__)
  return "GCC " __VERSION__;
#else
  return "unknown";
#endif
}

std::string sparse_solver()
{
#ifdef CGAL_SSMD_USE_CHOLMOD
  return "CHOLMOD " + std::to_string(CHOLMOD_MAIN_VERSION) + "." +
         std::to_string(CHOLMOD_SUB_VERSION) + "." + std::to_string(CHOLMOD_SUBSUB_VERSION) +
         " (`CGAL_SSMD_USE_CHOLMOD` defined)";
#else
  return "Eigen `SimplicialLDLT` (`CGAL_SSMD_USE_CHOLMOD` not defined)";
#endif
}

std::string utc_time(std::time_t time)
{
  char buffer[64];
  std::strftime(buffer, sizeof(buffer), "%Y-%m-%d %H:%M UTC", std::gmtime(&time));
  return buffer;
}

struct Run_info
{
  std::time_t start = std::time(nullptr);
  double load_at_start = load_average();
  Clock::time_point clock_start = Clock::now();
};

void write_definitions(std::ostream& out, const Options& options)
{
  out << "## Definitions\n\n"
      << "Every algorithm deforms its own copy of the input with the same region of interest "
         "(ROI: statuses 1 and 2), control vertices (the handle: status 2) and targets (the "
         "handle transformation applied to the rest positions of the handle vertices); "
         "vertices of status 0 are outside the ROI. All measures are taken on the whole mesh "
         "against the input. *D* is the bounding-box diagonal of the input mesh.\n\n"
      << "- *iterations*: for this package, `deform_report().iterations` (solves of the "
         "reduced or spatial system; *converged* when the relative step fell below the "
         "tolerance, otherwise the last step is given). CGAL's class does not report its "
         "iterations: they are counted by repeating `deform(1, 0)` on a new object (the same "
         "operations, one iteration per call) until the result is bitwise equal to that of "
         "the timed call (this count is not timed); *tolerance reached* means that CGAL's "
         "energy criterion stopped before the cap.\n"
      << "- *preprocess*: wall time of an explicit `preprocess()` after the ROI and control "
         "vertices were inserted (for this package: region, manifold harmonics basis, "
         "reduced matrices and factorizations; for CGAL: region of solution and "
         "factorization). *reused*: the run continues on the object of the row above after "
         "`reset()`, nothing is recomputed.\n"
      << "- *deform*: wall time of the `deform` call, targets set beforehand.\n"
      << "- *handle residual*: max and RMS over the handle vertices of the distance to the "
         "target, divided by *D*.\n"
      << "- *outside ROI*: the largest displacement of a vertex outside the ROI, divided by "
         "*D*; must be exactly 0.\n"
      << "- *ARAP energy*: `internal::arap_energy(input, result)` on the whole mesh: "
         "Σ w_ij ‖(x'_i − x'_j) − R_i (x_i − x_j)‖² / Σ w_ij ‖x_i − x_j‖² over the directed "
         "edges, w_ij = |cotangent weight| of the input, R_i the best rotation of the one-ring "
         "of i; 0 for a rigid motion, about the mean squared relative distortion otherwise.\n"
      << "- *edge change*: |ℓ' − ℓ| / ℓ over the edges with at least one ROI vertex "
         "(ℓ rest length, ℓ' deformed length); mean and max. *ROI border*: the max over the "
         "edges joining a vertex outside the ROI to a ROI vertex (a seam between the fixed "
         "part and the ROI shows there).\n"
      << "- *folded pairs*: interior edges whose two faces have (unnormalized) normals with a "
         "positive dot product in the input and a negative one in the result, i.e. the "
         "angle between the two face normals was below 90° and exceeds 90° after the "
         "deformation (a fold or a sharp crease created by the deformation). Only pairs with a "
         "positive dot product at rest are candidates (their number is given per case).\n"
      << "- *non-finite*: coordinates of the result that are NaN or infinite (the other "
         "measures are then not computed).\n"
      << "- CGAL ARAP: `CGAL::Surface_mesh_deformation<Surface_mesh>` with its default "
         "weights and sparse solver (Eigen `SparseLU`), tags `SPOKES_AND_RIMS` (default) and "
         "`ORIGINAL_ARAP`. `deform()` runs at most 5 iterations with the energy tolerance "
         "1e-4; when it stops at the cap, a new object runs `deform(N, 1e-4)` with N = "
         << options.long_iterations << ", capped at N = " << options.arap_large_iterations
         << " when the ROI has more than " << options.large_roi
         << " vertices (to bound the run time; see each case).\n"
      << "- This package: `CGAL::Spectral_surface_mesh_deformation<Surface_mesh, Default, "
         "Default, TAG>`, m = "
      << options.frequencies
      << " frequencies (`set_number_of_frequencies`), otherwise defaults (constraint weight "
         "1, at most 10 iterations, tolerance 1e-4); *exact* and *soft* are the "
         "`EXACT_CONSTRAINTS` and `SOFT_CONSTRAINTS` policies. When `deform()` stops at its "
         "cap, the same object continues with `reset()`, the same targets and `deform("
      << options.long_iterations << ", 1e-4)`.\n";
}

void write_report(const std::string& filename, const Options& options, const Run_info& run,
                  const std::vector<Case_report>& cases, bool complete)
{
  std::ofstream out(filename);
  if(!out)
    throw std::runtime_error("cannot write " + filename);
  const double minutes = std::chrono::duration<double>(Clock::now() - run.clock_start).count() / 60.0;
  out << "# Deformation quality: CGAL ARAP and the algorithms of this package\n\n";
  if(!complete)
    out << "**Incomplete: the run was still in progress when this was written.**\n\n";
  out << "- Date: " << utc_time(run.start) << ", whole run " << fixed(minutes, 1)
      << " min, load average (1 min) " << fixed(run.load_at_start, 2) << " at start, "
      << fixed(load_average(), 2) << " at the end\n"
      << "- Machine: " << first_line_value("/proc/cpuinfo", "model name") << ", "
      << ::sysconf(_SC_NPROCESSORS_ONLN) << " logical CPUs, " << fixed(memory_gib(), 1)
      << " GiB RAM\n"
      << "- Compiler: " << compiler() << "\n"
      << "- Build: `CMAKE_BUILD_TYPE=" << SSMD_QUALITY_BUILD_TYPE << "`, flags of the build type `"
      << SSMD_QUALITY_CXX_FLAGS_BUILD_TYPE << "`, `CMAKE_CXX_FLAGS` `" << SSMD_QUALITY_CXX_FLAGS
      << "`, compile options `" << SSMD_QUALITY_COMPILE_OPTIONS << "`"
#ifdef NDEBUG
      << ", `NDEBUG` defined\n"
#else
      << ", **`NDEBUG` not defined (assertions on)**\n"
#endif
      << "- Libraries: CGAL " << CGAL_VERSION_STR << ", Eigen " << EIGEN_WORLD_VERSION << "."
      << EIGEN_MAJOR_VERSION << "." << EIGEN_MINOR_VERSION << ", Spectra " << SPECTRA_MAJOR_VERSION
      << "." << SPECTRA_MINOR_VERSION << "." << SPECTRA_PATCH_VERSION
      << "; sparse SPD solver of this package: " << sparse_solver() << "\n"
      << "- Settings: m = " << options.frequencies << ", additional runs `deform("
      << options.long_iterations << ", 1e-4)` (CGAL on ROIs above " << options.large_roi
      << " vertices: " << options.arap_large_iterations
      << "); definitions of the columns at the end\n";
  for(const std::string& note : options.notes)
    out << "- Note: " << note << "\n";

  for(const Case_report& c : cases)
  {
    out << "\n## " << c.title << "\n\n";
    if(!c.skipped.empty())
    {
      out << "Skipped: " << c.skipped << "\n";
      continue;
    }
    out << "- Case `" << c.name << "`: " << c.source << "; " << c.vertices << " vertices, "
        << c.faces << " faces, D = " << format("%.4g", c.diagonal) << "\n"
        << "- Selection: ROI " << c.roi << " vertices (of which " << c.handles
        << " handle vertices), " << c.fixed << " vertices outside the ROI\n"
        << "- Handle transformation: " << c.transformation << "\n"
        << "- Folding candidates: " << c.flat_pairs << " of " << c.interior_edges
        << " interior edges; CGAL's additional runs capped at " << c.cgal_long_iterations
        << " iterations; case run in " << fixed(c.seconds, 1) << " s\n\n";
    out << "| algorithm | iterations | preprocess | deform | handle residual max / D | "
           "handle residual RMS / D | outside ROI / D | ARAP energy | edge change mean | "
           "edge change max | ROI border edge change max | folded pairs | non-finite |\n"
        << "|---|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|\n";
    for(const Run_result& r : c.results)
    {
      out << "| " << r.label << " | " << r.iterations << " | "
          << (r.preprocess_reused ? std::string("reused") : duration(r.preprocess_seconds)) << " | "
          << duration(r.deform_seconds) << " | ";
      if(!r.success)
      {
        out << "failed: " << r.message << " | | | | | | | | |\n";
        continue;
      }
      const Quality& q = r.quality;
      out << scientific(q.max_residual) << " | " << scientific(q.rms_residual) << " | "
          << scientific(q.max_outside_displacement) << " | " << scientific(q.arap_energy) << " | "
          << percent(q.mean_edge_change) << " | " << percent(q.max_edge_change) << " | "
          << percent(q.max_border_edge_change) << " | "
          << (q.non_finite ? std::string("n/a") : std::to_string(q.folded_pairs)) << " | "
          << q.non_finite << " |\n";
    }
  }
  out << "\n";
  write_definitions(out, options);
}

// ----------------------------------------------------------------------------
// Driver

bool selected(const Options& options, const std::string& name)
{
  return options.only.empty() ||
         std::find(options.only.begin(), options.only.end(), name) != options.only.end();
}

void run_case(const Deformation_case& c, const Options& options, Case_report& report)
{
  const Clock::time_point start = Clock::now();
  const Case_geometry g = case_geometry(c);
  report.name = c.name;
  report.title = c.title;
  report.source = c.source;
  report.vertices = num_vertices(c.mesh);
  report.faces = num_faces(c.mesh);
  report.roi = c.roi.size();
  report.handles = c.handles.size();
  report.fixed = g.outside_indices.size();
  report.interior_edges = g.interior_edges;
  report.flat_pairs = g.flat_face_pairs.size();
  report.diagonal = g.diagonal;
  report.transformation = describe_transformation(c, g);
  report.cgal_long_iterations =
      c.roi.size() > options.large_roi ? options.arap_large_iterations : options.long_iterations;
  if(!g.arrays_error.empty())
    std::cerr << "  warning: no ARAP energy: " << g.arrays_error << "\n";
  const std::string base = options.mesh_output_directory + "/" + c.name;
  if(!options.mesh_output_directory.empty())
  {
    write_off(base + ".input.off", c.mesh, g.rest);
    write_selection(base + ".selection.vtk", c, g);
  }
  if(options.selection_only)
  {
    std::cerr << "  " << report.vertices << " vertices, ROI " << report.roi << ", handle "
              << report.handles << ", outside the ROI " << report.fixed << "; "
              << report.transformation << "\n";
    return;
  }

  std::vector<Run_result>& results = report.results;
  std::size_t reported = 0;
  auto progress = [&results, &c, &reported](Clock::time_point since) {
    for(; reported < results.size(); ++reported)
      std::cerr << "  " << c.name << ": " << results[reported].label << ": "
                << results[reported].iterations << std::endl;
    std::cerr << "    (" << duration(seconds_since(since)) << ")" << std::endl;
  };
  Clock::time_point step = Clock::now();
  run_cgal_algorithm<CGAL::SPOKES_AND_RIMS>(c, report.cgal_long_iterations,
                                            "CGAL ARAP, spokes and rims", "cgal_spokes_and_rims",
                                            results);
  progress(step);
  step = Clock::now();
  run_cgal_algorithm<CGAL::ORIGINAL_ARAP>(c, report.cgal_long_iterations, "CGAL ARAP, original",
                                          "cgal_original", results);
  progress(step);
  const std::string m = "m = " + std::to_string(options.frequencies);
  step = Clock::now();
  run_package_algorithm<CGAL::SPECTRAL_DUAL_LAPLACIAN>(
      c, options, CGAL::EXACT_CONSTRAINTS, "spectral dual Laplacian, exact, " + m, "spectral_exact",
      results);
  progress(step);
  step = Clock::now();
  run_package_algorithm<CGAL::SPECTRAL_DUAL_LAPLACIAN>(
      c, options, CGAL::SOFT_CONSTRAINTS, "spectral dual Laplacian, soft, " + m, "spectral_soft",
      results);
  progress(step);
  step = Clock::now();
  run_package_algorithm<CGAL::SPECTRAL_LINEAR>(c, options, CGAL::EXACT_CONSTRAINTS,
                                               "spectral linear, exact, " + m, "spectral_linear",
                                               results);
  progress(step);
  step = Clock::now();
  run_package_algorithm<CGAL::SPATIAL_DUAL_LAPLACIAN>(c, options, CGAL::EXACT_CONSTRAINTS,
                                                      "spatial dual Laplacian", "spatial", results);
  progress(step);

  for(Run_result& r : results)
    if(r.success)
      r.quality = measure(g, r.after);

  if(!options.mesh_output_directory.empty())
    for(const Run_result& r : results)
      if(r.success)
        write_off(base + "." + r.key + ".off", c.mesh, r.after);
  for(Run_result& r : results)
    r.after.resize(0, 3);
  report.seconds = seconds_since(start);
}

} // namespace

int main(int argc, char** argv)
{
  Options options;
  try
  {
    options = parse_options(argc, argv);
  }
  catch(const std::exception& e)
  {
    std::cerr << "error: " << e.what() << "\n";
    print_usage(argv[0]);
    return EXIT_FAILURE;
  }
  try
  {
    const Run_info run;
    if(!options.mesh_output_directory.empty())
      std::filesystem::create_directories(options.mesh_output_directory);
    std::vector<Case_report> reports;

    // The Botsch & Sorkine 2008 cases.
    for(const std::string name : {"bar", "cactus", "cylinder", "plane"})
    {
      if(!selected(options, name))
        continue;
      Case_report report;
      report.name = name;
      report.title = name + " (Botsch & Sorkine 2008)";
      Deformation_case c;
      std::string why_not;
      if(options.botsch08_directory.empty())
        report.skipped = "no directory of the Botsch & Sorkine 2008 cases given (--botsch08)";
      else if(!read_botsch08_case(options.botsch08_directory, name, c, why_not))
        report.skipped = why_not;
      else
      {
        std::cerr << "case " << name << std::endl;
        run_case(c, options, report);
      }
      reports.push_back(std::move(report));
      if(!options.selection_only)
        write_report(options.output, options, run, reports, false);
    }

    // The cases of the case directory, by file name.
    std::vector<std::string> case_files;
    if(std::filesystem::is_directory(options.case_directory))
      for(const auto& entry : std::filesystem::directory_iterator(options.case_directory))
        if(entry.path().extension() == ".case")
          case_files.push_back(entry.path().string());
    std::sort(case_files.begin(), case_files.end());
    if(case_files.empty())
      std::cerr << "warning: no .case file in " << options.case_directory << "\n";
    for(const std::string& file : case_files)
    {
      Case_report report;
      Deformation_case c;
      try
      {
        c = read_case_file(file, options.mesh_directory);
      }
      catch(const std::exception& e)
      {
        report.name = report.title = std::filesystem::path(file).stem().string();
        if(!selected(options, report.name))
          continue;
        report.skipped = e.what();
        std::cerr << "skipped: " << e.what() << "\n";
        reports.push_back(std::move(report));
        continue;
      }
      if(!selected(options, c.name))
        continue;
      std::cerr << "case " << c.name << std::endl;
      run_case(c, options, report);
      reports.push_back(std::move(report));
      if(!options.selection_only)
        write_report(options.output, options, run, reports, false);
    }
    if(!options.selection_only)
    {
      write_report(options.output, options, run, reports, true);
      std::cerr << "wrote " << options.output << "\n";
    }
  }
  catch(const std::exception& e)
  {
    std::cerr << "error: " << e.what() << "\n";
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}

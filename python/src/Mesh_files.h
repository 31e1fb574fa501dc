// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// ssmd.from_file, ssmd.to_file, ssmd.read_selection and
// ssmd.read_handle_transformation: the files of the command-line tool
// ssmd_deform, read and written by the same CGAL readers and writers, so that
// a file gives the same mesh (same vertex order) in Python as in the tool.

#ifndef SSMD_PYTHON_MESH_FILES_H
#define SSMD_PYTHON_MESH_FILES_H

#include "Numpy_mesh.h"

#include <CGAL/Spectral_deformation/IO/deformation_selection.h>
#include <CGAL/Spectral_deformation/Spectral_deformation_error.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>

#include <unistd.h>

namespace ssmd_python {

namespace py = pybind11;

// Raises the OSError subclass that Python gives to `code` (FileNotFoundError
// for ENOENT, ...), with `file` as its filename.
[[noreturn]] inline void raise_os_error(int code, const std::string& message, const std::string& file)
{
  const py::object error = py::reinterpret_borrow<py::object>(PyExc_OSError)(code, message, file);
  PyErr_SetObject(reinterpret_cast<PyObject*>(Py_TYPE(error.ptr())), error.ptr());
  throw py::error_already_set();
}

inline std::string lowercase_extension(const std::filesystem::path& file)
{
  std::string extension = file.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

// The formats CGAL::IO::read_polygon_mesh and write_polygon_mesh handle
// without optional libraries (VTP needs VTK).
inline bool is_mesh_format(const std::string& extension)
{
  return extension == ".off" || extension == ".obj" || extension == ".ply" || extension == ".stl" ||
         extension == ".ts";
}

inline const char* mesh_formats() { return ".off, .obj, .ply, .stl or .ts"; }

// `file` exists, is not a directory and can be opened, or OSError.
inline void check_readable(const std::string& file)
{
  std::error_code error;
  if(!std::filesystem::exists(file, error))
    raise_os_error(ENOENT, "no such file", file);
  if(std::filesystem::is_directory(file, error))
    raise_os_error(EISDIR, "is a directory", file);
  errno = 0;
  if(!std::ifstream(file))
  {
    const int code = errno != 0 ? errno : EIO;
    raise_os_error(code, std::strerror(code), file);
  }
}

inline std::string path_string(const py::handle& file)
{
  return py::str(py::module_::import("os").attr("fspath")(file)).cast<std::string>();
}

// The positions (n, 3) and triangles (f, 3) of a mesh file, vertices in the
// order of the file.
inline py::tuple read_mesh_file(const py::handle& path)
{
  const std::string file = path_string(path);
  const std::string extension = lowercase_extension(file);
  if(!is_mesh_format(extension))
    throw py::value_error("cannot read " + file + ": the mesh formats are " + mesh_formats() +
                          (extension.empty() ? std::string(", and the file name has no extension")
                                             : ", not " + extension));
  check_readable(file);
  Mesh mesh;
  bool read = false;
  {
    py::gil_scoped_release release;
    try
    {
      read = CGAL::IO::read_polygon_mesh(file, mesh, CGAL::parameters::verbose(false));
    }
    catch(const std::exception&)
    {
      read = false;
    }
  }
  if(!read)
    throw py::value_error("cannot read a polygon mesh from " + file +
                          " (malformed or truncated file, or polygons that do not form a manifold mesh)");
  if(mesh.number_of_faces() == 0)
    throw py::value_error("the mesh " + file + " has no face");
  if(!CGAL::is_triangle_mesh(mesh))
  {
    std::size_t polygons = 0;
    for(Mesh::Face_index f : mesh.faces())
      polygons += (mesh.degree(f) != 3);
    throw py::value_error("the mesh " + file + " is not a triangle mesh: " + std::to_string(polygons) +
                          " of its " + std::to_string(mesh.number_of_faces()) + " faces are not triangles");
  }
  for(Vertex_index v : mesh.vertices())
  {
    const Point& p = mesh.point(v);
    if(!(std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z())))
      throw py::value_error("the mesh " + file + " has a non-finite coordinate (vertex " +
                            std::to_string(std::size_t(v)) + ")");
  }
  // A mesh just read has no removed element: its indices are 0..n-1.
  py::array_t<std::int64_t> faces({static_cast<py::ssize_t>(mesh.number_of_faces()), py::ssize_t(3)});
  std::int64_t* out = faces.mutable_data();
  for(Mesh::Face_index f : mesh.faces())
  {
    int k = 0;
    for(Vertex_index v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
      out[3 * std::size_t(f) + k++] = static_cast<std::int64_t>(std::size_t(v));
  }
  return py::make_tuple(positions(mesh), faces);
}

// Writes the mesh (V, F) to `path` through a temporary file in the same
// folder, renamed at the end, so that the file is either complete or
// untouched (as ssmd_deform writes its results).
inline void write_mesh_file(const py::handle& path, const py::handle& vertices, const py::handle& faces)
{
  const std::string file = path_string(path);
  const std::filesystem::path target(file);
  const std::string extension = lowercase_extension(target);
  if(!is_mesh_format(extension))
    throw py::value_error("cannot write " + file + ": the mesh formats are " + mesh_formats() +
                          (extension.empty() ? std::string(", and the file name has no extension")
                                             : ", not " + extension));
  Mesh mesh;
  fill_mesh(vertices, faces, mesh);
  const std::filesystem::path folder = target.has_parent_path() ? target.parent_path() : ".";
  std::error_code error;
  if(!std::filesystem::is_directory(folder, error))
    raise_os_error(ENOENT, "no such folder", folder.string());
  const std::filesystem::path temporary =
      folder / ("." + target.stem().string() + ".partial-" + std::to_string(::getpid()) + extension);
  bool written = false;
  {
    py::gil_scoped_release release;
    try
    {
      written = CGAL::IO::write_polygon_mesh(temporary.string(), mesh, CGAL::parameters::stream_precision(17));
    }
    catch(const std::exception&)
    {
      written = false;
    }
    if(written)
      std::filesystem::rename(temporary, target, error);
  }
  if(!written || error)
  {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    const int code = error ? error.value() : EIO;
    raise_os_error(code, "cannot write the mesh", file);
  }
}

// The region of interest and the handles of a .sel file: the vertices of
// status 1 or 2, and those of status 2, in increasing order.
inline py::tuple read_selection_file(const py::handle& path, long long number_of_vertices)
{
  const std::string file = path_string(path);
  if(number_of_vertices < 1)
    throw py::value_error("number_of_vertices must be positive, not " + std::to_string(number_of_vertices));
  check_readable(file);
  std::vector<CGAL::IO::Deformation_vertex_status> status;
  try
  {
    status = CGAL::IO::read_selection(file, static_cast<std::size_t>(number_of_vertices));
  }
  catch(const CGAL::Spectral_deformation_error& e)
  {
    // The file could be opened: what is wrong is its content.
    throw py::value_error(e.what());
  }
  std::vector<std::int64_t> roi, handles;
  for(std::size_t v = 0; v < status.size(); ++v)
  {
    if(status[v] != CGAL::IO::FIXED_VERTEX)
      roi.push_back(static_cast<std::int64_t>(v));
    if(status[v] == CGAL::IO::HANDLE_VERTEX)
      handles.push_back(static_cast<std::int64_t>(v));
  }
  py::array_t<std::int64_t> roi_array(static_cast<py::ssize_t>(roi.size()));
  std::copy(roi.begin(), roi.end(), roi_array.mutable_data());
  py::array_t<std::int64_t> handle_array(static_cast<py::ssize_t>(handles.size()));
  std::copy(handles.begin(), handles.end(), handle_array.mutable_data());
  return py::make_tuple(roi_array, handle_array);
}

// The 4 x 4 affine matrix of a .def file.
inline py::array_t<double> read_handle_transformation_file(const py::handle& path)
{
  const std::string file = path_string(path);
  check_readable(file);
  Eigen::Matrix4d T;
  try
  {
    T = CGAL::IO::read_handle_transformation(file);
  }
  catch(const CGAL::Spectral_deformation_error& e)
  {
    throw py::value_error(e.what());
  }
  py::array_t<double> result({py::ssize_t(4), py::ssize_t(4)});
  for(int i = 0; i < 4; ++i)
    for(int j = 0; j < 4; ++j)
      result.mutable_at(i, j) = T(i, j);
  return result;
}

} // namespace ssmd_python

#endif // SSMD_PYTHON_MESH_FILES_H

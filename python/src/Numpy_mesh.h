// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// NumPy arrays in, CGAL::Surface_mesh and NumPy arrays out: the checks of
// the Python module on its array arguments. Every check raises ValueError
// with a message that names the argument, before anything is built.

#ifndef SSMD_PYTHON_NUMPY_MESH_H
#define SSMD_PYTHON_NUMPY_MESH_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace ssmd_python {

namespace py = pybind11;

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef Mesh::Vertex_index Vertex_index;

// forcecast only converts other float types: a float64 C-contiguous array is
// read in place, without a copy.
typedef py::array_t<double, py::array::c_style | py::array::forcecast> Double_array;
typedef py::array_t<std::int64_t, py::array::c_style | py::array::forcecast> Index_array;

inline Double_array as_double_array(const py::handle& object, const char* name)
{
  const py::array any = py::array::ensure(object);
  if(!any)
    throw py::value_error(std::string(name) + " must be an array of numbers");
  const char kind = any.dtype().kind();
  if(kind != 'f' && kind != 'i' && kind != 'u')
    throw py::value_error(std::string(name) + " must hold real numbers, not dtype " +
                          py::str(any.dtype()).cast<std::string>());
  return Double_array::ensure(any);
}

// Integer arrays only: a float array of indices is refused rather than
// truncated.
inline Index_array as_index_array(const py::handle& object, const char* name)
{
  const py::array any = py::array::ensure(object);
  if(!any)
    throw py::value_error(std::string(name) + " must be an array of integers");
  const char kind = any.dtype().kind();
  // An empty list arrives as an empty float64 array.
  if(kind != 'i' && kind != 'u' && any.size() != 0)
    throw py::value_error(std::string(name) + " must hold integers, not dtype " +
                          py::str(any.dtype()).cast<std::string>());
  return Index_array::ensure(any);
}

inline void check_rows_of_3(const py::array& a, const char* name)
{
  if(a.ndim() != 2 || a.shape(1) != 3)
  {
    std::string shape = "(";
    for(py::ssize_t d = 0; d < a.ndim(); ++d)
      shape += (d ? ", " : "") + std::to_string(a.shape(d));
    shape += a.ndim() == 1 ? ",)" : ")";
    throw py::value_error(std::string(name) + " must have shape (k, 3), not " + shape);
  }
}

// A k x 3 array of finite coordinates.
inline Double_array checked_points(const py::handle& object, const char* name)
{
  Double_array a = as_double_array(object, name);
  check_rows_of_3(a, name);
  const double* data = a.data();
  for(py::ssize_t i = 0; i < a.size(); ++i)
    if(!std::isfinite(data[i]))
      throw py::value_error(std::string(name) + " has a non-finite coordinate in row " +
                            std::to_string(i / 3));
  return a;
}

// A vector of three finite numbers.
inline std::vector<double> checked_vector3(const py::handle& object, const char* name)
{
  Double_array a = as_double_array(object, name);
  if(a.size() != 3 || a.ndim() > 2)
    throw py::value_error(std::string(name) + " must hold 3 numbers");
  std::vector<double> v(a.data(), a.data() + 3);
  for(double x : v)
    if(!std::isfinite(x))
      throw py::value_error(std::string(name) + " must be finite");
  return v;
}

// Vertex indices in [0, n), each once.
inline std::vector<std::size_t> checked_vertex_indices(const py::handle& object, std::size_t n,
                                                       const char* name)
{
  Index_array a = as_index_array(object, name);
  if(a.ndim() != 1)
    throw py::value_error(std::string(name) + " must be a 1-D array of vertex indices");
  std::vector<std::size_t> indices;
  indices.reserve(static_cast<std::size_t>(a.size()));
  std::vector<char> seen(n, 0);
  const std::int64_t* data = a.data();
  for(py::ssize_t i = 0; i < a.size(); ++i)
  {
    if(data[i] < 0 || static_cast<std::uint64_t>(data[i]) >= n)
      throw py::value_error(std::string(name) + "[" + std::to_string(i) + "] = " +
                            std::to_string(data[i]) + " is not a vertex index in [0, " +
                            std::to_string(n) + ")");
    const std::size_t v = static_cast<std::size_t>(data[i]);
    if(seen[v])
      throw py::value_error(std::string(name) + " lists vertex " + std::to_string(v) + " twice");
    seen[v] = 1;
    indices.push_back(v);
  }
  return indices;
}

// Builds the mesh with vertex i at row i of V. Refuses what
// CGAL::Surface_mesh cannot represent (an index out of range, a face that
// repeats a vertex, a non-manifold edge or vertex, a vertex of no face); the
// geometric checks (degenerate faces, ...) are the library's.
inline void fill_mesh(const py::handle& vertices, const py::handle& faces, Mesh& mesh)
{
  const Double_array V = checked_points(vertices, "V");
  if(V.shape(0) == 0)
    throw py::value_error("V has no vertex");
  const Index_array F = as_index_array(faces, "F");
  check_rows_of_3(F, "F");
  if(F.shape(0) == 0)
    throw py::value_error("F has no face");
  const std::size_t n = static_cast<std::size_t>(V.shape(0));
  const double* p = V.data();
  const std::int64_t* f = F.data();

  mesh.clear();
  mesh.reserve(static_cast<Mesh::size_type>(n), static_cast<Mesh::size_type>(3 * F.shape(0)),
               static_cast<Mesh::size_type>(F.shape(0)));
  for(std::size_t i = 0; i < n; ++i)
    mesh.add_vertex(Point(p[3 * i], p[3 * i + 1], p[3 * i + 2]));
  for(py::ssize_t j = 0; j < F.shape(0); ++j)
  {
    const std::int64_t* face = f + 3 * j;
    for(int k = 0; k < 3; ++k)
      if(face[k] < 0 || static_cast<std::uint64_t>(face[k]) >= n)
        throw py::value_error("F[" + std::to_string(j) + "] refers to vertex " + std::to_string(face[k]) +
                              ", not in [0, " + std::to_string(n) + ")");
    if(face[0] == face[1] || face[1] == face[2] || face[0] == face[2])
      throw py::value_error("F[" + std::to_string(j) + "] repeats a vertex");
    const Mesh::Face_index added =
        mesh.add_face(Vertex_index(static_cast<Mesh::size_type>(face[0])),
                      Vertex_index(static_cast<Mesh::size_type>(face[1])),
                      Vertex_index(static_cast<Mesh::size_type>(face[2])));
    if(added == Mesh::null_face())
      throw py::value_error("F[" + std::to_string(j) +
                            "] cannot be added: it makes an edge or a vertex non-manifold, or is "
                            "oriented against a neighbour");
  }
  for(Vertex_index v : mesh.vertices())
    if(mesh.is_isolated(v))
      throw py::value_error("vertex " + std::to_string(std::size_t(v)) +
                            " belongs to no face; remove the unreferenced vertices of V");
}

// The positions of the mesh as a new n x 3 array.
inline py::array_t<double> positions(const Mesh& mesh)
{
  py::array_t<double> result({static_cast<py::ssize_t>(mesh.number_of_vertices()), py::ssize_t(3)});
  double* out = result.mutable_data();
  for(Vertex_index v : mesh.vertices())
  {
    const Point& q = mesh.point(v);
    out[3 * std::size_t(v)] = q.x();
    out[3 * std::size_t(v) + 1] = q.y();
    out[3 * std::size_t(v) + 2] = q.z();
  }
  return result;
}

} // namespace ssmd_python

#endif // SSMD_PYTHON_NUMPY_MESH_H

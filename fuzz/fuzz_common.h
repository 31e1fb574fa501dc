// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Shared by the libFuzzer harnesses and the seed generator: the mesh type,
// the fixed mesh of the basis cache harness, bitwise comparison of
// positions, and the property check that aborts with a message.
#ifndef SSMD_FUZZ_COMMON_H
#define SSMD_FUZZ_COMMON_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace ssmd_fuzz {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef Mesh::Vertex_index Vertex;

/// Reports a violated property and stops: libFuzzer records the input.
[[noreturn]] inline void violation(const std::string& what)
{
  std::fprintf(stderr, "PROPERTY VIOLATED: %s\n", what.c_str());
  std::fflush(stderr);
  __builtin_trap();
}

inline void require(bool condition, const std::string& what)
{
  if(!condition)
    violation(what);
}

/// Equal bit for bit (so that NaN equals the same NaN, and -0 differs from 0).
inline bool same_point(const Point& a, const Point& b)
{
  const double x[3] = {a.x(), a.y(), a.z()}, y[3] = {b.x(), b.y(), b.z()};
  return std::memcmp(x, y, sizeof(x)) == 0;
}

inline bool finite_point(const Point& p)
{
  return std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z());
}

/// The positions of all vertex slots (removed ones included), by index.
inline std::vector<Point> positions(const Mesh& mesh)
{
  std::vector<Point> x;
  x.reserve(mesh.number_of_vertices() + mesh.number_of_removed_vertices());
  for(std::size_t i = 0; i < mesh.number_of_vertices() + mesh.number_of_removed_vertices(); ++i)
    x.push_back(mesh.point(Vertex(static_cast<Mesh::size_type>(i))));
  return x;
}

inline bool same_positions(const std::vector<Point>& a, const std::vector<Point>& b)
{
  if(a.size() != b.size())
    return false;
  for(std::size_t i = 0; i < a.size(); ++i)
    if(!same_point(a[i], b[i]))
      return false;
  return true;
}

/// The tiny mesh of the basis cache harness: a bumpy 4×4 grid (25 vertices,
/// 32 faces, an open boundary).
inline Mesh basis_fixture_mesh()
{
  Mesh mesh;
  const int cells = 4;
  std::vector<Vertex> v;
  for(int j = 0; j <= cells; ++j)
    for(int i = 0; i <= cells; ++i)
    {
      const double x = double(i) / cells, y = double(j) / cells;
      v.push_back(mesh.add_vertex(Point(x, y, 0.2 * x * (1 - x) * y * (1 - y) + 0.01 * ((i * 7 + j * 3) % 5))));
    }
  auto id = [&](int i, int j) { return v[static_cast<std::size_t>(j * (cells + 1) + i)]; };
  for(int j = 0; j < cells; ++j)
    for(int i = 0; i < cells; ++i)
    {
      mesh.add_face(id(i, j), id(i + 1, j), id(i + 1, j + 1));
      mesh.add_face(id(i, j), id(i + 1, j + 1), id(i, j + 1));
    }
  return mesh;
}

/// Number of frequencies of the basis of the fixture.
constexpr std::size_t basis_fixture_frequencies = 6;

/// Rewrites the trailing checksum of a basis file so that it matches the
/// bytes before it: lets the fuzzer reach the checks behind the checksum.
/// The checksum is the 64-bit FNV-1a of those bytes, as the manual's layout
/// of the basis file says; it is computed here from that description, not
/// with the package's writer, so that the fuzzer checks the reader against
/// the documented format.
inline void fix_basis_checksum(std::string& bytes)
{
  if(bytes.size() < sizeof(std::uint64_t))
    return;
  const std::size_t payload = bytes.size() - sizeof(std::uint64_t);
  std::uint64_t value = 1469598103934665603ull; // FNV-1a's offset basis
  for(std::size_t i = 0; i < payload; ++i)
  {
    value ^= static_cast<unsigned char>(bytes[i]);
    value *= 1099511628211ull; // FNV's 64-bit prime
  }
  std::memcpy(&bytes[payload], &value, sizeof(value));
}

} // namespace ssmd_fuzz

#endif // SSMD_FUZZ_COMMON_H

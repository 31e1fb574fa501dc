// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Small meshes generated in code for the tests: exact, quick to build, and
// independent of any file on disk.
#ifndef SSMD_TEST_MESHES_H
#define SSMD_TEST_MESHES_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>

#include <array>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

namespace test_meshes {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Surface_mesh;
typedef CGAL::Polyhedron_3<Kernel> Polyhedron;

struct Soup
{
  std::vector<Point> points;
  std::vector<std::array<std::size_t, 3>> triangles;
};

template <class Mesh>
Mesh to_mesh(const Soup& soup)
{
  Mesh mesh;
  std::vector<std::vector<std::size_t>> polygons;
  for(const auto& t : soup.triangles)
    polygons.push_back({t[0], t[1], t[2]});
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(soup.points, polygons, mesh);
  return mesh;
}

/// Icosahedron subdivided `levels` times, vertices projected on the sphere of
/// radius `radius` (10·4^levels + 2 vertices).
inline Soup icosphere(int levels, double radius = 1.0)
{
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<std::array<double, 3>> p = {{-1, t, 0}, {1, t, 0},   {-1, -t, 0}, {1, -t, 0},
                                          {0, -1, t}, {0, 1, t},   {0, -1, -t}, {0, 1, -t},
                                          {t, 0, -1}, {t, 0, 1},   {-t, 0, -1}, {-t, 0, 1}};
  std::vector<std::array<std::size_t, 3>> f = {
      {0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
      {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
      {3, 8, 9},  {4, 9, 5},  {2, 4, 11},  {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  auto normalize = [](std::array<double, 3>& q) {
    const double l = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]);
    for(double& c : q)
      c /= l;
  };
  for(auto& q : p)
    normalize(q);
  for(int level = 0; level < levels; ++level)
  {
    std::map<std::pair<std::size_t, std::size_t>, std::size_t> midpoints;
    auto midpoint = [&](std::size_t a, std::size_t b) {
      const auto key = std::make_pair((std::min)(a, b), (std::max)(a, b));
      auto it = midpoints.find(key);
      if(it != midpoints.end())
        return it->second;
      std::array<double, 3> q = {(p[a][0] + p[b][0]) / 2, (p[a][1] + p[b][1]) / 2,
                                 (p[a][2] + p[b][2]) / 2};
      normalize(q);
      p.push_back(q);
      midpoints[key] = p.size() - 1;
      return p.size() - 1;
    };
    std::vector<std::array<std::size_t, 3>> refined;
    for(const auto& tri : f)
    {
      const std::size_t ab = midpoint(tri[0], tri[1]), bc = midpoint(tri[1], tri[2]),
                        ca = midpoint(tri[2], tri[0]);
      refined.push_back({tri[0], ab, ca});
      refined.push_back({tri[1], bc, ab});
      refined.push_back({tri[2], ca, bc});
      refined.push_back({ab, bc, ca});
    }
    f.swap(refined);
  }
  Soup soup;
  for(const auto& q : p)
    soup.points.emplace_back(radius * q[0], radius * q[1], radius * q[2]);
  soup.triangles = f;
  return soup;
}

/// A closed cylinder along z of radius `radius` and length `length`:
/// `rings` + 1 rings of 4·`per_side` vertices, capped with fans at both ends.
inline Soup bar(int rings = 20, int per_side = 3, double radius = 0.5, double length = 5.0)
{
  Soup soup;
  const int ring_size = 4 * per_side;
  const double pi = 3.14159265358979323846;
  auto ring_point = [&](int k) {
    const double angle = 2 * pi * k / ring_size;
    return std::array<double, 2>{radius * std::cos(angle), radius * std::sin(angle)};
  };
  for(int r = 0; r <= rings; ++r)
    for(int k = 0; k < ring_size; ++k)
    {
      const auto q = ring_point(k);
      soup.points.emplace_back(q[0], q[1], length * r / rings);
    }
  auto id = [&](int r, int k) { return std::size_t(r * ring_size + (k % ring_size)); };
  for(int r = 0; r < rings; ++r)
    for(int k = 0; k < ring_size; ++k)
    {
      // Alternating diagonals: a triangulation with all diagonals along one
      // helix direction is anisotropic and biases twists.
      if((r + k) % 2 == 0)
      {
        soup.triangles.push_back({id(r, k), id(r, k + 1), id(r + 1, k + 1)});
        soup.triangles.push_back({id(r, k), id(r + 1, k + 1), id(r + 1, k)});
      }
      else
      {
        soup.triangles.push_back({id(r, k), id(r, k + 1), id(r + 1, k)});
        soup.triangles.push_back({id(r, k + 1), id(r + 1, k + 1), id(r + 1, k)});
      }
    }
  const std::size_t bottom = soup.points.size();
  soup.points.emplace_back(0, 0, 0);
  const std::size_t top = soup.points.size();
  soup.points.emplace_back(0, 0, length);
  for(int k = 0; k < ring_size; ++k)
  {
    soup.triangles.push_back({bottom, id(0, k + 1), id(0, k)});
    soup.triangles.push_back({top, id(rings, k), id(rings, k + 1)});
  }
  return soup;
}

/// A square grid on [0,1]² with `cells`×`cells` cells and a smooth bump
/// z = amplitude·sin(πx)sin(πy)·(1 + 0.3 cos(6πx)): an open surface with a boundary.
inline Soup bumpy_plane(int cells = 20, double amplitude = 0.2)
{
  Soup soup;
  const double pi = 3.14159265358979323846;
  for(int j = 0; j <= cells; ++j)
    for(int i = 0; i <= cells; ++i)
    {
      const double x = double(i) / cells, y = double(j) / cells;
      soup.points.emplace_back(
          x, y, amplitude * std::sin(pi * x) * std::sin(pi * y) * (1 + 0.3 * std::cos(6 * pi * x)));
    }
  auto id = [&](int i, int j) { return std::size_t(j * (cells + 1) + i); };
  for(int j = 0; j < cells; ++j)
    for(int i = 0; i < cells; ++i)
    {
      soup.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      soup.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return soup;
}

/// Two disjoint icospheres of radius 1, centred at the origin and at (3, 0, 0).
inline Soup two_spheres(int levels = 2)
{
  Soup a = icosphere(levels), b = icosphere(levels);
  const std::size_t offset = a.points.size();
  for(const Point& q : b.points)
    a.points.emplace_back(q.x() + 3.0, q.y(), q.z());
  for(const auto& t : b.triangles)
    a.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  return a;
}

/// The interior edges whose two face normals make less than 89° in `rest`
/// and more than 90° in `deformed` (same connectivity): the folded pairs of
/// `benchmark/quality`. Right-angled edges of the input (the rims of a
/// capped bar) are at 90° to rounding, which contracted multiply-adds
/// (`-march=native`) round to either side, hence 89° at rest.
inline std::size_t folded_pairs(const Surface_mesh& rest, const Surface_mesh& deformed)
{
  auto normal = [](const Surface_mesh& mesh, Surface_mesh::Face_index face) {
    const auto h = mesh.halfedge(face);
    const Point& p = mesh.point(mesh.source(h));
    return CGAL::cross_product(mesh.point(mesh.target(h)) - p, mesh.point(mesh.target(mesh.next(h))) - p);
  };
  const double cos89 = std::cos(89.0 * 3.14159265358979323846 / 180.0);
  std::size_t folded = 0;
  for(auto e : deformed.edges())
  {
    if(deformed.is_border(e))
      continue;
    const auto h = deformed.halfedge(e);
    const auto f = deformed.face(h), g = deformed.face(deformed.opposite(h));
    const Kernel::Vector_3 nf = normal(rest, f), ng = normal(rest, g);
    if(nf * ng > cos89 * std::sqrt(nf.squared_length() * ng.squared_length()) &&
       normal(deformed, f) * normal(deformed, g) < 0)
      ++folded;
  }
  return folded;
}

} // namespace test_meshes

#endif // SSMD_TEST_MESHES_H

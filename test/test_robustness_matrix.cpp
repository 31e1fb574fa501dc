// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
// The robustness matrix of doc/robustness.md: the rows that the other test
// files do not cover. Every case asserts a clear error (exception code or
// report message) or the documented behaviour, the mesh untouched on failure
// (all coordinates compared) and no non-finite coordinate.
#include "test_meshes.h"

#include <CGAL/Manifold_harmonics_basis.h>
#include <CGAL/Spectral_surface_mesh_deformation.h>
#include <CGAL/Spectral_deformation/IO/deformation_selection.h>

#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>

#include <catch2/catch.hpp>

#include <cstdio>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>
#include <streambuf>

using namespace test_meshes;
typedef CGAL::Spectral_surface_mesh_deformation<Surface_mesh> Spectral;
typedef CGAL::Spectral_surface_mesh_deformation<Surface_mesh, CGAL::Default, CGAL::Default,
                                                CGAL::SPATIAL_DUAL_LAPLACIAN>
    Spatial;
typedef CGAL::Manifold_harmonics_basis<Surface_mesh> Basis;
typedef CGAL::Spectral_deformation_error Error;
typedef Surface_mesh::Vertex_index Vertex;

namespace {

// All coordinates, including those of removed vertex slots.
Eigen::MatrixXd coordinates(const Surface_mesh& mesh)
{
  const std::size_t slots = mesh.number_of_vertices() + mesh.number_of_removed_vertices();
  Eigen::MatrixXd x(slots, 3);
  for(std::size_t i = 0; i < slots; ++i)
  {
    const Point& p = mesh.point(Vertex(static_cast<Surface_mesh::size_type>(i)));
    x.row(static_cast<Eigen::Index>(i)) << p.x(), p.y(), p.z();
  }
  return x;
}

// Bit-for-bit equality, so that a NaN equals itself.
bool identical(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b)
{
  return a.rows() == b.rows() && a.cols() == b.cols() &&
         std::memcmp(a.data(), b.data(), sizeof(double) * static_cast<std::size_t>(a.size())) == 0;
}

std::vector<Vertex> vertex_list(const Surface_mesh& mesh)
{
  return std::vector<Vertex>(mesh.vertices().begin(), mesh.vertices().end());
}

template <class E>
Error::Code error_code_of(E&& f)
{
  try
  {
    f();
  }
  catch(const Error& e)
  {
    return e.code();
  }
  FAIL("no Spectral_deformation_error thrown");
  return Error::INVALID_ARGUMENT;
}

// The outcome of a deform() on `mesh`: success, or a message and the mesh
// untouched; never a non-finite coordinate that was not in the input.
template <class Deformation>
bool deform_checked(Deformation& deformation, Surface_mesh& mesh)
{
  const Eigen::MatrixXd before = coordinates(mesh);
  deformation.deform();
  const Eigen::MatrixXd after = coordinates(mesh);
  INFO(deformation.deform_report().message);
  if(!deformation.deform_report().success)
  {
    CHECK_FALSE(deformation.deform_report().message.empty());
    CHECK(identical(after, before));
    return false;
  }
  if(before.allFinite())
    CHECK(after.allFinite());
  for(Vertex v : deformation.roi_vertices())
    CHECK(after.row(v.idx()).allFinite());
  return true;
}

// A 2 by `cells` strip of the bumpy plane: ROI = x > 0.3, controls x > 0.9.
template <class Deformation>
void select_right_side(Deformation& deformation, const Surface_mesh& mesh, double shift = 0.2)
{
  for(Vertex v : mesh.vertices())
  {
    if(mesh.point(v).x() > 0.3)
      deformation.insert_roi_vertex(v);
    if(mesh.point(v).x() > 0.9)
      deformation.insert_control_vertex(v);
  }
  for(Vertex v : mesh.vertices())
    if(deformation.is_control_vertex(v))
      deformation.translate(v, Eigen::Vector3d(0, 0, shift));
}

// A stream buffer that cannot seek, as a pipe.
class Unseekable_buffer : public std::streambuf
{
public:
  explicit Unseekable_buffer(const std::string& bytes) : m_bytes(bytes)
  {
    char* begin = &m_bytes[0];
    setg(begin, begin, begin + m_bytes.size());
  }

private:
  std::string m_bytes;
};

} // namespace

TEST_CASE("matrix: non-triangle faces are refused by the deformation", "[robustness][matrix]")
{
  // A triangulated strip with one quad far from the ROI: the mesh is not a
  // triangle mesh, preprocess() says so and nothing moves.
  Surface_mesh mesh = to_mesh<Surface_mesh>(bumpy_plane(6));
  const auto a = mesh.add_vertex(Point(5, 0, 0)), b = mesh.add_vertex(Point(6, 0, 0)),
             c = mesh.add_vertex(Point(6, 1, 0)), d = mesh.add_vertex(Point(5, 1, 0));
  REQUIRE(mesh.add_face(a, b, c, d) != Surface_mesh::null_face());
  for(auto* deformation_tag : {"spectral", "spatial"})
  {
    INFO(deformation_tag);
    const Eigen::MatrixXd before = coordinates(mesh);
    auto run = [&](auto& deformation) {
      select_right_side(deformation, mesh);
      CHECK_FALSE(deformation.preprocess());
      CHECK(deformation.preprocess_report().message.find("triangulated") != std::string::npos);
      CHECK_FALSE(deform_checked(deformation, mesh));
    };
    if(std::strcmp(deformation_tag, "spectral") == 0)
    {
      Spectral deformation(mesh);
      run(deformation);
    }
    else
    {
      Spatial deformation(mesh);
      run(deformation);
    }
    CHECK(identical(coordinates(mesh), before));
  }
}

TEST_CASE("matrix: a non-manifold polygon soup is refused by CGAL's reader and repaired by "
          "Polygon_mesh_processing",
          "[robustness][matrix]")
{
  // A book of three pages on a common spine: the spine edges have three
  // faces. Also a duplicated point, a degenerate polygon and an unused point.
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> polygons;
  const int rows = 4, columns = 4;
  const double pi = 3.14159265358979323846;
  for(int j = 0; j <= rows; ++j)
    points.emplace_back(0, double(j) / rows, 0); // spine
  for(int page = 0; page < 3; ++page)
  {
    const double angle = 2 * pi * page / 3;
    const std::size_t first = points.size();
    for(int i = 1; i <= columns; ++i)
      for(int j = 0; j <= rows; ++j)
        points.emplace_back(std::cos(angle) * i / columns, double(j) / rows,
                            std::sin(angle) * i / columns + 0.02 * ((i + j) % 2));
    auto id = [&](int i, int j) {
      return i == 0 ? std::size_t(j) : first + std::size_t((i - 1) * (rows + 1) + j);
    };
    for(int i = 0; i < columns; ++i)
      for(int j = 0; j < rows; ++j)
      {
        polygons.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
        polygons.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
      }
  }
  points.push_back(points[6]);                    // duplicate of a point of the first page
  polygons.push_back({0, points.size() - 1, 1});  // ... in a duplicate of the face (0, 6, 1)
  polygons.push_back({2, 2, 7});                  // degenerate polygon
  points.emplace_back(9, 9, 9);                   // unused point
  const std::string filename = "robustness_matrix_book.off";
  REQUIRE(CGAL::IO::write_polygon_soup(filename, points, polygons));

  // CGAL's reader into a FaceGraph refuses it.
  Surface_mesh strict;
  CHECK_FALSE(CGAL::IO::read_polygon_mesh(filename, strict));

  // The repair: read the soup, merge duplicates and drop degenerate
  // polygons, orient (vertices on non-manifold edges are duplicated), convert.
  std::vector<Point> soup_points;
  std::vector<std::vector<std::size_t>> soup_polygons;
  REQUIRE(CGAL::IO::read_polygon_soup(filename, soup_points, soup_polygons));
  std::remove(filename.c_str());
  namespace PMP = CGAL::Polygon_mesh_processing;
  PMP::repair_polygon_soup(soup_points, soup_polygons);
  PMP::orient_polygon_soup(soup_points, soup_polygons); // false: points were duplicated
  REQUIRE(PMP::is_polygon_soup_a_polygon_mesh(soup_polygons));
  Surface_mesh mesh;
  PMP::polygon_soup_to_polygon_mesh(soup_points, soup_polygons, mesh);
  REQUIRE(CGAL::is_valid_polygon_mesh(mesh));
  CHECK(mesh.number_of_faces() == 3 * 2 * rows * columns);

  // The package accepts the result: deform the first page at its free edge.
  Spectral deformation(mesh);
  for(Vertex v : mesh.vertices())
  {
    const Point& p = mesh.point(v);
    if(p.x() > 0.3 && std::abs(p.z()) < 0.1)
      deformation.insert_roi_vertex(v);
    if(p.x() > 0.9 && std::abs(p.z()) < 0.1)
    {
      deformation.insert_control_vertex(v);
      deformation.translate(v, Eigen::Vector3d(0, 0, 0.3));
    }
  }
  const Eigen::MatrixXd before = coordinates(mesh);
  REQUIRE(deform_checked(deformation, mesh));
  const Eigen::MatrixXd after = coordinates(mesh);
  for(Vertex v : mesh.vertices())
    if(!deformation.is_roi_vertex(v))
      CHECK(identical(after.row(v.idx()), before.row(v.idx())));
}

TEST_CASE("matrix: a non-manifold vertex in the region", "[robustness][matrix]")
{
  // Two triangle fans that touch at one vertex (a bow tie): a valid
  // Surface_mesh, with a vertex that is not a manifold vertex.
  Surface_mesh mesh;
  const auto centre = mesh.add_vertex(Point(0, 0, 0));
  std::vector<Vertex> left, right;
  for(int k = 0; k < 4; ++k)
  {
    left.push_back(mesh.add_vertex(Point(-1, -0.6 + 0.4 * k, 0.05 * k)));
    right.push_back(mesh.add_vertex(Point(1, -0.6 + 0.4 * k, 0.05 * (k % 2))));
  }
  for(int k = 0; k < 3; ++k)
  {
    REQUIRE(mesh.add_face(centre, left[k + 1], left[k]) != Surface_mesh::null_face());
    REQUIRE(mesh.add_face(centre, right[k], right[k + 1]) != Surface_mesh::null_face());
  }
  Spectral deformation(mesh);
  deformation.insert_roi_vertex(centre);
  deformation.insert_roi_vertices(right.begin(), right.end());
  deformation.insert_control_vertex(right[0]);
  deformation.insert_control_vertex(right[3]);
  deformation.translate(right[3], Eigen::Vector3d(0, 0, 0.2));
  // Either outcome is acceptable; neither may corrupt the mesh.
  deform_checked(deformation, mesh);
}

TEST_CASE("matrix: needle faces", "[robustness][matrix]")
{
  // A triangle (a, b, c) of the ROI split in three at a point e close to its
  // edge ab: (a, b, e) is a needle. Of relative height 1e-7 it is a valid
  // face (finite result); of relative height 1e-14 it is degenerate (refused
  // with a message).
  for(double height : {1e-7, 1e-14})
  {
    INFO("relative height " << height);
    Soup soup = bumpy_plane(8);
    const std::size_t face = 2 * (4 * 8 + 5); // in the cell (5, 4), x in [0.625, 0.75]
    const auto t = soup.triangles[face];
    const Point& a = soup.points[t[0]];
    const Point& b = soup.points[t[1]];
    const Point& c = soup.points[t[2]];
    const Point middle = CGAL::midpoint(a, b);
    soup.points.push_back(middle + height * (c - middle));
    const std::size_t e = soup.points.size() - 1;
    soup.triangles[face] = {t[0], t[1], e};
    soup.triangles.push_back({t[1], t[2], e});
    soup.triangles.push_back({t[2], t[0], e});
    Surface_mesh mesh = to_mesh<Surface_mesh>(soup);
    Spectral deformation(mesh);
    select_right_side(deformation, mesh);
    const bool accepted = deformation.preprocess();
    if(height < 1e-12)
    {
      CHECK_FALSE(accepted);
      CHECK(deformation.preprocess_report().message.find("degenerate") != std::string::npos);
    }
    const bool deformed = deform_checked(deformation, mesh);
    CHECK(deformed == accepted);
  }
}

TEST_CASE("matrix: duplicate and isolated vertices", "[robustness][matrix]")
{
  SECTION("an isolated vertex in the ROI is ignored and never moves")
  {
    Surface_mesh mesh = to_mesh<Surface_mesh>(bumpy_plane(6));
    const Vertex isolated = mesh.add_vertex(Point(0.5, 0.5, 3));
    Spectral deformation(mesh);
    select_right_side(deformation, mesh);
    deformation.insert_roi_vertex(isolated);
    const Point before = mesh.point(isolated);
    REQUIRE(deform_checked(deformation, mesh));
    CHECK(mesh.point(isolated) == before);
  }
  SECTION("an isolated control vertex among others: its target cannot be met, a clear failure")
  {
    Surface_mesh mesh = to_mesh<Surface_mesh>(bumpy_plane(6));
    const Vertex isolated = mesh.add_vertex(Point(0.5, 0.5, 3));
    Spectral deformation(mesh);
    select_right_side(deformation, mesh);
    deformation.insert_control_vertex(isolated);
    deformation.translate(isolated, Eigen::Vector3d(1, 0, 0));
    CHECK_FALSE(deform_checked(deformation, mesh)); // the mesh untouched
    CHECK(deformation.preprocess_report().message.find("control vertex " + std::to_string(isolated.idx()) +
                                                       " belongs to no face") != std::string::npos);
    deformation.erase_control_vertex(isolated);
    CHECK(deform_checked(deformation, mesh));
  }
  SECTION("an isolated vertex as the only ROI vertex: no face, a clear failure")
  {
    Surface_mesh mesh = to_mesh<Surface_mesh>(bumpy_plane(4));
    const Vertex isolated = mesh.add_vertex(Point(0.5, 0.5, 3));
    Spectral deformation(mesh);
    deformation.insert_control_vertex(isolated);
    deformation.translate(isolated, Eigen::Vector3d(1, 0, 0));
    CHECK_FALSE(deform_checked(deformation, mesh));
    CHECK(deformation.preprocess_report().message.find("no face") != std::string::npos);
  }
  SECTION("duplicate vertices along a seam: the two sides are boundaries, the result is finite")
  {
    // The strip is cut along x = 0.5: the faces on the right use copies of
    // the vertices of the cut.
    Soup soup = bumpy_plane(6);
    std::map<std::size_t, std::size_t> copy;
    for(auto& t : soup.triangles)
    {
      const double centre_x =
          (soup.points[t[0]].x() + soup.points[t[1]].x() + soup.points[t[2]].x()) / 3;
      if(centre_x < 0.5)
        continue;
      for(std::size_t& i : t)
        if(std::abs(soup.points[i].x() - 0.5) < 1e-12)
        {
          if(!copy.count(i))
          {
            copy[i] = soup.points.size();
            soup.points.push_back(soup.points[i]);
          }
          i = copy[i];
        }
    }
    Surface_mesh mesh = to_mesh<Surface_mesh>(soup);
    REQUIRE(mesh.number_of_vertices() == 7 * 7 + 7);
    Spectral deformation(mesh);
    select_right_side(deformation, mesh);
    REQUIRE(deform_checked(deformation, mesh));
  }
}

TEST_CASE("matrix: a connected component outside the ROI is untouched", "[robustness][matrix]")
{
  Surface_mesh mesh = to_mesh<Surface_mesh>(two_spheres(1));
  const Eigen::MatrixXd before = coordinates(mesh);
  for(int algorithm = 0; algorithm < 2; ++algorithm)
  {
    Surface_mesh copy = mesh;
    auto run = [&](auto& deformation) {
      Vertex top;
      for(Vertex v : copy.vertices())
        if(copy.point(v).x() < 1.5 && copy.point(v).z() > 0.0)
        {
          deformation.insert_roi_vertex(v);
          if(top == Vertex() || copy.point(v).z() > copy.point(top).z())
            top = v;
        }
      deformation.insert_control_vertex(top);
      deformation.translate(top, Eigen::Vector3d(0, 0, 0.3));
      REQUIRE(deform_checked(deformation, copy));
    };
    if(algorithm == 0)
    {
      Spectral deformation(copy);
      run(deformation);
    }
    else
    {
      Spatial deformation(copy);
      run(deformation);
    }
    const Eigen::MatrixXd after = coordinates(copy);
    for(Eigen::Index i = 0; i < after.rows(); ++i)
      if(before(i, 0) > 1.5)
        CHECK(identical(after.row(i), before.row(i)));
  }
}

TEST_CASE("matrix: holes and boundaries in the ROI", "[robustness][matrix]")
{
  // A bumpy plane with a square hole in the middle of the ROI.
  Soup soup = bumpy_plane(10);
  std::vector<std::array<std::size_t, 3>> kept;
  for(const auto& t : soup.triangles)
  {
    double x = 0, y = 0;
    for(std::size_t i : t)
    {
      x += soup.points[i].x() / 3;
      y += soup.points[i].y() / 3;
    }
    if(!(x > 0.5 && x < 0.75 && y > 0.35 && y < 0.65))
      kept.push_back(t);
  }
  REQUIRE(kept.size() < soup.triangles.size());
  soup.triangles = kept;
  Surface_mesh mesh = to_mesh<Surface_mesh>(soup);
  for(auto policy : {CGAL::EXACT_CONSTRAINTS, CGAL::SOFT_CONSTRAINTS})
  {
    Surface_mesh copy = mesh;
    Spectral deformation(copy);
    deformation.set_constraint_policy(policy);
    select_right_side(deformation, copy);
    REQUIRE(deform_checked(deformation, copy));
    CHECK(deformation.deform_report().max_control_residual < 0.05);
  }
  Surface_mesh copy = mesh;
  Spatial spatial(copy);
  select_right_side(spatial, copy);
  REQUIRE(deform_checked(spatial, copy));
}

TEST_CASE("matrix: infinite coordinates and huge targets", "[robustness][matrix]")
{
  SECTION("an infinite coordinate outside the region does not matter")
  {
    Surface_mesh mesh = to_mesh<Surface_mesh>(bumpy_plane(6));
    const Vertex far = mesh.add_vertex(Point(-5, 0, std::numeric_limits<double>::infinity()));
    const Vertex b = mesh.add_vertex(Point(-6, 0, 0)), c = mesh.add_vertex(Point(-6, 1, 0));
    mesh.add_face(far, b, c); // degenerate too, but outside the region
    Spectral deformation(mesh);
    select_right_side(deformation, mesh);
    REQUIRE(deform_checked(deformation, mesh));
    CHECK(std::isinf(mesh.point(far).z()));
  }
  SECTION("an infinite coordinate in the region: a clear failure")
  {
    Surface_mesh mesh = to_mesh<Surface_mesh>(bumpy_plane(6));
    const auto all = vertex_list(mesh);
    const Point p = mesh.point(all[3 * 7 + 4]); // x = 2/3: in the ROI, not a control vertex
    mesh.point(all[3 * 7 + 4]) = Point(p.x(), p.y(), -std::numeric_limits<double>::infinity());
    Spatial deformation(mesh);
    select_right_side(deformation, mesh);
    CHECK_FALSE(deform_checked(deformation, mesh));
    CHECK(deformation.preprocess_report().message.find("non-finite") != std::string::npos);
  }
  SECTION("huge finite targets: a failure or a finite result")
  {
    for(double shift : {1e150, 1e300})
      for(int algorithm = 0; algorithm < 2; ++algorithm)
      {
        INFO("shift " << shift << ", algorithm " << algorithm);
        Surface_mesh mesh = to_mesh<Surface_mesh>(bumpy_plane(6));
        if(algorithm == 0)
        {
          Spectral deformation(mesh);
          select_right_side(deformation, mesh, shift);
          deform_checked(deformation, mesh);
        }
        else
        {
          Spatial deformation(mesh);
          select_right_side(deformation, mesh, shift);
          deform_checked(deformation, mesh);
        }
        CHECK(coordinates(mesh).allFinite());
      }
  }
}

TEST_CASE("matrix: control vertices outside the ROI, erased, or removed from the mesh",
          "[robustness][matrix]")
{
  Surface_mesh mesh = to_mesh<Surface_mesh>(bumpy_plane(6));
  const auto all = vertex_list(mesh);
  SECTION("a control vertex is always a ROI vertex")
  {
    Spectral deformation(mesh);
    CHECK(deformation.insert_control_vertex(all[3]));
    CHECK(deformation.is_roi_vertex(all[3]));
    CHECK(deformation.erase_roi_vertex(all[3]));
    CHECK_FALSE(deformation.is_control_vertex(all[3]));
  }
  SECTION("an erased control vertex is a free ROI vertex; its target is ignored")
  {
    Spectral deformation(mesh);
    select_right_side(deformation, mesh);
    const Vertex corner = all.back();
    REQUIRE(deformation.is_control_vertex(corner));
    CHECK(deformation.erase_control_vertex(corner));
    deformation.set_target_position(corner, Point(100, 100, 100)); // not a control vertex: ignored
    CHECK_FALSE(deformation.is_control_vertex(corner));
    REQUIRE(deform_checked(deformation, mesh));
    CHECK(CGAL::squared_distance(mesh.point(corner), Point(100, 100, 100)) > 1e4);
  }
  SECTION("a removed, not collected, vertex is refused; the others work")
  {
    Surface_mesh garbage = mesh;
    const Vertex removed = garbage.add_vertex(Point(3, 3, 3));
    garbage.add_vertex(Point(-4, 4, 4)); // isolated, after the removed one, outside the selection
    garbage.remove_vertex(removed);
    REQUIRE(garbage.has_garbage());
    Spectral deformation(garbage);
    CHECK(error_code_of([&] { deformation.insert_control_vertex(removed); }) == Error::INVALID_ARGUMENT);
    CHECK(error_code_of([&] { deformation.insert_roi_vertex(removed); }) == Error::INVALID_ARGUMENT);
    CHECK_FALSE(deformation.is_roi_vertex(removed));
    select_right_side(deformation, garbage);
    REQUIRE(deform_checked(deformation, garbage));
  }
}

TEST_CASE("matrix: tiny meshes with the spatial and the linear algorithms", "[robustness][matrix]")
{
  // The spatial system of a single triangle has no dual Laplacian row: its
  // free block is zero, which must be a clear failure (CHOLMOD's wrapper
  // crashed on it).
  typedef CGAL::Spectral_surface_mesh_deformation<Surface_mesh, CGAL::Default, CGAL::Default,
                                                  CGAL::SPECTRAL_LINEAR>
      Linear;
  for(int shape = 0; shape < 2; ++shape)
    for(int algorithm = 0; algorithm < 2; ++algorithm)
    {
      INFO("shape " << shape << ", algorithm " << algorithm);
      Surface_mesh mesh;
      if(shape == 0)
        mesh.add_face(mesh.add_vertex(Point(0, 0, 0)), mesh.add_vertex(Point(1, 0, 0)),
                      mesh.add_vertex(Point(0, 1, 0)));
      else
        CGAL::make_tetrahedron(Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(0, 0, 1), mesh);
      const auto all = vertex_list(mesh);
      auto run = [&](auto& deformation) {
        deformation.insert_roi_vertices(all.begin(), all.end());
        deformation.insert_control_vertex(all[0]);
        deformation.translate(all[0], Eigen::Vector3d(0, 0, 0.5));
        deform_checked(deformation, mesh);
      };
      if(algorithm == 0)
      {
        Spatial deformation(mesh);
        run(deformation);
      }
      else
      {
        Linear deformation(mesh);
        run(deformation);
      }
    }
}

TEST_CASE("matrix: deform() without preprocess() preprocesses", "[robustness][matrix]")
{
  Surface_mesh a = to_mesh<Surface_mesh>(bumpy_plane(6)), b = a;
  Spectral first(a), second(b);
  select_right_side(first, a);
  select_right_side(second, b);
  REQUIRE(second.preprocess());
  REQUIRE(deform_checked(first, a));
  REQUIRE(deform_checked(second, b));
  CHECK(first.preprocess_report().region_rebuilt);
  CHECK(identical(coordinates(a), coordinates(b)));
}

TEST_CASE("matrix: basis files with a huge header or from a stream that cannot seek",
          "[robustness][matrix][io]")
{
  const Surface_mesh mesh = to_mesh<Surface_mesh>(bumpy_plane(4));
  const Basis basis(mesh, 5);
  std::ostringstream out;
  basis.save(out);
  const std::string bytes = out.str();
  // The header claims 2^30 vertices (offset 12: after the tag and the version).
  std::string huge = bytes;
  const std::uint64_t n = std::uint64_t(1) << 30;
  std::memcpy(&huge[12], &n, sizeof(n));
  Basis loaded;
  const std::string* const files[] = {&huge, &bytes};
  for(const std::string* file : files)
    for(bool seekable : {true, false})
    {
      INFO("huge " << (file == &huge) << ", seekable " << seekable);
      std::istringstream seekable_stream(*file);
      Unseekable_buffer buffer(*file);
      std::istream unseekable_stream(&buffer);
      std::istream& is = seekable ? static_cast<std::istream&>(seekable_stream) : unseekable_stream;
      if(file == &huge)
      {
        // Refused as truncated, without allocating gigabytes first.
        CHECK(error_code_of([&] { loaded.load(is, mesh); }) == Error::IO_ERROR);
        CHECK(loaded.empty());
      }
      else
      {
        loaded.load(is, mesh);
        CHECK(loaded.basis() == basis.basis());
      }
    }
  // The same through the deformation class, and a truncated file.
  Surface_mesh copy = mesh;
  Spectral deformation(copy);
  const auto all = vertex_list(copy);
  deformation.insert_roi_vertices(all.begin(), all.end());
  deformation.insert_control_vertex(all.front());
  for(const std::string& file : {huge, bytes.substr(0, bytes.size() - 9)})
  {
    std::istringstream is(file);
    CHECK(error_code_of([&] { deformation.load_basis(is); }) == Error::IO_ERROR);
  }
  const Eigen::MatrixXd before = coordinates(copy);
  CHECK(deformation.preprocess());
  CHECK(deformation.preprocess_report().basis_computed);
  CHECK(identical(coordinates(copy), before));
}

// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Bad and unusual input for the deformation class: every case gets a clear
// error or a documented behaviour, leaves the mesh untouched on failure and
// never produces non-finite coordinates.
#include "test_meshes.h"

#include <CGAL/Spectral_surface_mesh_deformation.h>

#include <catch2/catch.hpp>

#include <limits>

using namespace test_meshes;
typedef CGAL::Spectral_surface_mesh_deformation<Surface_mesh> Spectral;
typedef CGAL::Spectral_surface_mesh_deformation<Surface_mesh, CGAL::Default, CGAL::Default,
                                                CGAL::SPATIAL_DUAL_LAPLACIAN>
    Spatial;
typedef CGAL::Spectral_deformation_error Error;

namespace {

Eigen::MatrixXd positions_of(const Surface_mesh& mesh)
{
  Eigen::MatrixXd x(mesh.number_of_vertices(), 3);
  for(auto v : mesh.vertices())
    x.row(v.idx()) << mesh.point(v).x(), mesh.point(v).y(), mesh.point(v).z();
  return x;
}

Soup scaled(Soup soup, double scale, double offset)
{
  for(Point& p : soup.points)
    p = Point(scale * p.x() + offset, scale * p.y() - offset, scale * p.z() + 0.5 * offset);
  return soup;
}

// Lifts the top of a cylinder with the bottom fixed by the ROI border, and
// returns the deformed positions mapped back to the unit scale.
template <class Deformation>
Eigen::MatrixXd lift_top(double scale, double offset)
{
  Surface_mesh mesh = to_mesh<Surface_mesh>(scaled(bar(16, 3), scale, offset));
  Deformation deformation(mesh);
  for(auto v : mesh.vertices())
  {
    const double z = (mesh.point(v).z() - 0.5 * offset) / scale;
    if(z > 1.0)
      deformation.insert_roi_vertex(v);
    if(z > 4.7)
      deformation.insert_control_vertex(v);
  }
  for(auto v : mesh.vertices())
    if(deformation.is_control_vertex(v))
      deformation.translate(v, Eigen::Vector3d(0.8 * scale, 0, 0));
  deformation.deform();
  REQUIRE(deformation.deform_report().success);
  Eigen::MatrixXd x = positions_of(mesh);
  x.col(0).array() -= offset;
  x.col(1).array() += offset;
  x.col(2).array() -= 0.5 * offset;
  return x / scale;
}

} // namespace

TEST_CASE("results are invariant under scaling and translation of the input", "[robustness]")
{
  const Eigen::MatrixXd reference = lift_top<Spectral>(1.0, 0.0);
  for(const auto& [scale, offset] : {std::pair<double, double>{1e-8, 1e-8}, {1e8, 1e8}, {1.0, 1e5}})
  {
    INFO("scale " << scale << ", offset " << offset);
    const Eigen::MatrixXd x = lift_top<Spectral>(scale, offset);
    CHECK(x.allFinite());
    CHECK((x - reference).cwiseAbs().maxCoeff() < 1e-6);
  }
  const Eigen::MatrixXd spatial = lift_top<Spatial>(1.0, 0.0);
  CHECK((lift_top<Spatial>(1e8, 1e8) - spatial).cwiseAbs().maxCoeff() < 1e-6);
}

TEST_CASE("vertices that are not in the mesh are refused", "[robustness]")
{
  Surface_mesh mesh = to_mesh<Surface_mesh>(bar(6, 2));
  Spectral deformation(mesh);
  const Surface_mesh::Vertex_index invalid;                 // the null vertex
  const Surface_mesh::Vertex_index beyond(static_cast<unsigned int>(mesh.number_of_vertices() + 7));
  for(auto v : {invalid, beyond})
  {
    CHECK_THROWS_AS(deformation.insert_roi_vertex(v), Error);
    CHECK_THROWS_AS(deformation.insert_control_vertex(v), Error);
    CHECK_FALSE(deformation.is_roi_vertex(v));
    CHECK_FALSE(deformation.is_control_vertex(v));
    CHECK_FALSE(deformation.erase_roi_vertex(v));
    CHECK_FALSE(deformation.erase_control_vertex(v));
    CHECK_THROWS_AS(deformation.target_position(v), Error);
  }
  CHECK(deformation.roi_vertices().empty());
}

TEST_CASE("a mesh with removed elements or grown after construction", "[robustness]")
{
  Surface_mesh mesh = to_mesh<Surface_mesh>(bar(6, 2));
  SECTION("removed, not collected, vertices are skipped")
  {
    Surface_mesh with_garbage = mesh;
    with_garbage.remove_vertex(with_garbage.add_vertex(Point(7, 7, 7)));
    REQUIRE(with_garbage.has_garbage());
    const Eigen::MatrixXd before = positions_of(mesh);
    Spectral deformation(with_garbage);
    auto all = std::vector<Surface_mesh::Vertex_index>(with_garbage.vertices().begin(),
                                                       with_garbage.vertices().end());
    deformation.insert_roi_vertices(all.begin(), all.end());
    deformation.insert_control_vertex(all.front());
    deformation.translate(all.front(), Eigen::Vector3d(0.1, 0, 0));
    deformation.deform();
    INFO(deformation.deform_report().message);
    CHECK(deformation.deform_report().success);
  }
  SECTION("vertices added after construction: preprocess() fails with a message")
  {
    Spectral deformation(mesh);
    auto all = std::vector<Surface_mesh::Vertex_index>(mesh.vertices().begin(), mesh.vertices().end());
    deformation.insert_roi_vertices(all.begin(), all.end());
    deformation.insert_control_vertex(all.front());
    mesh.add_vertex(Point(9, 9, 9));
    CHECK_FALSE(deformation.preprocess());
    CHECK(deformation.preprocess_report().message.find("changed") != std::string::npos);
  }
}

TEST_CASE("tiny meshes and unusual selections", "[robustness]")
{
  SECTION("a single triangle: a clear failure, the mesh untouched")
  {
    Surface_mesh triangle;
    const auto a = triangle.add_vertex(Point(0, 0, 0)), b = triangle.add_vertex(Point(1, 0, 0)),
               c = triangle.add_vertex(Point(0, 1, 0));
    triangle.add_face(a, b, c);
    const Eigen::MatrixXd before = positions_of(triangle);
    Spectral deformation(triangle);
    deformation.insert_roi_vertex(a);
    deformation.insert_roi_vertex(b);
    deformation.insert_roi_vertex(c);
    deformation.insert_control_vertex(a);
    deformation.translate(a, Eigen::Vector3d(0, 0, 1));
    deformation.deform();
    if(!deformation.deform_report().success)
    {
      CHECK_FALSE(deformation.deform_report().message.empty());
      CHECK(positions_of(triangle) == before);
    }
    else
      CHECK(positions_of(triangle).allFinite());
  }
  SECTION("a tetrahedron moved by one vertex")
  {
    Surface_mesh tetrahedron;
    CGAL::make_tetrahedron(Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(0, 0, 1), tetrahedron);
    Spectral deformation(tetrahedron);
    auto all = std::vector<Surface_mesh::Vertex_index>(tetrahedron.vertices().begin(),
                                                       tetrahedron.vertices().end());
    deformation.insert_roi_vertices(all.begin(), all.end());
    deformation.insert_control_vertex(all[0]);
    deformation.insert_control_vertex(all[1]);
    deformation.translate(all[0], Eigen::Vector3d(0.3, 0, 0));
    deformation.deform();
    INFO(deformation.deform_report().message);
    CHECK(deformation.preprocess_report().number_of_frequencies == 4); // m clamped to n
    if(deformation.deform_report().success)
      CHECK(positions_of(tetrahedron).allFinite());
    else
      CHECK_FALSE(deformation.deform_report().message.empty());
  }
  SECTION("a ROI without control vertex keeps its shape")
  {
    Surface_mesh mesh = to_mesh<Surface_mesh>(bar(10, 2));
    const Eigen::MatrixXd before = positions_of(mesh);
    Spectral deformation(mesh);
    for(auto v : mesh.vertices())
      if(mesh.point(v).z() > 2.0)
        deformation.insert_roi_vertex(v);
    deformation.deform();
    INFO(deformation.deform_report().message);
    REQUIRE(deformation.deform_report().success);
    // The tube may stretch along its axis at no cost: the regularization
    // keeps it where it is, up to round-off amplified by that free direction.
    CHECK((positions_of(mesh) - before).cwiseAbs().maxCoeff() < 1e-5);
  }
  SECTION("more frequencies than region vertices are clamped")
  {
    Surface_mesh mesh = to_mesh<Surface_mesh>(bar(4, 2));
    Spectral deformation(mesh);
    auto all = std::vector<Surface_mesh::Vertex_index>(mesh.vertices().begin(), mesh.vertices().end());
    deformation.insert_roi_vertices(all.begin(), all.end());
    deformation.insert_control_vertex(all.front());
    deformation.set_number_of_frequencies(100000);
    REQUIRE(deformation.preprocess());
    CHECK(deformation.preprocess_report().number_of_frequencies == mesh.number_of_vertices());
    CHECK_THROWS_AS(deformation.set_number_of_frequencies(0), Error);
    CHECK_THROWS_AS(deformation.set_constraint_weight(-1.0), Error);
    CHECK_THROWS_AS(deformation.set_constraint_weight(std::numeric_limits<double>::infinity()), Error);
  }
  SECTION("NaN in the mesh: preprocess() fails and nothing is written")
  {
    Surface_mesh mesh = to_mesh<Surface_mesh>(bar(6, 2));
    auto all = std::vector<Surface_mesh::Vertex_index>(mesh.vertices().begin(), mesh.vertices().end());
    mesh.point(all[5]) = Point(std::numeric_limits<double>::quiet_NaN(), 0, 0);
    Spectral deformation(mesh);
    deformation.insert_roi_vertices(all.begin(), all.end());
    deformation.insert_control_vertex(all.front());
    deformation.translate(all.front(), Eigen::Vector3d(1, 0, 0));
    deformation.deform();
    CHECK_FALSE(deformation.deform_report().success);
    CHECK(deformation.preprocess_report().message.find("non-finite") != std::string::npos);
    CHECK(mesh.point(all.front()) == Point(mesh.point(all.front())));
  }
}

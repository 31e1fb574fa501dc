// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include "test_meshes.h"

#include <CGAL/Dual_mesh_laplacian.h>
#include <CGAL/Spectral_deformation/internal/Linear_algebra/Stored_basis.h>
#include <CGAL/Spectral_deformation/internal/Linear_algebra/Operators_in_basis.h>
#include <CGAL/Spectral_deformation/internal/Linear_algebra/Sparse_times_dense.h>

#include <catch2/catch.hpp>

#include <cmath>

#ifdef _OPENMP
#include <omp.h>
#endif

using namespace test_meshes;
typedef CGAL::Dual_mesh_laplacian<Surface_mesh> Dual;
typedef Dual::Positions Positions;
typedef CGAL::Spectral_deformation_error Error;

namespace {

Positions rigidly_moved(const Positions& x, double scale)
{
  const Eigen::Matrix3d R =
      Eigen::AngleAxisd(1.1, Eigen::Vector3d(0.3, -0.5, 0.8).normalized()).toRotationMatrix();
  return ((scale * x * R.transpose()).rowwise() + Eigen::RowVector3d(4.0, -2.0, 7.5)).eval();
}

/// The triangles of a soup as the internal arrays.
CGAL::Spectral_deformation::internal::Mesh::Triangles dual_triangles(const Soup& soup)
{
  CGAL::Spectral_deformation::internal::Mesh::Triangles triangles(static_cast<Eigen::Index>(soup.triangles.size()), 3);
  for(std::size_t f = 0; f < soup.triangles.size(); ++f)
    for(int k = 0; k < 3; ++k)
      triangles(static_cast<Eigen::Index>(f), k) = static_cast<int>(soup.triangles[f][static_cast<std::size_t>(k)]);
  return triangles;
}

/// The points of a soup as the internal arrays.
CGAL::Spectral_deformation::internal::Mesh::Positions soup_positions(const Soup& soup)
{
  CGAL::Spectral_deformation::internal::Mesh::Positions positions(static_cast<Eigen::Index>(soup.points.size()), 3);
  for(std::size_t i = 0; i < soup.points.size(); ++i)
    positions.row(static_cast<Eigen::Index>(i)) << soup.points[i].x(), soup.points[i].y(), soup.points[i].z();
  return positions;
}

} // namespace

TEST_CASE("dual Laplacian weights sum to one and the coordinate is normal", "[dual]")
{
  for(const Soup& soup : {bumpy_plane(12), icosphere(3), bar(12, 3)})
  {
    const Dual dual(to_mesh<Surface_mesh>(soup));
    const Dual::Coordinates& c = dual.rest_coordinates();
    REQUIRE(dual.number_of_rows() > 0);
    CHECK(c.degenerate_rows == 0);
    CHECK((c.weights.rowwise().sum().array() - 1.0).abs().maxCoeff() < 1e-12);
    for(Eigen::Index r = 0; r < dual.number_of_rows(); ++r)
    {
      const Eigen::Vector3d l = c.coordinates.row(r).transpose();
      const Eigen::Vector3d n = c.normals.row(r).transpose();
      CHECK(std::abs(n.norm() - 1.0) < 1e-12);
      CHECK(l.cross(n).norm() < 1e-12 * (1.0 + l.norm()));
      CHECK((l + c.heights[r] * n).norm() < 1e-12);
    }
    // The operator reproduces the coordinates and annihilates constants.
    const Eigen::SparseMatrix<double> LF = dual.laplacian_operator();
    CHECK((LF * dual.positions() - c.coordinates).cwiseAbs().maxCoeff() < 1e-12);
    CHECK((LF * Eigen::VectorXd::Ones(dual.number_of_vertices())).cwiseAbs().maxCoeff() < 1e-13);
    // F has three entries 1/3 per row.
    const Eigen::SparseMatrix<double> F = dual.centroid_operator();
    CHECK((F * Eigen::VectorXd::Ones(dual.number_of_vertices()) -
           Eigen::VectorXd::Ones(dual.number_of_dual_vertices()))
              .cwiseAbs()
              .maxCoeff() < 1e-14);
  }
}

TEST_CASE("on a sphere every dual coordinate points inwards", "[dual]")
{
  // Outward-oriented convex surface: the dual vertex lies outside the plane of
  // its neighbours, so h > 0 and the normal points outwards.
  const Dual dual(to_mesh<Surface_mesh>(icosphere(3)));
  const Dual::Coordinates& c = dual.rest_coordinates();
  const Positions centroids = dual.dual_vertices(dual.positions());
  for(Eigen::Index r = 0; r < dual.number_of_rows(); ++r)
  {
    CHECK(c.heights[r] > 0);
    CHECK(c.normals.row(r).dot(centroids.row(dual.face_index_of_row(r))) > 0);
  }
}

TEST_CASE("weights are invariant under rigid motion and scaling", "[dual]")
{
  const Dual dual(to_mesh<Surface_mesh>(bumpy_plane(10)));
  const double s = 3.7;
  const Dual::Coordinates moved = dual.evaluate(rigidly_moved(dual.positions(), s));
  const Dual::Coordinates& rest = dual.rest_coordinates();
  CHECK((moved.weights - rest.weights).cwiseAbs().maxCoeff() < 1e-11);
  CHECK((moved.heights - s * rest.heights).cwiseAbs().maxCoeff() < 1e-11);
  // Normals turn with the rotation.
  const Positions turned = rigidly_moved(rest.normals, 1.0).rowwise() - Eigen::RowVector3d(4.0, -2.0, 7.5);
  CHECK((moved.normals - turned).cwiseAbs().maxCoeff() < 1e-11);
}

TEST_CASE("dual neighbours: order ab, bc, ca and no row on the border", "[dual]")
{
  const Surface_mesh mesh = to_mesh<Surface_mesh>(bumpy_plane(6));
  const Dual dual(mesh);
  std::vector<std::array<int, 3>> triangles;
  for(auto f : mesh.faces())
  {
    std::array<int, 3> t;
    int k = 0;
    for(auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
      t[k++] = int(v.idx());
    triangles.push_back(t);
  }
  Eigen::Index faces_with_three = 0;
  for(Eigen::Index f = 0; f < dual.number_of_dual_vertices(); ++f)
  {
    const auto nb = dual.dual_neighbours(f);
    int count = 0;
    for(int k = 0; k < 3; ++k)
    {
      if(nb[k] < 0)
        continue;
      ++count;
      // The neighbour across edge (t[k], t[k+1]) holds that edge reversed.
      const auto& t = triangles[std::size_t(f)];
      const auto& g = triangles[std::size_t(nb[k])];
      bool found = false;
      for(int j = 0; j < 3; ++j)
        found = found || (g[j] == t[(k + 1) % 3] && g[(j + 1) % 3] == t[k]);
      CHECK(found);
    }
    faces_with_three += (count == 3);
  }
  CHECK(dual.number_of_rows() == faces_with_three);
  CHECK(dual.number_of_rows() < dual.number_of_dual_vertices());
  for(Eigen::Index r = 0; r < dual.number_of_rows(); ++r)
    CHECK(dual.face_of_row(r) == *std::next(mesh.faces().begin(), dual.face_index_of_row(r)));
}

TEST_CASE("degenerate neighbour triangles fall back to uniform weights and keep the frame", "[dual]")
{
  const Dual dual(to_mesh<Surface_mesh>(icosphere(2)));
  // Flatten every vertex onto a line: all neighbour triangles are degenerate.
  Positions line = dual.positions();
  line.col(1).setZero();
  line.col(2).setZero();
  const Positions previous = dual.rest_coordinates().normals;
  const Dual::Coordinates c = dual.evaluate(line, &previous);
  CHECK(c.degenerate_rows == dual.number_of_rows());
  CHECK((c.weights.array() - 1.0 / 3.0).abs().maxCoeff() < 1e-15);
  CHECK(c.normals == previous);
  CHECK(c.heights.allFinite());
  CHECK(c.coordinates.allFinite());
}

TEST_CASE("Surface_mesh and Polyhedron_3 give the same dual coordinates", "[dual]")
{
  const Soup soup = bar(8, 2);
  const Dual a(to_mesh<Surface_mesh>(soup));
  const CGAL::Dual_mesh_laplacian<Polyhedron> b(to_mesh<Polyhedron>(soup));
  REQUIRE(a.number_of_rows() == b.number_of_rows());
  CHECK((a.rest_coordinates().weights - b.rest_coordinates().weights).cwiseAbs().maxCoeff() == 0.0);
  CHECK((a.rest_coordinates().heights - b.rest_coordinates().heights).cwiseAbs().maxCoeff() == 0.0);
}

TEST_CASE("non-manifold and inconsistently oriented faces are refused", "[dual][errors]")
{
  using CGAL::Spectral_deformation::internal::Mesh::Dual_mesh_operator;
  CGAL::Spectral_deformation::internal::Mesh::Triangles three_on_an_edge(3, 3);
  three_on_an_edge << 0, 1, 2, 1, 0, 3, 1, 0, 4;
  CHECK_THROWS_AS(Dual_mesh_operator(three_on_an_edge, 5), Error);
  CGAL::Spectral_deformation::internal::Mesh::Triangles flipped(2, 3);
  flipped << 0, 1, 2, 0, 1, 3;
  CHECK_THROWS_AS(Dual_mesh_operator(flipped, 4), Error);
  Surface_mesh quad;
  const auto a = quad.add_vertex(Point(0, 0, 0)), b = quad.add_vertex(Point(1, 0, 0)),
             c = quad.add_vertex(Point(1, 1, 0)), d = quad.add_vertex(Point(0, 1, 0));
  quad.add_face(a, b, c, d);
  CHECK_THROWS_AS(Dual(quad), Error);
}

TEST_CASE("the iteration kernels agree with the sparse operator and with Eigen's products", "[dual]")
{
  using namespace CGAL::Spectral_deformation::internal::Mesh;
  using CGAL::Spectral_deformation::internal::Linear_algebra::Stored_basis;
  // A plane with an open border: rows only where a face has three neighbours.
  const Soup soup = bumpy_plane(12);
  const Dual_mesh_operator op(dual_triangles(soup), static_cast<Eigen::Index>(soup.points.size()));
  const Positions rest_positions = soup_positions(soup);
  const Dual_coordinates rest = op.evaluate(rest_positions);
  const Positions moved = rigidly_moved(rest_positions, 1.7);
  const Dual_coordinates reference = op.evaluate(moved);
  REQUIRE(op.number_of_rows() > 0);
  REQUIRE(op.number_of_rows() < op.number_of_faces());

  Positions centroids, normals = rest.normals;
  op.update_normals(moved, centroids, normals);
  CHECK((normals - reference.normals).cwiseAbs().maxCoeff() < 1e-14);

  const Eigen::VectorXd factors = -rest.heights;
  const Eigen::SparseMatrix<double> LF = op.laplacian_operator(rest.weights);
  const Positions expected = LF.transpose() * (factors.asDiagonal() * normals);
  Positions faces, spread;
  op.apply_transpose(rest.weights, factors, normals, faces, spread);
  CHECK((spread - expected).cwiseAbs().maxCoeff() < 1e-14 * (1.0 + expected.cwiseAbs().maxCoeff()));

  const Eigen::MatrixXd C = Eigen::MatrixXd::Random(23, 3);
  Positions shape;
  Eigen::MatrixXd projected;

  // The basis read in place, by blocks larger than the panels: rows past
  // several whole blocks and a partial one.
  const Eigen::MatrixXd tall = Eigen::MatrixXd::Random(5 * 512 + 77, 23);
  const Positions tall_X = Positions::Random(tall.rows(), 3);
  Stored_basis columns;
  columns.assign(Eigen::MatrixXd(tall), false);
  CHECK_FALSE(columns.single_precision());
  CHECK(columns.bytes() == sizeof(double) * static_cast<std::size_t>(tall.size()));
  columns.multiply(C, shape);
  columns.multiply_transpose(tall_X, projected);
  CHECK(shape.rows() == tall.rows());
  CHECK((shape - tall * C).cwiseAbs().maxCoeff() < 1e-13);
  CHECK((projected - tall.transpose() * tall_X).cwiseAbs().maxCoeff() < 1e-11);
  CHECK((columns.row(100) - tall.row(100)).cwiseAbs().maxCoeff() == 0.0);

  // The same basis kept in float: the products of the rounded basis, in
  // double arithmetic, in half the memory.
  const Eigen::MatrixXd tall_rounded = tall.cast<float>().cast<double>();
  Eigen::MatrixXd handed_over = tall;
  columns.assign(std::move(handed_over), true);
  CHECK(handed_over.size() == 0);
  CHECK(columns.single_precision());
  CHECK(columns.bytes() == sizeof(float) * static_cast<std::size_t>(tall.size()));
  columns.multiply(C, shape);
  columns.multiply_transpose(tall_X, projected);
  CHECK((shape - tall_rounded * C).cwiseAbs().maxCoeff() < 1e-13);
  CHECK((projected - tall_rounded.transpose() * tall_X).cwiseAbs().maxCoeff() < 1e-11);
  CHECK((columns.row(100) - tall_rounded.row(100)).cwiseAbs().maxCoeff() == 0.0);
}

TEST_CASE("the blocked sparse-times-basis product is Eigen's, bit for bit, on any number of threads", "[dual]")
{
  using CGAL::Spectral_deformation::internal::Linear_algebra::sparse_times_dense;
  using namespace CGAL::Spectral_deformation::internal::Mesh;
  const Soup soup = bumpy_plane(40);
  const Dual_mesh_operator op(dual_triangles(soup), static_cast<Eigen::Index>(soup.points.size()));
  const Positions positions = soup_positions(soup);
  const Eigen::SparseMatrix<double> LF = op.laplacian_operator(op.evaluate(positions).weights);
  const Eigen::SparseMatrix<double> normal = Eigen::SparseMatrix<double>(LF.transpose()) * LF;
  REQUIRE(normal.nonZeros() * 100 > 1000000); // large enough for the threaded path
  // Column counts below, at and above a block, and one that leaves a partial block.
  for(Eigen::Index columns : {1, 8, 13, 100})
  {
    const Eigen::MatrixXd H = Eigen::MatrixXd::Random(normal.cols(), columns);
    const Eigen::MatrixXd expected = normal * H;
    Eigen::MatrixXd product;
    sparse_times_dense(normal, H, product);
    CHECK((product.array() == expected.array()).all());
#ifdef _OPENMP
    const int threads = omp_get_max_threads();
    omp_set_num_threads(1);
    Eigen::MatrixXd single;
    sparse_times_dense(normal, H, single);
    omp_set_num_threads(threads);
    CHECK((single.array() == product.array()).all());
#endif
  }
  // A rectangular operator (rows of dual coordinates by vertices).
  const Eigen::MatrixXd H = Eigen::MatrixXd::Random(LF.cols(), 11);
  Eigen::MatrixXd product;
  sparse_times_dense(LF, H, product);
  CHECK((product.array() == (LF * H).array()).all());
}

TEST_CASE("the reduced matrices are formed in the basis without n-sized intermediates", "[dual]")
{
  namespace LA = CGAL::Spectral_deformation::internal::Linear_algebra;
  using namespace CGAL::Spectral_deformation::internal::Mesh;
  const Soup soup = bumpy_plane(40);
  const Dual_mesh_operator op(dual_triangles(soup), static_cast<Eigen::Index>(soup.points.size()));
  const Positions positions = soup_positions(soup);
  const Eigen::Matrix<double, Eigen::Dynamic, 3> weights = op.evaluate(positions).weights;
  const Eigen::SparseMatrix<double> LF = op.laplacian_operator(weights);
  const Eigen::SparseMatrix<double> normal = Eigen::SparseMatrix<double>(LF.transpose()) * LF;
  const auto row_value = [&op, &weights](Eigen::Index r, const double* h) { return op.apply_row(weights, r, h); };

  // One row at a time, the operator without its matrix.
  const Eigen::VectorXd h = Eigen::VectorXd::Random(LF.cols());
  const Eigen::VectorXd rows = LF * h;
  for(Eigen::Index r = 0; r < LF.rows(); ++r)
    REQUIRE(std::abs(row_value(r, h.data()) - rows[r]) <= 1e-13 * (1 + std::abs(rows[r])));

  for(Eigen::Index columns : {1, 7, 100})
  {
    const Eigen::MatrixXd H = Eigen::MatrixXd::Random(LF.cols(), columns);
    const Eigen::MatrixXd LFH = LF * H;
    const Eigen::MatrixXd expected_gram = LFH.transpose() * LFH;
    const Eigen::MatrixXd expected_projection = H.transpose() * (normal * H);
    Eigen::MatrixXd gram, projection;
    LA::gram_in_basis(LF.rows(), row_value, H, gram);
    LA::sparse_in_basis(normal, H, projection);
    const double scale = expected_gram.cwiseAbs().maxCoeff();
    CHECK((gram - expected_gram).cwiseAbs().maxCoeff() < 1e-12 * scale);
    CHECK((projection - expected_projection).cwiseAbs().maxCoeff() < 1e-12 * scale);
    CHECK((gram.array() == gram.transpose().array()).all());
    CHECK((projection.array() == projection.transpose().array()).all());
#ifdef _OPENMP
    // The same bits on one thread.
    const int threads = omp_get_max_threads();
    omp_set_num_threads(1);
    Eigen::MatrixXd single_gram, single_projection;
    LA::gram_in_basis(LF.rows(), row_value, H, single_gram);
    LA::sparse_in_basis(normal, H, single_projection);
    omp_set_num_threads(threads);
    CHECK((single_gram.array() == gram.array()).all());
    CHECK((single_projection.array() == projection.array()).all());
#endif
  }
}

TEST_CASE("the reduced matrices of a float basis are those of its values in double", "[dual]")
{
  namespace LA = CGAL::Spectral_deformation::internal::Linear_algebra;
  using namespace CGAL::Spectral_deformation::internal::Mesh;
  // More vertices than a block of the widened rows (4096), with a partial one.
  const Soup soup = bumpy_plane(70);
  const Dual_mesh_operator op(dual_triangles(soup), static_cast<Eigen::Index>(soup.points.size()));
  const Eigen::Matrix<double, Eigen::Dynamic, 3> weights = op.evaluate(soup_positions(soup)).weights;
  const Eigen::SparseMatrix<double> LF = op.laplacian_operator(weights);
  const Eigen::SparseMatrix<double> normal = Eigen::SparseMatrix<double>(LF.transpose()) * LF;
  REQUIRE(normal.rows() > 4096);
  REQUIRE(normal.rows() % 4096 != 0);
  const auto row_value = [&op, &weights](Eigen::Index r, const auto* h) { return op.apply_row(weights, r, h); };
  const Eigen::MatrixXf H = Eigen::MatrixXf::Random(LF.cols(), 13);
  const Eigen::MatrixXd widened = H.cast<double>();
  Eigen::MatrixXd gram, projection, expected_gram, expected_projection;
  LA::gram_in_basis(LF.rows(), row_value, H, gram);
  LA::sparse_in_basis(normal, H, projection);
  LA::gram_in_basis(LF.rows(), row_value, widened, expected_gram);
  LA::sparse_in_basis(normal, widened, expected_projection);
  const double scale = expected_gram.cwiseAbs().maxCoeff();
  CHECK((gram - expected_gram).cwiseAbs().maxCoeff() < 1e-12 * scale);
  CHECK((projection - expected_projection).cwiseAbs().maxCoeff() < 1e-12 * scale);
  CHECK((projection.array() == projection.transpose().array()).all());
}

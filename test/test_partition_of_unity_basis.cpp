// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
// The approximate basis of Partition_of_unity_eigensolver_traits: the
// farthest point sampling, the partition of unity and its linear functions,
// the eigenpairs against the exact ones (upper bounds, close), and the
// deformations it gives against those of the exact basis.
#include "test_meshes.h"

#include <CGAL/Manifold_harmonics_basis.h>
#include <CGAL/Spectral_deformation/Partition_of_unity_eigensolver_traits.h>
#include <CGAL/Spectral_surface_mesh_deformation.h>
#include <CGAL/Spectral_deformation/cotangent_operators.h>
#include <CGAL/Spectral_deformation/internal/Mesh/Triangle_arrays.h>

#include <catch2/catch.hpp>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <vector>

#ifdef _OPENMP
#include <omp.h>
#endif

using namespace test_meshes;
namespace E = CGAL::Spectral_deformation::internal::Eigensolvers;
namespace Mesh_arrays = CGAL::Spectral_deformation::internal::Mesh;
typedef CGAL::Partition_of_unity_eigensolver_traits<> Partition_of_unity;
typedef boost::graph_traits<Surface_mesh>::vertex_descriptor SM_vertex;

namespace {

Mesh_arrays::Triangle_arrays arrays_of(const Surface_mesh& mesh)
{
  return Mesh_arrays::extract_triangle_arrays(mesh, CGAL::parameters::default_values());
}

// The graph of the edges of the mesh, as the traits build it.
E::Edge_length_graph graph_of(const Mesh_arrays::Triangle_arrays& arrays)
{
  return E::edge_length_graph(CGAL::Spectral_deformation::internal::cotangent_stiffness(arrays), arrays.positions);
}

// The reduced pair (A, B) = (Pᵀ Q P, Pᵀ M P) of a mesh's space of `samples`
// sampled functions (three per sample), as the traits build it, and the
// mesh's lumped mass.
struct Reduced_pair
{
  Eigen::SparseMatrix<double> A, B;
  Eigen::VectorXd mass;
};

Reduced_pair reduced_pair_of(const Surface_mesh& mesh, Eigen::Index samples)
{
  const Mesh_arrays::Triangle_arrays arrays = arrays_of(mesh);
  const Eigen::SparseMatrix<double> stiffness = CGAL::Spectral_deformation::internal::cotangent_stiffness(arrays);
  Reduced_pair pair;
  pair.mass = CGAL::Spectral_deformation::internal::lumped_mass(arrays);
  const E::Edge_length_graph graph = E::edge_length_graph(stiffness, arrays.positions);
  double covering_radius = 0;
  const std::vector<Eigen::Index> sampled = E::farthest_point_samples(graph, samples, covering_radius);
  const Eigen::SparseMatrix<double> functions =
      E::partition_of_unity_functions(graph, arrays.positions, sampled, 2 * covering_radius, true);
  const Eigen::SparseMatrix<double, Eigen::RowMajor> rows = functions;
  E::galerkin_matrices(stiffness, pair.mass, functions, rows, pair.A, pair.B);
  return pair;
}

Eigen::MatrixXd positions_of(const Surface_mesh& mesh)
{
  Eigen::MatrixXd x(mesh.number_of_vertices(), 3);
  for(auto v : mesh.vertices())
    x.row(v.idx()) << mesh.point(v).x(), mesh.point(v).y(), mesh.point(v).z();
  return x;
}

// Distances along the edges from the nearest of `sources`, by a full search.
std::vector<double> distances_from(const E::Edge_length_graph& graph, const std::vector<Eigen::Index>& sources)
{
  std::vector<double> nearest(static_cast<std::size_t>(graph.number_of_vertices()),
                              std::numeric_limits<double>::infinity());
  E::Bounded_dijkstra search(graph);
  for(Eigen::Index s : sources)
    search.run(s, std::numeric_limits<double>::infinity(), [&](Eigen::Index v, double d) {
      nearest[static_cast<std::size_t>(v)] = (std::min)(nearest[static_cast<std::size_t>(v)], d);
    });
  return nearest;
}

// A flat square grid in z = 0, `cells` × `cells`, diagonals alternating.
Soup flat_grid(int cells)
{
  Soup soup;
  for(int j = 0; j <= cells; ++j)
    for(int i = 0; i <= cells; ++i)
      soup.points.emplace_back(double(i) / cells, double(j) / cells, 0.0);
  auto id = [cells](int i, int j) { return std::size_t(j * (cells + 1) + i); };
  for(int j = 0; j < cells; ++j)
    for(int i = 0; i < cells; ++i)
      if((i + j) % 2 == 0)
      {
        soup.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
        soup.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
      }
      else
      {
        soup.triangles.push_back({id(i, j), id(i + 1, j), id(i, j + 1)});
        soup.triangles.push_back({id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
      }
  return soup;
}

} // namespace

TEST_CASE("Partition of unity basis: farthest point samples cover the mesh and stay apart", "[pou]")
{
  const Surface_mesh mesh = to_mesh<Surface_mesh>(icosphere(4));
  const Mesh_arrays::Triangle_arrays arrays = arrays_of(mesh);
  const E::Edge_length_graph graph = graph_of(arrays);
  double covering_radius = 0;
  const std::vector<Eigen::Index> samples = E::farthest_point_samples(graph, 60, covering_radius);
  REQUIRE(samples.size() == 60);
  CHECK(std::set<Eigen::Index>(samples.begin(), samples.end()).size() == 60);
  REQUIRE(covering_radius > 0);

  // Every vertex within the covering radius of a sample, and it is reached.
  const std::vector<double> nearest = distances_from(graph, samples);
  double largest = 0;
  for(double d : nearest)
    largest = (std::max)(largest, d);
  CHECK(largest == Approx(covering_radius).epsilon(1e-12));

  // Each sample was the farthest vertex when chosen: no two are closer than
  // the final covering radius.
  for(std::size_t a = 0; a < samples.size(); ++a)
  {
    const std::vector<double> from_a = distances_from(graph, {samples[a]});
    for(std::size_t b = 0; b < samples.size(); ++b)
      if(b != a)
        CHECK(from_a[static_cast<std::size_t>(samples[b])] >= covering_radius * (1 - 1e-12));
  }
}

TEST_CASE("Partition of unity basis: every component gets a sample first", "[pou]")
{
  const Surface_mesh mesh = to_mesh<Surface_mesh>(two_spheres(2));
  const Mesh_arrays::Triangle_arrays arrays = arrays_of(mesh);
  const E::Edge_length_graph graph = graph_of(arrays);
  double covering_radius = 0;
  std::vector<Eigen::Index> samples = E::farthest_point_samples(graph, 1, covering_radius);
  CHECK(covering_radius == std::numeric_limits<double>::infinity());
  samples = E::farthest_point_samples(graph, 2, covering_radius);
  REQUIRE(samples.size() == 2);
  CHECK(covering_radius < std::numeric_limits<double>::infinity());
  const Eigen::Index half = graph.number_of_vertices() / 2; // the second sphere's vertices follow the first's
  CHECK((samples[0] < half) != (samples[1] < half));
}

TEST_CASE("Partition of unity basis: the functions sum to one and reproduce linear functions", "[pou]")
{
  const Surface_mesh mesh = to_mesh<Surface_mesh>(flat_grid(40));
  const Mesh_arrays::Triangle_arrays arrays = arrays_of(mesh);
  const E::Edge_length_graph graph = graph_of(arrays);
  double covering_radius = 0;
  const std::vector<Eigen::Index> samples = E::farthest_point_samples(graph, 40, covering_radius);
  for(bool linear : {false, true})
  {
    INFO("linear functions " << linear);
    const Eigen::SparseMatrix<double> functions =
        E::partition_of_unity_functions(graph, arrays.positions, samples, 2 * covering_radius, linear);
    REQUIRE(functions.cols() == (linear ? 3 : 1) * 40);
    // The bumps themselves (the first column of each sample) sum to one.
    Eigen::VectorXd sum = Eigen::VectorXd::Zero(functions.rows());
    for(Eigen::Index s = 0; s < 40; ++s)
      sum += functions.col((linear ? 3 : 1) * s);
    CHECK((sum.array() - 1.0).abs().maxCoeff() < 1e-12);

    // The least-squares fit of x and y in the space: exact with the linear
    // functions, not without them.
    const Eigen::MatrixXd dense = Eigen::MatrixXd(functions);
    const Eigen::MatrixXd xy = arrays.positions.leftCols(2);
    const Eigen::MatrixXd fit = dense * dense.colPivHouseholderQr().solve(xy);
    const double residual = (fit - xy).cwiseAbs().maxCoeff();
    if(linear)
      CHECK(residual < 1e-10);
    else
      CHECK(residual > 1e-3);
  }
}

TEST_CASE("Partition of unity basis: the reduced operator and its eigenvectors on one and two threads are Eigen's to the last bit", "[pou]")
{
  // A reduced pair whose Gram factor is large enough for the threaded
  // solves (bumpy plane of 17,161 vertices, 1000 samples, 3000 functions).
  const Surface_mesh mesh = to_mesh<Surface_mesh>(bumpy_plane(130));
  const Reduced_pair pair = reduced_pair_of(mesh, 1000);
  const Eigen::SparseMatrix<double>& A = pair.A;
  const Eigen::SparseMatrix<double>& B = pair.B;
  const Eigen::VectorXd& mass = pair.mass;
  const double sigma = E::shift_invert_shift(mass);
  E::Standard_form_shift_invert_operator<CGAL::Default_sparse_spd_solver_traits> op(A, B);
  op.set_shift(sigma);

  // The operator as Eigen's products compose it: Gᵀ (A - σB)⁻¹ G, B = G Gᵀ.
  Eigen::SimplicialLLT<Eigen::SparseMatrix<double>> gram(B);
  REQUIRE(gram.info() == Eigen::Success);
  const Eigen::SparseMatrix<double> L = gram.matrixL();
  REQUIRE(L.nonZeros() > CGAL::Spectral_deformation::internal::parallel_sparse_solve_entries);
  CGAL::Default_sparse_spd_solver_traits shifted;
  REQUIRE(shifted.factor(Eigen::SparseMatrix<double>(A - sigma * B)));
  const Eigen::VectorXd x = Eigen::VectorXd::Random(A.rows());
  const Eigen::VectorXd Lx = L * x;
  Eigen::MatrixXd rhs = gram.permutationP().transpose() * Lx, solution;
  REQUIRE(shifted.solve(rhs, solution));
  const Eigen::VectorXd w = gram.permutationP() * solution.col(0);
  const Eigen::VectorXd expected = L.transpose() * w;
  const Eigen::MatrixXd z = Eigen::MatrixXd::Random(A.rows(), 21);
  const Eigen::MatrixXd expected_vectors =
      gram.permutationP().transpose() * Eigen::MatrixXd(L.transpose().triangularView<Eigen::Upper>().solve(z));

  for(int threads : {1, 2})
  {
    INFO(threads << " threads");
#ifdef _OPENMP
    const int previous = omp_get_max_threads();
    omp_set_num_threads(threads);
#endif
    Eigen::VectorXd y(A.rows());
    op.perform_op(x.data(), y.data());
    const Eigen::MatrixXd vectors = op.generalized_vectors(z);
#ifdef _OPENMP
    omp_set_num_threads(previous);
#endif
    CHECK((y.array() == expected.array()).all());
    CHECK((vectors.array() == expected_vectors.array()).all());
  }
}

TEST_CASE("Partition of unity basis: the reduced pair's eigenpairs by the single-vector method are the dense "
          "solver's",
          "[pou]")
{
  // A reduced pair small enough for a dense generalized solver (bumpy plane
  // of 1,681 vertices, 200 samples, 600 functions): B is not diagonal, and
  // A is singular (the constant function is in the space).
  const Surface_mesh mesh = to_mesh<Surface_mesh>(bumpy_plane(40));
  const Reduced_pair pair = reduced_pair_of(mesh, 200);
  const Eigen::SparseMatrix<double>& A = pair.A;
  const Eigen::SparseMatrix<double>& B = pair.B;
  const Eigen::VectorXd& mass = pair.mass;
  REQUIRE(A.rows() == 600);

  const Eigen::Index m = 30;
  const Eigen::MatrixXd dense_A = A, dense_B = B;
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> dense(dense_A, dense_B);
  REQUIRE(dense.info() == Eigen::Success);
  const Eigen::VectorXd dense_values = dense.eigenvalues().head(m);
  const Eigen::MatrixXd dense_vectors = dense.eigenvectors().leftCols(m);

  E::Single_vector_lanczos_settings settings;
  settings.max_dimension = 8 * m;
  settings.tolerance = 1e-10;
  auto ignore = [](Eigen::Index) {};
  Eigen::VectorXd values;
  Eigen::MatrixXd vectors;
  std::string message;
  REQUIRE(E::single_vector_lanczos_iteration<CGAL::Default_eigensolver_sparse_spd_solver_traits>(
      A, E::Sparse_mass(B), nullptr, E::shift_invert_shift(mass), m, settings, ignore, ignore, values, vectors,
      message));
  CHECK(message.empty());
  REQUIRE(values.size() == m);
  REQUIRE(vectors.rows() == 600);
  REQUIRE(vectors.cols() == m);
  CHECK(std::abs(values[0]) < 1e-8 * dense_values[1]);
  CHECK((values - dense_values).tail(m - 1).cwiseQuotient(dense_values.tail(m - 1)).cwiseAbs().maxCoeff() < 1e-9);
  const Eigen::MatrixXd gram = vectors.transpose() * B * vectors;
  CHECK((gram - Eigen::MatrixXd::Identity(m, m)).cwiseAbs().maxCoeff() < 1e-12);
  for(Eigen::Index i = 1; i < m; ++i)
  {
    INFO("eigenvector " << i);
    const double cosine = dense_vectors.col(i).dot(B * vectors.col(i));
    CHECK(std::abs(cosine) > 1.0 - 1e-8);
  }
}

TEST_CASE("Partition of unity basis: M-orthonormal, eigenvalues above the exact ones and close to them", "[pou]")
{
  const Surface_mesh mesh = to_mesh<Surface_mesh>(icosphere(5)); // 10242 vertices
  const std::size_t m = 16;                                        // l = 0..3 on the unit sphere
  Partition_of_unity traits;
  traits.set_number_of_samples(400);
  REQUIRE(double(num_vertices(mesh)) >= traits.exact_threshold() * 3 * 400); // the approximation runs
  const CGAL::Manifold_harmonics_basis<Surface_mesh, Partition_of_unity> approximate(
      mesh, m, CGAL::parameters::default_values(), traits);
  const CGAL::Manifold_harmonics_basis<Surface_mesh> exact(mesh, m);

  const Eigen::MatrixXd& H = approximate.basis();
  const Eigen::MatrixXd gram = H.transpose() * approximate.mass().asDiagonal() * H;
  CHECK((gram - Eigen::MatrixXd::Identity(m, m)).cwiseAbs().maxCoeff() < 1e-10);
  CHECK(std::abs(approximate.eigenvalues()[0]) < 1e-10);
  for(std::size_t k = 1; k < m; ++k)
  {
    const double a = approximate.eigenvalues()[k], e = exact.eigenvalues()[k];
    INFO("eigenvalue " << k << ": approximate " << a << ", exact " << e);
    CHECK(a >= e * (1 - 1e-10)); // Rayleigh-Ritz: an upper bound
    CHECK(a <= e * 1.01);
  }
  // The approximate functions lie in the span of the exact ones up to a small
  // angle: the projection of each on the exact span keeps almost all its norm
  // (l = 0..3 are complete groups of equal eigenvalues).
  const Eigen::MatrixXd coefficients = exact.basis().transpose() * exact.mass().asDiagonal() * H;
  for(std::size_t k = 0; k < m; ++k)
    CHECK(coefficients.col(k).norm() > 0.999);
}

TEST_CASE("Partition of unity basis: the eigenvectors in float are those in double, rounded", "[pou]")
{
  // Approximated (10242 vertices, 400 samples) and solved exactly (642 vertices).
  for(const int level : {5, 3})
  {
    const Surface_mesh mesh = to_mesh<Surface_mesh>(icosphere(level));
    const Mesh_arrays::Triangle_arrays arrays = arrays_of(mesh);
    const Eigen::SparseMatrix<double> stiffness = CGAL::Spectral_deformation::internal::cotangent_stiffness(arrays);
    const Eigen::VectorXd mass = CGAL::Spectral_deformation::internal::lumped_mass(arrays);
    Partition_of_unity traits;
    traits.set_number_of_samples(400);
    traits.set_vertex_positions(arrays.positions);
    INFO("icosphere " << level << ", solved exactly: " << traits.solves_exactly(16, arrays.number_of_vertices()));
    CHECK(traits.solves_exactly(16, arrays.number_of_vertices()) == (level == 3));
    Eigen::VectorXd values_in_double, values_in_float;
    Eigen::MatrixXd in_double;
    Eigen::MatrixXf in_float;
    REQUIRE(traits.compute(stiffness, mass, 16, values_in_double, in_double));
    REQUIRE(traits.compute(stiffness, mass, 16, values_in_float, in_float));
    CHECK((values_in_float - values_in_double).cwiseAbs().maxCoeff() <=
          1e-12 * values_in_double.cwiseAbs().maxCoeff());
    REQUIRE(in_float.rows() == in_double.rows());
    REQUIRE(in_float.cols() == 16);
    // Rounding leaves half a unit in the last place of float, some 3e-8 of
    // the largest entry; a column of another eigenvector, or of the other
    // sign, would be off by the size of the entries.
    const double largest = in_double.cwiseAbs().maxCoeff();
    CHECK((in_float.cast<double>() - in_double).cwiseAbs().maxCoeff() <= 1e-7 * largest);
  }
}

TEST_CASE("Partition of unity basis: clear failures", "[pou]")
{
  const Surface_mesh mesh = to_mesh<Surface_mesh>(icosphere(4));
  const Mesh_arrays::Triangle_arrays arrays = arrays_of(mesh);
  const Eigen::SparseMatrix<double> stiffness = CGAL::Spectral_deformation::internal::cotangent_stiffness(arrays);
  const Eigen::VectorXd mass = CGAL::Spectral_deformation::internal::lumped_mass(arrays);
  Eigen::VectorXd values;
  Eigen::MatrixXd vectors;

  Partition_of_unity traits;
  traits.set_number_of_samples(50);
  CHECK_FALSE(traits.compute(stiffness, mass, 10, values, vectors)); // no positions
  CHECK(traits.error_message().find("positions") != std::string::npos);

  traits.set_vertex_positions(arrays.positions);
  traits.set_support_factor(0.5);
  CHECK_FALSE(traits.compute(stiffness, mass, 10, values, vectors));
  CHECK(traits.error_message().find("support factor") != std::string::npos);

  traits.set_support_factor(2.0);
  CHECK_FALSE(traits.compute(stiffness, mass, 200, values, vectors)); // 150 functions for 200 frequencies
  CHECK(traits.error_message().find("too small") != std::string::npos);

  CHECK(traits.compute(stiffness, mass, 10, values, vectors));
  CHECK(values.size() == 10);

  // Through the basis class: the error is a Spectral_deformation_error and
  // the basis keeps its content.
  traits.set_support_factor(0.5);
  CGAL::Manifold_harmonics_basis<Surface_mesh, Partition_of_unity> basis;
  CHECK_THROWS_AS(basis.compute(mesh, 10, CGAL::parameters::default_values(), traits),
                  CGAL::Spectral_deformation_error);
  CHECK(basis.empty());
}

TEST_CASE("Partition of unity basis: small meshes are solved exactly", "[pou]")
{
  const Surface_mesh mesh = to_mesh<Surface_mesh>(icosphere(3)); // 642 vertices < 8 × 3 × 200
  const CGAL::Manifold_harmonics_basis<Surface_mesh, Partition_of_unity> approximate(mesh, 9);
  const CGAL::Manifold_harmonics_basis<Surface_mesh> exact(mesh, 9);
  CHECK((approximate.eigenvalues() - exact.eigenvalues()).cwiseAbs().maxCoeff() < 1e-8);
}

TEST_CASE("Partition of unity basis: the exact threshold decides what runs, and the progress says it", "[pou]")
{
  typedef Partition_of_unity::Progress Progress;
  const Surface_mesh mesh = to_mesh<Surface_mesh>(icosphere(5)); // 10242 vertices
  const Eigen::Index n = static_cast<Eigen::Index>(num_vertices(mesh));
  const std::size_t m = 16;
  Partition_of_unity traits;
  traits.set_number_of_samples(400);
  std::vector<Progress::Stage> stages;
  traits.set_progress_callback([&stages](const Progress& p) {
    stages.push_back(p.stage);
    CHECK(p.number_of_vertices == 10242);
    CHECK(p.number_of_eigenpairs == 16);
  });

  // 10242 vertices against 8 per function of 1200: approximated.
  CHECK_FALSE(traits.solves_exactly(m, n));
  const CGAL::Manifold_harmonics_basis<Surface_mesh, Partition_of_unity> approximate(
      mesh, m, CGAL::parameters::default_values(), traits);
  CHECK(stages == std::vector<Progress::Stage>{Progress::APPROXIMATION, Progress::FINISHED});

  // An infinite threshold: the exact solver, its stages, its eigenpairs.
  stages.clear();
  traits.set_exact_threshold(std::numeric_limits<double>::infinity());
  CHECK(traits.solves_exactly(m, n));
  const CGAL::Manifold_harmonics_basis<Surface_mesh, Partition_of_unity> exact_through_traits(
      mesh, m, CGAL::parameters::default_values(), traits);
  const CGAL::Manifold_harmonics_basis<Surface_mesh> exact(mesh, m);
  REQUIRE(stages.size() >= 3);
  CHECK(stages.front() == Progress::FACTORIZATION);
  CHECK(std::count(stages.begin(), stages.end(), Progress::ITERATION) >= 1);
  CHECK(std::count(stages.begin(), stages.end(), Progress::APPROXIMATION) == 0);
  CHECK(stages.back() == Progress::FINISHED);
  CHECK((exact_through_traits.eigenvalues() - exact.eigenvalues()).cwiseAbs().maxCoeff() < 1e-12);
  CHECK((exact_through_traits.basis() - exact.basis()).cwiseAbs().maxCoeff() < 1e-12);
  // The approximation's eigenvalues are upper bounds, not the exact ones.
  CHECK((approximate.eigenvalues() - exact.eigenvalues()).tail(m - 1).minCoeff() > 0);
}

TEST_CASE("Partition of unity basis: deformations reproduce rigid motions and follow the exact basis",
          "[pou]")
{
  typedef CGAL::Spectral_surface_mesh_deformation<Surface_mesh, CGAL::Default, CGAL::Default,
                                                  CGAL::SPECTRAL_DUAL_LAPLACIAN, Partition_of_unity>
      Approximate;
  typedef CGAL::Spectral_surface_mesh_deformation<Surface_mesh, CGAL::Default, CGAL::Default,
                                                  CGAL::SPECTRAL_DUAL_LAPLACIAN,
                                                  CGAL::Block_lanczos_eigensolver_traits<>>
      Exact;
  const double pi = 3.14159265358979323846;

  // A bar of 16k vertices, bottom fixed, top bent by 60 degrees.
  auto deform = [&](auto& deformation, Surface_mesh& mesh, const Eigen::Matrix3d& rotation,
                    const Eigen::Vector3d& center, bool move_bottom, unsigned int iterations,
                    double tolerance) {
    deformation.insert_roi_vertices(vertices(mesh).begin(), vertices(mesh).end());
    std::vector<SM_vertex> moved;
    for(auto v : vertices(mesh))
    {
      const double z = mesh.point(v).z();
      if(z < 0.3 || z > 4.7)
        deformation.insert_control_vertex(v);
      if(z > 4.7 || (move_bottom && z < 0.3))
        moved.push_back(v);
    }
    deformation.set_number_of_frequencies(50);
    for(SM_vertex v : moved)
    {
      const Point& p = mesh.point(v);
      const Eigen::Vector3d q = center + rotation * (Eigen::Vector3d(p.x(), p.y(), p.z()) - center);
      deformation.set_target_position(v, Point(q[0], q[1], q[2]));
    }
    deformation.deform(iterations, tolerance);
    INFO(deformation.deform_report().message);
    REQUIRE(deformation.deform_report().success);
  };
  const Soup soup = bar(200, 20);
  const Eigen::MatrixXd rest = positions_of(to_mesh<Surface_mesh>(soup));
  const double diagonal = (rest.colwise().maxCoeff() - rest.colwise().minCoeff()).norm();
  REQUIRE(rest.rows() > 8 * 3 * 500); // 10 m samples: the approximation runs

  {
    Surface_mesh mesh = to_mesh<Surface_mesh>(soup);
    Approximate deformation(mesh);
    const Eigen::Matrix3d turn = Eigen::AngleAxisd(2.0, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
    deform(deformation, mesh, turn, Eigen::Vector3d::Zero(), true, 2000, 1e-13);
    CHECK((positions_of(mesh) - rest * turn.transpose()).rowwise().norm().maxCoeff() < 1e-6 * diagonal);
  }

  const Eigen::Matrix3d bend = Eigen::AngleAxisd(pi / 3, Eigen::Vector3d::UnitX()).toRotationMatrix();
  const Eigen::Vector3d center(0, 0, 5.0);
  Surface_mesh approximate_mesh = to_mesh<Surface_mesh>(soup), exact_mesh = to_mesh<Surface_mesh>(soup);
  Approximate approximate(approximate_mesh);
  Exact exact(exact_mesh);
  deform(approximate, approximate_mesh, bend, center, false, 10, 0.0);
  deform(exact, exact_mesh, bend, center, false, 10, 0.0);
  const Eigen::MatrixXd a = positions_of(approximate_mesh), e = positions_of(exact_mesh);
  const double largest = (a - e).rowwise().norm().maxCoeff() / diagonal;
  const double moved = (e - rest).rowwise().norm().maxCoeff() / diagonal;
  INFO("largest distance to the result with the exact basis " << largest << " of the diagonal; the top moved by "
                                                               << moved);
  CHECK(largest < 0.01);
  CHECK(moved > 0.1);
}

TEST_CASE("Partition of unity basis: the default number of samples grows with the mesh between 10 m and 20 m",
          "[pou]")
{
  Partition_of_unity traits;
  const Eigen::Index m = 100, per_sample = Partition_of_unity::vertices_per_sample();
  CHECK(traits.number_of_samples(m) == 10 * m);                        // size not given
  CHECK(traits.number_of_samples(m, 5 * per_sample * m) == 10 * m);     // small meshes: the floor
  CHECK(traits.number_of_samples(m, 15 * per_sample * m) == 15 * m);    // in between: one per vertices_per_sample()
  CHECK(traits.number_of_samples(m, 100 * per_sample * m) == 20 * m);   // large meshes: the ceiling
  CHECK(traits.number_of_samples(5, 1000) == 200);                      // at least 200
  traits.set_number_of_samples(345);
  CHECK(traits.number_of_samples(m, 100 * per_sample * m) == 345);      // a set value wins
}

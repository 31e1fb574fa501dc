// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include "test_meshes.h"

#include <CGAL/Manifold_harmonics_basis.h>
#include <CGAL/Spectral_deformation/Spectra_eigensolver_traits.h>
#include <CGAL/Spectral_deformation/cotangent_operators.h>
#include <CGAL/Spectral_deformation/internal/Eigensolvers/Eigenvalue_count.h>
#include <CGAL/Spectral_deformation/internal/Eigensolvers/Single_vector_lanczos.h>
#include <CGAL/Spectral_deformation/internal/Linear_algebra/Dense_products.h>
#include <CGAL/Spectral_deformation/internal/Linear_algebra/Dirichlet_system.h>

#include <catch2/catch.hpp>

#ifdef _OPENMP
#include <omp.h>
#endif

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <cstdlib>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

using namespace test_meshes;
typedef CGAL::Manifold_harmonics_basis<Surface_mesh> Basis;
typedef CGAL::Spectral_deformation_error Error;

namespace {

Eigen::MatrixXd positions_of(const Surface_mesh& mesh)
{
  Eigen::MatrixXd x(mesh.number_of_vertices(), 3);
  for(auto v : mesh.vertices())
  {
    const Point& p = mesh.point(v);
    x.row(v.idx()) << p.x(), p.y(), p.z();
  }
  return x;
}

// Largest principal angle (as its sine) between the column spaces of A and B,
// both M-orthonormal: ||B - A Aᵀ M B|| measured column-wise in the M-norm.
double subspace_distance(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B,
                         const Eigen::VectorXd& mass)
{
  const Eigen::MatrixXd residual = B - A * (A.transpose() * mass.asDiagonal() * B);
  const Eigen::MatrixXd gram = residual.transpose() * mass.asDiagonal() * residual;
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(gram);
  return std::sqrt((std::max)(0.0, eig.eigenvalues().maxCoeff()));
}

template <class Function>
Error::Code error_code_of(Function f)
{
  try
  {
    f();
  }
  catch(const Error& e)
  {
    INFO(e.what());
    CHECK(std::string(e.what()).size() > 10);
    return e.code();
  }
  FAIL("no Spectral_deformation_error was thrown");
  return Error::INVALID_ARGUMENT;
}

} // namespace

TEST_CASE("cotangent operators: symmetry, zero row sums, area, linear precision", "[operators]")
{
  const Surface_mesh plane = to_mesh<Surface_mesh>(bumpy_plane(12, 0.0)); // flat
  const Eigen::SparseMatrix<double> Q = CGAL::cotangent_stiffness_matrix(plane);
  const Eigen::SparseMatrix<double> M = CGAL::lumped_mass_matrix(plane);
  const Eigen::Index n = Q.rows();

  CHECK((Eigen::MatrixXd(Q) - Eigen::MatrixXd(Q).transpose()).cwiseAbs().maxCoeff() < 1e-14);
  CHECK((Q * Eigen::VectorXd::Ones(n)).cwiseAbs().maxCoeff() < 1e-12);
  CHECK(M.sum() == Approx(1.0).epsilon(1e-12)); // the unit square

  // On a flat mesh the cotangent Laplacian of a linear function vanishes at
  // every interior vertex.
  const Eigen::MatrixXd x = positions_of(plane);
  const Eigen::VectorXd linear = 2.0 * x.col(0) - 3.0 * x.col(1) + Eigen::VectorXd::Constant(n, 0.5);
  const Eigen::VectorXd Qlinear = Q * linear;
  for(auto v : plane.vertices())
    if(!plane.is_border(v))
      CHECK(std::abs(Qlinear[v.idx()]) < 1e-12);

  // Positive semi-definite: xᵀQx is the Dirichlet energy, ≥ 0.
  const Eigen::VectorXd bumpy = x.col(0).array().square() + x.col(1).array().sin();
  CHECK(bumpy.dot(Q * bumpy) > 0);
}

TEST_CASE("sphere spectrum: l(l+1)/R^2 with multiplicities 2l+1", "[basis]")
{
  // 2562 vertices: above the dense threshold, so this is the block Lanczos path.
  const double R = 2.0;
  const Surface_mesh sphere = to_mesh<Surface_mesh>(icosphere(4, R));
  const Basis basis(sphere, 25);
  const Eigen::VectorXd& lambda = basis.eigenvalues();
  REQUIRE(lambda.size() == 25);
  for(Eigen::Index k = 1; k < 25; ++k)
    CHECK(lambda[k] >= lambda[k - 1]);

  // The cotangent Laplacian converges with O(h²) and the error of the l-th
  // eigenvalue grows like l(l+1)·h²; at 2562 vertices (h ≈ 0.076·R) the
  // measured relative error of l ≤ 4 is 0.67%. 1% leaves a margin
  // but still separates every cluster (l=4 and l=5 differ by 50%).
  CHECK(std::abs(lambda[0]) < 1e-8);
  Eigen::Index k = 1;
  for(int l = 1; l <= 4; ++l)
  {
    const double exact = l * (l + 1) / (R * R);
    for(int copy = 0; copy < 2 * l + 1; ++copy, ++k)
    {
      INFO("l = " << l << ", eigenvalue " << k << " = " << lambda[k]);
      CHECK(std::abs(lambda[k] - exact) < 0.01 * exact);
    }
  }
}

TEST_CASE("basis is M-orthonormal and solves the generalized problem", "[basis]")
{
  // The default solver (on this bar of a few hundred vertices the
  // single-vector method, checked, to its tolerance of 1e-6) and the dense
  // one (exact).
  const Surface_mesh mesh = to_mesh<Surface_mesh>(bar(30, 4));
  REQUIRE(std::ptrdiff_t(num_vertices(mesh)) > CGAL::Block_lanczos_eigensolver_traits<>().dense_threshold());
  const Basis basis(mesh, 40);
  const Basis dense_basis(mesh, 40, CGAL::parameters::default_values(),
                          CGAL::Block_lanczos_eigensolver_traits<>(1e-6, 0, 0, 100000));
  const Eigen::MatrixXd& H = basis.basis();
  const Eigen::VectorXd& mass = basis.mass();
  const Eigen::MatrixXd gram = H.transpose() * mass.asDiagonal() * H;
  CHECK((gram - Eigen::MatrixXd::Identity(40, 40)).cwiseAbs().maxCoeff() < 1e-9);

  const Eigen::SparseMatrix<double> Q = CGAL::cotangent_stiffness_matrix(mesh);
  for(const Basis* computed : {&basis, &dense_basis})
  {
    const double tolerance = computed == &basis ? 1e-5 : 1e-7;
    for(Eigen::Index k = 0; k < 40; ++k)
    {
      const Eigen::VectorXd Mh = mass.cwiseProduct(computed->basis().col(k));
      const Eigen::VectorXd residual = Q * computed->basis().col(k) - computed->eigenvalues()[k] * Mh;
      INFO((computed == &basis ? "default" : "dense") << " solver, eigenpair " << k);
      CHECK(residual.norm() < tolerance * (1.0 + computed->eigenvalues()[k]) * Mh.norm());
    }
  }
  // Deterministic signs: the entry of largest magnitude is positive.
  for(Eigen::Index k = 0; k < 40; ++k)
  {
    Eigen::Index i;
    H.col(k).cwiseAbs().maxCoeff(&i);
    CHECK(H(i, k) > 0);
  }
}

TEST_CASE("dense and Spectra solvers span the same subspace", "[basis]")
{
  const Surface_mesh mesh = to_mesh<Surface_mesh>(bumpy_plane(24));
  typedef CGAL::Spectra_eigensolver_traits<> Traits;
  typedef CGAL::Manifold_harmonics_basis<Surface_mesh, Traits> Spectra_basis;
  const Spectra_basis lanczos(mesh, 30, CGAL::parameters::default_values(), Traits(1000, 1e-10, 0));
  const Spectra_basis dense(mesh, 30, CGAL::parameters::default_values(), Traits(1000, 1e-10, 100000));
  CHECK((lanczos.eigenvalues() - dense.eigenvalues()).cwiseAbs().maxCoeff() <
        1e-8 * dense.eigenvalues().maxCoeff());
  // Compare subspaces, not vectors: eigenvalues may be (nearly) repeated. Cut
  // at 29 only if 29/30 is not a near-degenerate pair.
  const double gap = dense.eigenvalues()[30 - 1] - dense.eigenvalues()[30 - 2];
  const Eigen::Index cut = gap > 1e-6 * dense.eigenvalues()[29] ? 29 : 28;
  CHECK(subspace_distance(dense.basis().leftCols(cut), lanczos.basis().leftCols(cut),
                          dense.mass()) < 1e-6);
}

TEST_CASE("dense symmetric eigenpairs: some or all eigenvectors computed, the same pairs",
          "[basis][block_lanczos]")
{
  // A quarter or more of the pairs are computed with all eigenvectors
  // (divide and conquer), fewer with only those asked for: both must give
  // the pairs of Eigen's solver (a random matrix: simple eigenvalues).
  std::mt19937 generator(7);
  std::normal_distribution<double> normal;
  const Eigen::Index n = 80;
  Eigen::MatrixXd A(n, n);
  for(Eigen::Index j = 0; j < n; ++j)
    for(Eigen::Index i = 0; i < n; ++i)
      A(i, j) = normal(generator);
  A = (A + A.transpose()).eval();
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> reference(A);
  namespace E = CGAL::Spectral_deformation::internal::Eigensolvers;
  struct Range { Eigen::Index first, count; };
  for(const Range range : {Range{0, 10}, Range{70, 10}, Range{0, 40}, Range{45, 35}, Range{5, 20}})
  {
    INFO("eigenpairs " << range.first << " to " << range.first + range.count - 1);
    Eigen::VectorXd values;
    Eigen::MatrixXd vectors;
    REQUIRE(E::symmetric_eigenpairs_in_range(A, range.first, range.count, values, vectors));
    REQUIRE(values.size() == range.count);
    REQUIRE(vectors.cols() == range.count);
    CHECK((values - reference.eigenvalues().segment(range.first, range.count)).cwiseAbs().maxCoeff() <
          1e-10 * reference.eigenvalues().cwiseAbs().maxCoeff());
    const Eigen::MatrixXd overlap =
        reference.eigenvectors().middleCols(range.first, range.count).transpose() * vectors;
    CHECK((overlap.cwiseAbs() - Eigen::MatrixXd::Identity(range.count, range.count))
              .cwiseAbs()
              .maxCoeff() < 1e-8);
  }
  Eigen::VectorXd largest_values;
  Eigen::MatrixXd largest_vectors;
  REQUIRE(E::largest_symmetric_eigenpairs(A, 30, largest_values, largest_vectors));
  CHECK((largest_values - reference.eigenvalues().tail(30)).cwiseAbs().maxCoeff() <
        1e-10 * reference.eigenvalues().cwiseAbs().maxCoeff());
}

TEST_CASE("block Lanczos, Spectra and the dense solver agree", "[basis][block_lanczos]")
{
  // 2562 vertices; the dense path of both iterative solvers and the fallback
  // to the reference solver are disabled. The sphere's clusters of 2l + 1
  // eigenvalues are the hard case of a block method: it needs a larger
  // subspace than the default.
  const Surface_mesh mesh = to_mesh<Surface_mesh>(icosphere(4, 1.5));
  const Eigen::SparseMatrix<double> Q = CGAL::cotangent_stiffness_matrix(mesh);
  const Eigen::VectorXd mass = CGAL::lumped_mass_matrix(mesh).diagonal();
  const Eigen::Index m = 40;
  Eigen::VectorXd dense_values, block_values, spectra_values;
  Eigen::MatrixXd dense_vectors, block_vectors, spectra_vectors;
  std::string message;
  REQUIRE(CGAL::Spectral_deformation::internal::Eigensolvers::dense_generalized_eigenpairs(
      Q, mass, m, dense_values, dense_vectors, message));

  for(Eigen::Index block_size : {Eigen::Index(1), Eigen::Index(3), Eigen::Index(8), Eigen::Index(16)})
  {
    INFO("block size " << block_size);
    CGAL::Block_lanczos_eigensolver_traits<> block(1e-10, block_size, 12 * m, 0);
    block.set_checked_single_vector(false);
    block.set_reference_fallback(false);
    block.set_reference_threshold(0);
    std::vector<int> stages;
    std::size_t last_solves = 0;
    bool solves_grow = true;
    block.set_progress_callback(
        [&](const CGAL::Block_lanczos_eigensolver_traits<>::Progress& progress) {
          if(stages.empty() || stages.back() != int(progress.stage))
            stages.push_back(int(progress.stage));
          solves_grow = solves_grow && progress.solves >= last_solves &&
                        progress.solves % std::size_t(block_size) == 0 &&
                        progress.subspace_dimension <= progress.maximum_subspace_dimension;
          last_solves = progress.solves;
        });
    REQUIRE(block.compute(Q, mass, m, block_values, block_vectors));
    CHECK(block.error_message().empty());
    typedef CGAL::Block_lanczos_eigensolver_traits<>::Progress Progress;
    CHECK(stages == std::vector<int>{Progress::FACTORIZATION, Progress::ITERATION, Progress::FINISHED});
    CHECK(solves_grow);
    CHECK(last_solves > std::size_t(m));

    CHECK((block_values - dense_values).cwiseAbs().maxCoeff() < 1e-8 * dense_values.maxCoeff());
    // M-orthonormal to rounding, although the Lanczos vectors are only
    // orthogonal to sqrt(eps): the Ritz vectors are orthonormalized at the end.
    const Eigen::MatrixXd gram = block_vectors.transpose() * mass.asDiagonal() * block_vectors;
    CHECK((gram - Eigen::MatrixXd::Identity(m, m)).cwiseAbs().maxCoeff() < 1e-12);
    // The sphere's eigenvalues come in clusters of 2l + 1: compare the
    // subspaces of whole clusters (l ≤ 5 are the first 36 functions).
    CHECK(subspace_distance(dense_vectors.leftCols(36), block_vectors.leftCols(36), mass) < 1e-6);
  }

  CGAL::Spectra_eigensolver_traits<> spectra(1000, 1e-10, 0);
  REQUIRE(spectra.compute(Q, mass, m, spectra_values, spectra_vectors));
  CHECK((spectra_values - block_values).cwiseAbs().maxCoeff() < 1e-8 * dense_values.maxCoeff());
}

TEST_CASE("small problems: the single-vector method checked by an eigenvalue count, clusters included",
          "[basis][block_lanczos]")
{
  // 642 vertices, above the default dense threshold: the default traits run
  // the single-vector Lanczos method and count the eigenvalues below the
  // largest one it found. The sphere's eigenvalues come in clusters of 2l + 1
  // (split a little by the icosahedral symmetry), whose copies the single
  // vector method can miss: whatever it returns, the result must be the
  // dense solver's.
  const Surface_mesh mesh = to_mesh<Surface_mesh>(icosphere(3, 1.0));
  const Eigen::SparseMatrix<double> Q = CGAL::cotangent_stiffness_matrix(mesh);
  const Eigen::VectorXd mass = CGAL::lumped_mass_matrix(mesh).diagonal();
  REQUIRE(Q.rows() == 642);
  namespace Eigensolvers = CGAL::Spectral_deformation::internal::Eigensolvers;
  for(Eigen::Index m : {Eigen::Index(10), Eigen::Index(40), Eigen::Index(100)})
  {
    INFO("m = " << m);
    CGAL::Block_lanczos_eigensolver_traits<> defaults;
    REQUIRE(defaults.uses_checked_single_vector(Q.rows(), m));
    Eigen::VectorXd dense_values, values;
    Eigen::MatrixXd dense_vectors, vectors;
    std::string message;
    REQUIRE(Eigensolvers::dense_generalized_eigenpairs(Q, mass, m, dense_values, dense_vectors, message));
    // The single-vector method reports a subspace of one vector first,
    // which a block of the block method never is.
    bool single_vector_reported = false;
    defaults.set_progress_callback([&](const CGAL::Block_lanczos_eigensolver_traits<>::Progress& p) {
      single_vector_reported = single_vector_reported || (p.stage == p.ITERATION && p.subspace_dimension == 1);
    });
    REQUIRE(defaults.compute(Q, mass, m, values, vectors));
    CHECK(single_vector_reported);
    CHECK((values - dense_values).cwiseAbs().maxCoeff() < 1e-8 * dense_values.maxCoeff());
    // Whole clusters: l <= 2 (9 functions) for m = 10, l <= 5 (36) for
    // m = 40, l <= 8 (81) for m = 100.
    const Eigen::Index clusters = m == 10 ? 9 : m == 40 ? 36 : 81;
    CHECK(subspace_distance(dense_vectors.leftCols(clusters), vectors.leftCols(clusters), mass) < 1e-6);
    const Eigen::MatrixXd gram = vectors.transpose() * mass.asDiagonal() * vectors;
    CHECK((gram - Eigen::MatrixXd::Identity(m, m)).cwiseAbs().maxCoeff() < 1e-10);
  }

  // Disabled, the block method runs from 8 m <= n on.
  CGAL::Block_lanczos_eigensolver_traits<> block_only;
  block_only.set_checked_single_vector(false);
  bool other_reported = false;
  block_only.set_progress_callback([&](const CGAL::Block_lanczos_eigensolver_traits<>::Progress& p) {
    other_reported = other_reported || p.stage == p.DENSE_SOLVE || p.stage == p.REFERENCE_SOLVE;
  });
  Eigen::VectorXd values;
  Eigen::MatrixXd vectors;
  REQUIRE(block_only.compute(Q, mass, 40, values, vectors));
  CHECK_FALSE(other_reported);

  // Larger problems and more frequencies go to the block method.
  CHECK_FALSE(block_only.uses_checked_single_vector(Q.rows(), 40));
  CGAL::Block_lanczos_eigensolver_traits<> defaults;
  CHECK_FALSE(defaults.uses_checked_single_vector(5001, 10));
  CHECK_FALSE(defaults.uses_checked_single_vector(4100, 100));
  CHECK(defaults.uses_checked_single_vector(3900, 100));
  CHECK_FALSE(defaults.uses_checked_single_vector(642, 200));
  CHECK_FALSE(defaults.uses_checked_single_vector(defaults.dense_threshold(), 10));
}

TEST_CASE("largest tridiagonal eigenpairs: those of Eigen's dense solver", "[basis][block_lanczos]")
{
  // A Lanczos matrix's shape: a positive diagonal decreasing with noise,
  // couplings smaller than it; simple eigenvalues.
  std::mt19937 generator(11);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  namespace E = CGAL::Spectral_deformation::internal::Eigensolvers;
  for(const Eigen::Index k : {Eigen::Index(1), Eigen::Index(2), Eigen::Index(37), Eigen::Index(240)})
  {
    INFO("k = " << k);
    Eigen::VectorXd diagonal(k), subdiagonal = Eigen::VectorXd::Zero(k);
    for(Eigen::Index i = 0; i < k; ++i)
      diagonal[i] = 1.0 / (1.0 + double(i)) + 0.1 * uniform(generator);
    for(Eigen::Index i = 0; i + 1 < k; ++i)
      subdiagonal[i] = 0.05 * uniform(generator);
    Eigen::MatrixXd T = diagonal.asDiagonal();
    for(Eigen::Index i = 0; i + 1 < k; ++i)
      T(i + 1, i) = T(i, i + 1) = subdiagonal[i];
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> reference(T);
    const Eigen::Index count = (std::min)(k, Eigen::Index(30));
    Eigen::VectorXd values;
    Eigen::MatrixXd vectors;
    REQUIRE(E::largest_tridiagonal_eigenpairs(diagonal, subdiagonal, count, values, vectors));
    REQUIRE(values.size() == count);
    REQUIRE(vectors.rows() == k);
    REQUIRE(vectors.cols() == count);
    CHECK((values - reference.eigenvalues().tail(count)).cwiseAbs().maxCoeff() < 1e-13);
    CHECK((T * vectors - vectors * values.asDiagonal()).cwiseAbs().maxCoeff() < 1e-12);
    CHECK((vectors.transpose() * vectors - Eigen::MatrixXd::Identity(count, count)).cwiseAbs().maxCoeff() <
          1e-12);
  }
  Eigen::VectorXd values;
  Eigen::MatrixXd vectors;
  CHECK_FALSE(E::largest_tridiagonal_eigenpairs(Eigen::VectorXd::Ones(4), Eigen::VectorXd::Zero(4), 5, values,
                                                vectors));
}

TEST_CASE("single-vector Lanczos: checks spaced by their cost in steps", "[basis][block_lanczos]")
{
  namespace E = CGAL::Spectral_deformation::internal::Eigensolvers;
  // A check costs about k² / n steps: near convergence, where the forecast
  // asks for one more step (one pair missing, converging slowly), the next
  // check still comes that many steps later on small problems (at most
  // k / 4), and as the forecast says on large ones.
  auto next_after_slow_pair = [](Eigen::Index k, Eigen::Index n) {
    E::Convergence_forecast forecast;
    E::Ritz_pairs ritz;
    ritz.converged = 98;
    ritz.slowest = 10.0;
    E::next_single_vector_check(forecast, k - 10, n, 99, ritz);
    ritz.slowest = 1.001;
    return E::next_single_vector_check(forecast, k, n, 99, ritz);
  };
  CHECK(next_after_slow_pair(200, 1000) == 240);
  CHECK(next_after_slow_pair(200, 550) == 250);
  CHECK(next_after_slow_pair(200, 100000) <= 200 + 200 / 16);
  CHECK(next_after_slow_pair(200, 100000) > 200);
}

TEST_CASE("single-vector Lanczos: the dense solver's pairs, the constants deflated, a clear failure when the "
          "subspace is too small",
          "[basis][block_lanczos]")
{
  namespace E = CGAL::Spectral_deformation::internal::Eigensolvers;
  auto ignore = [](Eigen::Index) {};
  // A bumpy plane (961 vertices, a boundary): simple eigenvalues.
  {
    const Surface_mesh mesh = to_mesh<Surface_mesh>(bumpy_plane(30));
    const Eigen::SparseMatrix<double> Q = CGAL::cotangent_stiffness_matrix(mesh);
    const Eigen::VectorXd mass = CGAL::lumped_mass_matrix(mesh).diagonal();
    const Eigen::Index m = 60;
    Eigen::VectorXd dense_values, values;
    Eigen::MatrixXd dense_vectors, vectors;
    std::string message;
    REQUIRE(E::dense_generalized_eigenpairs(Q, mass, m, dense_values, dense_vectors, message));
    E::Single_vector_lanczos_settings settings;
    settings.max_dimension = 8 * m;
    settings.tolerance = 1e-10;
    Eigen::Index largest_subspace = 0, checks = 0, last_converged = 0;
    REQUIRE(E::single_vector_lanczos_eigenpairs<CGAL::Default_eigensolver_sparse_spd_solver_traits>(
        Q, mass, m, settings, [&](Eigen::Index k) { largest_subspace = k; },
        [&](Eigen::Index converged) {
          ++checks;
          last_converged = converged;
        },
        values, vectors, message));
    CHECK(message.empty());
    CHECK(last_converged == m);
    CHECK(checks >= 1);
    CHECK(largest_subspace > m);
    CHECK(largest_subspace < 4 * m);
    CHECK(values[0] == 0.0);
    CHECK((values - dense_values).tail(m - 1).cwiseQuotient(dense_values.tail(m - 1)).cwiseAbs().maxCoeff() <
          1e-10);
    const Eigen::MatrixXd gram = vectors.transpose() * mass.asDiagonal() * vectors;
    CHECK((gram - Eigen::MatrixXd::Identity(m, m)).cwiseAbs().maxCoeff() < 1e-12);
    // Each eigenvector is the dense solver's, up to its sign.
    for(Eigen::Index i = 0; i < m; ++i)
    {
      INFO("eigenvector " << i);
      const double cosine = dense_vectors.col(i).dot(mass.asDiagonal() * vectors.col(i));
      CHECK(std::abs(cosine) > 1.0 - 1e-8);
    }
    // The same start, the same result.
    Eigen::VectorXd again_values;
    Eigen::MatrixXd again_vectors;
    REQUIRE(E::single_vector_lanczos_eigenpairs<CGAL::Default_eigensolver_sparse_spd_solver_traits>(
        Q, mass, m, settings, ignore, ignore, again_values, again_vectors, message));
    CHECK(again_values == values);
    CHECK(again_vectors == vectors);

    // Too small a subspace: a failure with its reason, never a partial result.
    settings.max_dimension = m + 5;
    Eigen::VectorXd untouched_values = Eigen::VectorXd::Constant(3, 7.0);
    message.clear();
    CHECK_FALSE(E::single_vector_lanczos_eigenpairs<CGAL::Default_eigensolver_sparse_spd_solver_traits>(
        Q, mass, m, settings, ignore, ignore, untouched_values, again_vectors, message));
    CHECK(message.find("did not converge") != std::string::npos);
    CHECK(untouched_values == Eigen::VectorXd::Constant(3, 7.0));
  }
  // Two spheres: the constant of each one returned as an eigenvector of 0,
  // the rest from the Krylov subspace orthogonal to them.
  {
    const Surface_mesh spheres = to_mesh<Surface_mesh>(two_spheres(3));
    const Eigen::SparseMatrix<double> Q = CGAL::cotangent_stiffness_matrix(spheres);
    const Eigen::VectorXd mass = CGAL::lumped_mass_matrix(spheres).diagonal();
    E::Single_vector_lanczos_settings settings;
    settings.max_dimension = 200;
    Eigen::VectorXd values;
    Eigen::MatrixXd vectors;
    std::string message;
    REQUIRE(E::single_vector_lanczos_eigenpairs<CGAL::Default_eigensolver_sparse_spd_solver_traits>(
        Q, mass, 12, settings, ignore, ignore, values, vectors, message));
    CHECK(values[0] == 0.0);
    CHECK(values[1] == 0.0);
    CHECK(values[2] > 1.0);
    CHECK((Q * vectors.leftCols(2)).cwiseAbs().maxCoeff() < 1e-12);
    const Eigen::MatrixXd gram = vectors.transpose() * mass.asDiagonal() * vectors;
    CHECK((gram - Eigen::MatrixXd::Identity(12, 12)).cwiseAbs().maxCoeff() < 1e-12);
    // Only the constants wanted: no iteration at all.
    bool solved = false;
    REQUIRE(E::single_vector_lanczos_eigenpairs<CGAL::Default_eigensolver_sparse_spd_solver_traits>(
        Q, mass, 2, settings, [&](Eigen::Index) { solved = true; }, ignore, values, vectors, message));
    CHECK_FALSE(solved);
    CHECK(values == Eigen::VectorXd::Zero(2));
  }
}

TEST_CASE("the eigenvalue count finds a missing copy, and accepts any copies of the largest eigenvalue",
          "[basis][block_lanczos]")
{
  // Two unit spheres: the eigenvalue 0 twice, then the l = 1 eigenvalue
  // (about 2) six times, then l = 2 ten times.
  namespace Eigensolvers = CGAL::Spectral_deformation::internal::Eigensolvers;
  const Surface_mesh spheres = to_mesh<Surface_mesh>(two_spheres(3));
  const Eigen::SparseMatrix<double> Q = CGAL::cotangent_stiffness_matrix(spheres);
  const Eigen::VectorXd mass = CGAL::lumped_mass_matrix(spheres).diagonal();
  Eigen::VectorXd values;
  Eigen::MatrixXd vectors;
  std::string message;
  REQUIRE(Eigensolvers::dense_generalized_eigenpairs(Q, mass, 20, values, vectors, message));
  REQUIRE(values(7) < 2.2);
  REQUIRE(values(8) > 5.0);
  // The count below a shift is the count of the exact spectrum.
  CHECK(Eigensolvers::eigenvalues_below(Q, mass, 1.0) == 2);
  CHECK(Eigensolvers::eigenvalues_below(Q, mass, 0.5 * (values(7) + values(8))) == 8);
  CHECK(Eigensolvers::eigenvalues_below(Q, mass, 0.5 * (values(17) + values(18))) == 18);

  // The smallest eigenvalues, complete.
  CHECK(Eigensolvers::smallest_eigenvalues_complete(Q, mass, values.head(8)));
  CHECK(Eigensolvers::smallest_eigenvalues_complete(Q, mass, values.head(18)));
  // Four of the six copies of the cluster at the top: any of them will do.
  CHECK(Eigensolvers::smallest_eigenvalues_complete(Q, mass, values.head(6)));
  // A copy missing below the top: the l = 1 cluster given five times, then
  // an l = 2 eigenvalue.
  Eigen::VectorXd missing(9);
  missing << values.head(7), values(8), values(9);
  CHECK_FALSE(Eigensolvers::smallest_eigenvalues_complete(Q, mass, missing));
  // One zero missing (one component's constant).
  Eigen::VectorXd no_second_zero(7);
  no_second_zero << values(0), values.segment(2, 6);
  CHECK_FALSE(Eigensolvers::smallest_eigenvalues_complete(Q, mass, no_second_zero));
  // Only zeros: no positive shift separates them, so no answer.
  CHECK_FALSE(Eigensolvers::smallest_eigenvalues_complete(Q, mass, values.head(2)));
}

TEST_CASE("block Lanczos: several components, small problems and bad arguments",
          "[basis][block_lanczos]")
{
  // Two components give a zero eigenvalue of multiplicity 2, the two unit
  // spheres the l = 1 eigenvalue six times: more than a block of 4.
  const Surface_mesh spheres = to_mesh<Surface_mesh>(two_spheres(3));
  const Eigen::SparseMatrix<double> Q = CGAL::cotangent_stiffness_matrix(spheres);
  const Eigen::VectorXd mass = CGAL::lumped_mass_matrix(spheres).diagonal();
  Eigen::VectorXd values, dense_values;
  Eigen::MatrixXd vectors, dense_vectors;
  std::string message;
  REQUIRE(CGAL::Spectral_deformation::internal::Eigensolvers::dense_generalized_eigenpairs(
      Q, mass, 12, dense_values, dense_vectors, message));
  CGAL::Block_lanczos_eigensolver_traits<> block(1e-10, 4, 200, 0);
  block.set_checked_single_vector(false);
  block.set_reference_fallback(false);
  block.set_reference_threshold(0);
  REQUIRE(block.compute(Q, mass, 12, values, vectors));
  CHECK((values - dense_values).cwiseAbs().maxCoeff() < 1e-8 * dense_values.maxCoeff());
  CHECK(subspace_distance(dense_vectors.leftCols(8), vectors.leftCols(8), mass) < 1e-6);

  // Small problems (here 1284 vertices against a threshold of 2000) go to
  // the dense solver: exact, and reported as such.
  CGAL::Block_lanczos_eigensolver_traits<> small(1e-10, 0, 0, 2000);
  bool dense_reported = false;
  small.set_progress_callback([&](const CGAL::Block_lanczos_eigensolver_traits<>::Progress& p) {
    dense_reported = dense_reported || p.stage == p.DENSE_SOLVE;
  });
  REQUIRE(small.compute(Q, mass, 12, values, vectors));
  CHECK(dense_reported);
  CHECK((values - dense_values).cwiseAbs().maxCoeff() < 1e-10 * dense_values.maxCoeff());

  // Below reference_threshold() the reference solver runs.
  CGAL::Block_lanczos_eigensolver_traits<> delegating;
  delegating.set_checked_single_vector(false);
  delegating.set_reference_threshold(10000);
  bool delegated = false;
  delegating.set_progress_callback(
      [&](const CGAL::Block_lanczos_eigensolver_traits<>::Progress& p) {
        delegated = delegated || p.stage == p.REFERENCE_SOLVE;
      });
  REQUIRE(delegating.compute(Q, mass, 12, values, vectors));
  CHECK(delegated);
  CHECK((values - dense_values).cwiseAbs().maxCoeff() < 1e-8 * dense_values.maxCoeff());

  // When a typical subspace (4 m columns) does not fit in the memory limit,
  // the reference solver runs directly.
  CGAL::Block_lanczos_eigensolver_traits<> frugal(1e-10, 4, 200, 0);
  frugal.set_checked_single_vector(false);
  frugal.set_memory_limit(sizeof(double) * std::size_t(Q.rows()) * 40);
  bool frugal_delegated = false;
  frugal.set_progress_callback([&](const CGAL::Block_lanczos_eigensolver_traits<>::Progress& p) {
    frugal_delegated = frugal_delegated || p.stage == p.REFERENCE_SOLVE;
  });
  REQUIRE(frugal.compute(Q, mass, 12, values, vectors));
  CHECK(frugal_delegated);
  frugal_delegated = false;
  frugal.set_memory_limit(sizeof(double) * std::size_t(Q.rows()) * 220);
  REQUIRE(frugal.compute(Q, mass, 12, values, vectors));
  CHECK_FALSE(frugal_delegated);

  // With a subspace too small for the repeated eigenvalues the reference
  // solver takes over, and says so.
  CGAL::Block_lanczos_eigensolver_traits<> falling_back(1e-10, 4, 48, 0);
  falling_back.set_checked_single_vector(false);
  falling_back.set_reference_threshold(0);
  bool reference_reported = false;
  falling_back.set_progress_callback(
      [&](const CGAL::Block_lanczos_eigensolver_traits<>::Progress& p) {
        reference_reported = reference_reported || p.stage == p.REFERENCE_SOLVE;
      });
  REQUIRE(falling_back.compute(Q, mass, 12, values, vectors));
  CHECK(falling_back.error_message().empty());
  CHECK((values - dense_values).cwiseAbs().maxCoeff() < 1e-8 * dense_values.maxCoeff());
  CHECK(reference_reported);

  CHECK_FALSE(block.compute(Q, mass, 0, values, vectors));
  CHECK(!block.error_message().empty());
  CHECK_FALSE(block.compute(Q, mass, Q.rows() + 1, values, vectors));
}

#ifdef CGAL_SSMD_USE_OPENBLAS
extern "C" int openblas_get_num_threads(void);
#endif

TEST_CASE("block Lanczos: settings of the process change only on request",
          "[basis][block_lanczos]")
{
  // 1681 vertices: the block method runs (above the dense threshold, the
  // checked single-vector method of small problems disabled).
  const Surface_mesh mesh = to_mesh<Surface_mesh>(bumpy_plane(40));
  const Eigen::SparseMatrix<double> Q = CGAL::cotangent_stiffness_matrix(mesh);
  const Eigen::VectorXd mass = CGAL::lumped_mass_matrix(mesh).diagonal();
  typedef CGAL::Block_lanczos_eigensolver_traits<> Traits;
  Eigen::VectorXd values[2];
  Eigen::MatrixXd vectors[2];
  for(int tuning = 0; tuning < 2; ++tuning)
  {
    INFO("process-wide tuning " << tuning);
    Traits block;
    block.set_checked_single_vector(false);
    CHECK_FALSE(block.process_wide_tuning());
    block.set_process_wide_tuning(tuning == 1);
    CHECK(block.process_wide_tuning() == (tuning == 1));
    int blas_threads_before = 1;
    bool blas_threads_as_expected = true;
#ifdef CGAL_SSMD_USE_OPENBLAS
    blas_threads_before = openblas_get_num_threads();
    // While the subspace grows, OpenBLAS runs on one thread only when the
    // tuning was asked for.
    block.set_progress_callback([&](const Traits::Progress& progress) {
      if(progress.stage == progress.ITERATION)
        blas_threads_as_expected =
            blas_threads_as_expected &&
            openblas_get_num_threads() == (tuning == 1 ? 1 : blas_threads_before);
    });
#endif
    REQUIRE(block.compute(Q, mass, 20, values[tuning], vectors[tuning]));
    CHECK(blas_threads_as_expected);
#ifdef CGAL_SSMD_USE_OPENBLAS
    CHECK(openblas_get_num_threads() == blas_threads_before);
#endif
  }
  // The same eigenpairs either way (to rounding: a multi-threaded BLAS may
  // sum in another order).
  CHECK((values[0] - values[1]).cwiseAbs().maxCoeff() < 1e-10 * values[0].maxCoeff());
  CHECK(subspace_distance(vectors[0].leftCols(19), vectors[1].leftCols(19), mass) < 1e-6);
}

TEST_CASE("dense products: the pieces of the BLAS calls make the whole product, for every shape",
          "[basis][dense_products]")
{
  using CGAL::Spectral_deformation::internal::Linear_algebra::dense_product;
  // Shapes of the eigensolver (a tall block against a few columns, a panel
  // of Ritz vectors, a Gram matrix over a long inner dimension) and odd ones,
  // each far above the size of one piece or just at it; operands are blocks
  // of larger matrices (outer strides larger than their rows).
  struct Shape
  {
    Eigen::Index rows, cols, depth;
  };
  const Shape shapes[] = {{320, 8, 13552}, {13552, 8, 320}, {512, 100, 320}, {100, 100, 9000},
                          {7, 300, 1000},  {1, 1, 5000},    {64, 64, 64},    {3, 2, 1}};
  std::mt19937 generator(7);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  auto random_matrix = [&](Eigen::Index r, Eigen::Index c) {
    Eigen::MatrixXd X(r + 3, c + 2);
    for(Eigen::Index j = 0; j < X.cols(); ++j)
      for(Eigen::Index i = 0; i < X.rows(); ++i)
        X(i, j) = uniform(generator);
    return X;
  };
  for(const Shape& shape : shapes)
    for(int transposes = 0; transposes < 4; ++transposes)
    {
      const bool ta = (transposes & 1) != 0, tb = (transposes & 2) != 0;
      INFO(shape.rows << " x " << shape.cols << " x " << shape.depth << ", transposes " << ta << tb);
      Eigen::MatrixXd A_storage = ta ? random_matrix(shape.depth, shape.rows) : random_matrix(shape.rows, shape.depth);
      Eigen::MatrixXd B_storage = tb ? random_matrix(shape.cols, shape.depth) : random_matrix(shape.depth, shape.cols);
      Eigen::MatrixXd C_storage = random_matrix(shape.rows, shape.cols);
      const auto A = ta ? A_storage.block(1, 1, shape.depth, shape.rows) : A_storage.block(1, 1, shape.rows, shape.depth);
      const auto B = tb ? B_storage.block(2, 0, shape.cols, shape.depth) : B_storage.block(2, 0, shape.depth, shape.cols);
      const Eigen::MatrixXd opA = ta ? Eigen::MatrixXd(A.transpose()) : Eigen::MatrixXd(A);
      const Eigen::MatrixXd opB = tb ? Eigen::MatrixXd(B.transpose()) : Eigen::MatrixXd(B);
      const Eigen::MatrixXd C_before = C_storage;
      const Eigen::MatrixXd expected =
          0.25 * C_before.block(1, 1, shape.rows, shape.cols) + (-1.5) * (opA * opB);
      auto C = C_storage.block(1, 1, shape.rows, shape.cols);
      dense_product(ta, A, tb, B, -1.5, 0.25, C);
      // Each entry is a sum of `depth` products of entries of at most 1.
      const double tolerance = 1e-15 * static_cast<double>(shape.depth) + 1e-15;
      CHECK((C_storage.block(1, 1, shape.rows, shape.cols) - expected).cwiseAbs().maxCoeff() < tolerance);
      // Nothing of C outside the block changes.
      Eigen::MatrixXd outside = C_storage - C_before;
      outside.block(1, 1, shape.rows, shape.cols).setZero();
      CHECK(outside.cwiseAbs().maxCoeff() == 0.0);
      // beta = 0 ignores what C held, even non-finite values.
      C.setConstant(std::numeric_limits<double>::quiet_NaN());
      dense_product(ta, A, tb, B, 1.0, 0.0, C);
      CHECK((C - opA * opB).cwiseAbs().maxCoeff() < tolerance);
    }
}

// Its parallel sums are split in pieces fixed by the sizes and added in a
// fixed order, and its solves split by subtrees run the same operations on
// one thread: the basis does not depend on the number of OpenMP threads.
// 17,161 vertices: the tall products are split (from 16,384 rows).
TEST_CASE("block Lanczos: the same basis to the last bit on one and two threads", "[basis][block_lanczos]")
{
#ifdef _OPENMP
  const Surface_mesh mesh = to_mesh<Surface_mesh>(bumpy_plane(130));
  REQUIRE(num_vertices(mesh) >= 16384);
  const Eigen::SparseMatrix<double> Q = CGAL::cotangent_stiffness_matrix(mesh);
  const Eigen::VectorXd mass = CGAL::lumped_mass_matrix(mesh).diagonal();
  Eigen::VectorXd values[2];
  Eigen::MatrixXd vectors[2];
  const int threads = omp_get_max_threads();
  for(int t = 0; t < 2; ++t)
  {
    omp_set_num_threads(t + 1);
    CGAL::Block_lanczos_eigensolver_traits<> block;
    const bool computed = block.compute(Q, mass, 30, values[t], vectors[t]);
    omp_set_num_threads(threads);
    REQUIRE(computed);
  }
  CHECK(values[0] == values[1]);
  CHECK(vectors[0] == vectors[1]);
#else
  SUCCEED("without OpenMP the eigensolver runs on one thread");
#endif
}

TEST_CASE("block Lanczos: the constants of each component are deflated, only for a Laplacian",
          "[basis][block_lanczos]")
{
  const Surface_mesh spheres = to_mesh<Surface_mesh>(two_spheres(3));
  const Eigen::SparseMatrix<double> Q = CGAL::cotangent_stiffness_matrix(spheres);
  const Eigen::VectorXd mass = CGAL::lumped_mass_matrix(spheres).diagonal();
  const CGAL::Spectral_deformation::internal::Eigensolvers::Laplacian_null_space null_space(Q, mass);
  REQUIRE(null_space.dimension() == 2);
  const Eigen::MatrixXd constants = null_space.basis();
  CHECK((constants.transpose() * mass.asDiagonal() * constants - Eigen::MatrixXd::Identity(2, 2))
            .cwiseAbs()
            .maxCoeff() < 1e-14);
  CHECK((Q * constants).cwiseAbs().maxCoeff() < 1e-12 * Q.diagonal().maxCoeff());
  Eigen::MatrixXd x = Eigen::MatrixXd::Random(Q.rows(), 3);
  null_space.project_out(x);
  CHECK((constants.transpose() * mass.asDiagonal() * x).cwiseAbs().maxCoeff() < 1e-13);

  CGAL::Block_lanczos_eigensolver_traits<> block(1e-10, 4, 200, 0);
  block.set_checked_single_vector(false);
  block.set_reference_fallback(false);
  Eigen::VectorXd values;
  Eigen::MatrixXd vectors;
  // As many frequencies as components: the known constants, without a solve.
  std::size_t solves = 0;
  block.set_progress_callback(
      [&](const CGAL::Block_lanczos_eigensolver_traits<>::Progress& p) { solves = p.solves; });
  REQUIRE(block.compute(Q, mass, 2, values, vectors));
  CHECK(solves == 0);
  CHECK(values.cwiseAbs().maxCoeff() == 0);
  CHECK((vectors - constants).cwiseAbs().maxCoeff() < 1e-14);

  // Q + M is not a Laplacian (its rows do not sum to zero): nothing is
  // deflated, and its spectrum is the Laplacian's moved by one.
  Eigen::SparseMatrix<double> shifted = Q;
  for(Eigen::Index i = 0; i < Q.rows(); ++i)
    shifted.coeffRef(i, i) += mass[i];
  const CGAL::Spectral_deformation::internal::Eigensolvers::Laplacian_null_space nothing_known(shifted, mass);
  CHECK(nothing_known.dimension() == 0);
  // An empty basis of vectors of n entries, which the Ritz vectors' panels
  // take rows of.
  CHECK(nothing_known.basis().rows() == Q.rows());
  CHECK(nothing_known.basis().cols() == 0);
  Eigen::VectorXd dense_values, shifted_values;
  Eigen::MatrixXd dense_vectors;
  std::string message;
  REQUIRE(CGAL::Spectral_deformation::internal::Eigensolvers::dense_generalized_eigenpairs(
      Q, mass, 12, dense_values, dense_vectors, message));
  REQUIRE(block.compute(shifted, mass, 12, shifted_values, vectors));
  CHECK((shifted_values - dense_values - Eigen::VectorXd::Ones(12)).cwiseAbs().maxCoeff() <
        1e-8 * dense_values.maxCoeff());
  // The single-vector method likewise, for the smallest eigenvalue (1, one
  // per sphere: a single-vector method may find one copy only, which is
  // why the traits count the eigenvalues after it).
  CGAL::Spectral_deformation::internal::Eigensolvers::Single_vector_lanczos_settings settings;
  settings.max_dimension = 400;
  settings.tolerance = 1e-10;
  Eigen::VectorXd single_values;
  REQUIRE(CGAL::Spectral_deformation::internal::Eigensolvers::single_vector_lanczos_eigenpairs<
          CGAL::Default_eigensolver_sparse_spd_solver_traits>(
      shifted, mass, 1, settings, [](Eigen::Index) {}, [](Eigen::Index) {}, single_values, vectors, message));
  CHECK(std::abs(single_values[0] - 1.0) < 1e-8);
}

#ifdef CGAL_SSMD_USE_CHOLMOD
TEMPLATE_TEST_CASE("CHOLMOD solver traits: solves with reused work arrays match a simplicial LDLT",
                   "[basis][solver]", CGAL::Cholmod_sparse_spd_solver_traits,
                   CGAL::Cholmod_simplicial_sparse_spd_solver_traits)
{
  const Surface_mesh mesh = to_mesh<Surface_mesh>(bumpy_plane(20));
  const Eigen::SparseMatrix<double> Q = CGAL::cotangent_stiffness_matrix(mesh);
  const Eigen::SparseMatrix<double> M = CGAL::lumped_mass_matrix(mesh);
  TestType solver;
  Eigen::MatrixXd X;
  CHECK_FALSE(solver.solve(Eigen::MatrixXd::Ones(Q.rows(), 1), X)); // nothing factored

  for(double shift : {1.0, 10.0})
  {
    const Eigen::SparseMatrix<double> A = Q + shift * M;
    REQUIRE(solver.factor(A));
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> reference(A);
    // Different numbers of right-hand sides in turn: the work arrays are
    // resized, reused, and never leak a previous solution.
    for(Eigen::Index columns : {Eigen::Index(3), Eigen::Index(1), Eigen::Index(5), Eigen::Index(5)})
    {
      const Eigen::MatrixXd B = Eigen::MatrixXd::Random(Q.rows(), columns);
      REQUIRE(solver.solve(B, X));
      const Eigen::MatrixXd expected = reference.solve(B);
      INFO("shift " << shift << ", " << columns << " right-hand sides");
      CHECK((X - expected).norm() < 1e-10 * expected.norm());
    }
  }
  CHECK_FALSE(solver.solve(Eigen::MatrixXd::Ones(Q.rows() + 1, 1), X)); // wrong size
  CHECK_FALSE(solver.factor(-Q - M)); // negative definite
  CHECK_FALSE(solver.solve(Eigen::MatrixXd::Ones(Q.rows(), 1), X));
}

namespace {
std::size_t counted_allocations = 0;
void* counting_malloc(std::size_t bytes)
{
  ++counted_allocations;
  return std::malloc(bytes);
}
void* counting_calloc(std::size_t count, std::size_t size)
{
  ++counted_allocations;
  return std::calloc(count, size);
}
void* counting_realloc(void* block, std::size_t bytes)
{
  ++counted_allocations;
  return std::realloc(block, bytes);
}
typedef void* (*Malloc_function)(std::size_t);
#if SUITESPARSE_MAIN_VERSION >= 7
Malloc_function suitesparse_malloc() { return SuiteSparse_config_malloc_func_get(); }
void* (*suitesparse_calloc())(std::size_t, std::size_t) { return SuiteSparse_config_calloc_func_get(); }
void* (*suitesparse_realloc())(void*, std::size_t) { return SuiteSparse_config_realloc_func_get(); }
void set_suitesparse_allocator(Malloc_function allocate, void* (*allocate_zeros)(std::size_t, std::size_t),
                               void* (*reallocate)(void*, std::size_t))
{
  SuiteSparse_config_malloc_func_set(allocate);
  SuiteSparse_config_calloc_func_set(allocate_zeros);
  SuiteSparse_config_realloc_func_set(reallocate);
}
#else
Malloc_function suitesparse_malloc() { return SuiteSparse_config.malloc_func; }
void* (*suitesparse_calloc())(std::size_t, std::size_t) { return SuiteSparse_config.calloc_func; }
void* (*suitesparse_realloc())(void*, std::size_t) { return SuiteSparse_config.realloc_func; }
void set_suitesparse_allocator(Malloc_function allocate, void* (*allocate_zeros)(std::size_t, std::size_t),
                               void* (*reallocate)(void*, std::size_t))
{
  SuiteSparse_config.malloc_func = allocate;
  SuiteSparse_config.calloc_func = allocate_zeros;
  SuiteSparse_config.realloc_func = reallocate;
}
#endif
} // namespace

TEST_CASE("CHOLMOD solver traits: SuiteSparse's default allocator is restored, a user's own is kept",
          "[basis][solver]")
{
  const Surface_mesh mesh = to_mesh<Surface_mesh>(bumpy_plane(20));
  const Eigen::SparseMatrix<double> A =
      CGAL::cotangent_stiffness_matrix(mesh) + CGAL::lumped_mass_matrix(mesh);
  const Eigen::MatrixXd B = Eigen::MatrixXd::Random(A.rows(), 4);
  Eigen::MatrixXd X;
  // The default allocator (malloc, or a sanitizer's interceptor of it).
  const Malloc_function default_malloc = suitesparse_malloc();
  const auto default_calloc = suitesparse_calloc();
  const auto default_realloc = suitesparse_realloc();
  {
    CGAL::Cholmod_simplicial_sparse_spd_solver_traits solver;
    REQUIRE(solver.factor(A));
    REQUIRE(solver.solve(B, X));
    CHECK(suitesparse_malloc() == default_malloc);
  }
  CHECK(suitesparse_malloc() == default_malloc);
  CHECK(suitesparse_calloc() == default_calloc);
  CHECK(suitesparse_realloc() == default_realloc);

  set_suitesparse_allocator(counting_malloc, counting_calloc, counting_realloc);
  counted_allocations = 0;
  {
    CGAL::Cholmod_sparse_spd_solver_traits solver;
    REQUIRE(solver.factor(A));
    REQUIRE(solver.solve(B, X));
  }
  const bool kept = (suitesparse_malloc() == &counting_malloc);
  set_suitesparse_allocator(default_malloc, default_calloc, default_realloc);
  CHECK(kept);
  CHECK(counted_allocations > 0);
  CHECK((A * X - B).norm() < 1e-10 * B.norm());
}
#endif

#ifdef CGAL_SSMD_USE_CHOLMOD
TEST_CASE("CHOLMOD simplicial solver traits: a supernodal factorization converted gives the same solves",
          "[basis][solver]")
{
  const Surface_mesh mesh = to_mesh<Surface_mesh>(bumpy_plane(30));
  const Eigen::SparseMatrix<double> A =
      CGAL::cotangent_stiffness_matrix(mesh) + CGAL::lumped_mass_matrix(mesh);
  const Eigen::MatrixXd B = Eigen::MatrixXd::Random(A.rows(), 8);
  Eigen::MatrixXd X_simplicial, X_converted;
  CGAL::Cholmod_simplicial_sparse_spd_solver_traits simplicial, converted;
  simplicial.set_supernodal_factorization_switch(std::numeric_limits<double>::infinity());
  converted.set_supernodal_factorization_switch(0.0);
  REQUIRE(simplicial.factor(A));
  REQUIRE(converted.factor(A));
  REQUIRE(simplicial.solve(B, X_simplicial));
  REQUIRE(converted.solve(B, X_converted));
  CHECK((A * X_converted - B).norm() < 1e-10 * B.norm());
  CHECK((X_converted - X_simplicial).norm() < 1e-10 * X_simplicial.norm());
  // One right-hand side takes the single-thread path of the solve.
  Eigen::MatrixXd x;
  REQUIRE(converted.solve(B.col(3), x));
  CHECK((x - X_simplicial.col(3)).norm() < 1e-10 * X_simplicial.col(3).norm());
}

TEST_CASE("CHOLMOD solver traits: the fill-reducing ordering weighs nested dissection, which CHOLMOD's default skips",
          "[basis][solver]")
{
  // A closed surface of 10,242 vertices: nested dissection fills its factor
  // a fifth less than minimum degree, which CHOLMOD's default keeps there.
  // (On a flat grid minimum degree wins, and the ordering keeps it.)
  for(const bool closed : {true, false})
  {
    const Surface_mesh mesh = to_mesh<Surface_mesh>(closed ? icosphere(5) : bumpy_plane(100));
    const Eigen::SparseMatrix<double> A =
        CGAL::cotangent_stiffness_matrix(mesh) + CGAL::lumped_mass_matrix(mesh);
    const Eigen::MatrixXd B = Eigen::MatrixXd::Random(A.rows(), 3);
    CGAL::Cholmod_simplicial_sparse_spd_solver_traits solver;
    REQUIRE(solver.factor(A));
    const double default_nonzeros = solver.factor_nonzeros();
    Eigen::MatrixXd expected, X;
    REQUIRE(solver.solve(B, expected));
    solver.set_fill_reducing_ordering(solver.fill_reducing_ordering(A));
    REQUIRE(solver.factor(A));
    CAPTURE(closed, default_nonzeros);
    if(closed)
      CHECK(solver.factor_nonzeros() < 0.9 * default_nonzeros);
    else
      CHECK(solver.factor_nonzeros() <= default_nonzeros);
    REQUIRE(solver.solve(B, X));
    CHECK((X - expected).norm() < 1e-10 * expected.norm());
  }
}

TEMPLATE_TEST_CASE("CHOLMOD solver traits: a given fill-reducing ordering is used, and solves the same system",
                   "[basis][solver]", CGAL::Cholmod_sparse_spd_solver_traits,
                   CGAL::Cholmod_simplicial_sparse_spd_solver_traits)
{
  const Surface_mesh mesh = to_mesh<Surface_mesh>(bumpy_plane(30));
  const Eigen::SparseMatrix<double> A =
      CGAL::cotangent_stiffness_matrix(mesh) + CGAL::lumped_mass_matrix(mesh);
  const Eigen::MatrixXd B = Eigen::MatrixXd::Random(A.rows(), 3);
  TestType solver;
  std::vector<int> ordering = solver.fill_reducing_ordering(A);
  REQUIRE(static_cast<Eigen::Index>(ordering.size()) == A.rows());
  std::vector<int> sorted = ordering;
  std::sort(sorted.begin(), sorted.end());
  std::vector<int> identity(sorted.size());
  std::iota(identity.begin(), identity.end(), 0);
  CHECK(sorted == identity);

  Eigen::MatrixXd expected, X;
  REQUIRE(solver.factor(A));
  const double own = solver.factor_nonzeros();
  REQUIRE(solver.solve(B, expected));
  // A random order fills the factor far more: proof that it was used.
  std::vector<int> shuffled = identity;
  std::shuffle(shuffled.begin(), shuffled.end(), std::mt19937(7));
  solver.set_fill_reducing_ordering(shuffled);
  REQUIRE(solver.factor(A));
  CHECK(solver.factor_nonzeros() > 3 * own);
  REQUIRE(solver.solve(B, X));
  CHECK((X - expected).norm() < 1e-10 * expected.norm());
  // The ordering is for one factorization only; one of another size is ignored.
  REQUIRE(solver.factor(A));
  CHECK(solver.factor_nonzeros() == own);
  solver.set_fill_reducing_ordering({0, 1, 2});
  REQUIRE(solver.factor(A));
  CHECK(solver.factor_nonzeros() == own);
  // So is one of the right size that is not a permutation.
  std::vector<int> repeated = shuffled;
  repeated[1] = repeated[0];
  solver.set_fill_reducing_ordering(repeated);
  REQUIRE(solver.factor(A));
  CHECK(solver.factor_nonzeros() == own);
  std::vector<int> out_of_range = shuffled;
  out_of_range[0] = static_cast<int>(A.rows());
  solver.set_fill_reducing_ordering(out_of_range);
  REQUIRE(solver.factor(A));
  CHECK(solver.factor_nonzeros() == own);
  // CHOLMOD's own ordering handed back fills the factor as its own choice.
  solver.set_fill_reducing_ordering(ordering);
  REQUIRE(solver.factor(A));
  CHECK(solver.factor_nonzeros() <= 1.05 * own);
  REQUIRE(solver.solve(B, X));
  CHECK((X - expected).norm() < 1e-10 * expected.norm());
}

TEST_CASE("Dirichlet systems: a later set of prescribed unknowns reuses one ordering and solves as a fresh system",
          "[basis][solver]")
{
  using CGAL::Spectral_deformation::internal::Linear_algebra::Dirichlet_system;
  const Surface_mesh mesh = to_mesh<Surface_mesh>(bumpy_plane(30));
  const Eigen::SparseMatrix<double> Q = CGAL::cotangent_stiffness_matrix(mesh);
  const Eigen::Index n = Q.rows();
  const Eigen::MatrixXd rhs = Eigen::MatrixXd::Random(n, 3), values = Eigen::MatrixXd::Random(n, 3);
  // Prescribed: the first tenth of the vertices, then the first and last tenths.
  std::vector<char> first(static_cast<std::size_t>(n), 0), second(static_cast<std::size_t>(n), 0);
  for(Eigen::Index i = 0; i < n / 10; ++i)
  {
    first[static_cast<std::size_t>(i)] = second[static_cast<std::size_t>(i)] = 1;
    second[static_cast<std::size_t>(n - 1 - i)] = 1;
  }
  Dirichlet_system<CGAL::Cholmod_simplicial_sparse_spd_solver_traits> reused, fresh;
  REQUIRE(reused.factor(Q, first));
  REQUIRE(reused.factor(Q, second));
  REQUIRE(fresh.factor(Q, second));
  Eigen::MatrixXd x_reused, x_fresh;
  REQUIRE(reused.solve(rhs, values, x_reused));
  REQUIRE(fresh.solve(rhs, values, x_fresh));
  CHECK((x_reused - x_fresh).norm() < 1e-9 * x_fresh.norm());
  for(Eigen::Index i = 0; i < n; ++i)
    if(second[static_cast<std::size_t>(i)])
      CHECK(x_reused.row(i) == values.row(i));
  // The free rows satisfy their equations.
  const Eigen::MatrixXd residual = Q * x_reused - rhs;
  double largest = 0;
  for(Eigen::Index i = 0; i < n; ++i)
    if(!second[static_cast<std::size_t>(i)])
      largest = (std::max)(largest, residual.row(i).cwiseAbs().maxCoeff());
  CHECK(largest < 1e-9 * rhs.cwiseAbs().maxCoeff());
}

namespace {

// The solution of the Dirichlet system of `Q` for the prescribed flags,
// checked against an independent dense solve of the free block.
Eigen::MatrixXd dense_dirichlet_solution(const Eigen::SparseMatrix<double>& Q, const std::vector<char>& prescribed,
                                         const Eigen::MatrixXd& rhs, const Eigen::MatrixXd& values)
{
  std::vector<int> free;
  for(std::size_t i = 0; i < prescribed.size(); ++i)
    if(!prescribed[i])
      free.push_back(static_cast<int>(i));
  const Eigen::MatrixXd dense = Q;
  Eigen::MatrixXd fixed_values = values;
  for(int i : free)
    fixed_values.row(i).setZero();
  const Eigen::MatrixXd b = rhs - dense * fixed_values;
  const Eigen::Index m = static_cast<Eigen::Index>(free.size());
  Eigen::MatrixXd block(m, m), block_rhs(m, rhs.cols());
  for(Eigen::Index r = 0; r < m; ++r)
  {
    block_rhs.row(r) = b.row(free[static_cast<std::size_t>(r)]);
    for(Eigen::Index c = 0; c < m; ++c)
      block(r, c) = dense(free[static_cast<std::size_t>(r)], free[static_cast<std::size_t>(c)]);
  }
  const Eigen::MatrixXd x = block.ldlt().solve(block_rhs);
  Eigen::MatrixXd out = values;
  for(Eigen::Index r = 0; r < m; ++r)
    out.row(free[static_cast<std::size_t>(r)]) = x.row(r);
  return out;
}

} // namespace

TEST_CASE("Dirichlet systems: sets that differ in a few unknowns update the factor and solve as the dense system",
          "[basis][solver]")
{
  using CGAL::Spectral_deformation::internal::Linear_algebra::Dirichlet_system;
  // Two components, each with prescribed vertices.
  Surface_mesh mesh = to_mesh<Surface_mesh>(bumpy_plane(16));
  const Eigen::Index plane_vertices = static_cast<Eigen::Index>(mesh.number_of_vertices());
  mesh.join(to_mesh<Surface_mesh>(icosphere(2)));
  const Eigen::SparseMatrix<double> Q = CGAL::cotangent_stiffness_matrix(mesh);
  const Eigen::Index n = Q.rows();
  const Eigen::MatrixXd rhs = Eigen::MatrixXd::Random(n, 3), values = Eigen::MatrixXd::Random(n, 3);
  std::vector<char> prescribed(static_cast<std::size_t>(n), 0);
  for(Eigen::Index i = 0; i < plane_vertices / 10; ++i)
    prescribed[static_cast<std::size_t>(i)] = 1;
  prescribed[static_cast<std::size_t>(plane_vertices)] = 1;
  Dirichlet_system<CGAL::Cholmod_simplicial_sparse_spd_solver_traits> system;
  // On a mesh this small a factorization costs less than most updates: the
  // budget of the updates is lifted, then withdrawn for the last set.
  system.solver().set_row_update_budget(std::numeric_limits<double>::infinity());
  REQUIRE(system.factor(Q, prescribed));
  CHECK_FALSE(system.solver().rows_updated());
  auto check_solution = [&](bool updated) {
    CHECK(system.solver().rows_updated() == updated);
#ifdef _OPENMP
    CHECK(system.solver().solves_in_subtrees());
#endif
    Eigen::MatrixXd x;
    REQUIRE(system.solve(rhs, values, x));
    const Eigen::MatrixXd expected = dense_dirichlet_solution(Q, prescribed, rhs, values);
    CHECK((x - expected).norm() < 1e-9 * expected.norm());
    for(Eigen::Index i = 0; i < n; ++i)
      if(prescribed[static_cast<std::size_t>(i)])
        CHECK(x.row(i) == values.row(i));
  };
  // A vertex taken in the middle of the plane, one on the sphere.
  prescribed[static_cast<std::size_t>(plane_vertices / 2)] = 1;
  prescribed[static_cast<std::size_t>(n - 1)] = 1;
  REQUIRE(system.factor(Q, prescribed));
  check_solution(true);
  // Two released, a band of twenty taken.
  prescribed[0] = prescribed[3] = 0;
  for(Eigen::Index i = plane_vertices / 3; i < plane_vertices / 3 + 20; ++i)
    prescribed[static_cast<std::size_t>(i)] = 1;
  REQUIRE(system.factor(Q, prescribed));
  check_solution(true);
  // Back to a set close to the first one.
  for(Eigen::Index i = plane_vertices / 3; i < plane_vertices / 3 + 20; ++i)
    prescribed[static_cast<std::size_t>(i)] = 0;
  REQUIRE(system.factor(Q, prescribed));
  check_solution(true);
  // Half of the vertices change, without a budget for updates: a new
  // factorization.
  system.solver().set_row_update_budget(0);
  for(Eigen::Index i = 0; i < n; i += 2)
    prescribed[static_cast<std::size_t>(i)] = !prescribed[static_cast<std::size_t>(i)];
  REQUIRE(system.factor(Q, prescribed));
  check_solution(false);
}

TEST_CASE("CHOLMOD simplicial solver traits: rows replaced by updates give the factor of the new matrix",
          "[basis][solver]")
{
  // A mass term large enough that the matrix stays positive definite when
  // some of its rows change.
  Surface_mesh mesh = to_mesh<Surface_mesh>(bumpy_plane(20));
  const Eigen::SparseMatrix<double> A =
      CGAL::cotangent_stiffness_matrix(mesh) + 100 * CGAL::lumped_mass_matrix(mesh);
  const Eigen::Index n = A.rows();
  // B: the rows and columns of a few vertices from the matrix of the mesh
  // with those vertices moved (new couplings, same pattern).
  const std::vector<int> rows = {7, 150, 151, 300};
  for(int r : rows)
  {
    const Surface_mesh::Vertex_index v(static_cast<Surface_mesh::size_type>(r));
    mesh.point(v) = mesh.point(v) + Kernel::Vector_3(0.002, -0.003, 0.004);
  }
  const Eigen::SparseMatrix<double> moved =
      CGAL::cotangent_stiffness_matrix(mesh) + 100 * CGAL::lumped_mass_matrix(mesh);
  std::vector<char> listed(static_cast<std::size_t>(n), 0);
  for(int r : rows)
    listed[static_cast<std::size_t>(r)] = 1;
  std::vector<Eigen::Triplet<double>> entries;
  for(int k = 0; k < A.outerSize(); ++k)
    for(Eigen::SparseMatrix<double>::InnerIterator it(A, k); it; ++it)
    {
      const bool replaced = listed[static_cast<std::size_t>(it.row())] || listed[static_cast<std::size_t>(it.col())];
      entries.emplace_back(static_cast<int>(it.row()), static_cast<int>(it.col()),
                           replaced ? moved.coeff(it.row(), it.col()) : it.value());
    }
  Eigen::SparseMatrix<double> B(n, n);
  B.setFromTriplets(entries.begin(), entries.end());
  REQUIRE((B - A).norm() > 1e-6 * A.norm());
  const Eigen::MatrixXd right_hand_sides = Eigen::MatrixXd::Random(n, 3);
  const Eigen::LDLT<Eigen::MatrixXd> dense(B);
  REQUIRE(dense.vectorD().minCoeff() > 0);
  const Eigen::MatrixXd expected = dense.solve(right_hand_sides);
  // Updates without a limit (on a mesh this small they cost more than a
  // factorization), then none.
  for(const double budget : {std::numeric_limits<double>::infinity(), 0.0})
  {
    CGAL::Cholmod_simplicial_sparse_spd_solver_traits solver;
    solver.set_row_update_budget(budget);
    REQUIRE(solver.factor(A));
    REQUIRE(solver.refactor_rows(B, rows));
    CHECK(solver.rows_updated() == (budget > 0));
    Eigen::MatrixXd X;
    REQUIRE(solver.solve(right_hand_sides, X));
    CHECK((X - expected).norm() < 1e-10 * expected.norm());
    // A row that makes the matrix indefinite: the updates fail, so does the
    // factorization that replaces them; the solver then refuses to solve.
    Eigen::SparseMatrix<double> indefinite = B;
    indefinite.coeffRef(150, 150) = -1.0;
    CHECK_FALSE(solver.refactor_rows(indefinite, {150}));
    CHECK_FALSE(solver.solve(right_hand_sides, X));
    // And factors again afterwards.
    REQUIRE(solver.factor(B));
    REQUIRE(solver.solve(right_hand_sides, X));
    CHECK((X - expected).norm() < 1e-10 * expected.norm());
  }
}

TEST_CASE("CHOLMOD simplicial solver traits: solves split by subtrees agree with an independent solver",
          "[basis][solver]")
{
  // Two components: the elimination tree is a forest.
  Surface_mesh mesh = to_mesh<Surface_mesh>(bumpy_plane(30));
  {
    const Surface_mesh sphere = to_mesh<Surface_mesh>(icosphere(3));
    mesh.join(sphere);
  }
  const Eigen::SparseMatrix<double> A =
      CGAL::cotangent_stiffness_matrix(mesh) + CGAL::lumped_mass_matrix(mesh);
  CGAL::Eigen_sparse_spd_solver_traits<Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>> independent;
  REQUIRE(independent.factor(A));
  for(const double supernodal_switch : {std::numeric_limits<double>::infinity(), 0.0})
  {
    CGAL::Cholmod_simplicial_sparse_spd_solver_traits solver;
    solver.set_supernodal_factorization_switch(supernodal_switch);
    REQUIRE(solver.factor(A));
#ifdef _OPENMP
    CHECK(solver.solves_in_subtrees());
#endif
    // Widths 1, 2, 4, 8 and a block of eight followed by a tail of five.
    for(const Eigen::Index columns : {1, 2, 3, 5, 8, 13})
    {
      const Eigen::MatrixXd B = Eigen::MatrixXd::Random(A.rows(), columns);
      Eigen::MatrixXd X, expected;
      REQUIRE(solver.solve(B, X));
      REQUIRE(independent.solve(B, expected));
      CHECK((X - expected).norm() < 1e-10 * expected.norm());
      CHECK((A * X - B).norm() < 1e-10 * B.norm());
#ifdef _OPENMP
      // On one thread the subtrees are solved one after the other, with the
      // same operations: the same result to the last bit.
      const int threads = omp_get_max_threads();
      omp_set_num_threads(1);
      Eigen::MatrixXd X_one_thread;
      const bool solved_on_one_thread = solver.solve(B, X_one_thread);
      omp_set_num_threads(threads);
      REQUIRE(solved_on_one_thread);
      CHECK(X_one_thread == X);
#endif
    }
  }
}
#endif

TEST_CASE("transform then inverse is the identity when m = n", "[basis]")
{
  const Surface_mesh mesh = to_mesh<Surface_mesh>(icosphere(1));
  const Eigen::Index n = static_cast<Eigen::Index>(mesh.number_of_vertices());
  const Basis basis(mesh, static_cast<std::size_t>(n));
  const Eigen::MatrixXd x = positions_of(mesh) + Eigen::MatrixXd::Random(n, 3);
  const Eigen::MatrixXd coefficients = basis.transform(x);
  CHECK(coefficients.rows() == n);
  CHECK((basis.inverse_transform(coefficients) - x).cwiseAbs().maxCoeff() < 1e-10);
  CHECK((basis.low_pass(x) - x).cwiseAbs().maxCoeff() < 1e-10);
}

TEST_CASE("low-pass error falls as m grows", "[basis]")
{
  const Surface_mesh mesh = to_mesh<Surface_mesh>(bumpy_plane(20));
  const Basis basis(mesh, 120);
  const Eigen::MatrixXd x = positions_of(mesh);
  const Eigen::VectorXd& mass = basis.mass();
  auto error = [&](std::size_t k) {
    const Eigen::MatrixXd d = basis.low_pass(x, k) - x;
    return std::sqrt((d.transpose() * mass.asDiagonal() * d).trace());
  };
  double previous = error(1);
  for(std::size_t k : {5, 10, 20, 40, 80, 120})
  {
    const double e = error(k);
    INFO("k = " << k << ": " << e << " (previous " << previous << ")");
    CHECK(e <= previous + 1e-12);
    previous = e;
  }
  CHECK(error(120) < 0.2 * error(5));
  // The first function is constant: one frequency reproduces the centroid.
  const Eigen::RowVector3d centroid = (mass.transpose() * x) / mass.sum();
  CHECK((basis.low_pass(x, 1).rowwise() - centroid).cwiseAbs().maxCoeff() < 1e-10);
}

TEST_CASE("boundaries and several connected components", "[basis]")
{
  const Surface_mesh spheres = to_mesh<Surface_mesh>(two_spheres(3)); // 2·642 vertices
  const Basis basis(spheres, 10);
  // One constant function per component: two zero eigenvalues, then the
  // l = 1 eigenvalue (≈2) of both unit spheres, six times.
  CHECK(std::abs(basis.eigenvalues()[0]) < 1e-8);
  CHECK(std::abs(basis.eigenvalues()[1]) < 1e-8);
  for(int k = 2; k < 8; ++k)
    CHECK(basis.eigenvalues()[k] == Approx(2.0).epsilon(0.02));

  const Surface_mesh plane = to_mesh<Surface_mesh>(bumpy_plane(16));
  const Basis open(plane, 10);
  // Natural (Neumann) boundary: a single zero eigenvalue, then positive ones.
  CHECK(std::abs(open.eigenvalues()[0]) < 1e-8);
  CHECK(open.eigenvalues()[1] > 1.0);
}

TEST_CASE("eigenvalues scale as 1/s^2 and are invariant under rigid motions", "[basis]")
{
  Soup soup = bar(10, 2);
  const Basis reference(to_mesh<Surface_mesh>(soup), 12);
  const double s = 1e3, c = std::cos(0.7), sn = std::sin(0.7);
  for(Point& p : soup.points)
    p = Point(s * (c * p.x() - sn * p.y()) + 5, s * (sn * p.x() + c * p.y()) - 2, s * p.z() + 1e4);
  const Basis moved(to_mesh<Surface_mesh>(soup), 12);
  for(Eigen::Index k = 1; k < 12; ++k)
    CHECK(moved.eigenvalues()[k] * s * s == Approx(reference.eigenvalues()[k]).epsilon(1e-8));
}

TEST_CASE("Surface_mesh and Polyhedron_3 give the same basis", "[basis]")
{
  const Soup soup = bumpy_plane(14);
  const Surface_mesh sm = to_mesh<Surface_mesh>(soup);
  const Polyhedron poly = to_mesh<Polyhedron>(soup);
  const Basis a(sm, 20);
  const CGAL::Manifold_harmonics_basis<Polyhedron> b(poly, 20);
  CHECK((a.eigenvalues() - b.eigenvalues()).cwiseAbs().maxCoeff() < 1e-12);
  CHECK((a.basis() - b.basis()).cwiseAbs().maxCoeff() < 1e-10);
  CHECK(a.mesh_fingerprint() == b.mesh_fingerprint());
}

TEST_CASE("save and load: round trip, stale and corrupted files refused", "[basis][io]")
{
  Soup soup = bumpy_plane(10);
  const Surface_mesh mesh = to_mesh<Surface_mesh>(soup);
  const Basis basis(mesh, 15);
  std::stringstream stream;
  basis.save(stream);
  const std::string bytes = stream.str();

  Basis loaded;
  CHECK(loaded.empty());
  std::istringstream in(bytes);
  loaded.load(in, mesh);
  CHECK(loaded.eigenvalues() == basis.eigenvalues());
  CHECK(loaded.basis() == basis.basis());
  CHECK(loaded.mass() == basis.mass());

  // Another mesh (one vertex moved): refused, and the target basis is untouched.
  soup.points[7] = Point(soup.points[7].x(), soup.points[7].y(), soup.points[7].z() + 1e-9);
  const Surface_mesh moved = to_mesh<Surface_mesh>(soup);
  CHECK(error_code_of([&] {
          std::istringstream s(bytes);
          loaded.load(s, moved);
        }) == Error::MESH_MISMATCH);
  CHECK(loaded.basis() == basis.basis());
  // A mesh of another size.
  const Surface_mesh other = to_mesh<Surface_mesh>(bumpy_plane(11));
  CHECK(error_code_of([&] {
          std::istringstream s(bytes);
          loaded.load(s, other);
        }) == Error::MESH_MISMATCH);
  // One flipped byte in the payload.
  std::string corrupted = bytes;
  corrupted[bytes.size() / 2] ^= 0x10;
  CHECK(error_code_of([&] {
          std::istringstream s(corrupted);
          loaded.load(s, mesh);
        }) == Error::IO_ERROR);
  // Truncated.
  CHECK(error_code_of([&] {
          std::istringstream s(bytes.substr(0, bytes.size() - 100));
          loaded.load(s, mesh);
        }) == Error::IO_ERROR);
  // Not a basis file.
  CHECK(error_code_of([&] {
          std::istringstream s("OFF\n3 1 0\n");
          loaded.load(s, mesh);
        }) == Error::IO_ERROR);
  CHECK(loaded.basis() == basis.basis());
  // Saving an empty basis.
  CHECK(error_code_of([&] {
          std::ostringstream s;
          Basis().save(s);
        }) == Error::IO_ERROR);
}

TEST_CASE("bad input gives a clear error", "[basis][errors]")
{
  const Soup good = bumpy_plane(6);
  const Surface_mesh mesh = to_mesh<Surface_mesh>(good);
  const std::size_t n = mesh.number_of_vertices();

  SECTION("number of frequencies out of range")
  {
    CHECK(error_code_of([&] { Basis(mesh, 0); }) == Error::INVALID_ARGUMENT);
    CHECK(error_code_of([&] { Basis(mesh, n + 1); }) == Error::INVALID_ARGUMENT);
  }
  SECTION("not a triangle mesh")
  {
    Surface_mesh quad;
    const auto a = quad.add_vertex(Point(0, 0, 0)), b = quad.add_vertex(Point(1, 0, 0)),
               c = quad.add_vertex(Point(1, 1, 0)), d = quad.add_vertex(Point(0, 1, 0)),
               e = quad.add_vertex(Point(2, 0, 0));
    quad.add_face(a, b, c, d);
    quad.add_face(b, e, c);
    CHECK(error_code_of([&] { Basis(quad, 2); }) == Error::INVALID_MESH);
    CHECK(error_code_of([&] { CGAL::cotangent_stiffness_matrix(quad); }) == Error::INVALID_MESH);
  }
  SECTION("empty mesh")
  {
    CHECK(error_code_of([&] { Basis(Surface_mesh(), 1); }) == Error::INVALID_MESH);
  }
  SECTION("zero-area face")
  {
    Soup soup = good;
    // Collapse a triangle onto a line: its third vertex is put on its first edge.
    const auto t = soup.triangles[10];
    const Point& p = soup.points[t[0]];
    const Point& q = soup.points[t[1]];
    soup.points[t[2]] = Point((p.x() + q.x()) / 2, (p.y() + q.y()) / 2, (p.z() + q.z()) / 2);
    CHECK(error_code_of([&] { Basis(to_mesh<Surface_mesh>(soup), 5); }) == Error::INVALID_MESH);
  }
  SECTION("isolated vertex")
  {
    Surface_mesh with_isolated = mesh;
    with_isolated.add_vertex(Point(5, 5, 5));
    CHECK(error_code_of([&] { Basis(with_isolated, 5); }) == Error::INVALID_MESH);
  }
  SECTION("non-finite coordinates")
  {
    for(double bad : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()})
    {
      Surface_mesh broken = mesh;
      broken.point(*broken.vertices().begin()) = Point(bad, 0, 0);
      CHECK(error_code_of([&] { Basis(broken, 5); }) == Error::INVALID_MESH);
    }
  }
  SECTION("eigensolver that does not converge")
  {
    // One restart and a tolerance no Lanczos run can meet; dense path disabled.
    const Surface_mesh sphere = to_mesh<Surface_mesh>(icosphere(3));
    CGAL::Spectra_eigensolver_traits<> hopeless(1, 1e-300, 0);
    typedef CGAL::Manifold_harmonics_basis<Surface_mesh, CGAL::Spectra_eigensolver_traits<>>
        Spectra_basis;
    CHECK(error_code_of([&] {
            Spectra_basis(sphere, 40, CGAL::parameters::default_values(), hopeless);
          }) == Error::SOLVER_FAILURE);
    // The block solver with a subspace too small to converge in.
    CGAL::Block_lanczos_eigensolver_traits<> cramped(1e-10, 8, 48, 0);
    cramped.set_checked_single_vector(false);
    cramped.set_reference_fallback(false);
    cramped.set_reference_threshold(0);
    CHECK(error_code_of([&] { Basis(sphere, 40, CGAL::parameters::default_values(), cramped); }) ==
          Error::SOLVER_FAILURE);
  }
  SECTION("transform with the wrong number of rows")
  {
    const Basis basis(mesh, 5);
    CHECK(error_code_of([&] { basis.transform(Eigen::MatrixXd::Ones(n + 1, 3)); }) ==
          Error::INVALID_ARGUMENT);
    CHECK(error_code_of([&] { basis.inverse_transform(Eigen::MatrixXd::Ones(6, 3)); }) ==
          Error::INVALID_ARGUMENT);
    CHECK(error_code_of([&] { basis.low_pass(Eigen::MatrixXd::Ones(n, 3), 6); }) ==
          Error::INVALID_ARGUMENT);
  }
  SECTION("a failed compute leaves the basis unchanged")
  {
    Basis basis(mesh, 5);
    const Eigen::MatrixXd before = basis.basis();
    CHECK(error_code_of([&] { basis.compute(mesh, n + 3); }) == Error::INVALID_ARGUMENT);
    CHECK(basis.basis() == before);
  }
}

// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Concept conformance: archetypes of ManifoldHarmonicsEigensolverTraits and
// SparseSPDSolverTraits have exactly the members their concept pages list
// (anything else is deleted or absent), so that every class templated on a
// traits compiles with them only if it asks no more of a model than the
// concept promises. They compute with dense, plainly correct numerics, and
// the results must match those of the default traits.
#include "test_meshes.h"

#include <CGAL/Manifold_harmonics_basis.h>
// Deformations with other traits than the compiled core holds.
#include <CGAL/Spectral_deformation/Pipelines_from_headers.h>
#include <CGAL/Spectral_surface_mesh_deformation.h>
#include <CGAL/Spectral_deformation/Block_lanczos_eigensolver_traits.h>
#include <CGAL/Spectral_deformation/Spectra_eigensolver_traits.h>

#include <catch2/catch.hpp>

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <Eigen/Sparse>

#include <string>
#include <vector>

using namespace test_meshes;

namespace {

// SparseSPDSolverTraits: a default constructor, factor() and a const solve().
class Sparse_spd_solver_archetype
{
public:
  Sparse_spd_solver_archetype() = default;
  Sparse_spd_solver_archetype(const Sparse_spd_solver_archetype&) = delete;
  Sparse_spd_solver_archetype& operator=(const Sparse_spd_solver_archetype&) = delete;

  bool factor(const Eigen::SparseMatrix<double>& A)
  {
    m_llt.compute(Eigen::MatrixXd(A));
    m_factored = (m_llt.info() == Eigen::Success);
    return m_factored;
  }

  bool solve(const Eigen::MatrixXd& B, Eigen::MatrixXd& X) const
  {
    if(!m_factored)
      return false;
    X = m_llt.solve(B);
    return X.allFinite();
  }

private:
  Eigen::LLT<Eigen::MatrixXd> m_llt;
  bool m_factored = false;
};

// ManifoldHarmonicsEigensolverTraits: default and copy constructors,
// compute() and error_message().
class Eigensolver_archetype
{
public:
  Eigensolver_archetype() = default;
  Eigensolver_archetype(const Eigensolver_archetype&) = default;
  Eigensolver_archetype& operator=(const Eigensolver_archetype&) = delete;

  bool compute(const Eigen::SparseMatrix<double>& stiffness, const Eigen::VectorXd& mass, Eigen::Index m,
               Eigen::VectorXd& eigenvalues, Eigen::MatrixXd& eigenvectors)
  {
    const Eigen::MatrixXd M = mass.asDiagonal();
    Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(Eigen::MatrixXd(stiffness), M);
    if(solver.info() != Eigen::Success)
    {
      m_error = "dense generalized eigensolver failed";
      return false;
    }
    eigenvalues = solver.eigenvalues().head(m);
    eigenvectors = solver.eigenvectors().leftCols(m);
    return true;
  }

  const std::string& error_message() const { return m_error; }

private:
  std::string m_error;
};

const double pi = 3.14159265358979323846;

template <class Deformation>
Eigen::MatrixXd twist_bar(Surface_mesh mesh, std::size_t m)
{
  Deformation deformation(mesh);
  std::vector<Surface_mesh::Vertex_index> top;
  for(auto v : mesh.vertices())
  {
    const double z = mesh.point(v).z();
    if(z > 0.3)
      deformation.insert_roi_vertex(v);
    if(z > 4.7)
      top.push_back(v);
  }
  deformation.insert_control_vertices(top.begin(), top.end());
  if constexpr(Deformation::has_basis)
    deformation.set_number_of_frequencies(m);
  const Eigen::Quaterniond q(Eigen::AngleAxisd(pi / 4, Eigen::Vector3d::UnitZ()));
  deformation.rotate(top.begin(), top.end(), Eigen::Vector3d(0, 0, 5), q);
  deformation.deform();
  INFO(deformation.deform_report().message);
  REQUIRE(deformation.deform_report().success);
  Eigen::MatrixXd x(mesh.number_of_vertices(), 3);
  for(auto v : mesh.vertices())
    x.row(v.idx()) << mesh.point(v).x(), mesh.point(v).y(), mesh.point(v).z();
  return x;
}

template <CGAL::Spectral_deformation_algorithm_tag TAG, class ET = CGAL::Default, class ST = CGAL::Default>
using Deformation = CGAL::Spectral_surface_mesh_deformation<Surface_mesh, CGAL::Default, CGAL::Default, TAG, ET, ST>;

} // namespace

TEST_CASE("concepts: eigensolvers work with a minimal sparse solver", "[concepts]")
{
  const Surface_mesh mesh = to_mesh<Surface_mesh>(bar(8, 2));
  const Eigen::Index m = 12;
  const CGAL::Manifold_harmonics_basis<Surface_mesh> reference(mesh, m);
  const CGAL::Manifold_harmonics_basis<Surface_mesh, Eigensolver_archetype> dense(mesh, m);
  const CGAL::Manifold_harmonics_basis<Surface_mesh, CGAL::Block_lanczos_eigensolver_traits<Sparse_spd_solver_archetype>>
      block(mesh, m);
  const CGAL::Manifold_harmonics_basis<Surface_mesh, CGAL::Spectra_eigensolver_traits<Sparse_spd_solver_archetype>>
      spectra(mesh, m);
  for(const auto* basis : {&dense.eigenvalues(), &block.eigenvalues(), &spectra.eigenvalues()})
    CHECK((*basis - reference.eigenvalues()).cwiseAbs().maxCoeff() < 1e-8 * reference.eigenvalues().maxCoeff());
}

TEST_CASE("concepts: every algorithm works with the archetypes", "[concepts]")
{
  const Surface_mesh mesh = to_mesh<Surface_mesh>(bar(10, 2));
  const std::size_t n = mesh.number_of_vertices(); // all frequencies: the subspace is the whole space
  const Eigen::MatrixXd spectral = twist_bar<Deformation<CGAL::SPECTRAL_DUAL_LAPLACIAN>>(mesh, n);
  const Eigen::MatrixXd spectral_archetypes = twist_bar<
      Deformation<CGAL::SPECTRAL_DUAL_LAPLACIAN, Eigensolver_archetype, Sparse_spd_solver_archetype>>(mesh, n);
  CHECK((spectral - spectral_archetypes).cwiseAbs().maxCoeff() < 1e-7);

  const Eigen::MatrixXd linear = twist_bar<Deformation<CGAL::SPECTRAL_LINEAR>>(mesh, n);
  const Eigen::MatrixXd linear_archetypes =
      twist_bar<Deformation<CGAL::SPECTRAL_LINEAR, Eigensolver_archetype, Sparse_spd_solver_archetype>>(mesh, n);
  CHECK((linear - linear_archetypes).cwiseAbs().maxCoeff() < 1e-7);

  const Eigen::MatrixXd spatial = twist_bar<Deformation<CGAL::SPATIAL_DUAL_LAPLACIAN>>(mesh, n);
  const Eigen::MatrixXd spatial_archetypes = twist_bar<
      Deformation<CGAL::SPATIAL_DUAL_LAPLACIAN, Eigensolver_archetype, Sparse_spd_solver_archetype>>(mesh, n);
  CHECK((spatial - spatial_archetypes).cwiseAbs().maxCoeff() < 1e-9);
  // The twist moved the mesh: the comparisons are not between rest shapes.
  Eigen::MatrixXd rest(n, 3);
  for(auto v : mesh.vertices())
    rest.row(v.idx()) << mesh.point(v).x(), mesh.point(v).y(), mesh.point(v).z();
  CHECK((spectral - rest).cwiseAbs().maxCoeff() > 0.1);
  CHECK((spatial - rest).cwiseAbs().maxCoeff() > 0.1);
}

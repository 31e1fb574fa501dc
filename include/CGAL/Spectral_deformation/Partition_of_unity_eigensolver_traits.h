// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_PARTITION_OF_UNITY_EIGENSOLVER_TRAITS_H
#define CGAL_SPECTRAL_DEFORMATION_PARTITION_OF_UNITY_EIGENSOLVER_TRAITS_H

#include <CGAL/Spectral_deformation/Block_lanczos_eigensolver_traits.h>
#include <CGAL/Spectral_deformation/Sparse_spd_solver_traits.h>
#include <CGAL/Spectral_deformation/internal/Eigensolvers/Farthest_point_sampling.h>
#include <CGAL/Spectral_deformation/internal/Eigensolvers/Partition_of_unity_space.h>
#include <CGAL/Spectral_deformation/internal/Traits_requirements.h>

#include <CGAL/tags.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <algorithm>
#include <exception>
#include <limits>
#include <new>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {

/// \ingroup PkgSpectralSurfaceMeshDeformationTraits
/// A model of `ManifoldHarmonicsEigensolverTraits` that approximates the
/// basis in a space of smooth, locally supported functions whose size does
/// not depend on the mesh (after Nasikun, Brandt and Hildebrandt, *Fast
/// Approximation of Laplace-Beltrami Eigenproblems*, SGP 2018). It is
/// several times cheaper than the exact solvers on large meshes, and its cost
/// grows about linearly with the number of vertices.
///
/// The space is built from `number_of_samples()` vertices spread evenly over
/// the mesh by farthest point sampling. Each sample carries a smooth bump of
/// the distance to it (measured along the edges), whose radius is
/// `support_factor()` times the largest distance of a vertex to its nearest
/// sample; the bumps divided by their sum form a partition of unity, so the
/// constant functions, the eigenvectors of 0, are in the space exactly.
/// Each function is also multiplied by the two coordinates of the plane
/// that fits its support (`set_linear_functions()`, on by default), three
/// functions per sample. The eigenpairs of the cotangent Laplacian
/// restricted to this space (a Rayleigh-Ritz projection: `Pᵀ Q P` against
/// `Pᵀ M P`, `P` the `n × 3k` matrix of the functions) are computed by the
/// shift-invert single-vector Lanczos method that
/// `Block_lanczos_eigensolver_traits` uses on small meshes, with `Pᵀ M P`
/// as its inner product (Spectra's shift-invert Lanczos on the standard form
/// of the problem when its subspace fills up unconverged), and the basis is
/// `H = P Y`. Only the sampling, the functions, `Pᵀ Q P`, `Pᵀ M P` and `H`
/// cost time proportional to `n`; the eigenproblem has `3k` unknowns
/// whatever the size of the mesh.
///
/// What the approximation gives:
/// - the basis is M-orthonormal (`Hᵀ M H = I`) like the exact one, and every
///   eigenvalue is an upper bound of the exact one (Rayleigh-Ritz);
/// - the functions of the basis are smooth, and the higher frequencies of
///   the basis are approximated less well than the lower ones. A deformation
///   uses the basis only for the smooth mesh, whose detail the deformation
///   transfer adds back, so what matters is the deformation it gives, not
///   the eigenvalues; the user manual compares both.
///
/// Meshes that are small against the space (fewer than
/// `exact_threshold()` vertices per sampled function) are solved exactly by
/// `Block_lanczos_eigensolver_traits`, which is then as cheap.
///
/// It is the default eigensolver of `Spectral_surface_mesh_deformation`.
///
/// The traits needs the vertex positions, which
/// `CGAL::Manifold_harmonics_basis` and the deformation class hand it through
/// `set_vertex_positions()` before `compute()`.
///
/// \tparam SparseSPDSolverTraits a model of `SparseSPDSolverTraits`, used to
///         factor the reduced shifted matrix (and by the exact solver on
///         small meshes).
template <class SparseSPDSolverTraits = Default_eigensolver_sparse_spd_solver_traits>
class Partition_of_unity_eigensolver_traits
{
  typedef Block_lanczos_eigensolver_traits<SparseSPDSolverTraits> Exact_traits;

public:
  /// Declares the optional members `process_wide_tuning()` and
  /// `set_process_wide_tuning()` (see `ManifoldHarmonicsEigensolverTraits`).
  typedef CGAL::Tag_true Supports_process_wide_tuning;
  /// Declares the optional member `set_vertex_positions()` (see
  /// `ManifoldHarmonicsEigensolverTraits`): the sampled functions are built
  /// around vertices chosen by their positions.
  typedef CGAL::Tag_true Uses_vertex_positions;
  /// Declares the optional `compute()` with the eigenvectors in float (see
  /// `ManifoldHarmonicsEigensolverTraits`): the prolongation writes each
  /// eigenvector straight in float, so that a large basis the deformation
  /// keeps in float never exists in double.
  typedef CGAL::Tag_true Supports_single_precision_eigenvectors;
  /// Positions of the vertices, one row per vertex.
  typedef Eigen::Matrix<double, Eigen::Dynamic, 3> Positions;
  /// The state of a running `compute()`, passed to the progress callback:
  /// the type of `Block_lanczos_eigensolver_traits`, whose stages the exact
  /// solve of small meshes reports; the approximation reports
  /// `Progress::APPROXIMATION`, then `Progress::FINISHED`.
  typedef typename Exact_traits::Progress Progress;
  /// The type of the progress callback.
  typedef typename Exact_traits::Progress_callback Progress_callback;

  /// The number of sampled vertices `k` for `m` frequencies on a mesh of
  /// `n` vertices: the value set by `set_number_of_samples()`, or, by default
  /// (0), one per `vertices_per_sample()` vertices, between `10 m` and
  /// `20 m`, and at least 200 (`10 m` when `n` is not given).
  ///
  /// The range is what the quality benchmark measured: `10 m` samples give
  /// the deformations of the exact basis up to some 10⁵ vertices, at the
  /// lowest cost of the reduced eigenproblem, which dominates there; on the
  /// armadillo subdivided twice (416,002 vertices) they left the ARAP energy
  /// of a raised hand 8 % above the exact basis's, and `20 m` samples brought
  /// it below.
  Eigen::Index number_of_samples(Eigen::Index m, Eigen::Index n = 0) const
  {
    if(m_samples > 0)
      return m_samples;
    const Eigen::Index by_size = std::clamp<Eigen::Index>(n / vertices_per_sample(), 10 * m, 20 * m);
    return (std::max<Eigen::Index>)(by_size, 200);
  }
  /// Sets the number of sampled vertices; 0 (the default) means the rule of
  /// `number_of_samples()`.
  void set_number_of_samples(Eigen::Index samples) { m_samples = (std::max<Eigen::Index>)(samples, 0); }
  /// The vertices per sample of the default number of samples (200).
  static constexpr Eigen::Index vertices_per_sample() { return 200; }

  /// The radius of each bump over the largest distance of a vertex to its
  /// nearest sample (default 2: each vertex lies under about eight bumps on the armadillo).
  double support_factor() const { return m_support_factor; }
  /// Sets the support factor; values below 1 would leave vertices under no
  /// bump, and `compute()` then fails.
  void set_support_factor(double factor) { m_support_factor = factor; }

  /// Whether each bump is also multiplied by the two coordinates of its
  /// tangent plane (default `true`).
  bool linear_functions() const { return m_linear; }
  /// Sets whether the linear functions are used.
  void set_linear_functions(bool linear) { m_linear = linear; }

  /// The number of vertices per function of the space below which
  /// `compute()` solves exactly (default 8).
  double exact_threshold() const { return m_exact_threshold; }
  /// Sets the exact threshold.
  void set_exact_threshold(double vertices_per_function) { m_exact_threshold = vertices_per_function; }

  /// Whether `compute()` solves `m` eigenpairs on `n` vertices exactly:
  /// when `n` is below `exact_threshold()` vertices per function of the space.
  /// Setting the threshold to infinity makes every solve exact.
  bool solves_exactly(Eigen::Index m, Eigen::Index n) const
  {
    const double functions = static_cast<double>(number_of_samples(m, n) * (m_linear ? 3 : 1));
    return static_cast<double>(n) < m_exact_threshold * functions;
  }

  /// Sets a function that `compute()` calls at the start of every stage (see
  /// `Progress`) and once before it returns; the exact solve of small meshes
  /// also reports its block solves. An empty function (the default) disables
  /// the reports. The callback must not throw; it is copied with the traits.
  void set_progress_callback(const Progress_callback& callback) { m_progress_callback = callback; }

  /// Whether the exact solve of small meshes may change state of the whole
  /// process to run faster (default `false`); the approximation itself
  /// never does. See `Block_lanczos_eigensolver_traits::set_process_wide_tuning()`.
  bool process_wide_tuning() const { return m_process_wide_tuning; }
  /// Sets `process_wide_tuning()`.
  void set_process_wide_tuning(bool enabled) { m_process_wide_tuning = enabled; }

  /// Sets the positions of the vertices of the next `compute()`: rows in the
  /// order of the rows of its stiffness matrix.
  void set_vertex_positions(const Positions& positions) { m_positions = positions; }

  /// Computes an approximation of the `m` smallest eigenpairs of
  /// `Q h = lambda M h` with `M = diag(mass)`: `eigenvalues` ascending,
  /// `eigenvectors` (n×m) M-orthonormal. Returns `false`, with
  /// `error_message()` set, when no positions of the right size were set,
  /// when the space is too small for `m` functions (more samples are needed),
  /// or when the reduced eigenproblem fails.
  bool compute(const Eigen::SparseMatrix<double>& stiffness, const Eigen::VectorXd& mass,
               Eigen::Index m, Eigen::VectorXd& eigenvalues, Eigen::MatrixXd& eigenvectors)
  {
    return compute_in(stiffness, mass, m, eigenvalues, eigenvectors);
  }

  /// As above, with the eigenvectors rounded to float: the prolongation
  /// sums them in double by panels of rows and rounds each panel as it
  /// writes it, so that they take half the memory of the double ones at any
  /// time (an exact solve of a small mesh is rounded once it is done).
  bool compute(const Eigen::SparseMatrix<double>& stiffness, const Eigen::VectorXd& mass,
               Eigen::Index m, Eigen::VectorXd& eigenvalues, Eigen::MatrixXf& eigenvectors)
  {
    return compute_in(stiffness, mass, m, eigenvalues, eigenvectors);
  }

  /// The reason of the last failure of `compute()`.
  const std::string& error_message() const { return m_error_message; }

private:
  template <typename Scalar>
  bool compute_in(const Eigen::SparseMatrix<double>& stiffness, const Eigen::VectorXd& mass, Eigen::Index m,
                  Eigen::VectorXd& eigenvalues, Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>& eigenvectors)
  {
    m_error_message.clear();
    const Eigen::Index n = stiffness.rows();
    if(m < 1 || m > n)
      return fail("the number of eigenpairs must be between 1 and the number of vertices");
    if(solves_exactly(m, n))
    {
      Exact_traits exact;
      exact.set_progress_callback(m_progress_callback);
      exact.set_process_wide_tuning(m_process_wide_tuning);
      if constexpr(std::is_same_v<Scalar, double>)
      {
        if(exact.compute(stiffness, mass, m, eigenvalues, eigenvectors))
          return true;
      }
      else
      {
        Eigen::MatrixXd computed;
        if(exact.compute(stiffness, mass, m, eigenvalues, computed))
        {
          eigenvectors = computed.cast<Scalar>();
          return true;
        }
      }
      return fail(exact.error_message());
    }
    Progress progress;
    progress.number_of_eigenpairs = static_cast<std::size_t>(m);
    progress.number_of_vertices = static_cast<std::size_t>(n);
    report(progress, Progress::APPROXIMATION);
    const bool success = approximate(stiffness, mass, m, eigenvalues, eigenvectors);
    report(progress, Progress::FINISHED);
    return success;
  }

  template <typename Scalar>
  bool approximate(const Eigen::SparseMatrix<double>& stiffness, const Eigen::VectorXd& mass, Eigen::Index m,
                   Eigen::VectorXd& eigenvalues, Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>& eigenvectors)
  {
    namespace E = Spectral_deformation::internal::Eigensolvers;
    const Eigen::Index n = stiffness.rows();
    const Eigen::Index samples = number_of_samples(m, n);
    if(m_positions.rows() != n)
      return fail("the vertex positions were not set (set_vertex_positions()) or do not match "
                  "the stiffness matrix");
    if(!(m_support_factor >= 1.0))
      return fail("the support factor must be at least 1");
    try
    {
      // The graph is freed before the basis, the largest allocation of the
      // computation, is made.
      Eigen::SparseMatrix<double> space;
      {
        const E::Edge_length_graph graph = E::edge_length_graph(stiffness, m_positions);
        double covering_radius = 0.0;
        const std::vector<Eigen::Index> sampled =
            E::farthest_point_samples(graph, samples, covering_radius);
        if(!(covering_radius < std::numeric_limits<double>::infinity()))
          return fail("the mesh has more connected components than samples");
        if(!(covering_radius > 0.0))
          return fail("every vertex is a sample: the mesh is too small for the sampled space");
        space = E::partition_of_unity_functions(graph, m_positions, sampled,
                                                m_support_factor * covering_radius, m_linear);
      }
      std::string message;
      if(!E::reduced_eigenpairs<SparseSPDSolverTraits>(stiffness, mass, std::move(space), m, eigenvalues,
                                                       eigenvectors, message))
        return fail(message);
    }
    catch(const std::bad_alloc&)
    {
      return fail("out of memory while building the space of sampled functions");
    }
    catch(const std::exception& e)
    {
      return fail(e.what());
    }
    if(!eigenvalues.allFinite() || !eigenvectors.allFinite())
      return fail("the reduced eigenproblem gave non-finite values");
    return true;
  }

  void report(Progress& progress, typename Progress::Stage stage) const
  {
    progress.stage = stage;
    if(m_progress_callback)
      m_progress_callback(progress);
  }

  bool fail(const std::string& message)
  {
    m_error_message = message;
    return false;
  }

  Eigen::Index m_samples = 0;
  double m_support_factor = 2.0;
  bool m_linear = true;
  double m_exact_threshold = 8.0;
  bool m_process_wide_tuning = false;
  Progress_callback m_progress_callback;
  Positions m_positions;
  std::string m_error_message;
};

} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_PARTITION_OF_UNITY_EIGENSOLVER_TRAITS_H

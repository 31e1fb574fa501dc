// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_PARTITION_OF_UNITY_SPACE_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_PARTITION_OF_UNITY_SPACE_H

#include <CGAL/Spectral_deformation/internal/available_threads.h>
#include <CGAL/Spectral_deformation/internal/compiled_core.h>
#include <CGAL/Spectral_deformation/internal/Eigensolvers/Farthest_point_sampling.h>
#include <CGAL/Spectral_deformation/internal/Eigensolvers/Galerkin_matrices.h>
#include <CGAL/Spectral_deformation/internal/Eigensolvers/Parallel_exception.h>
#include <CGAL/Spectral_deformation/internal/Eigensolvers/Shift_invert.h>
#include <CGAL/Spectral_deformation/internal/Eigensolvers/Single_vector_lanczos.h>
#include <CGAL/Spectral_deformation/internal/Eigensolvers/Spectra_lanczos.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <Spectra/SymEigsShiftSolver.h>

#include <algorithm>
#include <cstddef>
#include <exception>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Spectral_deformation {
namespace internal {
namespace Eigensolvers {

// A space of smooth, locally supported functions on a mesh, in which the
// low eigenpairs of the Laplace-Beltrami operator are approximated by a
// Rayleigh-Ritz projection (after Nasikun, Brandt and Hildebrandt, "Fast
// Approximation of Laplace-Beltrami Eigenproblems", SGP 2018):
//
// - k vertices are sampled by farthest point sampling; r is the largest
//   distance of a vertex to its nearest sample;
// - each sample s carries the bump phi_s(x) = w(d(x, s) / rho), d the distance
//   along the edges, rho = support_factor * r, w the Wendland function
//   (1 - t)^4 (4 t + 1), C2 and zero for t >= 1;
// - the bumps, divided by their sum at each vertex, are a partition of unity
//   psi_s (so the constant functions are in the space, and the eigenvalue 0
//   of every component is exact);
// - with `linear`, each psi_s is also multiplied by the two coordinates of
//   the plane that fits its support best (3 functions per sample), which
//   makes the space reproduce every function that is linear over a support,
//   so that its error on smooth functions falls as the square of the sample
//   spacing instead of linearly.
//
// The functions are the columns of a sparse n × k' matrix P; the reduced
// problem (Pᵀ Q P) y = lambda (Pᵀ M P) y has k' unknowns whatever n is, and
// its eigenvectors give the basis H = P Y, M-orthonormal like the exact one.
struct Partition_of_unity_settings
{
  Eigen::Index samples = 0;     // k
  double support_factor = 2.0;  // rho / r
  bool linear = true;
};

double wendland_bump(double t);

// A vertex in the support of a sampled function, and the bump there.
typedef std::pair<Eigen::Index, double> Support_entry;

// The vertices within `radius` of each of the `samples` along the edges of
// `graph`, with the bump there, sorted by vertex.
std::vector<std::vector<Support_entry>>
sample_supports(const Edge_length_graph& graph, const std::vector<Eigen::Index>& samples, double radius);

// The tangent plane of each support: the two principal directions of its
// vertices, weighted by the bump. A support too small or too flat in one
// direction to carry the linear functions keeps the constant one only
// (its entry of `has_linear`, one per support like `tangents`, stays 0).
void support_tangent_planes(const std::vector<std::vector<Support_entry>>& supports,
                            const Eigen::Matrix<double, Eigen::Dynamic, 3>& positions, double radius,
                            std::vector<Eigen::Matrix<double, 3, 2>>& tangents,
                            std::vector<char>& has_linear);

// The columns of P (see above), column-major with sorted rows. Throws
// std::runtime_error when a vertex is in no support (a component without a
// sample: more components than samples).
Eigen::SparseMatrix<double>
partition_of_unity_functions(const Edge_length_graph& graph,
                      const Eigen::Matrix<double, Eigen::Dynamic, 3>& positions,
                      const std::vector<Eigen::Index>& samples, double radius, bool linear);

// H = P Y by panels of rows on all threads: each panel of H is summed in
// double in a small row-major buffer from the rows of P and of Y, then
// written to the column-major H, of scalar type `Scalar`: a float H is the
// rounding of the double one, and never needs the double one's memory.
template <typename Scalar>
void prolongate(const Eigen::SparseMatrix<double, Eigen::RowMajor>& rows, const Eigen::MatrixXd& coefficients,
                Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>& result)
{
  const Eigen::Index n = rows.rows();
  const Eigen::Index m = coefficients.cols();
  const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> y = coefficients;
  result.resize(n, m);
  const Eigen::Index panel = 256;
  const Eigen::Index panels = (n + panel - 1) / panel;
  typedef Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> Buffer;
  Parallel_exception failure;
#ifdef _OPENMP
#pragma omp parallel if(n > parallel_loop_items)
#endif
  {
    std::unique_ptr<Buffer> buffer;
    failure.run([&] { buffer = std::make_unique<Buffer>(panel, m); });
#ifdef _OPENMP
#pragma omp for schedule(static)
#endif
    for(Eigen::Index b = 0; b < panels; ++b)
      failure.run([&] {
        const Eigen::Index first = b * panel;
        const Eigen::Index count = (std::min)(panel, n - first);
        buffer->topRows(count).setZero();
        for(Eigen::Index r = 0; r < count; ++r)
          for(Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator p(rows, first + r); p; ++p)
            buffer->row(r) += p.value() * y.row(p.col());
        result.middleRows(first, count) = buffer->topRows(count).template cast<Scalar>();
      });
  }
  failure.rethrow();
}

// The reduced problem A y = lambda B y (B = Pᵀ M P, not diagonal) in standard
// form: with B = G Gᵀ (a sparse Cholesky factor, G = Pᵀ L for the fill-reducing
// permutation P of Eigen's factorization), C = G⁻¹ A G⁻ᵀ has the same
// eigenvalues and the eigenvectors z = Gᵀ y. Its shift-invert operator
// (C - sigma I)⁻¹ = Gᵀ (A - sigma B)⁻¹ G costs two sparse triangular
// products and one solve, and the Lanczos iteration then works in the
// Euclidean inner product (Spectra's generalized mode made several products
// with B per step, 1.0-1.1 s against 0.55-0.65 s at 3,000 functions). The
// Spectra iteration on this operator is the fallback of
// `reduced_eigenpairs()`, whose single-vector method keeps M v_j from the
// step before instead, one product with B per step.
template <class SparseSPDSolverTraits>
class Standard_form_shift_invert_operator
{
public:
  typedef double Scalar;

  Standard_form_shift_invert_operator(const Eigen::SparseMatrix<double>& a,
                                      const Eigen::SparseMatrix<double>& b)
    : m_a(a), m_b(b)
  {
    m_mass_factor.compute(b);
    if(m_mass_factor.info() != Eigen::Success)
      throw std::runtime_error("the Gram matrix of the sampled functions is not positive definite");
    m_lower = m_mass_factor.matrixL();
  }

  Eigen::Index rows() const { return m_a.rows(); }
  Eigen::Index cols() const { return m_a.cols(); }

  void set_shift(double sigma)
  {
    const Eigen::SparseMatrix<double> shifted = m_a - sigma * m_b;
    if(!m_solver.factor(shifted))
      throw std::runtime_error("the factorization of the reduced shifted matrix failed");
  }

  // y = Gᵀ (A - sigma B)⁻¹ G x
  void perform_op(const double* x_in, double* y_out) const
  {
    const Eigen::Map<const Eigen::VectorXd> x(x_in, rows());
    m_work = m_lower * x;
    m_rhs = m_mass_factor.permutationP().transpose() * m_work;
    if(!m_solver.solve(m_rhs, m_solution))
      throw std::runtime_error("a reduced shift-invert solve failed");
    m_work = m_mass_factor.permutationP() * m_solution.col(0);
    Eigen::Map<Eigen::VectorXd>(y_out, rows()).noalias() = m_lower.transpose() * m_work;
  }

  // y = G⁻ᵀ z, the eigenvectors of the reduced problem from those of C.
  Eigen::MatrixXd generalized_vectors(const Eigen::MatrixXd& z) const
  {
    // Column by column, as Eigen solves them: blocks of columns on the threads.
    constexpr Eigen::Index block = 8;
    const Eigen::Index blocks = (z.cols() + block - 1) / block;
    Eigen::MatrixXd solved(z.rows(), z.cols());
    Parallel_exception failure;
#ifdef _OPENMP
#pragma omp parallel for schedule(dynamic, 1) if(m_lower.nonZeros() > parallel_sparse_solve_entries)
#endif
    for(Eigen::Index b = 0; b < blocks; ++b)
      failure.run([&] {
        const Eigen::Index first = b * block, width = (std::min)(block, z.cols() - first);
        solved.middleCols(first, width) =
            m_lower.transpose().triangularView<Eigen::Upper>().solve(z.middleCols(first, width));
      });
    failure.rethrow();
    return m_mass_factor.permutationP().transpose() * solved;
  }

private:
  const Eigen::SparseMatrix<double>& m_a;
  const Eigen::SparseMatrix<double>& m_b;
  Eigen::SimplicialLLT<Eigen::SparseMatrix<double>> m_mass_factor;
  Eigen::SparseMatrix<double> m_lower;
  SparseSPDSolverTraits m_solver;
  mutable Eigen::VectorXd m_work;
  mutable Eigen::MatrixXd m_rhs, m_solution;
};

// The m smallest eigenpairs of Q h = lambda M h (M = diag(mass)) in the span
// of the columns of `functions`: the shift-invert single-vector Lanczos
// method of the exact basis on the reduced pair (A, B) = (Pᵀ Q P, Pᵀ M P),
// B-inner products through one sparse product with B per step, then
// H = P Y. Spectra's restarted Lanczos on the standard form
// Gᵀ (A - σB)⁻¹ G (B = G Gᵀ), used before, made two products with the
// Cholesky factor G per step (as costly as the solve), restarted, and
// needed G⁻ᵀ Z for the vectors: 0.35-0.55 s on 3,000 functions whatever
// the region's size. It remains the fallback when the subspace of the
// single-vector method reaches its cap unconverged. Returns false with
// `message` set when the reduced problem is too small, singular or does not
// converge.
// `functions` is released once the reduced pair is made (H is made from a
// copy by rows). H is in double or float (`Scalar`).
template <class SparseSPDSolverTraits, typename Scalar>
bool reduced_eigenpairs(const Eigen::SparseMatrix<double>& stiffness, const Eigen::VectorXd& mass,
                        Eigen::SparseMatrix<double>&& functions, Eigen::Index m,
                        Eigen::VectorXd& eigenvalues, Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>& eigenvectors,
                        std::string& message)
{
  const Eigen::Index reduced = functions.cols();
  if(reduced < m + 2)
  {
    message = "the space of sampled functions (" + std::to_string(reduced) +
              " functions) is too small for " + std::to_string(m) + " frequencies";
    return false;
  }
  try
  {
    // P by rows, read by both the Galerkin products and the prolongation.
    const Eigen::SparseMatrix<double, Eigen::RowMajor> rows = functions;
    Eigen::SparseMatrix<double> reduced_stiffness, reduced_mass;
    galerkin_matrices(stiffness, mass, functions, rows, reduced_stiffness, reduced_mass);
    Eigen::SparseMatrix<double>().swap(functions);

    const double sigma = shift_invert_shift(mass);
    Single_vector_lanczos_settings settings;
    settings.max_dimension = (std::min)(reduced - 1, 8 * m);
    settings.tolerance = 1e-10;
    Eigen::MatrixXd coefficients;
    auto ignore = [](Eigen::Index) {};
    std::string unconverged;
    if(!single_vector_lanczos_iteration<SparseSPDSolverTraits>(reduced_stiffness, Sparse_mass(reduced_mass), nullptr,
                                                               sigma, m, settings, ignore, ignore, eigenvalues,
                                                               coefficients, unconverged))
    {
      typedef Standard_form_shift_invert_operator<SparseSPDSolverTraits> Op;
      Op op(reduced_stiffness, reduced_mass);
      Spectra::SymEigsShiftSolver<Op> solver(op, m, spectra_subspace_dimension(reduced, m), sigma);
      solver.init();
      solver.compute(Spectra::SortRule::LargestMagn, 1000, 1e-10, Spectra::SortRule::SmallestAlge);
      if(solver.info() != Spectra::CompInfo::Successful)
      {
        message = "the Lanczos iteration on the reduced problem did not converge (" + unconverged + ")";
        return false;
      }
      eigenvalues = solver.eigenvalues();
      coefficients = op.generalized_vectors(solver.eigenvectors());
    }
    prolongate(rows, coefficients, eigenvectors);
    return true;
  }
  catch(const std::exception& e)
  {
    message = e.what();
    return false;
  }
}

} // namespace Eigensolvers
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#if CGAL_SSMD_CORE_DEFINITIONS
#include <CGAL/Spectral_deformation/internal/Eigensolvers/Partition_of_unity_space_impl.h>
#endif

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_PARTITION_OF_UNITY_SPACE_H
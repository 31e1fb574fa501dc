// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_RITZ_VECTORS_IMPL_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_RITZ_VECTORS_IMPL_H

// The definitions of the functions declared in Ritz_vectors.h (see
// internal/compiled_core.h: the compiled core holds them).

#include <CGAL/Spectral_deformation/internal/Eigensolvers/Ritz_vectors.h>

namespace CGAL {
namespace Spectral_deformation {
namespace internal {
namespace Eigensolvers {

CGAL_SSMD_CORE_FUNCTION Eigen::Index ritz_panel_rows()
{ return 128; }

CGAL_SSMD_CORE_FUNCTION int ritz_vector_threads()
{
#ifdef _OPENMP
  return omp_in_parallel() ? 1 : (std::min)(omp_get_max_threads(), 8);
#else
  return 1;
#endif
}

CGAL_SSMD_CORE_FUNCTION Eigen::MatrixXd ritz_vectors_with_gram(Eigen::MatrixXd& V, Eigen::Index k,
                                                               const Eigen::MatrixXd& S, const Eigen::VectorXd& mass,
                                                               const Eigen::MatrixXd& known_vectors)
{
  typedef Eigen::MatrixXd Matrix;
  const Eigen::Index n = V.rows(), known = known_vectors.cols(), wanted = S.cols();
  const Eigen::Index panel = ritz_panel_rows(), panels = (n + panel - 1) / panel;
  const int threads = ritz_vector_threads();
  (void)threads; // without OpenMP
  // The Gram matrix is summed in groups of consecutive panels whose number
  // depends on the sizes only, then group after group: the same result
  // whatever the number of threads.
  const Eigen::Index groups = (std::max)(Eigen::Index(1), (std::min)(panels, Eigen::Index(8)));
  std::vector<Matrix> grams(static_cast<std::size_t>(groups), Matrix::Zero(wanted, wanted));
#ifdef _OPENMP
#pragma omp parallel num_threads(threads)
#endif
  {
    Matrix ritz(panel, wanted), weighted(panel, wanted);
#ifdef _OPENMP
#pragma omp for schedule(static)
#endif
    for(Eigen::Index g = 0; g < groups; ++g)
    {
      Matrix& gram = grams[static_cast<std::size_t>(g)];
      for(Eigen::Index p = panels * g / groups; p < panels * (g + 1) / groups; ++p)
      {
        const Eigen::Index first = p * panel, rows = (std::min)(panel, n - first);
        auto ritz_rows = ritz.topRows(rows);
        auto weighted_rows = weighted.topRows(rows);
        dense_product(false, V.block(first, 0, rows, k), false, S, 1.0, 0.0, ritz_rows);
        weighted_rows = mass.segment(first, rows).asDiagonal() * ritz_rows;
        dense_product(true, ritz_rows, false, weighted_rows, 1.0, 1.0, gram);
        V.block(first, 0, rows, known) = known_vectors.middleRows(first, rows);
        V.block(first, known, rows, wanted) = ritz_rows;
      }
    }
  }
  for(std::size_t g = 1; g < grams.size(); ++g)
    grams[0] += grams[g];
  return 0.5 * (grams[0] + grams[0].transpose());
}

CGAL_SSMD_CORE_FUNCTION bool orthonormalize_in_place(Eigen::MatrixXd& V, Eigen::Index known,
                                                     const Eigen::MatrixXd& gram)
{
  typedef Eigen::MatrixXd Matrix;
  const Eigen::Index n = V.rows(), wanted = gram.rows();
  if((gram - Matrix::Identity(wanted, wanted)).cwiseAbs().maxCoeff() <= 1e-13)
    return true;
  Eigen::LLT<Matrix> cholesky(gram);
  if(cholesky.info() != Eigen::Success)
    return false;
  const Matrix inverse_upper = cholesky.matrixU().solve(Matrix::Identity(wanted, wanted));
  const Eigen::Index panel = ritz_panel_rows(), panels = (n + panel - 1) / panel;
  const int threads = ritz_vector_threads();
  (void)threads;
#ifdef _OPENMP
#pragma omp parallel num_threads(threads)
#endif
  {
    Matrix rotated(panel, wanted);
#ifdef _OPENMP
#pragma omp for schedule(static)
#endif
    for(Eigen::Index p = 0; p < panels; ++p)
    {
      const Eigen::Index first = p * panel, rows = (std::min)(panel, n - first);
      auto rotated_rows = rotated.topRows(rows);
      dense_product(false, V.block(first, known, rows, wanted), false, inverse_upper, 1.0, 0.0,
                    rotated_rows);
      V.block(first, known, rows, wanted) = rotated_rows;
    }
  }
  return true;
}

CGAL_SSMD_CORE_FUNCTION bool ritz_vectors_in_place(Eigen::MatrixXd& V, Eigen::Index k, const Eigen::MatrixXd& S,
                                                   const Eigen::VectorXd& mass, const Eigen::MatrixXd& known_vectors)
{
  const Eigen::MatrixXd gram = ritz_vectors_with_gram(V, k, S, mass, known_vectors);
  return orthonormalize_in_place(V, known_vectors.cols(), gram);
}

} // namespace Eigensolvers
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_RITZ_VECTORS_IMPL_H

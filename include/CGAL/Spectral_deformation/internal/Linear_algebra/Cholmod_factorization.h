// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_LINEAR_ALGEBRA_CHOLMOD_FACTORIZATION_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_LINEAR_ALGEBRA_CHOLMOD_FACTORIZATION_H

#include <Eigen/CholmodSupport>
#include <Eigen/Sparse>

#include <cholmod.h>

#include <mutex>
#include <vector>

namespace CGAL {
namespace Spectral_deformation {
namespace internal {

// The lock of CHOLMOD's analyses: one for the whole process, whichever form
// of the factor, since METIS's random generator is shared by all of them.
inline std::mutex& cholmod_analysis_mutex()
{
  static std::mutex mutex;
  return mutex;
}

namespace Linear_algebra {

// A Cholesky factor of a symmetric positive definite matrix (lower triangle
// read) owned through CHOLMOD's C API, with the CHOLMOD workspace it was
// made in. The solver traits need the factor itself (CHOLMOD's solves with
// kept work arrays, its row updates, the solves by subtrees), which Eigen's
// `CholmodDecomposition` keeps protected; the settings of the workspace are
// those of Eigen's wrapper in the same mode, so that the factor is the one
// Eigen would make.
class Cholmod_factorization
{
public:
  typedef Eigen::SparseMatrix<double> Matrix;

  // Supernodal: the factor stays supernodal (Eigen's CholmodSupernodalLLt).
  // Otherwise CHOLMOD chooses the form of the factorization from the
  // analysis (supernodal above common().supernodal_switch flops per entry)
  // and converts the factor to the simplicial LLᵀ the solves are split on,
  // without the zeros the supernodes carried.
  explicit Cholmod_factorization(bool supernodal)
  {
    cholmod_start(&m_common);
    if(supernodal)
    {
      m_common.final_asis = 1;
      m_common.supernodal = CHOLMOD_SUPERNODAL;
    }
    else
    {
      m_common.supernodal = CHOLMOD_AUTO;
      m_common.final_asis = 0;
      m_common.final_super = 0;
      m_common.final_ll = 1;
      m_common.final_pack = 1;
      m_common.final_monotonic = 1;
      m_common.final_resymbol = 1;
    }
  }
  Cholmod_factorization(const Cholmod_factorization&) = delete;
  Cholmod_factorization& operator=(const Cholmod_factorization&) = delete;
  ~Cholmod_factorization()
  {
    release_factor();
    cholmod_finish(&m_common);
  }

  cholmod_common& common() const { return m_common; }
  cholmod_factor* factor() const { return m_factor; }

  // The sparser of the orderings of the pattern of A by minimum degree
  // (AMD) and by nested dissection (METIS, when CHOLMOD has it), the
  // current factor left as it is. Empty when the analysis fails.
  std::vector<int> ordering_of(const Matrix& A)
  {
    cholmod_sparse a = lower_triangle_view(A);
    const int methods = m_common.nmethods, first_method = m_common.method[0].ordering,
              second_method = m_common.method[1].ordering;
    m_common.nmethods = 2;
    m_common.method[0].ordering = CHOLMOD_AMD;
    m_common.method[1].ordering = CHOLMOD_METIS;
    m_common.status = CHOLMOD_OK;
    cholmod_factor* analysis = analyze_serialized(a);
    if(analysis == nullptr && m_common.status != CHOLMOD_OUT_OF_MEMORY)
    {
      // A CHOLMOD built without METIS refuses that method: AMD alone.
      m_common.nmethods = 1;
      m_common.status = CHOLMOD_OK;
      analysis = analyze_serialized(a);
    }
    m_common.nmethods = methods;
    m_common.method[0].ordering = first_method;
    m_common.method[1].ordering = second_method;
    std::vector<int> ordering;
    if(analysis != nullptr && m_common.status >= CHOLMOD_OK && analysis->Perm != nullptr)
    {
      const int* permutation = static_cast<const int*>(analysis->Perm);
      ordering.assign(permutation, permutation + analysis->n);
    }
    if(analysis != nullptr)
      cholmod_free_factor(&analysis, &m_common);
    m_common.status = CHOLMOD_OK;
    return ordering;
  }

  // Analyzes and factors A, with `ordering` as the fill-reducing ordering
  // when given (CHOLMOD's own choice if the analysis with it fails). When
  // CHOLMOD runs out of memory its analysis returns no factor and an
  // interrupted factorization leaves a status below CHOLMOD_OK: both are
  // failures, as is a matrix that is not positive definite.
  bool compute(const Matrix& A, std::vector<int>* ordering = nullptr) { return analyze(A, ordering) && factorize(A); }

  // The first half of compute(): the symbolic analysis, which also decides
  // whether the factor is supernodal (factor()->is_super).
  bool analyze(const Matrix& A, std::vector<int>* ordering = nullptr)
  {
    m_common.status = CHOLMOD_OK;
    cholmod_sparse a = lower_triangle_view(A);
    if(ordering != nullptr)
      analyze_with_ordering(a, *ordering);
    if(ordering == nullptr || m_factor == nullptr || m_common.status < CHOLMOD_OK)
    {
      release_factor();
      m_common.status = CHOLMOD_OK;
      m_factor = analyze_serialized(a);
    }
    return m_factor != nullptr && m_common.status >= CHOLMOD_OK;
  }

  // The second half of compute(): the numerical factorization of A, whose
  // pattern analyze() was given.
  bool factorize(const Matrix& A)
  {
    cholmod_sparse a = lower_triangle_view(A);
    double no_shift[2] = {0, 0};
    cholmod_factorize_p(&a, no_shift, nullptr, 0, m_factor, &m_common);
    return m_factor->minor == m_factor->n && m_common.status >= CHOLMOD_OK;
  }

private:
  static cholmod_sparse lower_triangle_view(const Matrix& A)
  {
    return Eigen::viewAsCholmod(A.template selfadjointView<Eigen::Lower>());
  }

  void release_factor()
  {
    if(m_factor != nullptr)
      cholmod_free_factor(&m_factor, &m_common);
    m_factor = nullptr;
  }

  void analyze_with_ordering(cholmod_sparse& a, std::vector<int>& ordering)
  {
    release_factor();
    const int methods = m_common.nmethods, first_method = m_common.method[0].ordering;
    const int postorder = m_common.postorder;
    m_common.nmethods = 1;
    m_common.method[0].ordering = CHOLMOD_GIVEN;
    m_common.postorder = 1;
    m_factor = cholmod_analyze_p(&a, ordering.data(), nullptr, 0, &m_common);
    m_common.nmethods = methods;
    m_common.method[0].ordering = first_method;
    m_common.postorder = postorder;
  }

  // CHOLMOD's analysis of `a`, one at a time in the process. METIS, which
  // the analysis may call, draws from a random generator that all its
  // callers share: two analyses at once could get different orderings than
  // one after the other, and so factors and results that differ in their
  // last bits.
  cholmod_factor* analyze_serialized(cholmod_sparse& a)
  {
    std::lock_guard<std::mutex> lock(cholmod_analysis_mutex());
    return cholmod_analyze(&a, &m_common);
  }

  // CHOLMOD's calls take the workspace by non-const pointer, also in the
  // solves, which are const for the traits.
  mutable cholmod_common m_common;
  cholmod_factor* m_factor = nullptr;
};

} // namespace Linear_algebra
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_LINEAR_ALGEBRA_CHOLMOD_FACTORIZATION_H

// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_RAYLEIGH_RITZ_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_RAYLEIGH_RITZ_H

#include <CGAL/Spectral_deformation/internal/compiled_core.h>
#include <CGAL/Spectral_deformation/internal/Eigensolvers/Block_lanczos_state.h>
#include <CGAL/Spectral_deformation/internal/Eigensolvers/Symmetric_eigenpairs.h>
#include <CGAL/Spectral_deformation/internal/Eigensolvers/Shift_invert.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <algorithm>
#include <cmath>
#include <limits>

namespace CGAL {
namespace Spectral_deformation {
namespace internal {
namespace Eigensolvers {

// The Rayleigh-Ritz check of the block Lanczos method and its schedule: the
// eigenpairs of T approximate those of the operator on the subspace.

// The wanted Ritz pairs of the subspace: the `wanted` largest eigenvalues
// theta of T (ascending) and their coordinates in V; `converged` of them
// satisfy the tolerance; `slowest` is the largest ratio of a residual to
// what the tolerance allows (at most 1 when all converged).
struct Ritz_pairs
{
  Eigen::VectorXd values;
  Eigen::MatrixXd coordinates;
  Eigen::Index converged = 0;
  double slowest = 0;
};

// Rayleigh-Ritz on the k leading columns. The residual of a Ritz pair
// (theta, y) is ‖R y_tail‖_M, with y_tail its last b coordinates and R the
// coupling of the next block: it converged when the residual is at most
// `tolerance * |theta|`. Returns false when the dense eigensolver fails.
bool rayleigh_ritz(const Block_lanczos_state& state, Eigen::Index k, Eigen::Index wanted,
                   double tolerance, const Eigen::MatrixXd& R, Ritz_pairs& ritz);

// Each Rayleigh-Ritz check costs a dense k × k eigendecomposition: the
// checks start where convergence is plausible.
Eigen::Index first_check_dimension(Eigen::Index m, Eigen::Index b);

// Where the next check goes. A check costs a dense k × k eigendecomposition
// (3 to 14 ms at k = 150 to 340 on the 2-core machine of the notes), more
// than the blocks it may save on regions of a few thousand vertices: the
// checks are put where the convergence seen so far says the wanted pairs
// will have converged, three quarters of the way there so as not to
// overshoot. Two forecasts, the nearer one wins: the converged pairs grow
// about linearly with k (about b / 3 a block on the armadillo and dinosaur
// meshes), and the slowest residual falls about geometrically in k once
// the wanted pairs start converging (tenfold every 10 to 20 columns there),
// so that its log, extrapolated from the last two checks, says when it
// meets the tolerance. Without a forecast (the first check, no progress),
// the next check is 1/16 of k further, every block when fewer than 2 b
// pairs are missing. No step is longer than k.
class Convergence_forecast
{
public:
  Eigen::Index next_check(Eigen::Index k, Eigen::Index b, Eigen::Index wanted,
                          const Ritz_pairs& ritz)
  {
    const Eigen::Index missing = wanted - ritz.converged;
    double columns = std::numeric_limits<double>::infinity();
    if(m_first_k > 0 && ritz.converged > m_first_converged)
      columns = double(missing) * double(k - m_first_k) / double(ritz.converged - m_first_converged);
    if(m_previous_k > 0 && ritz.slowest > 1 && ritz.slowest < m_previous_slowest)
    {
      const double decay = std::log(m_previous_slowest / ritz.slowest) / double(k - m_previous_k);
      columns = (std::min)(columns, std::log(ritz.slowest) / decay);
    }
    if(m_first_k < 0)
    {
      m_first_k = k;
      m_first_converged = ritz.converged;
    }
    m_previous_k = k;
    m_previous_slowest = ritz.slowest;
    const Eigen::Index step =
        std::isfinite(columns)
            ? round_up((std::max)(b, static_cast<Eigen::Index>(0.75 * (std::min)(columns, double(k)))), b)
            : (std::min)(round_up((std::max)(b, k / 16), b),
                         b * (std::max)(Eigen::Index(1), missing / b));
    return k + (std::min)(step, round_up(k, b));
  }

private:
  Eigen::Index m_first_k = -1;
  Eigen::Index m_first_converged = 0;
  Eigen::Index m_previous_k = -1;
  double m_previous_slowest = 0;
};

// The eigenpairs of the converged Ritz pairs: the known zero eigenvalues,
// then lambda = sigma + 1 / theta, ascending; `selected` (k × wanted)
// receives the coordinates in the same order.
Eigen::VectorXd ritz_eigenvalues(const Ritz_pairs& ritz, Eigen::Index known, double sigma,
                                 Eigen::Index k, Eigen::MatrixXd& selected);

// Checks ‖Q h - lambda M h‖ against the tolerance directly, relative to the
// spread of the computed spectrum and the shift, as the residuals reported
// by the benchmarks.
bool verify_eigenpairs(const Eigen::SparseMatrix<double>& stiffness,
                       const Eigen::VectorXd& mass, const Eigen::VectorXd& eigenvalues,
                       const Eigen::MatrixXd& eigenvectors, double tolerance);

} // namespace Eigensolvers
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#if CGAL_SSMD_CORE_DEFINITIONS
#include <CGAL/Spectral_deformation/internal/Eigensolvers/Rayleigh_ritz_impl.h>
#endif

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_EIGENSOLVERS_RAYLEIGH_RITZ_H

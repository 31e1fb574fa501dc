// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_LINEAR_ALGEBRA_TWO_SUBTREE_TRIANGULAR_SOLVE_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_LINEAR_ALGEBRA_TWO_SUBTREE_TRIANGULAR_SOLVE_H

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace CGAL {
namespace Spectral_deformation {
namespace internal {
namespace Linear_algebra {

// Solves L Lᵀ y = b with a simplicial Cholesky factor L (compressed columns,
// rows sorted, diagonal first) on two threads, each on its own subtrees of
// the elimination tree. The columns need not be in a postorder of the tree:
// a factor modified row by row (`Cholmod_llt_solver_traits::refactor_rows()`)
// keeps the numbering of its first analysis.
//
// The columns of a subtree only update rows of the subtree and of its
// ancestors. The tree is cut below a few top columns (the ancestors of
// everything, typically the last separator of the ordering) into subtrees
// dealt to the two threads with about equal numbers of entries: the forward
// solve runs the subtrees concurrently, each thread collecting its updates
// of the top rows apart, then the top columns; the backward solve runs the
// top columns, then the subtrees concurrently.
//
// Both threads read the whole block of right-hand sides stored row by row,
// so that an entry of L updates all of them at once (the reason to prefer
// this to CHOLMOD's own solve, which reads L once per four right-hand sides
// and, split by right-hand sides over two threads, twice per block of eight).
class Two_subtree_triangular_solve
{
public:
  // The solve's structure: the subtrees, one per thread, that its two
  // parallel sweeps run on.
  static constexpr int number_of_subtrees = 2;

  // Analyzes the pattern of L (n columns starting at `starts`, of
  // `counts` entries each, or, when `counts` is null, packed: n + 1 starts;
  // `rows` the row indices). `usable()` tells whether the split was found:
  // a pattern that is not sorted, or a tree whose top columns would hold
  // more than a quarter of the entries, is left to the caller's sequential
  // solve.
  void analyze(int n, const int* starts, const int* counts, const int* rows)
  {
    *this = Two_subtree_triangular_solve();
    if(n < 2)
      return;
    m_ends.resize(static_cast<std::size_t>(n));
    for(int j = 0; j < n; ++j)
      m_ends[static_cast<std::size_t>(j)] = counts != nullptr ? starts[j] + counts[j] : starts[j + 1];
    Elimination_tree tree;
    if(!read_tree(n, starts, m_ends.data(), rows, tree))
    {
      m_ends.clear();
      return;
    }
    const std::vector<int>& parent = tree.parent;
    const std::vector<double>& entries = tree.entries;
    const std::vector<double>& subtree_entries = tree.subtree_entries;
    // The children of each column in compressed rows (a vector per column
    // cost more than the rest of the analysis on large factors).
    std::vector<int> child_start(static_cast<std::size_t>(n) + 1, 0), children;
    for(int j = 0; j < n; ++j)
      if(parent[j] >= 0)
        ++child_start[static_cast<std::size_t>(parent[j]) + 1];
    for(int j = 0; j < n; ++j)
      child_start[static_cast<std::size_t>(j) + 1] += child_start[static_cast<std::size_t>(j)];
    children.resize(static_cast<std::size_t>(child_start[static_cast<std::size_t>(n)]));
    {
      std::vector<int> next(child_start.begin(), child_start.end() - 1);
      for(int j = 0; j < n; ++j)
        if(parent[j] >= 0)
          children[static_cast<std::size_t>(next[static_cast<std::size_t>(parent[j])]++)] = j;
    }
    // Columns alone in their tree (the rows of the identity of a Dirichlet
    // system) are dealt last, one by one, to balance the two threads.
    std::vector<int> candidates, isolated;
    double total = 0;
    for(int j = 0; j < n; ++j)
    {
      total += entries[j];
      if(parent[j] >= 0)
        continue;
      if(subtree_entries[j] > 1)
        candidates.push_back(j);
      else
        isolated.push_back(j);
    }
    // Deal the candidate subtrees, largest first, to the lighter thread;
    // while that leaves them unbalanced, replace the largest by its
    // children, its root becoming a top column.
    std::vector<int> top;
    double top_entries = 0;
    std::vector<int> assignment;
    double load[number_of_subtrees];
    for(;;)
    {
      std::sort(candidates.begin(), candidates.end(),
                [&](int a, int b) { return subtree_entries[a] > subtree_entries[b]; });
      load[0] = load[1] = 0;
      assignment.assign(candidates.size(), 0);
      for(std::size_t c = 0; c < candidates.size(); ++c)
      {
        assignment[c] = load[0] <= load[1] ? 0 : 1;
        load[assignment[c]] += subtree_entries[candidates[c]];
      }
      if(std::abs(load[0] - load[1]) <= 0.02 * total)
        break;
      const int largest = candidates.front();
      top.push_back(largest);
      top_entries += entries[largest];
      if(top_entries > 0.25 * total)
        return;
      candidates.erase(candidates.begin());
      candidates.insert(candidates.end(), children.begin() + child_start[static_cast<std::size_t>(largest)],
                        children.begin() + child_start[static_cast<std::size_t>(largest) + 1]);
      if(candidates.empty())
        return;
    }
    std::sort(top.begin(), top.end());
    m_top = std::move(top);
    m_top_slot.assign(n, -1);
    for(std::size_t t = 0; t < m_top.size(); ++t)
      m_top_slot[m_top[t]] = static_cast<int>(t);
    // Every other column lies below one candidate and belongs to its thread;
    // a parent comes after its children, so one pass from the last column
    // down finds the owners, and the columns of each thread, increasing, are
    // an order in which children come before their parents.
    std::vector<signed char> owner(n, -1);
    for(std::size_t c = 0; c < candidates.size(); ++c)
      owner[candidates[c]] = static_cast<signed char>(assignment[c]);
    for(const int j : isolated)
    {
      const int lighter = load[0] <= load[1] ? 0 : 1;
      owner[j] = static_cast<signed char>(lighter);
      load[lighter] += 1;
    }
    for(int j = n - 1; j >= 0; --j)
      if(owner[j] < 0 && m_top_slot[j] < 0 && parent[j] >= 0)
        owner[j] = owner[parent[j]];
    std::size_t owned[number_of_subtrees] = {0, 0};
    for(int j = 0; j < n; ++j)
      if(owner[j] >= 0)
        ++owned[owner[j]];
    m_columns[0].reserve(owned[0]);
    m_columns[1].reserve(owned[1]);
    for(int j = 0; j < n; ++j)
      if(owner[j] >= 0)
        m_columns[owner[j]].push_back(j);
    m_usable = true;
  }

  bool usable() const { return m_usable; }

  // Overwrites y (n rows of W values, stored row after row) with
  // (L Lᵀ)^{-1} y; `starts`, `rows` as given to analyze(), `values` the
  // entries of L. With `parallel`, the two subtrees are solved on two
  // threads, otherwise one after the other: the same operations in the same
  // order, so the same result to the last bit.
  template <int W>
  void solve(const int* starts, const int* rows, const double* values, double* y, bool parallel) const
  {
    (void)parallel; // without OpenMP
    const std::size_t top_size = m_top.size();
    const int* const ends = m_ends.data();
    std::vector<double> top_updates[number_of_subtrees];
#ifdef _OPENMP
#pragma omp parallel for num_threads(number_of_subtrees) schedule(static, 1) if(parallel)
#endif
    for(int thread = 0; thread < number_of_subtrees; ++thread)
    {
      std::vector<double>& updates = top_updates[thread];
      updates.assign(top_size * W, 0.0);
      for(const int j : m_columns[thread])
      {
        double solved[W]; // a copy, so that the updates below cannot alias it
        divide_by_diagonal<W>(j, starts, values, y, solved);
        for(int k = starts[j] + 1; k < ends[j]; ++k)
        {
          // Row i is an ancestor of j: in the same subtree, or a top column.
          const int i = rows[k];
          const int slot = m_top_slot[i];
          double* target = slot < 0 ? y + std::size_t(W) * i : updates.data() + std::size_t(W) * slot;
          const double l = values[k];
          for(int c = 0; c < W; ++c)
            target[c] -= l * solved[c];
        }
      }
    }
    for(std::size_t t = 0; t < top_size; ++t)
    {
      double* y_t = y + std::size_t(W) * m_top[t];
      for(int c = 0; c < W; ++c)
        y_t[c] += top_updates[0][t * W + c] + top_updates[1][t * W + c];
    }
    for(const int j : m_top)
    {
      double solved[W];
      divide_by_diagonal<W>(j, starts, values, y, solved);
      for(int k = starts[j] + 1; k < ends[j]; ++k)
      {
        double* y_i = y + std::size_t(W) * rows[k];
        const double l = values[k];
        for(int c = 0; c < W; ++c)
          y_i[c] -= l * solved[c];
      }
    }

    auto backward = [&](int j) {
      double* y_j = y + std::size_t(W) * j;
      double sum[W];
      for(int c = 0; c < W; ++c)
        sum[c] = y_j[c];
      for(int k = starts[j] + 1; k < ends[j]; ++k)
      {
        const double* y_i = y + std::size_t(W) * rows[k];
        const double l = values[k];
        for(int c = 0; c < W; ++c)
          sum[c] -= l * y_i[c];
      }
      const double inverse_diagonal = 1.0 / values[starts[j]];
      for(int c = 0; c < W; ++c)
        y_j[c] = sum[c] * inverse_diagonal;
    };
    for(auto j = m_top.rbegin(); j != m_top.rend(); ++j)
      backward(*j);
#ifdef _OPENMP
#pragma omp parallel for num_threads(number_of_subtrees) schedule(static, 1) if(parallel)
#endif
    for(int thread = 0; thread < number_of_subtrees; ++thread)
      for(auto j = m_columns[thread].rbegin(); j != m_columns[thread].rend(); ++j)
        backward(*j);
  }

  // X = A^{-1} B for A = P L Lᵀ Pᵀ, row k of A being row position[k] of
  // L: eight right-hand sides at a time (fewer for the last ones), permuted
  // into rows of `work` and solved by solve(), on two threads with
  // `parallel`.
  void solve_permuted(const int* starts, const int* rows, const double* values,
                      const int* position, const Eigen::MatrixXd& B, Eigen::MatrixXd& X,
                      std::vector<double>& work, bool parallel) const
  {
    (void)parallel; // without OpenMP
    const Eigen::Index n = B.rows();
    for(Eigen::Index first = 0; first < B.cols();)
    {
      const Eigen::Index count = (std::min)(Eigen::Index(8), B.cols() - first);
      const int width = count > 4 ? 8 : count > 2 ? 4 : static_cast<int>(count);
      work.resize(static_cast<std::size_t>(n) * width);
      // The rows of B are read in order and written to their place in the
      // factor's ordering (a cache line for eight right-hand sides), on both
      // threads: on one thread these copies were a large part of the solve.
      double* const y = work.data();
#ifdef _OPENMP
#pragma omp parallel for schedule(static) if(parallel)
#endif
      for(Eigen::Index k = 0; k < n; ++k)
      {
        double* target = y + static_cast<std::size_t>(position[k]) * width;
        for(Eigen::Index c = 0; c < count; ++c)
          target[c] = B(k, first + c);
        for(Eigen::Index c = count; c < width; ++c)
          target[c] = 0.0;
      }
      switch(width)
      {
      case 8: solve<8>(starts, rows, values, y, parallel); break;
      case 4: solve<4>(starts, rows, values, y, parallel); break;
      case 2: solve<2>(starts, rows, values, y, parallel); break;
      default: solve<1>(starts, rows, values, y, parallel); break;
      }
#ifdef _OPENMP
#pragma omp parallel for schedule(static) if(parallel)
#endif
      for(Eigen::Index k = 0; k < n; ++k)
      {
        const double* source = y + static_cast<std::size_t>(position[k]) * width;
        for(Eigen::Index c = 0; c < count; ++c)
          X(k, first + c) = source[c];
      }
      first += count;
    }
  }

private:
  // The elimination tree of L: the parent of each column (-1 for a root),
  // its entries and those of its subtree.
  struct Elimination_tree
  {
    std::vector<int> parent;
    std::vector<double> entries, subtree_entries;
  };

  // Reads the tree off the pattern of L. Returns false when the pattern is
  // not sorted with the diagonal first.
  static bool read_tree(int n, const int* starts, const int* ends, const int* rows, Elimination_tree& tree)
  {
    std::vector<int>& parent = tree.parent;
    std::vector<double>& subtree_entries = tree.subtree_entries;
    parent.assign(n, -1);
    tree.entries.resize(n);
    subtree_entries.resize(n);
    for(int j = 0; j < n; ++j)
    {
      if(ends[j] <= starts[j] || rows[starts[j]] != j)
        return false;
      for(int k = starts[j] + 1; k < ends[j]; ++k)
        if(rows[k] <= rows[k - 1] || rows[k] >= n)
          return false;
      if(ends[j] - starts[j] > 1)
        parent[j] = rows[starts[j] + 1];
      tree.entries[j] = subtree_entries[j] = double(ends[j] - starts[j]);
    }
    // A parent comes after its children (a lower triangular factor).
    for(int j = 0; j < n; ++j)
      if(parent[j] >= 0)
        subtree_entries[parent[j]] += subtree_entries[j];
    return true;
  }

  // y_j /= L_jj, also copied into `solved`.
  template <int W>
  static void divide_by_diagonal(int j, const int* starts, const double* values, double* y,
                                 double* solved)
  {
    double* y_j = y + std::size_t(W) * j;
    const double inverse_diagonal = 1.0 / values[starts[j]];
    for(int c = 0; c < W; ++c)
      solved[c] = y_j[c] = y_j[c] * inverse_diagonal;
  }

  std::vector<int> m_ends;                      // one past the last entry of each column
  std::vector<int> m_columns[number_of_subtrees];               // the columns of each thread's subtrees, increasing
  std::vector<int> m_top;                       // the other columns, increasing
  std::vector<int> m_top_slot;                  // column -> index in m_top, or -1
  bool m_usable = false;
};

} // namespace Linear_algebra
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_LINEAR_ALGEBRA_TWO_SUBTREE_TRIANGULAR_SOLVE_H

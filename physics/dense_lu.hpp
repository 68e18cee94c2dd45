// LU factorisation with partial pivoting of a small dense row-major matrix, and its solves: the
// row solves' linear algebra (physics/row_lcp.cpp on the rows, primal_solve.cpp on the
// coordinates). Internal to physics/.
#pragma once

#include <cmath>
#include <cstddef>
#include <utility>

namespace gearsim::physics {

// P·A = L·U of the k×k row-major a, in place (L's multipliers below the diagonal, U on and above
// it; pivots[c]: the row swapped with row c at step c, whole rows). False when a pivot vanishes.
// N > 0: k is N, known when compiling (the loops then unroll; the same arithmetic).
template <int N = 0>
inline bool lu_factor(int k_arg, double* a, int* pivots) {
  const int k = N > 0 ? N : k_arg;
  const auto at = [&](int i, int j) -> double& {
    return a[static_cast<std::size_t>(i) * static_cast<std::size_t>(k) + static_cast<std::size_t>(j)];
  };
  for (int c = 0; c < k; ++c) {
    int p = c;
    for (int i = c + 1; i < k; ++i)
      if (std::abs(at(i, c)) > std::abs(at(p, c))) p = i;
    pivots[c] = p;
    if (!(std::abs(at(p, c)) > 0)) return false;
    if (p != c)
      for (int j = 0; j < k; ++j) std::swap(at(p, j), at(c, j));
    const double inv = 1 / at(c, c);
    double* __restrict pivot_row = &at(c, 0);
    for (int i = c + 1; i < k; ++i) {
      const double f = at(i, c) * inv;
      at(i, c) = f;
      if (f == 0) continue;
      double* __restrict row = &at(i, 0);
      for (int j = c + 1; j < k; ++j) row[j] -= f * pivot_row[j];
    }
  }
  return true;
}

// x ← A⁻¹·x from lu_factor()'s factors: the row interchanges first, as they were made, then the
// two substitutions.
template <int N = 0>
inline void lu_solve(int k_arg, const double* a, const int* pivots, double* x) {
  const int k = N > 0 ? N : k_arg;
  const auto at = [&](int i, int j) { return a[static_cast<std::size_t>(i) * static_cast<std::size_t>(k) + static_cast<std::size_t>(j)]; };
  for (int c = 0; c < k; ++c)
    if (pivots[c] != c) std::swap(x[c], x[pivots[c]]);
  for (int c = 0; c < k; ++c)
    for (int i = c + 1; i < k; ++i) x[i] -= at(i, c) * x[c];
  for (int i = k - 1; i >= 0; --i) {
    double s = x[i];
    for (int j = i + 1; j < k; ++j) s -= at(i, j) * x[j];
    x[i] = s / at(i, i);
  }
}

}  // namespace gearsim::physics

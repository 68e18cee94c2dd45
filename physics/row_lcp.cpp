#include "physics/row_lcp.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "physics/dense_lu.hpp"

namespace gearsim::physics {
namespace {

constexpr double kRelativeTolerance = 1e-9;

// The k×k row-major m solved for right-hand side r (the solution on return; m overwritten). False
// when a pivot vanishes.
bool solve_dense(int k, double* m, double* r, std::vector<int>& pivots) {
  pivots.resize(static_cast<std::size_t>(k));
  if (!lu_factor(k, m, pivots.data())) return false;
  lu_solve(k, m, pivots.data(), r);
  return true;
}

// A friction row whose normal sits on a zero lower bound carries nothing, whatever its state.
bool pinned_row(int i, const int* findex, const RowBound* state, const double* lo) {
  return findex[i] >= 0 && state[findex[i]] == RowBound::lower && lo[findex[i]] == 0;
}

// The reduced system of the free rows (s.rows_of) into s.m and s.rhs, the rows on a bound held
// at their value (friction on a bound: bound_value·x_normal) and those values into x.
void fold_rows(int n, const double* A, const double* b, const double* lo, const double* hi, const int* findex, double* x,
               const RowBound* state, RowLcpScratch& s) {
  const std::size_t un = static_cast<std::size_t>(n);
  const int k = static_cast<int>(s.rows_of.size());
  const std::size_t uk = static_cast<std::size_t>(k);
  const auto pinned = [&](int i) { return pinned_row(i, findex, state, lo); };
  // Constant impulses of the rows on a bound (friction on a bound: its factor on the normal).
  const auto bound_value = [&](int c) { return state[c] == RowBound::lower ? lo[c] : hi[c]; };
  for (int c = 0; c < n; ++c) {
    if (s.unknown_of[static_cast<std::size_t>(c)] >= 0) continue;
    if (pinned(c))
      x[c] = 0;
    else if (findex[c] < 0)
      x[c] = bound_value(c);
  }
  s.m.assign(uk * uk, 0.0);
  s.rhs.assign(uk, 0.0);
  // Where each column's entry goes (the same for every row): an unknown's column into its
  // unknown; a friction row on a bound into its normal's unknown times bound_value, or with its
  // normal's constant impulse to the right-hand side; a constant's to the right-hand side.
  // (Factors of 1 keep every product what it was: aic·1 = aic exactly.)
  s.target.resize(un);
  s.factor.resize(un);
  s.constant.resize(un);
  for (int c = 0; c < n; ++c) {
    const std::size_t uc = static_cast<std::size_t>(c);
    const int u = s.unknown_of[uc];
    if (u >= 0) {
      s.target[uc] = u, s.factor[uc] = 1, s.constant[uc] = 1;
    } else if (findex[c] >= 0 && !pinned(c)) {  // friction on a bound: bound_value·x_normal
      const int f = findex[c];
      s.target[uc] = s.unknown_of[static_cast<std::size_t>(f)], s.factor[uc] = bound_value(c), s.constant[uc] = x[f];
    } else {
      s.target[uc] = -1, s.factor[uc] = x[c], s.constant[uc] = 1;
    }
  }
  const int* target = s.target.data();
  const double *factor = s.factor.data(), *constant = s.constant.data();
  for (int r = 0; r < k; ++r) {
    const int i = s.rows_of[static_cast<std::size_t>(r)];
    double rhs = b[i];
    double* row = s.m.data() + static_cast<std::size_t>(r) * uk;
    const double* ai = A + static_cast<std::size_t>(i) * un;
    for (int c = 0; c < n; ++c) {
      const double aic = ai[c];
      if (aic == 0) continue;
      const int t = target[c];
      if (t >= 0)
        row[t] += aic * factor[c];
      else
        rhs -= aic * factor[c] * constant[c];
    }
    s.rhs[static_cast<std::size_t>(r)] = rhs;
  }
}

// w = A·x − b into s.w and the scales of x and of A·x, b; false where a value is not finite
// (not a solution: Dantzig's to say).
bool residuals(int n, const double* A, const double* b, const double* x, RowLcpScratch& s, double& x_scale, double& w_scale) {
  const std::size_t un = static_cast<std::size_t>(n);
  x_scale = 0, w_scale = 0;
  // A·x four rows at a time: each row's sum in column order, as one row at a time, but four
  // independent chains of additions in flight instead of one.
  int row = 0;
  for (; row + 4 <= n; row += 4) {
    const double *a0 = A + static_cast<std::size_t>(row) * un, *a1 = a0 + un, *a2 = a1 + un, *a3 = a2 + un;
    double s0 = 0, s1 = 0, s2 = 0, s3 = 0;
    for (int c = 0; c < n; ++c) {
      const double xc = x[c];
      s0 += a0[c] * xc;
      s1 += a1[c] * xc;
      s2 += a2[c] * xc;
      s3 += a3[c] * xc;
    }
    s.w[static_cast<std::size_t>(row)] = s0;
    s.w[static_cast<std::size_t>(row) + 1] = s1;
    s.w[static_cast<std::size_t>(row) + 2] = s2;
    s.w[static_cast<std::size_t>(row) + 3] = s3;
  }
  for (; row < n; ++row) {
    double ax = 0;
    const double* ar = A + static_cast<std::size_t>(row) * un;
    for (int c = 0; c < n; ++c) ax += ar[c] * x[c];
    s.w[static_cast<std::size_t>(row)] = ax;
  }
  for (int i = 0; i < n; ++i) {
    const double ax = s.w[static_cast<std::size_t>(i)];
    s.w[static_cast<std::size_t>(i)] = ax - b[i];
    if (!std::isfinite(x[i]) || !std::isfinite(ax)) return false;
    x_scale = std::max(x_scale, std::abs(x[i]));
    w_scale = std::max({w_scale, std::abs(b[i]), std::abs(ax)});
  }
  return true;
}

}  // namespace

int solve_row_lcp(int n, const double* A, const double* b, const double* lo, const double* hi, const int* findex, double* x,
                  RowBound* state, RowLcpScratch& s, int max_solves) {
  const std::size_t un = static_cast<std::size_t>(n);
  s.unknown_of.assign(un, -1);
  s.w.assign(un, 0.0);
  const auto pinned = [&](int i) { return pinned_row(i, findex, state, lo); };
  for (int solves = 1; solves <= max_solves; ++solves) {
    // Unknowns: the free rows (not pinned). Rows on a bound are constants, or (friction) ±μ times
    // their normal's unknown.
    s.rows_of.clear();
    for (int i = 0; i < n; ++i) {
      s.unknown_of[static_cast<std::size_t>(i)] = -1;
      if (state[i] == RowBound::free && !pinned(i)) {
        s.unknown_of[static_cast<std::size_t>(i)] = static_cast<int>(s.rows_of.size());
        s.rows_of.push_back(i);
      }
    }
    const int k = static_cast<int>(s.rows_of.size());
    const std::size_t uk = static_cast<std::size_t>(k);
    if (k == n) {
      // Every row free (the common step: every contact pressed, sliding friction folded out by
      // the caller): the equations are A·x = b itself, and only the bounds on x are conditions
      // (w = 0 on every row). The same numbers the general path below forms (its factors are 1
      // and it adds each nonzero entry to a zero), zeros stored as +0 as it leaves them.
      s.m.resize(uk * uk);
      for (std::size_t e = 0; e < uk * uk; ++e) s.m[e] = A[e] == 0 ? 0.0 : A[e];
      s.rhs.assign(b, b + n);
      if (!solve_dense(k, s.m.data(), s.rhs.data(), s.pivots)) return 0;
      double x_scale = 0;
      for (int i = 0; i < n; ++i) {
        x[i] = s.rhs[static_cast<std::size_t>(i)];
        if (!std::isfinite(x[i])) return 0;  // not a solution: Dantzig's to say
        x_scale = std::max(x_scale, std::abs(x[i]));
      }
      if (settle_row_states(n, x, nullptr, lo, hi, findex, state, solves, kRelativeTolerance * x_scale, 0)) return solves;
      continue;
    }
    fold_rows(n, A, b, lo, hi, findex, x, state, s);
    if (k > 0 && !solve_dense(k, s.m.data(), s.rhs.data(), s.pivots)) return 0;
    for (int r = 0; r < k; ++r) x[s.rows_of[static_cast<std::size_t>(r)]] = s.rhs[static_cast<std::size_t>(r)];
    for (int c = 0; c < n; ++c)
      if (s.unknown_of[static_cast<std::size_t>(c)] < 0 && findex[c] >= 0 && !pinned(c))
        x[c] = (state[c] == RowBound::lower ? lo[c] : hi[c]) * x[findex[c]];
    // The conditions, to tolerances relative to the problem's scale.
    double x_scale, w_scale;
    if (!residuals(n, A, b, x, s, x_scale, w_scale)) return 0;
    if (settle_row_states(n, x, s.w.data(), lo, hi, findex, state, solves, kRelativeTolerance * x_scale, kRelativeTolerance * w_scale))
      return solves;
  }
  return 0;
}

bool settle_row_states(int n, const double* x, const double* w, const double* lo, const double* hi, const int* findex, RowBound* state,
                       int solves, double tol_x, double tol_w) {
  // A friction row whose normal sits on a zero lower bound carries nothing, whatever its state.
  const auto pinned = [&](int i) { return pinned_row(i, findex, state, lo); };
  // Every row that breaks its condition changes its state (block pivoting); after three solves,
  // only the worst one, relative to its tolerance (block pivoting can cycle, single pivots less so).
  const bool single = solves > 3;
  int worst = -1;
  RowBound worst_to = RowBound::free;
  double worst_by = 1;
  bool settled = true;
  for (int i = 0; i < n; ++i) {
    if (pinned(i)) continue;
    const double l = findex[i] >= 0 ? lo[i] * x[findex[i]] : lo[i], h = findex[i] >= 0 ? hi[i] * x[findex[i]] : hi[i];
    RowBound to = state[i];
    double by = 0;
    if (!(hi[i] > lo[i])) {  // a row held at one value (lo = hi; friction: one multiple of its normal): every w is allowed there
      if (state[i] == RowBound::free) state[i] = RowBound::lower, settled = false;
      continue;
    }
    switch (state[i]) {
      case RowBound::free:
        if (x[i] < l - tol_x)
          to = RowBound::lower, by = (l - x[i]) / tol_x;
        else if (x[i] > h + tol_x)
          to = RowBound::upper, by = (x[i] - h) / tol_x;
        break;
      case RowBound::lower:
        if (w[i] < -tol_w) to = RowBound::free, by = -w[i] / tol_w;
        break;
      case RowBound::upper:
        if (w[i] > tol_w) to = RowBound::free, by = w[i] / tol_w;
        break;
    }
    if (to == state[i]) continue;
    settled = false;
    if (!single)
      state[i] = to;
    else if (by > worst_by)
      worst = i, worst_to = to, worst_by = by;
  }
  if (single && worst >= 0) state[worst] = worst_to;
  return settled;
}

}  // namespace gearsim::physics

#include "physics/folded_solve.hpp"

#include <cstddef>

namespace gearsim::physics {

// The active set on the folded rows (docs/solver.md, "The planar mass matrix"): a friction row
// held at a fixed multiple c of its normal's impulse (lo = hi: sliding friction) is no unknown and
// has no condition, so it leaves the problem, its impulse folded into its normal's column —
// A'_iu = g_i·(g_u + Σ c_t·g_t) over the held rows t of normal u — and restored after the solve
// (c·λ_u; 0 where the normal carries nothing). The same solution as the full rows' (the active set
// there does the same folding, row by row); n² dot products of the full A become (n − held)².
// Returns the linear solves it took, 0 where it did not settle.
int FoldedSolve::solve(RowSystem& rows, const std::vector<double>& g_by_dof, std::vector<RowBound>& states, RowLcpScratch& lcp) {
  const std::size_t n = rows.rows.size(), ud = rows.dofs;
  const double* g = g_by_dof.data();
  index_.assign(n, -1);
  kept_.clear();
  for (std::size_t i = 0; i < n; ++i)
    if (!rows.held_friction(i)) index_[i] = static_cast<int>(kept_.size()), kept_.push_back(static_cast<int>(i));
  const std::size_t m = kept_.size();
  // Per kept row its g and its column's h = g plus its held friction rows' c·g, by row.
  g_.resize(m * ud);
  h_.resize(m * ud);
  for (std::size_t r = 0; r < m; ++r)
    for (std::size_t k = 0; k < ud; ++k) h_[r * ud + k] = g_[r * ud + k] = g[k * n + static_cast<std::size_t>(kept_[r])];
  for (std::size_t t = 0; t < n; ++t) {
    if (index_[t] >= 0) continue;
    double* h = h_.data() + static_cast<std::size_t>(index_[static_cast<std::size_t>(rows.findex[t])]) * ud;
    for (std::size_t k = 0; k < ud; ++k) h[k] += rows.lo[t] * g[k * n + t];
  }
  a_.resize(m * m);
  b_.resize(m);
  lo_.resize(m);
  hi_.resize(m);
  x_.resize(m);
  findex_.resize(m);
  states_.resize(m);
  for (std::size_t r = 0; r < m; ++r) {
    const std::size_t i = static_cast<std::size_t>(kept_[r]);
    const double* gr = g_.data() + r * ud;
    for (std::size_t c = 0; c < m; ++c) {
      const double* hc = h_.data() + c * ud;
      double v = 0;
      for (std::size_t k = 0; k < ud; ++k) v += gr[k] * hc[k];
      a_[r * m + c] = v;
    }
    a_[r * m + r] += rows.compliance[i];
    b_[r] = rows.b[i];
    lo_[r] = rows.lo[i];
    hi_[r] = rows.hi[i];
    findex_[r] = rows.findex[i] >= 0 ? index_[static_cast<std::size_t>(rows.findex[i])] : -1;
    states_[r] = states[i];
  }
  const int solves =
      solve_row_lcp(static_cast<int>(m), a_.data(), b_.data(), lo_.data(), hi_.data(), findex_.data(), x_.data(), states_.data(), lcp);
  if (solves == 0) return 0;
  for (std::size_t r = 0; r < m; ++r) {
    const std::size_t i = static_cast<std::size_t>(kept_[r]);
    rows.x[i] = x_[r];
    states[i] = states_[r];
  }
  for (std::size_t t = 0; t < n; ++t) {
    if (index_[t] >= 0) continue;
    const double normal = rows.x[static_cast<std::size_t>(rows.findex[t])];
    rows.x[t] = normal == 0 ? 0.0 : rows.lo[t] * normal;
    states[t] = RowBound::lower;
  }
  return solves;
}

}  // namespace gearsim::physics

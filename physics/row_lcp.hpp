// The multibody engine's rows as a mixed linear complementarity problem, solved by an active-set
// iteration warm-started from the last step (docs/solver.md, "The row solve"). Bullet's convention
// (btSolveDantzigLCP): find x, w with A·x = b + w and, per row i,
//   x_i = lo_i ⇒ w_i ≥ 0,   x_i = hi_i ⇒ w_i ≤ 0,   lo_i < x_i < hi_i ⇒ w_i = 0;
// a row with findex[i] ≥ 0 (friction) has the bounds lo_i·x_f … hi_i·x_f of row f = findex[i] (its
// normal, x_f ≥ 0), lo_i = −hi_i, or lo_i = hi_i for a friction impulse fixed at that multiple. The rows keep their bound states from step to step (the same
// tooth contacts slide the same way), so one linear solve usually settles a step where Dantzig's
// pivoting adds the rows one by one.
#pragma once

#include <vector>

namespace gearsim::physics {

// Where a row's impulse sits: between its bounds (w = 0), on the lower or on the upper one.
enum class RowBound : signed char { lower = -1, free = 0, upper = 1 };

struct RowLcpScratch {
  std::vector<double> m, rhs, w;
  std::vector<int> unknown_of, rows_of, pivots;
  // Per column of A, where its entry goes in a free row's equation: into unknown `target` times
  // `factor`, or (target −1) to the right-hand side as entry · factor · constant.
  std::vector<int> target;
  std::vector<double> factor, constant;
};

// Solves the problem above from `state` (a guess of each row's bound; on return the solution's),
// pivoting every row that breaks its condition at once, at most max_solves linear solves. Returns
// the number of solves it took, or 0 when it did not settle (x, state then unspecified: use
// Dantzig). A: n×n row-major. Conditions hold to tolerances relative to the largest |x| and |b|
// (1e-9): what Dantzig's own pivoting reaches on these systems.
int solve_row_lcp(int n, const double* A, const double* b, const double* lo, const double* hi, const int* findex, double* x,
                  RowBound* state, RowLcpScratch& scratch, int max_solves = 8);

// The conditions above for a solution x of the present states (w = A·x − b; nullptr where every
// row is free, which needs none): every row that breaks its condition by more than its tolerance
// (tol_x on x against its bounds, tol_w on w) changes its state — all at once up to the third
// solve, then only the worst (block pivoting can cycle, single pivots less so); a row held at one
// value (lo = hi) goes to lower. True when no row changed: x is the solution.
bool settle_row_states(int n, const double* x, const double* w, const double* lo, const double* hi, const int* findex, RowBound* state,
                       int solves, double tol_x, double tol_w);

}  // namespace gearsim::physics

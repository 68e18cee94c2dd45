// The active set on the folded rows of a planar tree (docs/solver.md, "The planar mass matrix"):
// a friction row held at a fixed multiple c of its normal's impulse (lo = hi: sliding friction)
// is no unknown and has no condition, so it leaves the problem, its impulse folded into its
// normal's column — A'_iu = g_i·(g_u + Σ c_t·g_t) over the held rows t of normal u — and restored
// after the solve. The row-space fallback of the dof-space solve (primal_solve.hpp). Internal to
// physics/.
#pragma once

#include <vector>

#include "physics/multibody_rows.hpp"
#include "physics/row_lcp.hpp"

namespace gearsim::physics {

class FoldedSolve {
 public:
  // The rows from their bound states (updated to the solution's) into rows.x, with G = L⁻¹·Jᵀ of
  // this step's rows (dofs × rows, PlanarMass::g()): the linear solves it took, 0 where it did
  // not settle.
  int solve(RowSystem& rows, const std::vector<double>& g, std::vector<RowBound>& states, RowLcpScratch& lcp);

 private:
  // The rows kept (not friction held at a multiple of its normal), each row's index among them
  // (−1: held), their g and column vectors h, and the folded problem.
  std::vector<int> kept_, index_, findex_;
  std::vector<double> g_, h_, a_, b_, lo_, hi_, x_;
  std::vector<RowBound> states_;
};

}  // namespace gearsim::physics

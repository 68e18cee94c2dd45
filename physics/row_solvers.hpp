// The multibody engine's row solvers' working data (docs/solver.md, "The row solve"): the active
// set's warm start (each row's identity and bound state, this step's and the last's), the folded
// row-space solve (friction held at a multiple of its normal folded into that normal's column)
// and the dof-space solve of a planar tree (the rows solved through the coordinates' velocity
// change, one dofs × dofs factorisation per solve). Dantzig (Bullet's) is the fallback of all.
// Internal to physics/.
#pragma once

#include <array>
#include <vector>

#include "physics/row_lcp.hpp"

namespace gearsim::physics {

struct ActiveSetSolve {
  bool on = false;  // solver.row_solver active_set
  std::vector<std::array<int, 5>> row_keys, row_keys_before;  // (kind, contact or joint …) per row
  std::vector<RowBound> row_states, row_states_before;
  RowLcpScratch lcp;
};

// The rows kept (not friction held at a multiple of its normal), each row's index among them
// (−1: held), their g and column vectors h, and the folded problem.
struct FoldedSolve {
  std::vector<int> kept, index, findex;
  std::vector<double> g, h, a, b, lo, hi, x;
  std::vector<RowBound> states;
};

// Per row its unknown's index (−1: a constant or a folded friction row), the unknowns' rows,
// whether each is stiff (no spring: solved by its Schur complement), their folded columns by
// unknown (unknowns × dofs), the constant rows' impulses on the coordinates, K and its LU
// pivots, and the solutions.
struct PrimalSolve {
  std::vector<int> unknown, rows, pivots, stiff, stiff_pivots;
  std::vector<double> cols, constant, k, rhs, y, s, t, dv, w;
  std::vector<char> soft;  // per row: a spring soft enough for K (else stiff)
  std::vector<RowBound> states_before;
  std::vector<double> x_check;
  std::vector<RowBound> states_check;
  bool dv_of_x = false;  // dv is the velocity change of x: the dof-space solve settled x
};

}  // namespace gearsim::physics

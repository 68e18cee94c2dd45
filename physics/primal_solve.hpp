// The rows of a planar tree solved in the space of its coordinates (docs/solver.md, "The row
// solve in the coordinates' space"): the same mixed LCP as solve_row_lcp() on the folded rows,
// from the same bound states and to the same conditions, with one factorisation of a dofs × dofs
// matrix K = M + Σ_springs J·Jᵀ/D per solve instead of one of the rows' (n × n); the stiff rows
// (no spring, or one far stiffer than the step resolves) through their Schur complement. Where
// it settles, the velocity change it solved with is that of its impulses (dv()). The folded
// row-space solve (folded_solve.hpp) is its fallback. Internal to physics/.
#pragma once

#include <cstddef>
#include <vector>

#include "physics/multibody_rows.hpp"
#include "physics/planar_mass.hpp"
#include "physics/row_lcp.hpp"

namespace gearsim::physics {

// The dof-space solve's working storage (PrimalSolve's; its steps are primal_solve.cpp's).
// Per row its unknown's index (−1: a constant or a folded friction row), the unknowns' rows,
// whether each is stiff (no spring: solved by its Schur complement), their folded columns by
// unknown (unknowns × dofs), the constant rows' impulses on the coordinates, K and its LU
// pivots, and the solutions.
struct PrimalWork {
  std::vector<int> unknown, rows, pivots, stiff, stiff_pivots;
  std::vector<double> cols, constant, k, rhs, y, s, t, dv, w;
  std::vector<char> soft;  // per row: a spring soft enough for K (else stiff)
  bool dv_of_x = false;
};

class PrimalSolve {
 public:
  // Which of this step's rows enter K (soft springs) and which the Schur system (the rest): once
  // per step, after the rows' compliances.
  void classify_rows(const RowSystem& rows, PlanarMass& mass, int dofs);
  // The rows from their bound states (updated to the solution's) into rows.x, M (lower triangle)
  // of this pose: the linear solves it took, 0 where it did not settle.
  int solve(RowSystem& rows, std::vector<RowBound>& states, const std::vector<double>& mass, int dofs);
  // Whether dv() is the velocity change of the rows' present impulses (the last solve settled
  // them), and that change; forget() before the rows are solved another way.
  bool has_dv() const { return w_.dv_of_x; }
  const std::vector<double>& dv() const { return w_.dv; }
  void forget() { w_.dv_of_x = false; }

 private:
  template <int N>
  void classify_rows_n(const RowSystem& rows, PlanarMass& mass, int dofs);
  PrimalWork w_;
};

}  // namespace gearsim::physics

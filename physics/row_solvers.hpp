// The multibody engine's row solvers (docs/solver.md, "The row solve"), each with its own working
// data: the active set, warm-started from the bound states the same rows had in the step before
// (physics/row_lcp.hpp on the dense A; on a planar tree the dof-space solve, primal_solve.hpp,
// or the folded one, folded_solve.hpp), and Bullet's Dantzig solver, the fallback of all.
// Internal to physics/.
#pragma once

#include <BulletDynamics/MLCPSolvers/btDantzigLCP.h>

#include <array>
#include <mutex>
#include <vector>

#include "physics/multibody_rows.hpp"
#include "physics/row_lcp.hpp"
#include "physics/world.hpp"

namespace gearsim::physics {

// Bullet's Dantzig solver's global failure flag: held around every call.
std::mutex& dantzig_flag();

class ActiveSetSolve {
 public:
  ActiveSetSolve() = default;
  explicit ActiveSetSolve(bool on) : on_(on) {}
  bool on() const { return on_; }  // verify.row_solver active_set
  // This step's rows' identities (the contacts' tooth pairs and flanks, the joints) and their
  // bound states in the step before, where they had one (else free).
  void warm_start(const RowSystem& rows, const std::vector<ContactSample>& contacts);
  // The rows by solve_row_lcp() on the dense A (rows.a): the linear solves it took, 0 where it
  // did not settle.
  int solve_dense(RowSystem& rows);
  // After no solution: no impulses, and the next step starts cold.
  void start_cold(RowSystem& rows);
  std::vector<RowBound>& states() { return states_; }  // this step's, per row
  RowLcpScratch& lcp() { return lcp_; }

 private:
  bool on_ = false;
  std::vector<std::array<int, 5>> keys_, keys_before_;  // (kind, contact or joint …) per row
  std::vector<RowBound> states_, states_before_;
  RowLcpScratch lcp_;
};

class DantzigSolve {
 public:
  // Bullet's Dantzig solver on the dense A (rows.a), holding dantzig_flag(); with
  // fixed_friction, friction rows held at a multiple of their normal's impulse (lo = hi) are
  // taken out of its problem and solved by rounds. False where it found no solution.
  bool solve(RowSystem& rows, bool fixed_friction);

 private:
  bool solve_fixed_friction(RowSystem& rows);
  btDantzigScratchMemory scratch_;
};

}  // namespace gearsim::physics

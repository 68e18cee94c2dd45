// The multibody engine's rows of one step (docs/solver.md, "The row solve"): every interaction
// that is not a joint — tooth contacts (normal, friction), bearing springs, torsional springs,
// motors — as a row with its Jacobian over the tree's coordinates, compliance, target and bounds,
// and the mixed LCP they make, A·x = b + w with lo ≤ x ≤ hi (friction bounds relative to their
// normal's impulse through findex). The row solvers (row_solvers.hpp) solve it; the engine
// (multibody_engine.hpp) builds it. Internal to physics/.
#pragma once

#include <Eigen/Dense>

#include <cstddef>
#include <vector>

namespace gearsim::physics {

struct MultibodyRow {
  enum Kind { contact_normal, contact_friction, bearing, torsion, motor } kind = contact_normal;
  int owner = -1;  // contact_*: index into State::contacts; the others: joint index
  double cfm = 0;  // compliance of the implicit spring–damper, (N·s)⁻¹·… per unit impulse
  double target = 0;  // right-hand side before the predicted velocity is taken off
  double lo = 0, hi = 0;
  int friction_of = -1;  // contact_friction: the row of its normal (bounds ±μ times its impulse)
  double start_rate_weight = 0;  // trapezoidal spring rows: 1 (the start-of-step rate enters)
  double move_rate_weight = 0;  // BDF2 spring rows: k·h/(3σ) (the spring at the extrapolated position)
};

struct RowSystem {
  std::size_t dofs = 0;  // the tree's coordinates
  std::vector<MultibodyRow> rows;
  std::vector<double> jrows;  // this step's row Jacobians, rows × dofs, row-major
  // The articulated path (verify.mass_matrix articulated): J as a matrix, M⁻¹ and M⁻¹·Jᵀ.
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> jac;
  Eigen::MatrixXd inverse_mass;  // dofs × dofs
  Eigen::MatrixXd minv_jt;  // dofs × rows
  // J·v* (the predicted velocities), J·v at the step's start, J·v_move of the last step (BDF2).
  Eigen::VectorXd row_rate, row_rate_start, row_rate_move;
  // The problem: A (n × n, row-major; the articulated path, or formed for a fallback), b, the
  // solution x and w, bounds, each friction row's normal, each row's compliance (planar path).
  std::vector<double> a, b, x, w, lo, hi;
  std::vector<int> findex;
  std::vector<double> compliance;

  // Row i is friction held at a fixed multiple of its normal's impulse (lo = hi): no unknown of the solve.
  bool held_friction(std::size_t i) const { return findex[i] >= 0 && !(hi[i] > lo[i]); }
  // Row i of this step's Jacobian times v (one entry per coordinate), summed in coordinate order.
  double row_dot(std::size_t i, const double* v) const {
    const std::size_t ud = dofs;
    const double* j = jrows.data() + i * ud;
    double s = 0;
    for (std::size_t k = 0; k < ud; ++k) s += j[k] * v[k];
    return s;
  }
  // rates = J·v over this step's rows.
  void rows_times(const double* v, Eigen::VectorXd& rates) const {
    rates.resize(static_cast<Eigen::Index>(rows.size()));
    for (std::size_t i = 0; i < rows.size(); ++i) rates[static_cast<Eigen::Index>(i)] = row_dot(i, v);
  }
};

}  // namespace gearsim::physics

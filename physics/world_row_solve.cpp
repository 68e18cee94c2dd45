#include <algorithm>
#include <mutex>

#include "physics/world_impl.hpp"

// The multibody step's rows solved (docs/solver.md, "The row solve"): their right-hand sides,
// bounds and compliances (solve_multibody_rows), then with solver.row_solver active_set from the
// bound states the same rows had in the step before — a tooth contact's rows are the same rows
// while its tooth pair and flank stay in contact, a joint's rows are always the same — by
// physics/row_lcp.hpp, or on a planar tree in the coordinates' space (world_primal_solve.cpp),
// falling back to Bullet's Dantzig solver when that does not settle.
namespace gearsim::physics {
namespace {

// A row without a spring gets a compliance of this times its own diagonal (solve_multibody_rows).
constexpr double kStiffRow = 1e-8;

}  // namespace

// λ from (J·M⁻¹·Jᵀ + Γ)·λ = target − J·v* + w (Dantzig), then v⁺ = v* + M⁻¹·Jᵀ·λ.
void World::Impl::solve_multibody_rows() {
  MultibodyEngine& e = *mb;
  btMultiBody& t = *e.tree;
  const int n = static_cast<int>(e.rows.size()), dofs = e.dofs;
  e.x.assign(static_cast<std::size_t>(n), 0);
  if (n == 0) return;
  if (!e.planar_mass) e.a.resize(static_cast<std::size_t>(n) * static_cast<std::size_t>(n));
  Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> a(e.a.data(), e.planar_mass ? 0 : n, e.planar_mass ? 0 : n);
  if (e.planar_mass) {
    e.g_formed = e.a_formed = false;  // G and A of this step's rows, where a fallback needs them
  } else {
    // M⁻¹, column by column, from the articulated-body inertias of this step.
    for (int k = 0; k < dofs; ++k) {
      std::fill(e.buf.begin(), e.buf.end(), 0.0);
      e.buf[static_cast<std::size_t>(6 + k)] = 1;
      t.calcAccelerationDeltasMultiDof(e.buf.data(), e.out.data(), e.scratch_r, e.scratch_v);
      for (int r = 0; r < dofs; ++r) e.inverse_mass(r, k) = e.out[static_cast<std::size_t>(6 + r)];
    }
    e.minv_jt.noalias() = e.inverse_mass * e.jac.transpose();
    a.noalias() = e.jac * e.minv_jt;
  }
  const Eigen::Map<const Eigen::VectorXd> v_pred(t.getVelocityVector() + 6, dofs), v_start(e.v_start.data(), dofs);
  e.rows_times(v_pred.data(), e.row_rate);
  e.rows_times(v_start.data(), e.row_rate_start);
  if (e.bdf2 && e.has_history) e.rows_times(e.v_move.data(), e.row_rate_move);
  const Eigen::VectorXd &j_v = e.row_rate, &j_v_start = e.row_rate_start;
  e.b.resize(static_cast<std::size_t>(n));
  e.w.assign(static_cast<std::size_t>(n), 0);
  e.lo.resize(static_cast<std::size_t>(n));
  e.hi.resize(static_cast<std::size_t>(n));
  e.findex.resize(static_cast<std::size_t>(n));
  e.slip_drift.assign(static_cast<std::size_t>(n), 0.0);
  if (e.planar_mass) e.compliance.resize(static_cast<std::size_t>(n));
  std::size_t drift_hint = 0;
  for (int i = 0; i < n; ++i) {
    const MultibodyRow& r = e.rows[static_cast<std::size_t>(i)];
    // Rows without a spring (friction sticking, a motor) get a compliance of kStiffRow times their
    // own diagonal: the matrix is then positive definite, so the solve exists and is unique even
    // for dependent rows (several sticking contacts on two one-coordinate gears), while a
    // sticking contact creeps by 1e-8 of the velocity change its impulse makes.
    if (!e.planar_mass) a(i, i) += r.cfm > 0 ? r.cfm : kStiffRow * a(i, i);
    e.b[static_cast<std::size_t>(i)] = r.target - r.start_rate_weight * j_v_start(i) - j_v(i);
    if (r.move_rate_weight != 0) e.b[static_cast<std::size_t>(i)] -= r.move_rate_weight * e.row_rate_move(i);
    e.lo[static_cast<std::size_t>(i)] = r.lo;
    e.hi[static_cast<std::size_t>(i)] = r.hi;
    e.findex[static_cast<std::size_t>(i)] = r.friction_of;
    // sliding: a contact sliding at the step's start is solved with μ·λ_n against that slip
    // first (a fixed multiple of its normal: lo = hi); one starting without slip keeps the box.
    if (e.sliding_friction) e.slip_drift[static_cast<std::size_t>(i)] = r.kind == MultibodyRow::contact_friction ? slip_drift(i, j_v_start(i), drift_hint) * (e.slip_end_h > 0 ? e.h_step / e.slip_end_h : 1.0) : 0.0;
    if (e.sliding_friction && r.kind == MultibodyRow::contact_friction && j_v_start(i) != 0)
      e.lo[static_cast<std::size_t>(i)] = e.hi[static_cast<std::size_t>(i)] = j_v_start(i) > 0 ? -r.hi : r.hi;  // r.hi = μ
    // Friction held at a multiple of its normal's impulse is no unknown of the solve: its
    // compliance is never used (0).
    if (e.planar_mass)
      e.compliance[static_cast<std::size_t>(i)] = r.cfm > 0 ? r.cfm : e.held_friction(static_cast<std::size_t>(i)) ? 0.0 : kStiffRow * planar_diag_a(static_cast<std::size_t>(i));
  }
  if (e.planar_mass) planar_soft_rows();
  e.dv_of_x = false;
  e.primal_dv_of_x = false;
  bool solved = e.active_set && solve_rows_active_set();
  if (!solved) {
    ++profile.dantzig_solves;
    if (e.planar_mass) planar_full_a();
    const std::lock_guard<std::mutex> lock(dantzig_flag());
    solved = e.sliding_friction ? solve_rows_dantzig_fixed_friction()
                                : btSolveDantzigLCP(n, e.a.data(), e.x.data(), e.b.data(), e.w.data(), 0, e.lo.data(), e.hi.data(), e.findex.data(), e.dantzig);
  }
  if (e.sliding_friction) solved = locate_slip_reversals(solved);
  if (!solved) ++e.failed_solves;
  if (e.dv_of_x) {
    std::fill(e.buf.begin(), e.buf.begin() + 6, 0.0);
  } else {
    std::fill(e.buf.begin(), e.buf.end(), 0.0);
    velocity_change_of_x(e.buf.data() + 6);
  }
  t.applyDeltaVeeMultiDof(e.buf.data(), 1);
}

bool World::Impl::solve_rows_active_set() {
  MultibodyEngine& e = *mb;
  const std::size_t n = e.rows.size();
  std::swap(e.row_keys, e.row_keys_before);
  std::swap(e.row_states, e.row_states_before);
  e.row_keys.resize(n);
  e.row_states.assign(n, RowBound::free);
  for (std::size_t i = 0; i < n; ++i) {
    const MultibodyRow& r = e.rows[i];
    std::array<int, 5> key{static_cast<int>(r.kind), r.owner, 0, 0, 0};
    if (r.kind == MultibodyRow::contact_normal || r.kind == MultibodyRow::contact_friction) {
      const ContactSample& c = contacts[static_cast<std::size_t>(r.owner)];
      key = {static_cast<int>(r.kind), c.pair, c.geometry.tooth_a, c.geometry.tooth_b, static_cast<int>(c.geometry.flank_a)};
    } else {
      for (std::size_t j = 0; j < i; ++j)  // a bearing's two radial rows: its first and second
        if (e.row_keys[j][0] == key[0] && e.row_keys[j][1] == key[1]) key[2] = std::max(key[2], e.row_keys[j][2] + 1);
    }
    e.row_keys[i] = key;
    // The row's state in the step before: at the same place in the list, or anywhere in it.
    if (i < e.row_keys_before.size() && e.row_keys_before[i] == key) {
      e.row_states[i] = e.row_states_before[i];
    } else {
      const auto it = std::find(e.row_keys_before.begin(), e.row_keys_before.end(), key);
      if (it != e.row_keys_before.end()) e.row_states[i] = e.row_states_before[static_cast<std::size_t>(it - e.row_keys_before.begin())];
    }
  }
  const int solves = e.planar_mass ? solve_rows_planar()
                                   : solve_row_lcp(static_cast<int>(n), e.a.data(), e.b.data(), e.lo.data(), e.hi.data(), e.findex.data(),
                                                   e.x.data(), e.row_states.data(), e.lcp);
  if (solves > 0) {
    ++profile.active_set_solves;
    return true;
  }
  std::fill(e.x.begin(), e.x.end(), 0.0);
  std::fill(e.row_states.begin(), e.row_states.end(), RowBound::free);  // the next step starts cold
  return false;
}

}  // namespace gearsim::physics

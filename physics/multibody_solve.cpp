#include <algorithm>
#include <mutex>

#include "physics/multibody_engine.hpp"

// The multibody step's rows solved (docs/solver.md, "The row solve"): their right-hand sides,
// bounds and compliances (solve_rows), then with solver.row_solver active_set from the
// bound states the same rows had in the step before — a tooth contact's rows are the same rows
// while its tooth pair and flank stay in contact, a joint's rows are always the same — by
// physics/row_lcp.hpp, or on a planar tree in the coordinates' space (world_primal_solve.cpp),
// falling back to Bullet's Dantzig solver when that does not settle.
namespace gearsim::physics {
namespace {

// A row without a spring gets a compliance of this times its own diagonal (solve_rows).
constexpr double kStiffRow = 1e-8;

}  // namespace

// λ from (J·M⁻¹·Jᵀ + Γ)·λ = target − J·v* + w (Dantzig), then v⁺ = v* + M⁻¹·Jᵀ·λ.
void MultibodyEngine::solve_rows() {
  btMultiBody& t = *tree_;
  const int n = static_cast<int>(rows_.rows.size()), dofs = dofs_;
  rows_.x.assign(static_cast<std::size_t>(n), 0);
  if (n == 0) return;
  if (!planar_mass_) rows_.a.resize(static_cast<std::size_t>(n) * static_cast<std::size_t>(n));
  Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> a(rows_.a.data(), planar_mass_ ? 0 : n, planar_mass_ ? 0 : n);
  if (planar_mass_) {
    mass_.g_formed = rows_.a_formed = false;  // G and A of this step's rows, where a fallback needs them
  } else {
    // M⁻¹, column by column, from the articulated-body inertias of this step.
    for (int k = 0; k < dofs; ++k) {
      std::fill(buf_.begin(), buf_.end(), 0.0);
      buf_[static_cast<std::size_t>(6 + k)] = 1;
      t.calcAccelerationDeltasMultiDof(buf_.data(), out_.data(), scratch_r_, scratch_v_);
      for (int r = 0; r < dofs; ++r) rows_.inverse_mass(r, k) = out_[static_cast<std::size_t>(6 + r)];
    }
    rows_.minv_jt.noalias() = rows_.inverse_mass * rows_.jac.transpose();
    a.noalias() = rows_.jac * rows_.minv_jt;
  }
  const Eigen::Map<const Eigen::VectorXd> v_pred(t.getVelocityVector() + 6, dofs), v_start(v_start_.data(), dofs);
  rows_.rows_times(v_pred.data(), rows_.row_rate);
  rows_.rows_times(v_start.data(), rows_.row_rate_start);
  if (bdf2_ && has_history_) rows_.rows_times(v_move_.data(), rows_.row_rate_move);
  const Eigen::VectorXd &j_v = rows_.row_rate, &j_v_start = rows_.row_rate_start;
  rows_.b.resize(static_cast<std::size_t>(n));
  rows_.w.assign(static_cast<std::size_t>(n), 0);
  rows_.lo.resize(static_cast<std::size_t>(n));
  rows_.hi.resize(static_cast<std::size_t>(n));
  rows_.findex.resize(static_cast<std::size_t>(n));
  slip_.drift.assign(static_cast<std::size_t>(n), 0.0);
  if (planar_mass_) rows_.compliance.resize(static_cast<std::size_t>(n));
  std::size_t drift_hint = 0;
  for (int i = 0; i < n; ++i) {
    const MultibodyRow& r = rows_.rows[static_cast<std::size_t>(i)];
    // Rows without a spring (friction sticking, a motor) get a compliance of kStiffRow times their
    // own diagonal: the matrix is then positive definite, so the solve exists and is unique even
    // for dependent rows (several sticking contacts on two one-coordinate gears), while a
    // sticking contact creeps by 1e-8 of the velocity change its impulse makes.
    if (!planar_mass_) a(i, i) += r.cfm > 0 ? r.cfm : kStiffRow * a(i, i);
    rows_.b[static_cast<std::size_t>(i)] = r.target - r.start_rate_weight * j_v_start(i) - j_v(i);
    if (r.move_rate_weight != 0) rows_.b[static_cast<std::size_t>(i)] -= r.move_rate_weight * rows_.row_rate_move(i);
    rows_.lo[static_cast<std::size_t>(i)] = r.lo;
    rows_.hi[static_cast<std::size_t>(i)] = r.hi;
    rows_.findex[static_cast<std::size_t>(i)] = r.friction_of;
    // sliding: a contact sliding at the step's start is solved with μ·λ_n against that slip
    // first (a fixed multiple of its normal: lo = hi); one starting without slip keeps the box.
    if (slip_.on) slip_.drift[static_cast<std::size_t>(i)] = r.kind == MultibodyRow::contact_friction ? slip_drift(i, j_v_start(i), drift_hint) * (slip_.end_h > 0 ? h_step_ / slip_.end_h : 1.0) : 0.0;
    if (slip_.on && r.kind == MultibodyRow::contact_friction && j_v_start(i) != 0)
      rows_.lo[static_cast<std::size_t>(i)] = rows_.hi[static_cast<std::size_t>(i)] = j_v_start(i) > 0 ? -r.hi : r.hi;  // r.hi = μ
    // Friction held at a multiple of its normal's impulse is no unknown of the solve: its
    // compliance is never used (0).
    if (planar_mass_)
      rows_.compliance[static_cast<std::size_t>(i)] = r.cfm > 0 ? r.cfm : rows_.held_friction(static_cast<std::size_t>(i)) ? 0.0 : kStiffRow * planar_diag_a(static_cast<std::size_t>(i));
  }
  if (planar_mass_) planar_soft_rows();
  rows_.dv_of_x = false;
  primal_.dv_of_x = false;
  bool solved = active_.on && solve_rows_active_set();
  if (!solved) {
    ++state_.profile.dantzig_solves;
    if (planar_mass_) planar_full_a();
    const std::lock_guard<std::mutex> lock(dantzig_flag());
    solved = slip_.on ? solve_rows_dantzig_fixed_friction()
                                : btSolveDantzigLCP(n, rows_.a.data(), rows_.x.data(), rows_.b.data(), rows_.w.data(), 0, rows_.lo.data(), rows_.hi.data(), rows_.findex.data(), dantzig_);
  }
  if (slip_.on) solved = locate_slip_reversals(solved);
  if (!solved) ++failed_solves_;
  if (rows_.dv_of_x) {
    std::fill(buf_.begin(), buf_.begin() + 6, 0.0);
  } else {
    std::fill(buf_.begin(), buf_.end(), 0.0);
    velocity_change_of_x(buf_.data() + 6);
  }
  t.applyDeltaVeeMultiDof(buf_.data(), 1);
}

bool MultibodyEngine::solve_rows_active_set() {
  const std::size_t n = rows_.rows.size();
  std::swap(active_.row_keys, active_.row_keys_before);
  std::swap(active_.row_states, active_.row_states_before);
  active_.row_keys.resize(n);
  active_.row_states.assign(n, RowBound::free);
  for (std::size_t i = 0; i < n; ++i) {
    const MultibodyRow& r = rows_.rows[i];
    std::array<int, 5> key{static_cast<int>(r.kind), r.owner, 0, 0, 0};
    if (r.kind == MultibodyRow::contact_normal || r.kind == MultibodyRow::contact_friction) {
      const ContactSample& c = state_.contacts[static_cast<std::size_t>(r.owner)];
      key = {static_cast<int>(r.kind), c.pair, c.geometry.tooth_a, c.geometry.tooth_b, static_cast<int>(c.geometry.flank_a)};
    } else {
      for (std::size_t j = 0; j < i; ++j)  // a bearing's two radial rows: its first and second
        if (active_.row_keys[j][0] == key[0] && active_.row_keys[j][1] == key[1]) key[2] = std::max(key[2], active_.row_keys[j][2] + 1);
    }
    active_.row_keys[i] = key;
    // The row's state in the step before: at the same place in the list, or anywhere in it.
    if (i < active_.row_keys_before.size() && active_.row_keys_before[i] == key) {
      active_.row_states[i] = active_.row_states_before[i];
    } else {
      const auto it = std::find(active_.row_keys_before.begin(), active_.row_keys_before.end(), key);
      if (it != active_.row_keys_before.end()) active_.row_states[i] = active_.row_states_before[static_cast<std::size_t>(it - active_.row_keys_before.begin())];
    }
  }
  const int solves = planar_mass_ ? solve_rows_planar()
                                   : solve_row_lcp(static_cast<int>(n), rows_.a.data(), rows_.b.data(), rows_.lo.data(), rows_.hi.data(), rows_.findex.data(),
                                                   rows_.x.data(), active_.row_states.data(), active_.lcp);
  if (solves > 0) {
    ++state_.profile.active_set_solves;
    return true;
  }
  std::fill(rows_.x.begin(), rows_.x.end(), 0.0);
  std::fill(active_.row_states.begin(), active_.row_states.end(), RowBound::free);  // the next step starts cold
  return false;
}

}  // namespace gearsim::physics

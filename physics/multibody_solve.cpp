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
  slip_.begin_rows(static_cast<std::size_t>(n));
  if (planar_mass_) rows_.compliance.resize(static_cast<std::size_t>(n));
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
    if (slip_.on()) slip_.start_row(rows_, static_cast<std::size_t>(i), state_.contacts, j_v_start(i), h_step_);
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
    solved = slip_.on() ? solve_rows_dantzig_fixed_friction()
                                : btSolveDantzigLCP(n, rows_.a.data(), rows_.x.data(), rows_.b.data(), rows_.w.data(), 0, rows_.lo.data(), rows_.hi.data(), rows_.findex.data(), dantzig_);
  }
  if (slip_.on()) solved = locate_slip_reversals(solved);
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

// After the first solve (`solved`: it found a solution), where a contact's slip at the step's end
// disagrees with the share its friction was solved with (SlipFriction::reshare): solved again.
// Returns whether the last solve found a solution. Records each contact's end slip for the next
// step's drift.
bool MultibodyEngine::locate_slip_reversals(bool solved) {
  const int n = static_cast<int>(rows_.rows.size()), dofs = dofs_;
  Eigen::Map<Eigen::VectorXd> dv(buf_.data() + 6, dofs);
  slip_.begin_rounds(static_cast<std::size_t>(n));
  bool dv_of_x = false;  // dv is M⁻¹·Jᵀ·x of the present x
  for (int round = 0; solved && round < kSlipRounds; ++round) {
    velocity_change_of_x(dv.data());
    dv_of_x = true;
    if (!slip_.reshare(rows_, dv.data())) break;
    ++state_.profile.friction_rounds;
    dv_of_x = false;
    if (active_.on && (planar_mass_ ? solve_rows_planar()
                                    : solve_row_lcp(n, rows_.a.data(), rows_.b.data(), rows_.lo.data(), rows_.hi.data(), rows_.findex.data(), rows_.x.data(),
                                                    active_.row_states.data(), active_.lcp)) > 0)
      continue;
    if (planar_mass_) planar_full_a();
    const std::lock_guard<std::mutex> lock(dantzig_flag());
    solved = solve_rows_dantzig_fixed_friction();
  }
  // Each contact's slip at the step's end on this step's rows, for the next step's drift.
  if (!dv_of_x) velocity_change_of_x(dv.data());
  rows_.dv_of_x = true;  // solve_rows applies it
  slip_.record_end_slips(rows_, state_.contacts, dv.data(), h_step_);
  return solved;
}

// Dantzig for rows some of which are friction fixed at a multiple of their normal's impulse
// (contact.friction_model sliding: lo = hi on a row with findex ≥ 0). Bullet's solver takes such a
// row's bounds as ±|hi·x_f|, a box, so the fixed rows leave its problem: their impulses c·x_f,
// with x_f from the last round, move to the others' right-hand side, and rounds repeat until the
// impulses settle (each round changes the normals by about μ times the last change: a
// contraction). The caller holds dantzig_flag(). false when a round fails or they do not settle.
bool MultibodyEngine::solve_rows_dantzig_fixed_friction() {
  const int n = static_cast<int>(rows_.rows.size());
  const auto at = [](int i) { return static_cast<std::size_t>(i); };
  std::vector<int> kept, fixed, slot(at(n), -1);
  for (int i = 0; i < n; ++i) {
    if (rows_.held_friction(at(i))) fixed.push_back(i);
    else slot[at(i)] = static_cast<int>(kept.size()), kept.push_back(i);
  }
  const int m = static_cast<int>(kept.size());
  std::vector<double> a(at(m) * at(m)), b(at(m)), x(at(m)), w(at(m)), lo(at(m)), hi(at(m));
  std::vector<int> findex(at(m));
  std::fill(rows_.x.begin(), rows_.x.begin() + n, 0.0);
  constexpr int kRounds = 50;
  for (int round = 0; round < kRounds; ++round) {
    for (const int t : fixed) rows_.x[at(t)] = rows_.lo[at(t)] * rows_.x[at(rows_.findex[at(t)])];
    for (int r = 0; r < m; ++r) {
      const int i = kept[at(r)];
      for (int c = 0; c < m; ++c) a[at(r) * at(m) + at(c)] = rows_.a[at(i) * at(n) + at(kept[at(c)])];
      b[at(r)] = rows_.b[at(i)];
      for (const int t : fixed) b[at(r)] -= rows_.a[at(i) * at(n) + at(t)] * rows_.x[at(t)];
      lo[at(r)] = rows_.lo[at(i)], hi[at(r)] = rows_.hi[at(i)];
      findex[at(r)] = rows_.findex[at(i)] >= 0 ? slot[at(rows_.findex[at(i)])] : -1;
      x[at(r)] = 0, w[at(r)] = 0;
    }
    if (!btSolveDantzigLCP(m, a.data(), x.data(), b.data(), w.data(), 0, lo.data(), hi.data(), findex.data(), dantzig_)) return false;
    double change = 0, scale = 0;
    for (int r = 0; r < m; ++r) {
      const std::size_t i = at(kept[at(r)]);
      change = std::max(change, std::abs(x[at(r)] - rows_.x[i]));
      scale = std::max(scale, std::abs(x[at(r)]));
      rows_.x[i] = x[at(r)];
    }
    if (change <= 1e-12 * scale) {
      for (const int t : fixed) rows_.x[at(t)] = rows_.lo[at(t)] * rows_.x[at(rows_.findex[at(t)])];
      return true;
    }
  }
  return false;
}

}  // namespace gearsim::physics

#include <algorithm>
#include <mutex>

#include "physics/multibody_engine.hpp"

// The multibody step's rows solved (docs/solver.md, "The row solve"): their right-hand sides,
// bounds and compliances (solve_rows), then with verify.row_solver active_set from the
// bound states the same rows had in the step before — a tooth contact's rows are the same rows
// while its tooth pair and flank stay in contact, a joint's rows are always the same — by
// physics/row_lcp.hpp, or on a planar tree in the coordinates' space (primal_solve.hpp),
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
  Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> a(rows_.a.data(), planar_mass_ ? 0 : n,
                                                                                       planar_mass_ ? 0 : n);
  if (planar_mass_) {
    mass_.new_rows();  // G and A of this step's rows, where a fallback needs them
  } else {
    // M⁻¹, column by column, from the articulated-body inertias of this step.
    for (int k = 0; k < dofs; ++k) {
      std::fill(buf_.begin(), buf_.end(), 0.0);
      buf_[static_cast<std::size_t>(6 + k)] = 1;
      t.calcAccelerationDeltasMultiDof(buf_.data(), out_.data(), scratch_.r, scratch_.v);
      for (int r = 0; r < dofs; ++r) rows_.inverse_mass(r, k) = out_[static_cast<std::size_t>(6 + r)];
    }
    rows_.minv_jt.noalias() = rows_.inverse_mass * rows_.jac.transpose();
    a.noalias() = rows_.jac * rows_.minv_jt;
  }
  const Eigen::Map<const Eigen::VectorXd> v_pred(t.getVelocityVector() + 6, dofs), v_start(integ_.v_start().data(), dofs);
  rows_.rows_times(v_pred.data(), rows_.row_rate);
  rows_.rows_times(v_start.data(), rows_.row_rate_start);
  if (integ_.two_step()) rows_.rows_times(integ_.v_move().data(), rows_.row_rate_move);
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
    if (slip_.on()) slip_.start_row(rows_, static_cast<std::size_t>(i), state_.contacts, j_v_start(i), integ_.h_step());
    // Friction held at a multiple of its normal's impulse is no unknown of the solve: its
    // compliance is never used (0).
    if (planar_mass_)
      rows_.compliance[static_cast<std::size_t>(i)] = r.cfm > 0 ? r.cfm
                                                      : rows_.held_friction(static_cast<std::size_t>(i))
                                                          ? 0.0
                                                          : kStiffRow * mass_.diag_a(rows_, static_cast<std::size_t>(i));
  }
  if (planar_mass_) primal_.classify_rows(rows_, mass_, dofs_);
  primal_.forget();
  bool solved = active_.on() && solve_rows_active_set();
  if (!solved) {
    ++state_.profile.dantzig_solves;
    if (planar_mass_) mass_.full_a(rows_);
    solved = dantzig_.solve(rows_, slip_.on());
  }
  // Sliding friction's rounds leave the velocity change of the impulses in buf_[6…].
  if (slip_.on()) solved = locate_slip_reversals(solved);
  if (!solved) ++failed_solves_;
  if (slip_.on()) {
    std::fill(buf_.begin(), buf_.begin() + 6, 0.0);
  } else {
    std::fill(buf_.begin(), buf_.end(), 0.0);
    velocity_change_of_x(buf_.data() + 6);
  }
  t.applyDeltaVeeMultiDof(buf_.data(), 1);
}

bool MultibodyEngine::solve_rows_active_set() {
  active_.warm_start(rows_, state_.contacts);
  const int solves = planar_mass_ ? solve_rows_planar() : active_.solve_dense(rows_);
  if (solves > 0) {
    ++state_.profile.active_set_solves;
    return true;
  }
  active_.start_cold(rows_);
  return false;
}

// After the first solve (`solved`: it found a solution), where a contact's slip at the step's end
// disagrees with the share its friction was solved with (SlipFriction::reshare): solved again.
// Returns whether the last solve found a solution, and leaves the velocity change of its
// impulses in buf_[6…] (solve_rows applies it). Records each contact's end slip for the next
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
    if (active_.on() && (planar_mass_ ? solve_rows_planar() : active_.solve_dense(rows_)) > 0) continue;
    if (planar_mass_) mass_.full_a(rows_);
    solved = dantzig_.solve(rows_, true);
  }
  // Each contact's slip at the step's end on this step's rows, for the next step's drift.
  if (!dv_of_x) velocity_change_of_x(dv.data());
  slip_.record_end_slips(rows_, state_.contacts, dv.data(), integ_.h_step());
  return solved;
}

// dv = M⁻¹·Jᵀ·λ over this step's rows: by M⁻¹·Jᵀ on the articulated path, by L on the planar one.
void MultibodyEngine::velocity_change(const double* lambda, double* dv) {
  const std::size_t n = rows_.rows.size();
  if (!planar_mass_) {
    Eigen::Map<Eigen::VectorXd>(dv, dofs_).noalias() =
        rows_.minv_jt * Eigen::Map<const Eigen::VectorXd>(lambda, static_cast<Eigen::Index>(n));
    return;
  }
  mass_.velocity_change(rows_, lambda, dv);
}

// The velocity change of this step's impulses rows_.x. Where the dof-space solve found them
// (solve_rows_planar), the dv it solved them with: M·dv = Jᵀ·x to rounding, so M⁻¹·Jᵀ·x need
// not be formed again (World::set_mass_matrix_check compares the two).
void MultibodyEngine::velocity_change_of_x(double* dv) {
  if (!(planar_mass_ && primal_.has_dv())) {
    velocity_change(rows_.x.data(), dv);
    return;
  }
  std::copy(primal_.dv().begin(), primal_.dv().end(), dv);
  if (!check_mass_) return;
  std::vector<double> reference(primal_.dv().size());
  velocity_change(rows_.x.data(), reference.data());
  double scale = 0, difference = 0;
  for (std::size_t k = 0; k < reference.size(); ++k) {
    scale = std::max(scale, std::abs(reference[k]));
    difference = std::max(difference, std::abs(reference[k] - dv[k]));
  }
  ++mass_check_.velocity_changes_compared;
  if (scale > 0) mass_check_.velocity_change_difference = std::max(mass_check_.velocity_change_difference, difference / scale);
}

// The rows by the dof-space solve; where it does not settle, by the folded row-space one from
// the same bound states. With World::set_mass_matrix_check, both, compared
// (Multibody.TheDofSpaceSolveIsTheRowSpaceSolve).
int MultibodyEngine::solve_rows_planar() {
  planar_check_.states_before = active_.states();
  const int solves = primal_.solve(rows_, active_.states(), mass_.mass(), dofs_);
  if (solves > 0 && check_mass_) {
    planar_check_.x = rows_.x;
    planar_check_.states = active_.states();
    active_.states() = planar_check_.states_before;
    if (folded_.solve(rows_, mass_.g(rows_), active_.states(), active_.lcp()) > 0) {
      double scale = 0, difference = 0;
      for (std::size_t i = 0; i < rows_.x.size(); ++i) {
        scale = std::max(scale, std::abs(rows_.x[i]));
        difference = std::max(difference, std::abs(rows_.x[i] - planar_check_.x[i]));
      }
      ++mass_check_.row_solves_compared;
      if (scale > 0) mass_check_.row_solve_difference = std::max(mass_check_.row_solve_difference, difference / scale);
    }
    rows_.x = planar_check_.x;
    active_.states() = planar_check_.states;
  }
  if (solves > 0) return solves;
  active_.states() = planar_check_.states_before;
  const int folded = folded_.solve(rows_, mass_.g(rows_), active_.states(), active_.lcp());
  if (check_mass_) ++mass_check_.row_solve_fallbacks, mass_check_.row_solve_fallbacks_settled += folded > 0;
  return folded;
}

}  // namespace gearsim::physics

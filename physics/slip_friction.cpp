#include <algorithm>
#include <cmath>
#include <mutex>

#include "physics/row_lcp.hpp"
#include "physics/multibody_engine.hpp"

// Tooth friction in the multibody engine, contact.friction_model sliding (docs/solver.md,
// "Friction at the pitch point"): each friction row is a fixed multiple of its normal's impulse,
// −μ·λ_n times the mean sign of the slip over the step, the reversal at the pitch point shared
// within the step where it falls.

namespace gearsim::physics {
namespace {

// contact.friction_model sliding: the mean over the step of the sign of a slip that runs linearly
// from s0 at the step's start to s1 at its end (the θ-method's velocities are linear over the
// step): where it changes sign the step is shared at the crossing, φ = s0 / (s0 − s1) on the first
// side, φ·sgn(s0) + (1 − φ)·sgn(s1). Continuous in s1 for s0 ≠ 0.
double sliding_share(double s0, double s1) {
  const auto sign = [](double v) { return v > 0 ? 1.0 : v < 0 ? -1.0 : 0.0; };
  if (s0 != 0 && s1 != 0 && (s0 > 0) != (s1 > 0)) {
    const double phi = s0 / (s0 - s1);
    return phi * sign(s0) + (1 - phi) * sign(s1);
  }
  return s0 != 0 ? sign(s0) : sign(s1);
}

}  // namespace

// contact.friction_model sliding: how friction row i's slip changes over a step by the contact
// point's travel along the flanks, m/s. The rows are linearised at the step's start: within the
// step the slip they measure changes only with the velocities, while the contact point, and with
// it the sliding speed (ω_a ± ω_b)·(its distance from the pitch point), moves on; the next step's
// rows see that move as a jump from this step's end slip to its start slip. The last such jump
// (this step's start slip less the last step's end slip, same tooth pair) is taken as this
// step's: geometry changes smoothly. 0 for a contact new this step.
double MultibodyEngine::slip_drift(int i, double s0, std::size_t& hint) const {
  const ContactKey key = contact_key(state_.contacts[static_cast<std::size_t>(rows_.rows[static_cast<std::size_t>(i)].owner)]);
  const auto& before = slip_.end_before;
  if (hint < before.size() && before[hint].first == key) return s0 - before[hint++].second;  // where the last step had it, usually
  for (std::size_t j = 0; j < before.size(); ++j)
    if (before[j].first == key) return hint = j + 1, s0 - before[j].second;
  return 0;
}

// After the first solve (`solved`: it found a solution), where a contact's slip at the step's end
// disagrees with the share its friction was solved with: solved again. Returns whether the last
// solve found a solution. Records each contact's end slip for the next step's drift.
bool MultibodyEngine::locate_slip_reversals(bool solved) {
  const int n = static_cast<int>(rows_.rows.size()), dofs = dofs_;
  const Eigen::VectorXd &j_v = rows_.row_rate, &j_v_start = rows_.row_rate_start;
  // Where the slip at the step's end, s1 = J·(v* + M⁻¹·Jᵀ·λ) plus its drift, has the other
  // sign, the friction is shared at the crossing (sliding_share) and the rows solved again, until
  // each share agrees with the slip it produces. A share moves that slip against itself (friction
  // opposes the slip), so g(share) = sliding_share(s0, s1(share)) − share falls strictly with the
  // share and has one root in [−1, 1]: found per row by regula falsi with the Illinois rule on a
  // bracket each round's g narrows (other rows held: the coupling between contacts is weak).
  Eigen::Map<Eigen::VectorXd> dv(buf_.data() + 6, dofs);
  slip_.brackets.assign(static_cast<std::size_t>(n), SlipFriction::Bracket{});
  bool dv_of_x = false;  // dv is M⁻¹·Jᵀ·x of the present x
  for (int round = 0; solved && round < kSlipRounds; ++round) {
    velocity_change_of_x(dv.data());
    dv_of_x = true;
    bool changed = false;
    for (int i = 0; i < n; ++i) {
      const MultibodyRow& r = rows_.rows[static_cast<std::size_t>(i)];
      const std::size_t at = static_cast<std::size_t>(i);
      if (r.kind != MultibodyRow::contact_friction || j_v_start(i) == 0) continue;
      const double s1 = j_v(i) + rows_.row_dot(at, dv.data()) + slip_.drift[at];
      const double now = -rows_.lo[at] / r.hi, want = sliding_share(j_v_start(i), s1), g = want - now;
      if (std::abs(g) <= kSlipShareTolerance) continue;
      SlipFriction::Bracket& br = slip_.brackets[at];
      if (g > 0) {
        if (br.last > 0) br.g_hi *= 0.5;  // the other end kept twice: Illinois
        br.lo = now, br.g_lo = g, br.last = 1;
      } else {
        if (br.last < 0) br.g_lo *= 0.5;
        br.hi = now, br.g_hi = g, br.last = -1;
      }
      double share = want;
      if (br.g_lo > 0 && br.g_hi < 0) share = (br.lo * br.g_hi - br.hi * br.g_lo) / (br.g_hi - br.g_lo);
      if (!(share > br.lo && share < br.hi)) share = 0.5 * (br.lo + br.hi);
      rows_.lo[at] = rows_.hi[at] = -r.hi * share;
      changed = true;
    }
    if (!changed) break;
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
  {  // each contact's slip at the step's end on this step's rows, for the next step's drift
    if (!dv_of_x) velocity_change_of_x(dv.data());
    rows_.dv_of_x = true;  // solve_multibody_rows applies it
    std::swap(slip_.end_before, slip_.end);
    slip_.end.clear();
    slip_.end_h = h_step_;  // the (sub)step these end slips close (the drift is per its length)
    for (int i = 0; i < n; ++i)
      if (rows_.rows[static_cast<std::size_t>(i)].kind == MultibodyRow::contact_friction) slip_.end.emplace_back(contact_key(state_.contacts[static_cast<std::size_t>(rows_.rows[static_cast<std::size_t>(i)].owner)]), j_v(i) + rows_.row_dot(static_cast<std::size_t>(i), dv.data()));
  }
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

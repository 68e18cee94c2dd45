#include "physics/slip_friction.hpp"

#include <algorithm>
#include <cmath>

// Tooth friction in the multibody engine, verify.friction_model sliding (docs/solver.md,
// "Friction at the pitch point"): each friction row is a fixed multiple of its normal's impulse,
// −μ·λ_n times the mean sign of the slip over the step, the reversal at the pitch point shared
// within the step where it falls.

namespace gearsim::physics {
namespace {

// verify.friction_model sliding: the mean over the step of the sign of a slip that runs linearly
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

void SlipFriction::begin_rows(std::size_t n) {
  drift_.assign(n, 0.0);
  hint_ = 0;
}

void SlipFriction::start_row(RowSystem& rows, std::size_t i, const std::vector<ContactSample>& contacts, double s0, double h_step) {
  const MultibodyRow& r = rows.rows[i];
  drift_[i] = r.kind == MultibodyRow::contact_friction
                  ? drift_of(contact_key(contacts[static_cast<std::size_t>(r.owner)]), s0) * (end_h_ > 0 ? h_step / end_h_ : 1.0)
                  : 0.0;
  if (r.kind == MultibodyRow::contact_friction && s0 != 0) rows.lo[i] = rows.hi[i] = s0 > 0 ? -r.hi : r.hi;  // r.hi = μ
}

// How a friction row's slip changes over a step by the contact point's travel along the flanks,
// m/s. The rows are linearised at the step's start: within the step the slip they measure
// changes only with the velocities, while the contact point, and with it the sliding speed
// (ω_a ± ω_b)·(its distance from the pitch point), moves on; the next step's rows see that move
// as a jump from this step's end slip to its start slip. The last such jump (this step's start
// slip s0 less the last step's end slip, same tooth pair) is taken as this step's: geometry
// changes smoothly. 0 for a contact new this step.
double SlipFriction::drift_of(const ContactKey& key, double s0) {
  const auto& before = end_before_;
  if (hint_ < before.size() && before[hint_].first == key) return s0 - before[hint_++].second;  // where the last step had it, usually
  for (std::size_t j = 0; j < before.size(); ++j)
    if (before[j].first == key) return hint_ = j + 1, s0 - before[j].second;
  return 0;
}

// Where the slip at the step's end, s1 = J·(v* + M⁻¹·Jᵀ·λ) plus its drift, has the other sign,
// the friction is shared at the crossing (sliding_share) and the rows solved again, until each
// share agrees with the slip it produces. A share moves that slip against itself (friction
// opposes the slip), so g(share) = sliding_share(s0, s1(share)) − share falls strictly with the
// share and has one root in [−1, 1]: found per row by regula falsi with the Illinois rule on a
// bracket each round's g narrows (other rows held: the coupling between contacts is weak).
bool SlipFriction::reshare(RowSystem& rows, const double* dv) {
  const int n = static_cast<int>(rows.rows.size());
  const Eigen::VectorXd &j_v = rows.row_rate, &j_v_start = rows.row_rate_start;
  bool changed = false;
  for (int i = 0; i < n; ++i) {
    const MultibodyRow& r = rows.rows[static_cast<std::size_t>(i)];
    const std::size_t at = static_cast<std::size_t>(i);
    if (r.kind != MultibodyRow::contact_friction || j_v_start(i) == 0) continue;
    const double s1 = j_v(i) + rows.row_dot(at, dv) + drift_[at];
    const double now = -rows.lo[at] / r.hi, want = sliding_share(j_v_start(i), s1), g = want - now;
    if (std::abs(g) <= kSlipShareTolerance) continue;
    Bracket& br = brackets_[at];
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
    rows.lo[at] = rows.hi[at] = -r.hi * share;
    changed = true;
  }
  return changed;
}

void SlipFriction::record_end_slips(const RowSystem& rows, const std::vector<ContactSample>& contacts, const double* dv, double h_step) {
  const int n = static_cast<int>(rows.rows.size());
  const Eigen::VectorXd& j_v = rows.row_rate;
  std::swap(end_before_, end_);
  end_.clear();
  end_h_ = h_step;  // the (sub)step these end slips close (the drift is per its length)
  for (int i = 0; i < n; ++i)
    if (rows.rows[static_cast<std::size_t>(i)].kind == MultibodyRow::contact_friction)
      end_.emplace_back(contact_key(contacts[static_cast<std::size_t>(rows.rows[static_cast<std::size_t>(i)].owner)]),
                        j_v(i) + rows.row_dot(static_cast<std::size_t>(i), dv));
}

}  // namespace gearsim::physics

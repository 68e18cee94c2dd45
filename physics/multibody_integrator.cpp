#include <algorithm>
#include <limits>
#include <tuple>

#include "physics/multibody_engine.hpp"

// How the multibody engine integrates its spring rows (docs/solver.md): the θ-method's row for a
// spring–damper (also BDF2's, with h_eff and the extrapolated position), and the per-step θ of
// solver.integrator trapezoid_closed. The step itself is multibody_engine.cpp's.
namespace gearsim::physics {

// A spring–damper row (stiffness k, damping c) whose spring force at the start of the step is
// `force0` (k·δ for a contact, −k·s for a bearing). Implicit Euler: the force at the end of the
// step, f = force0 − (h·k + c)·ṡ⁺, σ = h·k + c. Trapezoidal: the force at mid-step,
// f = force0 − σ·(ṡ + ṡ⁺) with σ = h·k/4 + c/2 (ṡ_mid = (ṡ + ṡ⁺)/2, s_mid = s + h/2·ṡ_mid). Either
// way λ/h = f gives the row (A + 1/(h·σ))·λ = force0/σ − w·ṡ − ṡ*, w = 0 or 1.
// BDF2 (θ = 1 with h_eff = 2h/3): the spring at the extrapolated position x̂ = (4x − x_prev)/3 =
// x + h·v_move_prev/3, so force0 − k·(h/3)·ṡ_move enters.
MultibodyRow MultibodyEngine::spring_row(double k, double c, double force0) const {
  const double h = h_eff_, theta = theta_;
  const double sigma = theta * (theta * h * k + c);
  MultibodyRow r;
  r.cfm = 1 / (h * sigma);
  r.target = force0 / sigma;
  r.start_rate_weight = (1 - theta) / theta;
  if (bdf2_ && has_history_) r.move_rate_weight = k * model_.scenario.solver.time_step_s / (3 * sigma);
  r.lo = -std::numeric_limits<double>::infinity();  // bilateral
  r.hi = std::numeric_limits<double>::infinity();
  return r;
}

// solver.integrator trapezoid_closed: θ for this step. ½ (the trapezoidal rule) unless a tooth
// contact is new: found at the first step that starts with the teeth overlapping, it has
// penetrated δ₀ without force since it touched, so its spring holds ½·k·δ₀² that no work put in.
// The θ-method dissipates (θ − ½)·k·Δs² in a spring row whose extension changes by Δs over the
// step, so θ = ½ + E_new / Σ k·Δs² (Δs ≈ h·ṡ at the step's start, over every contact row) takes
// out of the step the energy the late detection added, at most 1. One θ per step: the positions
// advance with it too. (Until 2026-11-26 a persisting contact whose depth was below 2·h times
// its rate also took θ = 1, meant for contacts about to open but with the rate's sign inverted,
// so it hit shallow contacts still closing; with the sign right, damping opening contacts
// spread the planet–ring harmonics 3.2 % between dt 2e-5 and 5e-6 s: docs/solver.md.)
double MultibodyEngine::trapezoid_closed_theta() {
  const double h = h_step_;
  std::swap(touching_, touching_before_);
  touching_.clear();
  // New contacts first (their energy Σ ½kδ₀²); the rates only where there is one. The contacts
  // come in the last step's order, mostly: the search for a key starts after the last one found.
  double added_J = 0;
  std::size_t hint = 0;
  for (std::size_t p = 0; p < model_.pairs.size(); ++p) {
    const PairContacts& pr = state_.pairs[p];
    for (std::size_t i = 0; i < pr.found.size(); ++i) {
      if (!pr.active[i]) continue;
      const contact::ToothContact& c = pr.found[i];
      const ContactKey key = contact_key(static_cast<int>(p), c);
      touching_.push_back(key);
      const std::vector<ContactKey>& before = touching_before_;
      if (hint < before.size() && before[hint] == key) {
        ++hint;
        continue;
      }
      const auto at = std::find(before.begin(), before.end(), key);
      if (at != before.end()) {
        hint = static_cast<std::size_t>(at - before.begin()) + 1;
        continue;
      }
      added_J += 0.5 * pr.pair_stiffness[i] * c.depth_m * c.depth_m;
    }
  }
  if (added_J == 0) return 0.5;
  double dissipation_weight_J = 0;  // Σ k·(h·ṡ)² over every contact row
  for (std::size_t p = 0; p < model_.pairs.size(); ++p) {
    const ModelPair& mp = model_.pairs[p];
    const PairContacts& pr = state_.pairs[p];
    const btRigidBody &ra = *model_.bodies[static_cast<std::size_t>(mp.a)].rigid, &rb = *model_.bodies[static_cast<std::size_t>(mp.b)].rigid;
    for (std::size_t i = 0; i < pr.found.size(); ++i) {
      if (!pr.active[i]) continue;
      const contact::ToothContact& c = pr.found[i];
      const btVector3 n(c.normal_on_b.x(), c.normal_on_b.y(), 0), at(c.point_m.x(), c.point_m.y(), ra.getCenterOfMassPosition().z());
      const btVector3 va = ra.getVelocityInLocalPoint(at - ra.getCenterOfMassPosition());
      const double rate = (va - rb.getVelocityInLocalPoint(at - rb.getCenterOfMassPosition())).dot(n);  // ṡ, the row's rate
      dissipation_weight_J += pr.pair_stiffness[i] * (h * rate) * (h * rate);
    }
  }
  if (!(added_J < 0.5 * dissipation_weight_J)) return 1.0;
  return 0.5 + added_J / dissipation_weight_J;
}

}  // namespace gearsim::physics

#include <algorithm>
#include <limits>
#include <tuple>

#include "physics/multibody_integrator.hpp"

// How the multibody engine integrates (docs/solver.md): the θ-method's row for a spring–damper
// (also BDF2's, with h_eff and the extrapolated position), the per-step θ of solver.integrator
// trapezoid_closed, and the velocities a step starts from and moves its positions with. The
// step itself is multibody_engine.cpp's.
namespace gearsim::physics {

Integrator::Integrator(const SolverDef& solver, int dofs)
    : dofs_(dofs),
      time_step_s_(solver.time_step_s),
      bdf2_(solver.integrator == SolverDef::Integrator::bdf2),
      trapezoid_closed_(solver.integrator == SolverDef::Integrator::trapezoid_closed) {
  theta_ = bdf2_ ? 1.0 : trapezoid_closed_ ? 0.5 : solver.theta;
  h_eff_ = h_step_ = solver.time_step_s;
  v_mid_.assign(static_cast<std::size_t>(dofs), 0);
}

const double* Integrator::start(double h, const double* v) {
  two_step_ = bdf2_ && has_history_;
  h_step_ = h;
  h_eff_ = two_step_ ? 2 * h / 3 : h;
  v_start_.assign(v, v + dofs_);
  if (!two_step_) return nullptr;
  // BDF2 starts from v̂ = (4v − v_prev)/3.
  for (int k = 0; k < dofs_; ++k)
    v_mid_[static_cast<std::size_t>(k)] = (4 * v_start_[static_cast<std::size_t>(k)] - v_prev_[static_cast<std::size_t>(k)]) / 3;
  return v_mid_.data();
}

// The positions move with v_move (BDF2), the θ-weighted mean of the start and end velocities,
// or v⁺; the velocities stay v⁺.
const double* Integrator::position_velocities(const double* v_end) {
  if (bdf2_) {
    // x⁺ = (4x − x_prev)/3 + h_eff·v⁺ = x + h·v_move, v_move = (v_move_prev + 2v⁺)/3.
    v_end_.assign(v_end, v_end + dofs_);
    for (int k = 0; k < dofs_; ++k) {
      const std::size_t u = static_cast<std::size_t>(k);
      v_mid_[u] = two_step_ ? (v_move_[u] + 2 * v_end_[u]) / 3 : v_end_[u];
    }
    v_prev_ = v_start_;
    v_move_ = v_mid_;
    has_history_ = true;
    return v_mid_.data();
  }
  if (theta_ < 1) {
    v_end_.assign(v_end, v_end + dofs_);
    for (int k = 0; k < dofs_; ++k)
      v_mid_[static_cast<std::size_t>(k)] =
          (1 - theta_) * v_start_[static_cast<std::size_t>(k)] + theta_ * v_end_[static_cast<std::size_t>(k)];
    return v_mid_.data();
  }
  return v_end;
}

// Work of a row over the step: its force times its travel, h·J·v_θ (positions moved with v_θ).
const Eigen::VectorXd& Integrator::work_velocities(const double* v_end_ptr) {
  const Eigen::Map<const Eigen::VectorXd> v_end(v_end_ptr, dofs_), v_start(v_start_.data(), dofs_);
  if (bdf2_)
    v_theta_ = Eigen::Map<const Eigen::VectorXd>(v_move_.data(), dofs_);  // BDF2: positions moved with v_move
  else
    v_theta_.noalias() = (1 - theta_) * v_start + theta_ * v_end;
  return v_theta_;
}

// A spring–damper row (stiffness k, damping c) whose spring force at the start of the step is
// `force0` (k·δ for a contact, −k·s for a bearing). Implicit Euler: the force at the end of the
// step, f = force0 − (h·k + c)·ṡ⁺, σ = h·k + c. Trapezoidal: the force at mid-step,
// f = force0 − σ·(ṡ + ṡ⁺) with σ = h·k/4 + c/2 (ṡ_mid = (ṡ + ṡ⁺)/2, s_mid = s + h/2·ṡ_mid). Either
// way λ/h = f gives the row (A + 1/(h·σ))·λ = force0/σ − w·ṡ − ṡ*, w = 0 or 1.
// BDF2 (θ = 1 with h_eff = 2h/3): the spring at the extrapolated position x̂ = (4x − x_prev)/3 =
// x + h·v_move_prev/3, so force0 − k·(h/3)·ṡ_move enters.
MultibodyRow Integrator::spring_row(double k, double c, double force0) const {
  const double h = h_eff_, theta = theta_;
  const double sigma = theta * (theta * h * k + c);
  MultibodyRow r;
  r.cfm = 1 / (h * sigma);
  r.target = force0 / sigma;
  r.start_rate_weight = (1 - theta) / theta;
  if (bdf2_ && has_history_) r.move_rate_weight = k * time_step_s_ / (3 * sigma);
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
// advance with it too. (Only new contacts raise θ: damping contacts about to open spreads the
// planet–ring harmonics 3.2 % between dt 2e-5 and 5e-6 s: docs/solver.md.)
void Integrator::choose_theta(const Model& model, const State& state) {
  if (trapezoid_closed_) theta_ = trapezoid_closed_theta(model, state);
}

double Integrator::trapezoid_closed_theta(const Model& model, const State& state) {
  const double h = h_step_;
  std::swap(touching_, touching_before_);
  touching_.clear();
  // New contacts first (their energy Σ ½kδ₀²); the rates only where there is one. The contacts
  // come in the last step's order, mostly: the search for a key starts after the last one found.
  double added_J = 0;
  std::size_t hint = 0;
  for (std::size_t p = 0; p < model.pairs.size(); ++p) {
    const PairContacts& pr = state.pairs[p];
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
  for (std::size_t p = 0; p < model.pairs.size(); ++p) {
    const ModelPair& mp = model.pairs[p];
    const PairContacts& pr = state.pairs[p];
    const btRigidBody &ra = *model.bodies[static_cast<std::size_t>(mp.a)].rigid, &rb = *model.bodies[static_cast<std::size_t>(mp.b)].rigid;
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

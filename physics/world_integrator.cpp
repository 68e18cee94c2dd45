#include <algorithm>
#include <limits>
#include <tuple>

#include "physics/world_impl.hpp"

// How the multibody engine integrates its spring rows (docs/solver.md): the θ-method's row for a
// spring–damper (also BDF2's, with h_eff and the extrapolated position), and the per-step θ of
// solver.integrator trapezoid_closed. The step itself is world_multibody.cpp's.
namespace gearsim::physics {

// A spring–damper row (stiffness k, damping c) whose spring force at the start of the step is
// `force0` (k·δ for a contact, −k·s for a bearing). Implicit Euler: the force at the end of the
// step, f = force0 − (h·k + c)·ṡ⁺, σ = h·k + c. Trapezoidal: the force at mid-step,
// f = force0 − σ·(ṡ + ṡ⁺) with σ = h·k/4 + c/2 (ṡ_mid = (ṡ + ṡ⁺)/2, s_mid = s + h/2·ṡ_mid). Either
// way λ/h = f gives the row (A + 1/(h·σ))·λ = force0/σ − w·ṡ − ṡ*, w = 0 or 1.
// BDF2 (θ = 1 with h_eff = 2h/3): the spring at the extrapolated position x̂ = (4x − x_prev)/3 =
// x + h·v_move_prev/3, so force0 − k·(h/3)·ṡ_move enters.
MultibodyRow World::Impl::spring_row(double k, double c, double force0) const {
  const double h = mb->h_eff, theta = mb->theta;
  const double sigma = theta * (theta * h * k + c);
  MultibodyRow r;
  r.cfm = 1 / (h * sigma);
  r.target = force0 / sigma;
  r.start_rate_weight = (1 - theta) / theta;
  if (mb->bdf2 && mb->has_history) r.move_rate_weight = k * scenario.solver.time_step_s / (3 * sigma);
  r.lo = -std::numeric_limits<double>::infinity();  // bilateral
  r.hi = std::numeric_limits<double>::infinity();
  return r;
}

// solver.integrator trapezoid_closed: θ for this step, ½ (the trapezoidal rule) where every tooth
// contact touched in the step before too and cannot open within this one at its present rate of
// separation (twice it, for margin), else 1 (implicit Euler) for the whole step: a trapezoidal
// force over a step a contact lasts only part of hands out more impulse than the spring held,
// and rattling teeth gain energy by it. One θ per step: the positions advance with it too.
double World::Impl::trapezoid_closed_theta() {
  MultibodyEngine& e = *mb;
  const double h = scenario.solver.time_step_s;
  std::swap(e.touching, e.touching_before);
  e.touching.clear();
  bool closed = true;
  for (std::size_t p = 0; p < pairs.size(); ++p) {
    const PairRec& pr = pairs[p];
    const btRigidBody &ra = *bodies[static_cast<std::size_t>(pr.a)].rigid, &rb = *bodies[static_cast<std::size_t>(pr.b)].rigid;
    for (std::size_t i = 0; i < pr.found.size(); ++i) {
      if (!pr.active[i]) continue;
      const contact::ToothContact& c = pr.found[i];
      const std::tuple<int, int, int, int> key{static_cast<int>(p), c.tooth_a, c.tooth_b, static_cast<int>(c.flank_a)};
      e.touching.push_back(key);
      if (!closed) continue;
      if (std::find(e.touching_before.begin(), e.touching_before.end(), key) == e.touching_before.end()) {
        closed = false;
        continue;
      }
      const btVector3 n(c.normal_on_b.x(), c.normal_on_b.y(), 0), at(c.point_m.x(), c.point_m.y(), ra.getCenterOfMassPosition().z());
      const btVector3 va = ra.getVelocityInLocalPoint(at - ra.getCenterOfMassPosition());
      const btVector3 vb = rb.getVelocityInLocalPoint(at - rb.getCenterOfMassPosition());
      const double separating = -(va - vb).dot(n);  // n points from b toward a
      if (!(c.depth_m > 2 * h * std::max(0.0, separating))) closed = false;
    }
  }
  return closed ? 0.5 : 1.0;
}

}  // namespace gearsim::physics

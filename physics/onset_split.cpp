#include "physics/onset_split.hpp"

#include <algorithm>
#include <tuple>

// The multibody step split where a tooth contact starts (verify.locate_contact_onset,
// docs/solver.md "Contact onset"): when to split, and the step's forces and flows from the pieces.
namespace gearsim::physics {

// Where to split the rest of a step (within_s long) so that the first near tooth pair to touch,
// moving at its present rate of approach, touches just before the split: that instant plus
// kMinOnsetFraction of the step (the pair then overlaps by that much of its approach, which the
// next search finds, whatever the rate's small change over the piece). within_s when no pair
// touches before the last such fraction of the rest (it starts late by at most that much).
double OnsetSplit::onset_s(const Model& model, const State& state, double within_s) const {
  const double margin = kMinOnsetFraction * model.scenario.solver.time_step_s, hi = within_s - margin;
  double onset = within_s;
  for (std::size_t p = 0; p < model.pairs.size(); ++p) {
    const ModelPair& pr = model.pairs[p];
    const btRigidBody &ra = *model.bodies[static_cast<std::size_t>(pr.a)].rigid, &rb = *model.bodies[static_cast<std::size_t>(pr.b)].rigid;
    for (const contact::ToothContact& c : state.pairs[p].near) {
      const btVector3 n(c.normal_on_b.x(), c.normal_on_b.y(), 0), at(c.point_m.x(), c.point_m.y(), ra.getCenterOfMassPosition().z());
      const btVector3 va = ra.getVelocityInLocalPoint(at - ra.getCenterOfMassPosition());
      const double closing = -(va - rb.getVelocityInLocalPoint(at - rb.getCenterOfMassPosition())).dot(n);  // d(depth)/dt
      if (!(closing > 0)) continue;
      const double t = -c.depth_m / closing + margin;
      if (t < hi && t < onset) onset = t;
    }
  }
  return onset;
}

// The sub-step of length h just taken into the step's sums (`first`: the step's first piece).
void OnsetSplit::accumulate(const State& state, const std::vector<double>& motor_torque, double h, bool first) {
  Accumulated& acc = accumulated_;
  if (first) {
    acc.contacts.clear();
    acc.power = PowerFlows{};
    acc.motor_torque.assign(motor_torque.size(), 0.0);
  }
  for (const ContactSample& c : state.contacts) {
    auto it =
        std::find_if(acc.contacts.begin(), acc.contacts.end(), [&](const ContactSample& o) { return contact_key(o) == contact_key(c); });
    if (it == acc.contacts.end()) {
      ContactSample z = c;
      z.normal_force_N = z.friction_force_N = 0;
      acc.contacts.push_back(z);
      it = acc.contacts.end() - 1;
    }
    it->normal_force_N += c.normal_force_N * h;
    it->friction_force_N += c.friction_force_N * h;
    it->geometry = c.geometry;  // the latest sub-step's
    it->stiffness_N_per_m = c.stiffness_N_per_m;
  }
  acc.power.motor_W += state.power.motor_W * h;
  acc.power.load_W += state.power.load_W * h;
  acc.power.joint_W += state.power.joint_W * h;
  acc.power.contact_W += state.power.contact_W * h;
  acc.power.impulse_W += state.power.impulse_W * h;
  for (std::size_t j = 0; j < acc.motor_torque.size(); ++j) acc.motor_torque[j] += motor_torque[j] * h;
}

// The step's contacts (every tooth pair that touched in a sub-step, ordered as a step's are),
// forces, power flows and motor torques from the sub-steps' sums.
void OnsetSplit::finish(State& state, std::vector<double>& motor_torque, double h) const {
  const Accumulated& acc = accumulated_;
  state.contacts = acc.contacts;
  for (ContactSample& c : state.contacts) c.normal_force_N /= h, c.friction_force_N /= h;
  std::stable_sort(state.contacts.begin(), state.contacts.end(),
                   [](const ContactSample& u, const ContactSample& v) { return contact_key(u) < contact_key(v); });
  const double kinetic = state.power.kinetic_J;
  state.power = acc.power;
  state.power.motor_W /= h, state.power.load_W /= h, state.power.joint_W /= h, state.power.contact_W /= h, state.power.impulse_W /= h;
  state.power.kinetic_J = kinetic;
  for (std::size_t j = 0; j < acc.motor_torque.size(); ++j) motor_torque[j] = acc.motor_torque[j] / h;
}

}  // namespace gearsim::physics

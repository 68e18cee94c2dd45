#include <algorithm>
#include <tuple>

#include "physics/multibody_engine.hpp"

// The multibody step, split where a tooth contact starts (solver.locate_contact_onset,
// docs/solver.md "Contact onset").

namespace gearsim::physics {

void MultibodyEngine::step() {
  const double h = model_.scenario.solver.time_step_s;
  generate_contacts();
  double onset = onset_.on ? contact_onset_s(h) : h;
  if (!(onset < h)) {
    advance(h);
    ++state_.steps;
    return;
  }
  // Split at each instant a near pair touches, so a contact starts with its spring at rest
  // instead of found a step late with a depth no work put in (docs/solver.md, "Contact onset").
  const double start = state_.time;
  double done = 0;
  double deepest = state_.max_penetration;
  for (int split = 0;; ++split) {
    const bool cut = onset < h - done;
    const double sub = cut ? onset : h - done;
    advance(sub);
    accumulate_substep(sub, split == 0);
    done += sub;
    if (!cut) break;  // the step's last piece
    ++state_.profile.onset_splits;
    generate_contacts();
    deepest = std::max(deepest, state_.max_penetration);
    onset = split + 1 < kMaxOnsetSplits ? contact_onset_s(h - done) : h;
  }
  state_.max_penetration = deepest;
  state_.time = start + h;
  finish_split_step(h);
  ++state_.steps;
}

// Where to split the rest of a step (within_s long) so that the first near tooth pair to touch,
// moving at its present rate of approach, touches just before the split: that instant plus
// kMinOnsetFraction of the step (the pair then overlaps by that much of its approach, which the
// next search finds, whatever the rate's small change over the piece). within_s when no pair
// touches before the last such fraction of the rest (it starts late by at most that much).
double MultibodyEngine::contact_onset_s(double within_s) const {
  const double margin = kMinOnsetFraction * model_.scenario.solver.time_step_s, hi = within_s - margin;
  double onset = within_s;
  for (std::size_t p = 0; p < model_.pairs.size(); ++p) {
    const ModelPair& pr = model_.pairs[p];
    const btRigidBody &ra = *model_.bodies[static_cast<std::size_t>(pr.a)].rigid, &rb = *model_.bodies[static_cast<std::size_t>(pr.b)].rigid;
    for (const contact::ToothContact& c : state_.pairs[p].near) {
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

void MultibodyEngine::accumulate_substep(double h, bool first) {
  OnsetSplit::Accumulated& acc = onset_.accumulated;
  if (first) {
    acc.contacts.clear();
    acc.power = PowerFlows{};
    acc.motor_torque.assign(motor_torque_.size(), 0.0);
  }
  for (const ContactSample& c : state_.contacts) {
    auto it = std::find_if(acc.contacts.begin(), acc.contacts.end(), [&](const ContactSample& o) { return contact_key(o) == contact_key(c); });
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
  acc.power.motor_W += state_.power.motor_W * h;
  acc.power.load_W += state_.power.load_W * h;
  acc.power.joint_W += state_.power.joint_W * h;
  acc.power.contact_W += state_.power.contact_W * h;
  acc.power.impulse_W += state_.power.impulse_W * h;
  for (std::size_t j = 0; j < acc.motor_torque.size(); ++j) acc.motor_torque[j] += motor_torque_[j] * h;
}

// The step's contacts (every tooth pair that touched in a sub-step, ordered as a step's are),
// forces, power flows and motor torques from the sub-steps' sums.
void MultibodyEngine::finish_split_step(double h) {
  OnsetSplit::Accumulated& acc = onset_.accumulated;
  state_.contacts = acc.contacts;
  for (ContactSample& c : state_.contacts) c.normal_force_N /= h, c.friction_force_N /= h;
  std::stable_sort(state_.contacts.begin(), state_.contacts.end(), [](const ContactSample& u, const ContactSample& v) { return contact_key(u) < contact_key(v); });
  const double kinetic = state_.power.kinetic_J;
  state_.power = acc.power;
  state_.power.motor_W /= h, state_.power.load_W /= h, state_.power.joint_W /= h, state_.power.contact_W /= h, state_.power.impulse_W /= h;
  state_.power.kinetic_J = kinetic;
  for (std::size_t j = 0; j < acc.motor_torque.size(); ++j) motor_torque_[j] = acc.motor_torque[j] / h;
}

}  // namespace gearsim::physics

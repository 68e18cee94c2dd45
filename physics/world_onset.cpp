#include <algorithm>
#include <tuple>

#include "physics/world_impl.hpp"

// The multibody step, split where a tooth contact starts (solver.locate_contact_onset,
// docs/solver.md "Contact onset").

namespace gearsim::physics {

void World::Impl::step_multibody() {
  MultibodyEngine& e = *mb;
  const double h = scenario.solver.time_step_s;
  generate_contacts();
  double onset = e.locate_onset ? contact_onset_s(h) : h;
  if (!(onset < h)) {
    advance_multibody(h);
    ++steps;
    return;
  }
  // Split at each instant a near pair touches, so a contact starts with its spring at rest
  // instead of found a step late with a depth no work put in (docs/solver.md, "Contact onset").
  const double start = time;
  double done = 0;
  double deepest = max_penetration;
  for (int split = 0;; ++split) {
    const bool cut = onset < h - done;
    const double sub = cut ? onset : h - done;
    advance_multibody(sub);
    accumulate_substep(sub, split == 0);
    done += sub;
    if (!cut) break;  // the step's last piece
    ++profile.onset_splits;
    generate_contacts();
    deepest = std::max(deepest, max_penetration);
    onset = split + 1 < kMaxOnsetSplits ? contact_onset_s(h - done) : h;
  }
  max_penetration = deepest;
  time = start + h;
  finish_split_step(h);
  ++steps;
}

// Where to split the rest of a step (within_s long) so that the first near tooth pair to touch,
// moving at its present rate of approach, touches just before the split: that instant plus
// kMinOnsetFraction of the step (the pair then overlaps by that much of its approach, which the
// next search finds, whatever the rate's small change over the piece). within_s when no pair
// touches before the last such fraction of the rest (it starts late by at most that much).
double World::Impl::contact_onset_s(double within_s) const {
  const double margin = kMinOnsetFraction * scenario.solver.time_step_s, hi = within_s - margin;
  double onset = within_s;
  for (const PairRec& pr : pairs) {
    const btRigidBody &ra = *bodies[static_cast<std::size_t>(pr.a)].rigid, &rb = *bodies[static_cast<std::size_t>(pr.b)].rigid;
    for (const contact::ToothContact& c : pr.near) {
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

void World::Impl::accumulate_substep(double h, bool first) {
  MultibodyEngine& e = *mb;
  MultibodyEngine::Accumulated& acc = e.accumulated;
  if (first) {
    acc.contacts.clear();
    acc.power = PowerFlows{};
    acc.motor_torque.assign(e.motor_torque_N_m.size(), 0.0);
  }
  for (const ContactSample& c : contacts) {
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
  acc.power.motor_W += power.motor_W * h;
  acc.power.load_W += power.load_W * h;
  acc.power.joint_W += power.joint_W * h;
  acc.power.contact_W += power.contact_W * h;
  acc.power.impulse_W += power.impulse_W * h;
  for (std::size_t j = 0; j < acc.motor_torque.size(); ++j) acc.motor_torque[j] += e.motor_torque_N_m[j] * h;
}

// The step's contacts (every tooth pair that touched in a sub-step, ordered as a step's are),
// forces, power flows and motor torques from the sub-steps' sums.
void World::Impl::finish_split_step(double h) {
  MultibodyEngine& e = *mb;
  MultibodyEngine::Accumulated& acc = e.accumulated;
  contacts = acc.contacts;
  for (ContactSample& c : contacts) c.normal_force_N /= h, c.friction_force_N /= h;
  std::stable_sort(contacts.begin(), contacts.end(), [](const ContactSample& u, const ContactSample& v) { return contact_key(u) < contact_key(v); });
  const double kinetic = power.kinetic_J;
  power = acc.power;
  power.motor_W /= h, power.load_W /= h, power.joint_W /= h, power.contact_W /= h, power.impulse_W /= h;
  power.kinetic_J = kinetic;
  for (std::size_t j = 0; j < acc.motor_torque.size(); ++j) e.motor_torque_N_m[j] = acc.motor_torque[j] / h;
}

}  // namespace gearsim::physics

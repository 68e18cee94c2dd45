#include "physics/measure.hpp"

#include <cmath>

#include "geometry/constants.hpp"

namespace gearsim::physics {
namespace {

// std::remainder(d, 2π) without the libm call where |d| < 9 rad (below 3π: a joint turns less
// than 1.4 turns per step): d − 2π·n with n the integer nearest to d/2π (ties to even: n = 0 at
// |d| = π) is then d or d ∓ 2π, exact by Sterbenz's lemma (π < |d| < 9 < 4π), as remainder's
// result is exact. Bit for bit std::remainder's answer.
double wrapped_turn(double d) {
  constexpr double kTwoPi = 2 * constants::kPi;
  if (!(std::abs(d) < 9.0)) return std::remainder(d, kTwoPi);
  if (d > 0.5 * kTwoPi) return d - kTwoPi;
  if (d < -0.5 * kTwoPi) return d + kTwoPi;
  return d;
}

}  // namespace

double joint_raw_angle(const Model& model, const ModelJoint& j) {
  const BuiltBody& b = model.bodies[static_cast<std::size_t>(j.body)];
  // The gear frame's x axis: the first column of (body basis · com_from_gear basis).
  auto gear_x = [](const BuiltBody& g) { return eig(g.rigid->getWorldTransform().getBasis() * g.com_from_gear.getBasis().getColumn(0)); };
  const Eigen::Vector3d ax = j.axis_world;
  const Eigen::Vector3d xb = gear_x(b);
  Eigen::Vector3d ref = j.parent >= 0 ? gear_x(model.bodies[static_cast<std::size_t>(j.parent)]) : Eigen::Vector3d::UnitX();
  if (std::abs(ref.dot(ax)) > 0.9) ref = Eigen::Vector3d::UnitY();
  ref = (ref - ref.dot(ax) * ax).normalized();
  const Eigen::Vector3d ref2 = ax.cross(ref);
  return std::atan2(xb.dot(ref2), xb.dot(ref));
}

void measure_joints_from_bodies(const Model& model, State& state) {
  // Joint angles: the body's gear-frame x axis against the parent's, about the joint axis.
  for (std::size_t k = 0; k < model.joints.size(); ++k) {
    const ModelJoint& j = model.joints[k];
    UnwrappedAngle& angle = state.joint_angles[k];
    const BuiltBody& b = model.bodies[j.body];
    const Eigen::Vector3d omega_parent = j.parent >= 0 ? eig(model.bodies[j.parent].rigid->getAngularVelocity()) : Eigen::Vector3d::Zero();
    const Eigen::Vector3d ax = j.axis_world;
    const double raw = joint_raw_angle(model, j);
    angle.unwrapped += wrapped_turn(raw - angle.last_raw);
    angle.last_raw = raw;
    BodyState& s = state.bodies[j.body];
    s.angle_rad = angle.unwrapped;
    s.speed_rad_s = (eig(b.rigid->getAngularVelocity()) - omega_parent).dot(ax);
  }
  for (std::size_t i = 0; i < model.bodies.size(); ++i)
    state.bodies[i].position_m = eig(model.bodies[i].rigid->getWorldTransform() * model.bodies[i].com_from_gear.getOrigin());
}

double kinetic_energy_of_bodies_J(const Model& model) {
  double kinetic = 0;
  for (const BuiltBody& b : model.bodies) {
    const btRigidBody& r = *b.rigid;
    if (r.getInvMass() == 0) continue;
    const btVector3 v = r.getLinearVelocity(), w = r.getAngularVelocity();
    const btMatrix3x3 inertia = r.getInvInertiaTensorWorld().inverse();
    kinetic += 0.5 * v.dot(v) / r.getInvMass() + 0.5 * w.dot(inertia * w);
  }
  return kinetic;
}

double impulse_power_W(const Model& model, const State& state, double h) {
  double w = 0;
  for (const ImpulseDef& i : model.scenario.impulses) {
    const double share = impulse_shape(i, state.time - h);
    if (share == 0) continue;
    const btRigidBody& r = *model.bodies[static_cast<std::size_t>(model.body_index.at(i.body))].rigid;
    if (r.getInvMass() == 0) continue;
    w += share * (bt(i.force_N).dot(r.getLinearVelocity()) + bt(i.torque_N_m).dot(r.getAngularVelocity()));
  }
  return w;
}

}  // namespace gearsim::physics

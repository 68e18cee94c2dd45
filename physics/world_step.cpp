#include <algorithm>
#include <cmath>

#include "core/errors.hpp"
#include "geometry/constants.hpp"
#include "physics/world_impl.hpp"

#if defined(__x86_64__)
#include <cpuid.h>
#include <x86intrin.h>
#endif

// World::step and what it does: tooth contacts into the pairs' manifolds (Bullet calls
// generate_contacts before each solve), motors and loads, the solve, then the measurements.
namespace gearsim::physics {

void World::Impl::generate_contacts() {
  const std::uint64_t start = clock.now();
  max_penetration = 0;
  // Each gear's planar pose once per step (a gear meshes in several pairs).
  gear_poses.resize(bodies.size());
  for (std::size_t i = 0; i < bodies.size(); ++i)
    if (bodies[i].flanks) gear_poses[i] = mb && mb->planar_mass ? planar_gear_pose(i) : planar_pose(bodies[i]);
  // Where the near pairs predict onsets and some may be parked, each gear's velocity too: a
  // parked pair must not be one that closes within the step (CoherentToothSearch::find()).
  const bool with_motion = mb && mb->locate_onset && scenario.contact.park_near_pairs;
  if (with_motion) {
    gear_twists.resize(bodies.size());
    for (std::size_t i = 0; i < bodies.size(); ++i)
      if (bodies[i].flanks) gear_twists[i] = gear_twist(i);
  }
  for (PairRec& pr : pairs) {
    const BuiltBody &a = bodies[pr.a], &b = bodies[pr.b];
    std::vector<contact::ToothContact>& found = pr.found;
    // Gears from a spec: the continued contact stands; CAD meshes: the deeper of it and the search's.
    using Continuation = contact::CoherentToothSearch::Continuation;
    pr.search.set_continuation(!scenario.contact.continued_search                ? Continuation::off
                               : a.flanks_from_spec && b.flanks_from_spec ? Continuation::replace
                                                                            : Continuation::deeper);
    pr.search.set_park_near_pairs(scenario.contact.park_near_pairs);
    std::vector<contact::ToothContact>* near = mb && mb->locate_onset ? &pr.near : nullptr;
    contact::CoherentToothSearch::Motion motion;
    if (with_motion) motion = {gear_twists[pr.a], gear_twists[pr.b], scenario.solver.time_step_s};
    if (scenario.contact.coherent_search)
      pr.search.find(*a.flanks, gear_poses[pr.a], *b.flanks, gear_poses[pr.b], found, near, with_motion ? &motion : nullptr);
    else contact::find_tooth_contacts(*a.flanks, gear_poses[pr.a], *b.flanks, gear_poses[pr.b], found, near);
    // A manifold holds kMaxPointsPerPair points; the multibody engine's rows have no such limit.
    if (pr.manifold && static_cast<int>(found.size()) > kMaxPointsPerPair) {
      std::sort(found.begin(), found.end(), [](const contact::ToothContact& x, const contact::ToothContact& y) { return x.depth_m > y.depth_m; });
      dropped_points += static_cast<long>(found.size()) - kMaxPointsPerPair;
      found.resize(kMaxPointsPerPair);
    }
    pr.current.clear();
    pr.current_stiffness_N_per_m.clear();
    pair_stiffnesses(pr);
    for (const contact::ToothContact& c : found) max_penetration = std::max(max_penetration, c.depth_m);
    if (!pr.manifold) continue;  // the multibody engine makes its rows from pr.found itself
    pr.manifold->clearManifold();
    const double z = 0.5 * ((a.rigid->getWorldTransform() * a.com_from_gear).getOrigin().z() +
                            (b.rigid->getWorldTransform() * b.com_from_gear).getOrigin().z());
    add_manifold_points(pr, z);
  }
  tooth_contact_ticks += clock.now() - start;
}

// A gear's planar velocity: its centre's (gear_poses[i].centre_m) and its angular velocity, world.
contact::CoherentToothSearch::PlanarTwist World::Impl::gear_twist(std::size_t i) const {
  const btRigidBody& r = *bodies[i].rigid;
  const contact::PlanarPose& p = gear_poses[i];
  const btVector3 at(p.centre_m.x(), p.centre_m.y(), r.getCenterOfMassPosition().z());
  const btVector3 v = r.getVelocityInLocalPoint(at - r.getCenterOfMassPosition());
  return {Eigen::Vector2d(v.x(), v.y()), r.getAngularVelocity().z()};
}

// pr.pair_stiffness and pr.active for this step's contacts pr.found.
void World::Impl::pair_stiffnesses(PairRec& pr) {
  const contact::PlanarPose table_gear = pr.stiffness.table ? gear_poses[pr.stiffness.table_on_a ? pr.a : pr.b] : contact::PlanarPose{};
  table_misses += tooth_pair_stiffnesses(pr.stiffness, pr.found, table_gear, pr.pair_stiffness, pr.active);
}

// One manifold point per active tooth contact, at height z, with its stiffness and damping, warm
// started from the same tooth pair's impulse of the last step.
void World::Impl::add_manifold_points(PairRec& pr, double z) {
  const BuiltBody &a = bodies[pr.a], &b = bodies[pr.b];
  for (std::size_t i = 0; i < pr.found.size(); ++i) {
    const contact::ToothContact& c = pr.found[i];
    if (!pr.active[i]) continue;
    const btVector3 n(c.normal_on_b.x(), c.normal_on_b.y(), 0);
    const btVector3 mid(c.point_m.x(), c.point_m.y(), z);
    const btVector3 on_b = mid + n * (0.5 * c.depth_m), on_a = mid - n * (0.5 * c.depth_m);
    btManifoldPoint pt(a.rigid->getWorldTransform().invXform(on_a), b.rigid->getWorldTransform().invXform(on_b), n,
                       -c.depth_m);
    pt.m_positionWorldOnA = on_a;
    pt.m_positionWorldOnB = on_b;
    pt.m_combinedFriction = scenario.contact.friction;
    pt.m_combinedRestitution = 0;
    pt.m_contactPointFlags |= BT_CONTACT_FLAG_CONTACT_STIFFNESS_DAMPING;
    const double k = pr.pair_stiffness[i];
    pt.m_combinedContactStiffness1 = k;
    pt.m_combinedContactDamping1 = contact_damping(pr, k);
    const auto key = std::make_tuple(c.tooth_a, c.tooth_b, static_cast<int>(c.flank_a));
    for (const auto& [k_last, impulse] : pr.last_impulse)
      if (k_last == key) pt.m_appliedImpulse = impulse;
    pt.m_userPersistentData = nullptr;
    pr.manifold->addManifoldPoint(pt, false);
    pr.current.push_back(c);
    pr.current_stiffness_N_per_m.push_back(k);
  }
}

// Damping of a tooth-pair contact of stiffness k (N/m) in pair pr, N·s/m.
double World::Impl::contact_damping(const PairRec& pr, double k) const {
  // A constant mesh stiffness has a constant mesh damping too (ζ of the whole mesh), shared alike.
  return pr.stiffness.mesh_stiffness_N_per_m > 0
             ? contact_damping_N_s_per_m(pr.stiffness.mesh_stiffness_N_per_m, pr.info.reduced_mass_kg, scenario.contact.damping_ratio) *
                   (k / pr.stiffness.mesh_stiffness_N_per_m)
         : pr.stiffness.table || pr.stiffness.body_stiffness_N_per_m > 0
             ? contact_damping_N_s_per_m(k, pr.info.reduced_mass_kg, scenario.contact.damping_ratio)
             : pr.info.damping_N_s_per_m;
}

void World::Impl::apply_motors_and_loads() {
  for (JointRec& j : joints) {
    if (j.motor) {
      const double target = motor_target_rad_s(*j.motor, time + scenario.solver.time_step_s);  // the speed at the step's end
      if (j.hinge) j.hinge->enableAngularMotor(true, target, j.motor->max_torque_N_m * scenario.solver.time_step_s);
      if (j.spring) {
        j.spring->enableMotor(5, true);
        // The spring constraint drives body A (the parent, or the ground) relative to B.
        j.spring->setTargetVelocity(5, -target);
        j.spring->setMaxMotorForce(5, j.motor->max_torque_N_m);
      }
    }
    if (j.load) {
      const double speed = states.empty() ? 0.0 : states[j.body].speed_rad_s;
      const double torque = load_torque_N_m(*j.load, time, speed);
      const btVector3 t = bt(j.axis_world * torque);
      bodies[j.body].rigid->applyTorque(t);
      if (j.parent >= 0 && !bodies[j.parent].fixed) bodies[j.parent].rigid->applyTorque(-t);
    }
  }
}

void World::Impl::apply_impulses() {
  for (const ImpulseDef& i : scenario.impulses) {
    const double share = impulse_shape(i, time);
    if (share == 0) continue;
    btRigidBody& r = *bodies[static_cast<std::size_t>(body_index.at(i.body))].rigid;
    r.applyCentralForce(bt(i.force_N * share));
    r.applyTorque(bt(i.torque_N_m * share));
  }
}

void World::Impl::measure() {
  measure_joints();
  if (mb) return;  // step_multibody measured its rows
  measure_contacts();
}

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

void World::Impl::measure_joints() {
  if (mb && mb->planar_mass) {
    planar_measure_joints();
    return;
  }
  // Joint angles: the body's gear-frame x axis against the parent's, about the joint axis.
  for (JointRec& j : joints) {
    const BuiltBody& b = bodies[j.body];
    const Eigen::Vector3d omega_parent = j.parent >= 0 ? eig(bodies[j.parent].rigid->getAngularVelocity()) : Eigen::Vector3d::Zero();
    const Eigen::Vector3d ax = j.axis_world;
    const double raw = joint_raw_angle(j);
    j.unwrapped += wrapped_turn(raw - j.last_raw);
    j.last_raw = raw;
    BodyState& s = states[j.body];
    s.angle_rad = j.unwrapped;
    s.speed_rad_s = (eig(b.rigid->getAngularVelocity()) - omega_parent).dot(ax);
  }
  for (std::size_t i = 0; i < bodies.size(); ++i)
    states[i].position_m = eig(bodies[i].rigid->getWorldTransform() * bodies[i].com_from_gear.getOrigin());
}

void World::Impl::measure_contacts() {
  contacts.clear();
  const double dt = scenario.solver.time_step_s;
  for (std::size_t p = 0; p < pairs.size(); ++p) {
    PairRec& pr = pairs[p];
    pr.last_impulse.clear();
    GEARSIM_CHECK(pr.manifold->getNumContacts() == static_cast<int>(pr.current.size()),
                  "tooth contacts and manifold points must correspond one to one");
    for (int k = 0; k < pr.manifold->getNumContacts(); ++k) {
      const btManifoldPoint& pt = pr.manifold->getContactPoint(k);
      ContactSample cs;
      cs.pair = static_cast<int>(p);
      cs.geometry = pr.current[static_cast<std::size_t>(k)];
      cs.normal_force_N = pt.m_appliedImpulse / dt;
      cs.friction_force_N = std::hypot(pt.m_appliedImpulseLateral1, pt.m_appliedImpulseLateral2) / dt;
      cs.stiffness_N_per_m = pr.current_stiffness_N_per_m[static_cast<std::size_t>(k)];
      contacts.push_back(cs);
      // Each tooth pair's impulse warm-starts the same pair's point next step.
      const contact::ToothContact& c = cs.geometry;
      pr.last_impulse.emplace_back(std::make_tuple(c.tooth_a, c.tooth_b, static_cast<int>(c.flank_a)), pt.m_appliedImpulse);
    }
  }
}

void World::step() {
  Impl& m = *impl_;
  const std::uint64_t start = m.clock.now();
  if (m.mb) {
    m.step_multibody();
    m.step_total_ticks += m.clock.now() - start;
    return;
  }
  m.apply_motors_and_loads();
  m.apply_impulses();
  m.world.stepSimulation(m.scenario.solver.time_step_s, 0, m.scenario.solver.time_step_s);
  m.time += m.scenario.solver.time_step_s;
  ++m.steps;
  m.measure();
  m.measure_power();
  m.step_total_ticks += m.clock.now() - start;
}

const World::Profile& World::profile() const {
  Impl& m = *impl_;
  const double per_tick = m.clock.seconds_per_tick();
  m.profile.tooth_contact_s = static_cast<double>(m.tooth_contact_ticks) * per_tick;
  m.profile.row_solve_s = static_cast<double>(m.row_solve_ticks) * per_tick;
  m.profile.step_total_s = static_cast<double>(m.step_total_ticks) * per_tick;
  m.profile.flank_visits = {};
  for (const PairRec& pr : m.pairs) m.profile.flank_visits += pr.search.counts();
  return m.profile;
}

#if defined(__x86_64__)
ProfileClock::ProfileClock() : t0_(std::chrono::steady_clock::now()) {
  unsigned a = 0, b = 0, c = 0, d = 0;
  tsc_ = __get_cpuid(0x80000007u, &a, &b, &c, &d) && ((d >> 8) & 1u);  // invariant TSC
  tick0_ = now();
}
std::uint64_t ProfileClock::now() const {
  if (tsc_) return __rdtsc();
  return static_cast<std::uint64_t>(std::chrono::steady_clock::now().time_since_epoch().count());
}
#else
ProfileClock::ProfileClock() : t0_(std::chrono::steady_clock::now()) { tick0_ = now(); }
std::uint64_t ProfileClock::now() const {
  return static_cast<std::uint64_t>(std::chrono::steady_clock::now().time_since_epoch().count());
}
#endif

double ProfileClock::seconds_per_tick() const {
  using Period = std::chrono::steady_clock::period;
  if (!tsc_) return static_cast<double>(Period::num) / static_cast<double>(Period::den);
  const std::uint64_t ticks = now() - tick0_;
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
  return ticks > 0 ? seconds / static_cast<double>(ticks) : 0.0;
}
const PowerFlows& World::power() const { return impl_->power; }
long World::dropped_contacts() const { return impl_->dropped_points; }
long World::stiffness_table_misses() const { return impl_->table_misses; }
long World::failed_solves() const { return impl_->mb ? impl_->mb->failed_solves : 0; }

// Power of the force and torque pulses applied in the step just taken (at time − dt), with the
// bodies' velocities after it, as load_W takes its joint speeds.
double World::Impl::impulse_power_W(double h) const {
  double w = 0;
  for (const ImpulseDef& i : scenario.impulses) {
    const double share = impulse_shape(i, time - h);
    if (share == 0) continue;
    const btRigidBody& r = *bodies[static_cast<std::size_t>(body_index.at(i.body))].rigid;
    if (r.getInvMass() == 0) continue;
    w += share * (bt(i.force_N).dot(r.getLinearVelocity()) + bt(i.torque_N_m).dot(r.getAngularVelocity()));
  }
  return w;
}

double World::Impl::kinetic_energy_J() const {
  double kinetic = 0;
  if (mb && mb->planar_mass) {
    // The planar tree's links turn about z: ½·m·|v|² + ½·I_zz·ω² each, from this pose's link
    // velocities (this path holds no world inertia tensors of the bodies).
    const MultibodyEngine& e = *mb;
    for (std::size_t l = 0; l < e.link_w.size(); ++l)
      kinetic += 0.5 * e.link_mass_kg[l] * (e.link_vx[l] * e.link_vx[l] + e.link_vy[l] * e.link_vy[l]) + 0.5 * e.link_izz_kg_m2[l] * e.link_w[l] * e.link_w[l];
    return kinetic;
  }
  for (const BuiltBody& b : bodies) {
    const btRigidBody& r = *b.rigid;
    if (r.getInvMass() == 0) continue;
    const btVector3 v = r.getLinearVelocity(), w = r.getAngularVelocity();
    const btMatrix3x3 inertia = r.getInvInertiaTensorWorld().inverse();
    kinetic += 0.5 * v.dot(v) / r.getInvMass() + 0.5 * w.dot(inertia * w);
  }
  return kinetic;
}

void World::Impl::measure_power() {
  const double dt = scenario.solver.time_step_s;
  PowerFlows pw;
  pw.kinetic_J = kinetic_energy_J();
  pw.impulse_W = impulse_power_W(scenario.solver.time_step_s);
  for (const JointRec& j : joints) {
    const btRigidBody& a = j.constraint->getRigidBodyA();
    const btRigidBody& b = j.constraint->getRigidBodyB();
    // The whole constraint's power on both bodies (force at the centre of mass, torque about it).
    const double total = j.feedback.m_appliedForceBodyA.dot(a.getLinearVelocity()) +
                         j.feedback.m_appliedTorqueBodyA.dot(a.getAngularVelocity()) +
                         j.feedback.m_appliedForceBodyB.dot(b.getLinearVelocity()) +
                         j.feedback.m_appliedTorqueBodyB.dot(b.getAngularVelocity());
    const double speed = states[static_cast<std::size_t>(j.body)].speed_rad_s;
    double motor = 0;
    if (j.motor) {
      const btVector3& t = j.hinge ? j.feedback.m_appliedTorqueBodyA : j.feedback.m_appliedTorqueBodyB;
      motor = eig(t).dot(j.axis_world) * speed;
    }
    pw.motor_W += motor;
    pw.joint_W += total - motor;
    if (j.load) pw.load_W += load_torque_N_m(*j.load, time - dt, speed) * speed;  // as applied in the step
  }
  for (const PairRec& pr : pairs) {
    const btRigidBody &a = *bodies[pr.a].rigid, &b = *bodies[pr.b].rigid;
    for (int k = 0; k < pr.manifold->getNumContacts(); ++k) {
      const btManifoldPoint& pt = pr.manifold->getContactPoint(k);
      // Impulses act on a along +normal (+friction directions) and on b the opposite way.
      const btVector3 impulse = pt.m_normalWorldOnB * pt.m_appliedImpulse + pt.m_lateralFrictionDir1 * pt.m_appliedImpulseLateral1 +
                                pt.m_lateralFrictionDir2 * pt.m_appliedImpulseLateral2;
      const btVector3 va = a.getVelocityInLocalPoint(pt.m_positionWorldOnA - a.getCenterOfMassPosition());
      const btVector3 vb = b.getVelocityInLocalPoint(pt.m_positionWorldOnB - b.getCenterOfMassPosition());
      pw.contact_W += impulse.dot(va - vb) / dt;
    }
  }
  power = pw;
}

double World::time_s() const { return impl_->time; }
long World::steps() const { return impl_->steps; }
const std::vector<BodyState>& World::bodies() const { return impl_->states; }
const std::vector<ContactSample>& World::contacts() const { return impl_->contacts; }
const std::vector<GearPairInfo>& World::gear_pairs() const { return impl_->pair_infos; }
double World::max_penetration_m() const { return impl_->max_penetration; }

double World::motor_torque_N_m(const std::string& joint) const {
  for (const JointRec& j : impl_->joints)
    if (j.def.name == joint) {
      if (impl_->mb) return impl_->mb->motor_torque_N_m[static_cast<std::size_t>(&j - impl_->joints.data())];
      // The joint's own body is Bullet's body A of a hinge and body B of a bearing constraint.
      const btVector3& t = j.hinge ? j.feedback.m_appliedTorqueBodyA : j.feedback.m_appliedTorqueBodyB;
      return eig(t).dot(j.axis_world);
    }
  throw InputError("no joint named '" + joint + "'");
}

WorldStructure World::structure() const {
  const Impl& m = *impl_;
  WorldStructure w;
  for (const BuiltBody& b : m.bodies) {
    StructureBody sb;
    sb.name = b.name;
    sb.mass_kg = b.mass_kg;
    sb.inertia_z_kg_m2 = b.inertia_axis_kg_m2;
    const btVector3 c = b.rigid->getCenterOfMassPosition();
    sb.centre_of_mass_m = {c.x(), c.y()};
    sb.fixed = b.fixed;
    sb.flanks = b.flanks.get();
    if (b.flanks) sb.gear_pose = planar_pose(b);
    w.bodies.push_back(sb);
  }
  for (const JointRec& j : m.joints) w.joints.push_back({&j.def, j.body, j.parent, j.motor, j.load});
  for (std::size_t p = 0; p < m.pairs.size(); ++p)
    w.pairs.push_back({m.pairs[p].a, m.pairs[p].b, &m.pair_infos[p], m.pairs[p].stiffness});
  return w;
}

}  // namespace gearsim::physics

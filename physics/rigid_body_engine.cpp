#include "physics/rigid_body_engine.hpp"

#include <algorithm>
#include <cmath>

#include "core/errors.hpp"
#include "physics/measure.hpp"
#include "physics/tooth_contacts.hpp"

// The rigid_bodies engine's construction (bodies, constraints, manifolds into Bullet's world)
// and its step: tooth contacts into the pairs' manifolds (Bullet calls generate_contacts before
// each solve), motors and loads, the solve, then the measurements.
namespace gearsim::physics {
namespace {

// Collision groups: gears reach each other only through tooth contact, never through Bullet's
// own narrowphase (whose point counts and GJK chatter are what tooth contact replaces).
// Shapeless bodies (a carrier arm) collide with nothing.
constexpr int kGearGroup = 1 << 6;
constexpr int kOtherGroup = 1 << 7;
constexpr int kShapelessGroup = 1 << 8;

// A Bullet manifold holds at most 4 points: enough for one point per tooth pair at contact
// ratios below 4. Extra pairs (never seen in a healthy mesh) are dropped and counted.
constexpr int kMaxPointsPerPair = 4;

void pretick(btDynamicsWorld* w, btScalar) { static_cast<RigidBodyEngine*>(w->getWorldUserInfo())->generate_contacts(); }

// Joint jd's spring constraint (a bearing): its radial directions springs, the axial one locked
// and the spin free (or held by a torsional spring).
btGeneric6DofSpring2Constraint* make_spring(const JointDef& jd, btRigidBody& rb, btRigidBody* parent, const btTransform& in_body,
                                            const btTransform& frame_world) {
  btGeneric6DofSpring2Constraint* spring = nullptr;
  if (parent) {
    const btTransform in_parent = parent->getWorldTransform().inverse() * frame_world;
    spring = new btGeneric6DofSpring2Constraint(*parent, rb, in_parent, in_body);
  } else {
    spring = new btGeneric6DofSpring2Constraint(rb, in_body);
  }
  // x, y free (lower > upper) on their springs, z locked; all locked for a shaft.
  const double radial = jd.bearing->radially_rigid ? 0 : 1;
  spring->setLinearLowerLimit(btVector3(radial, radial, 0));
  spring->setLinearUpperLimit(btVector3(-radial, -radial, 0));
  spring->setAngularLowerLimit(btVector3(0, 0, 1));  // tilts locked, spin free
  spring->setAngularUpperLimit(btVector3(0, 0, -1));
  for (int axis = 0; axis < 2 && !jd.bearing->radially_rigid; ++axis) {
    spring->enableSpring(axis, true);
    spring->setStiffness(axis, jd.bearing->radial_stiffness_N_per_m);
    spring->setDamping(axis, jd.bearing->radial_damping_N_s_per_m);
  }
  if (jd.bearing->torsional_stiffness_N_m_per_rad > 0 || jd.bearing->torsional_damping_N_m_s_per_rad > 0) {
    // The spin (axis 5) held by a torsional spring about the start angle, not locked.
    spring->enableSpring(5, true);
    spring->setStiffness(5, jd.bearing->torsional_stiffness_N_m_per_rad);
    spring->setDamping(5, jd.bearing->torsional_damping_N_m_s_per_rad);
  }
  spring->setEquilibriumPoint();
  return spring;
}

}  // namespace

RigidBodyEngine::RigidBodyEngine(const Model& model, State& state) : model_(model), state_(state) {
  world_.setGravity(btVector3(0, 0, 0));
  btContactSolverInfo& info = world_.getSolverInfo();
  info.m_numIterations = model.scenario.solver.iterations;
  // Split impulse would move the contact springs' position error out of the velocity solve and
  // so remove their force: off. Warm starting on (impulses carried per tooth pair).
  info.m_splitImpulse = false;
  info.m_solverMode |= SOLVER_USE_WARMSTARTING;
  world_.setInternalTickCallback(pretick, this, true);
  add_bodies();
  add_joints();
  pairs_.resize(model.pairs.size());
  for (std::size_t p = 0; p < pairs_.size(); ++p) {
    const ModelPair& mp = model.pairs[p];
    pairs_[p].manifold = dispatcher_.getNewManifold(model.bodies[mp.a].rigid.get(), model.bodies[mp.b].rigid.get());
    pairs_[p].manifold->setContactProcessingThreshold(BT_LARGE_FLOAT);
  }
  measure();
}

RigidBodyEngine::~RigidBodyEngine() {
  for (Joint& j : joints_) {
    if (!j.constraint) continue;
    world_.removeConstraint(j.constraint);
    delete j.constraint;
  }
  for (Pair& p : pairs_)
    if (p.manifold) dispatcher_.releaseManifold(p.manifold);
  for (const BuiltBody& b : model_.bodies)
    if (b.rigid && b.rigid->getBroadphaseHandle()) world_.removeRigidBody(b.rigid.get());
}

void RigidBodyEngine::add_bodies() {
  for (const BuiltBody& b : model_.bodies) {
    const bool gear = b.flanks != nullptr;
    const bool shapeless = b.shape->getShapeType() == EMPTY_SHAPE_PROXYTYPE;
    if (shapeless)
      world_.addRigidBody(b.rigid.get(), kShapelessGroup, 0);
    else
      world_.addRigidBody(b.rigid.get(), gear ? kGearGroup : kOtherGroup, gear ? kOtherGroup : (kGearGroup | kOtherGroup));
  }
}

// The Bullet constraint of each joint: a hinge, or (with a bearing) a 6-dof spring constraint.
void RigidBodyEngine::add_joints() {
  joints_.resize(model_.joints.size());
  for (std::size_t k = 0; k < joints_.size(); ++k) {
    const ModelJoint& mj = model_.joints[k];
    Joint& jr = joints_[k];
    const JointDef& jd = mj.def;
    btRigidBody& rb = *model_.bodies[mj.body].rigid;
    btRigidBody* parent = mj.parent >= 0 ? model_.bodies[mj.parent].rigid.get() : nullptr;
    // Joint frame: origin at the pivot, z along the axis.
    btTransform frame_world;
    frame_world.setOrigin(bt(jd.pivot_m));
    const Eigen::Quaterniond q = Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), mj.axis_world);
    frame_world.setRotation(btQuaternion(q.x(), q.y(), q.z(), q.w()));
    const btTransform in_body = rb.getWorldTransform().inverse() * frame_world;
    if (jd.bearing) {
      jr.spring = make_spring(jd, rb, parent, in_body, frame_world);
      jr.constraint = jr.spring;
    } else if (parent) {
      const btTransform in_parent = parent->getWorldTransform().inverse() * frame_world;
      jr.constraint = jr.hinge = new btHingeConstraint(rb, *parent, in_body, in_parent);
    } else {
      // To Bullet's fixed body with an explicit world frame: the one-body constructor reads the
      // body-local frame's basis as a world basis, which flips the axis of a body whose
      // principal frame is turned (and with it the motor's sense).
      jr.constraint = jr.hinge = new btHingeConstraint(rb, btTypedConstraint::getFixedBody(), in_body, frame_world);
    }
    jr.constraint->setJointFeedback(&jr.feedback);
    world_.addConstraint(jr.constraint, true);
  }
}

void RigidBodyEngine::generate_contacts() {
  const std::uint64_t start = state_.clock.now();
  gear_poses_from_bodies(model_, state_);
  find_tooth_contacts(model_, state_, {kMaxPointsPerPair, false});
  for (std::size_t p = 0; p < pairs_.size(); ++p) {
    Pair& pr = pairs_[p];
    pr.current.clear();
    pr.current_stiffness_N_per_m.clear();
    pr.manifold->clearManifold();
    const BuiltBody &a = model_.bodies[model_.pairs[p].a], &b = model_.bodies[model_.pairs[p].b];
    const double z = 0.5 * ((a.rigid->getWorldTransform() * a.com_from_gear).getOrigin().z() +
                            (b.rigid->getWorldTransform() * b.com_from_gear).getOrigin().z());
    add_manifold_points(p, z);
  }
  state_.tooth_contact_ticks += state_.clock.now() - start;
}

// One manifold point per active tooth contact, at height z, with its stiffness and damping, warm
// started from the same tooth pair's impulse of the last step.
void RigidBodyEngine::add_manifold_points(std::size_t p, double z) {
  Pair& pr = pairs_[p];
  const ModelPair& mp = model_.pairs[p];
  const PairContacts& pc = state_.pairs[p];
  const BuiltBody &a = model_.bodies[mp.a], &b = model_.bodies[mp.b];
  for (std::size_t i = 0; i < pc.found.size(); ++i) {
    const contact::ToothContact& c = pc.found[i];
    if (!pc.active[i]) continue;
    const btVector3 n(c.normal_on_b.x(), c.normal_on_b.y(), 0);
    const btVector3 mid(c.point_m.x(), c.point_m.y(), z);
    const btVector3 on_b = mid + n * (0.5 * c.depth_m), on_a = mid - n * (0.5 * c.depth_m);
    btManifoldPoint pt(a.rigid->getWorldTransform().invXform(on_a), b.rigid->getWorldTransform().invXform(on_b), n, -c.depth_m);
    pt.m_positionWorldOnA = on_a;
    pt.m_positionWorldOnB = on_b;
    pt.m_combinedFriction = model_.scenario.contact.friction;
    pt.m_combinedRestitution = 0;
    pt.m_contactPointFlags |= BT_CONTACT_FLAG_CONTACT_STIFFNESS_DAMPING;
    const double k = pc.pair_stiffness[i];
    pt.m_combinedContactStiffness1 = k;
    pt.m_combinedContactDamping1 = contact_damping(model_, mp, k);
    const auto key = std::make_tuple(c.tooth_a, c.tooth_b, static_cast<int>(c.flank_a));
    for (const auto& [k_last, impulse] : pr.last_impulse)
      if (k_last == key) pt.m_appliedImpulse = impulse;
    pt.m_userPersistentData = nullptr;
    pr.manifold->addManifoldPoint(pt, false);
    pr.current.push_back(c);
    pr.current_stiffness_N_per_m.push_back(k);
  }
}

void RigidBodyEngine::apply_motors_and_loads() {
  const double dt = model_.scenario.solver.time_step_s;
  for (std::size_t k = 0; k < joints_.size(); ++k) {
    const ModelJoint& mj = model_.joints[k];
    Joint& j = joints_[k];
    if (mj.motor) {
      const double target = motor_target_rad_s(*mj.motor, state_.time + dt);  // the speed at the step's end
      if (j.hinge) j.hinge->enableAngularMotor(true, target, mj.motor->max_torque_N_m * dt);
      if (j.spring) {
        j.spring->enableMotor(5, true);
        // The spring constraint drives body A (the parent, or the ground) relative to B.
        j.spring->setTargetVelocity(5, -target);
        j.spring->setMaxMotorForce(5, mj.motor->max_torque_N_m);
      }
    }
    if (mj.load) {
      const double speed = state_.bodies.empty() ? 0.0 : state_.bodies[mj.body].speed_rad_s;
      const double torque = load_torque_N_m(*mj.load, state_.time, speed);
      const btVector3 t = bt(mj.axis_world * torque);
      model_.bodies[mj.body].rigid->applyTorque(t);
      if (mj.parent >= 0 && !model_.bodies[mj.parent].fixed) model_.bodies[mj.parent].rigid->applyTorque(-t);
    }
  }
}

void RigidBodyEngine::apply_impulses() {
  for (const ImpulseDef& i : model_.scenario.impulses) {
    const double share = impulse_shape(i, state_.time);
    if (share == 0) continue;
    btRigidBody& r = *model_.bodies[static_cast<std::size_t>(model_.body_index.at(i.body))].rigid;
    r.applyCentralForce(bt(i.force_N * share));
    r.applyTorque(bt(i.torque_N_m * share));
  }
}

void RigidBodyEngine::step() {
  const double dt = model_.scenario.solver.time_step_s;
  apply_motors_and_loads();
  apply_impulses();
  world_.stepSimulation(dt, 0, dt);
  state_.time += dt;
  ++state_.steps;
  measure();
  measure_power();
}

void RigidBodyEngine::measure() {
  measure_joints_from_bodies(model_, state_);
  measure_contacts();
}

void RigidBodyEngine::measure_contacts() {
  std::vector<ContactSample>& contacts = state_.contacts;
  contacts.clear();
  const double dt = model_.scenario.solver.time_step_s;
  for (std::size_t p = 0; p < pairs_.size(); ++p) {
    Pair& pr = pairs_[p];
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

void RigidBodyEngine::measure_power() {
  const double dt = model_.scenario.solver.time_step_s;
  PowerFlows pw;
  pw.kinetic_J = kinetic_energy_of_bodies_J(model_);
  pw.impulse_W = impulse_power_W(model_, state_, dt);
  for (std::size_t k = 0; k < joints_.size(); ++k) {
    const ModelJoint& mj = model_.joints[k];
    const Joint& j = joints_[k];
    const btRigidBody& a = j.constraint->getRigidBodyA();
    const btRigidBody& b = j.constraint->getRigidBodyB();
    // The whole constraint's power on both bodies (force at the centre of mass, torque about it).
    const double total =
        j.feedback.m_appliedForceBodyA.dot(a.getLinearVelocity()) + j.feedback.m_appliedTorqueBodyA.dot(a.getAngularVelocity()) +
        j.feedback.m_appliedForceBodyB.dot(b.getLinearVelocity()) + j.feedback.m_appliedTorqueBodyB.dot(b.getAngularVelocity());
    const double speed = state_.bodies[static_cast<std::size_t>(mj.body)].speed_rad_s;
    const double motor = mj.motor ? motor_torque_N_m(k) * speed : 0.0;
    pw.motor_W += motor;
    pw.joint_W += total - motor;
    if (mj.load) pw.load_W += load_torque_N_m(*mj.load, state_.time - dt, speed) * speed;  // as applied in the step
  }
  for (std::size_t p = 0; p < pairs_.size(); ++p) {
    const Pair& pr = pairs_[p];
    const btRigidBody &a = *model_.bodies[model_.pairs[p].a].rigid, &b = *model_.bodies[model_.pairs[p].b].rigid;
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
  state_.power = pw;
}

// The joint's own body is Bullet's body A of a hinge and body B of a bearing constraint.
double RigidBodyEngine::motor_torque_N_m(std::size_t joint) const {
  const Joint& j = joints_[joint];
  const btVector3& t = j.hinge ? j.feedback.m_appliedTorqueBodyA : j.feedback.m_appliedTorqueBodyB;
  return eig(t).dot(model_.joints[joint].axis_world);
}

}  // namespace gearsim::physics

#include "physics/world.hpp"

#include <btBulletDynamicsCommon.h>
#include <BulletDynamics/ConstraintSolver/btGeneric6DofSpring2Constraint.h>

#include <chrono>
#include <cmath>
#include <map>
#include <numbers>
#include <tuple>

#include "core/errors.hpp"
#include "physics/world_bodies.hpp"
#include "geometry/constants.hpp"

namespace gearsim::physics {
namespace {

using gearsim::constants::kPi;

// Collision groups: gears reach each other only through tooth contact, never through Bullet's
// own narrowphase (whose point counts and GJK chatter are what tooth contact replaces).
// Shapeless bodies (a carrier arm) collide with nothing.
constexpr int kGearGroup = 1 << 6;
constexpr int kOtherGroup = 1 << 7;
constexpr int kShapelessGroup = 1 << 8;

// A Bullet manifold holds at most 4 points: enough for one point per tooth pair at contact
// ratios below 4. Extra pairs (never seen in a healthy mesh) are dropped and counted.
constexpr int kMaxPointsPerPair = 4;

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

btVector3 bt(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }
Eigen::Vector3d eig(const btVector3& v) { return {v.x(), v.y(), v.z()}; }

}  // namespace

struct JointRec {
  JointDef def;
  int body = -1, parent = -1;  // parent -1 = ground
  btTypedConstraint* constraint = nullptr;
  btJointFeedback feedback;
  btHingeConstraint* hinge = nullptr;
  btGeneric6DofSpring2Constraint* spring = nullptr;
  Eigen::Vector3d axis_world = Eigen::Vector3d::UnitZ();
  double last_raw = 0, unwrapped = 0;
  const MotorDef* motor = nullptr;
  const LoadDef* load = nullptr;
};

struct PairRec {
  int a = -1, b = -1;
  btPersistentManifold* manifold = nullptr;
  GearPairInfo info;
  // Warm start per tooth pair: last step's impulse of each (tooth_a, tooth_b, flank_a), at most
  // kMaxPointsPerPair of them, searched in place (no allocation per step).
  std::vector<std::pair<std::tuple<int, int, int>, double>> last_impulse;
  std::vector<contact::ToothContact> found;                            // this step's, kept for its storage
  std::vector<double> pair_stiffness;                         // per found contact, N/m (storage kept)
  std::vector<char> active;                                   // per found contact: passed to the solver
  std::vector<contact::ToothContact> current;                          // in manifold point order
  std::vector<double> current_stiffness_N_per_m;              // the stiffness each was given
  // The pair's stiffness table, if any, and whether its radius is measured on gear a (else b).
  const contact::StiffnessTable* table = nullptr;
  bool table_on_a = true;
  double body_stiffness_N_per_m = 0;  // gear bodies in series with the pairs (0: rigid)
};

struct World::Impl {
  Scenario scenario;
  btDefaultCollisionConfiguration config;
  btCollisionDispatcher dispatcher{&config};
  btDbvtBroadphase broadphase;
  btSequentialImpulseConstraintSolver solver;
  btDiscreteDynamicsWorld world{&dispatcher, &broadphase, &solver, &config};
  std::vector<BuiltBody> bodies;
  std::vector<JointRec> joints;
  std::vector<PairRec> pairs;
  std::vector<BodyState> states;
  std::vector<ContactSample> contacts;
  std::vector<contact::PlanarPose> gear_poses;  // this step's, per body (gears only)
  std::vector<GearPairInfo> pair_infos;
  std::map<std::string, int> body_index;
  double time = 0;
  long steps = 0;
  double max_penetration = 0;
  long dropped_points = 0;
  long table_misses = 0;
  World::Profile profile;
  PowerFlows power;

  // Takes constraints, manifolds and bodies out of Bullet's world before its members go: also
  // when World's constructor throws half way (then ~World never runs, but ~Impl does).
  ~Impl();
  void generate_contacts();
  void apply_motors_and_loads();
  void measure();
  void measure_power();
};

World::Impl::~Impl() {
  for (JointRec& j : joints) {
    if (!j.constraint) continue;
    world.removeConstraint(j.constraint);
    delete j.constraint;
  }
  for (PairRec& p : pairs) dispatcher.releaseManifold(p.manifold);
  for (BuiltBody& b : bodies)
    if (b.rigid && b.rigid->getBroadphaseHandle()) world.removeRigidBody(b.rigid.get());
}

namespace {

void pretick(btDynamicsWorld* w, btScalar) { static_cast<World::Impl*>(w->getWorldUserInfo())->generate_contacts(); }

// Gear-frame pose projected on the common plane (the gear axes must be parallel to world z).
contact::PlanarPose planar_pose(const BuiltBody& b) {
  const btTransform t = b.rigid->getWorldTransform() * b.com_from_gear;
  const btVector3 x = t.getBasis().getColumn(0);
  return {{t.getOrigin().x(), t.getOrigin().y()}, std::atan2(x.y(), x.x())};
}

}  // namespace

void World::Impl::generate_contacts() {
  const auto start = Clock::now();
  max_penetration = 0;
  // Each gear's planar pose once per step (a gear meshes in several pairs).
  gear_poses.resize(bodies.size());
  for (std::size_t i = 0; i < bodies.size(); ++i)
    if (bodies[i].flanks) gear_poses[i] = planar_pose(bodies[i]);
  for (std::size_t p = 0; p < pairs.size(); ++p) {
    PairRec& pr = pairs[p];
    const BuiltBody &a = bodies[pr.a], &b = bodies[pr.b];
    std::vector<contact::ToothContact>& found = pr.found;
    contact::find_tooth_contacts(*a.flanks, gear_poses[pr.a], *b.flanks, gear_poses[pr.b], found);
    if (static_cast<int>(found.size()) > kMaxPointsPerPair) {
      std::sort(found.begin(), found.end(), [](const contact::ToothContact& x, const contact::ToothContact& y) { return x.depth_m > y.depth_m; });
      dropped_points += static_cast<long>(found.size()) - kMaxPointsPerPair;
      found.resize(kMaxPointsPerPair);
    }
    pr.manifold->clearManifold();
    const double z = 0.5 * ((a.rigid->getWorldTransform() * a.com_from_gear).getOrigin().z() +
                            (b.rigid->getWorldTransform() * b.com_from_gear).getOrigin().z());
    pr.current.clear();
    pr.current_stiffness_N_per_m.clear();
    const contact::PlanarPose table_gear = pr.table ? gear_poses[pr.table_on_a ? pr.a : pr.b] : contact::PlanarPose{};
    // Each pair's own stiffness: the constant, or its table's at the contact radius on the table's
    // gear (the point on that gear's own surface, half the depth from the overlap's mid-point).
    std::vector<double>& k_pair = pr.pair_stiffness;
    k_pair.assign(found.size(), pr.info.stiffness_N_per_m);
    if (pr.table)
      for (std::size_t i = 0; i < found.size(); ++i) {
        const contact::ToothContact& c = found[i];
        const Eigen::Vector2d on = c.point_m + (pr.table_on_a ? -0.5 : 0.5) * c.depth_m * c.normal_on_b;
        bool outside = false;
        k_pair[i] = contact::stiffness_at(*pr.table, (on - table_gear.centre_m).norm(), &outside) * pr.info.face_width_m;
        if (outside) ++table_misses;
      }
    // Gear bodies in series with all pairs (PairStiffnessDef::body_stiffness_N_per_m, compliance
    // c): F_i = k_i (δ_i − c F), F = Σ k_i δ_i / (1 + c Σ k_i) over the pairs with δ_i > c F (found
    // by dropping the others until none is left to drop). Each active pair then gets the secant
    // stiffness F_i/δ_i = k_i (1 − c F/δ_i), continuous as a pair comes into load; the others are
    // not passed to the solver.
    std::vector<char>& active = pr.active;
    active.assign(found.size(), 1);
    if (pr.body_stiffness_N_per_m > 0) {
      const double c_body = 1.0 / pr.body_stiffness_N_per_m;
      double F = 0;
      for (bool dropped = true; dropped;) {
        double num = 0, den = 1;
        for (std::size_t i = 0; i < found.size(); ++i)
          if (active[i]) num += k_pair[i] * found[i].depth_m, den += c_body * k_pair[i];
        F = num / den;
        dropped = false;
        for (std::size_t i = 0; i < found.size(); ++i)
          if (active[i] && found[i].depth_m <= c_body * F) active[i] = 0, dropped = true;
      }
      for (std::size_t i = 0; i < found.size(); ++i)
        if (active[i]) k_pair[i] *= 1.0 - c_body * F / found[i].depth_m;
    }
    for (std::size_t i = 0; i < found.size(); ++i) {
      const contact::ToothContact& c = found[i];
      max_penetration = std::max(max_penetration, c.depth_m);
      if (!active[i]) continue;
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
      const double k = k_pair[i];
      const double damping = pr.table || pr.body_stiffness_N_per_m > 0
                                 ? contact_damping_N_s_per_m(k, pr.info.reduced_mass_kg, scenario.contact.damping_ratio)
                                 : pr.info.damping_N_s_per_m;
      pt.m_combinedContactStiffness1 = k;
      pt.m_combinedContactDamping1 = damping;
      const auto key = std::make_tuple(c.tooth_a, c.tooth_b, static_cast<int>(c.flank_a));
      for (const auto& [k_last, impulse] : pr.last_impulse)
        if (k_last == key) pt.m_appliedImpulse = impulse;
      pt.m_userPersistentData = nullptr;
      pr.manifold->addManifoldPoint(pt, false);
      pr.current.push_back(c);
      pr.current_stiffness_N_per_m.push_back(k);
    }
  }
  profile.tooth_contact_s += seconds_since(start);
}

void World::Impl::apply_motors_and_loads() {
  for (JointRec& j : joints) {
    if (j.motor) {
      const double ramp = j.motor->ramp_time_s > 0 ? std::min(1.0, time / j.motor->ramp_time_s) : 1.0;
      const double target = j.motor->target_speed_rad_s * ramp;
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

void World::Impl::measure() {
  // Joint angles: the body's gear-frame x axis against the parent's, about the joint axis.
  for (JointRec& j : joints) {
    const BuiltBody& b = bodies[j.body];
    const btTransform tb = b.rigid->getWorldTransform() * b.com_from_gear;
    const Eigen::Vector3d ax = j.axis_world;
    const Eigen::Vector3d xb = eig(tb.getBasis().getColumn(0));
    Eigen::Vector3d ref = Eigen::Vector3d::UnitX(), ref2;
    Eigen::Vector3d omega_parent = Eigen::Vector3d::Zero();
    if (j.parent >= 0) {
      const BuiltBody& p = bodies[j.parent];
      ref = eig((p.rigid->getWorldTransform() * p.com_from_gear).getBasis().getColumn(0));
      omega_parent = eig(p.rigid->getAngularVelocity());
    }
    if (std::abs(ref.dot(ax)) > 0.9) ref = Eigen::Vector3d::UnitY();
    ref = (ref - ref.dot(ax) * ax).normalized();
    ref2 = ax.cross(ref);
    const double raw = std::atan2(xb.dot(ref2), xb.dot(ref));
    j.unwrapped += std::remainder(raw - j.last_raw, 2 * kPi);
    j.last_raw = raw;
    BodyState& s = states[j.body];
    s.angle_rad = j.unwrapped;
    s.speed_rad_s = (eig(b.rigid->getAngularVelocity()) - omega_parent).dot(ax);
  }
  for (std::size_t i = 0; i < bodies.size(); ++i)
    states[i].position_m = eig((bodies[i].rigid->getWorldTransform() * bodies[i].com_from_gear).getOrigin());
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

World::World(const Scenario& s) : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.scenario = s;
  m.world.setGravity(btVector3(0, 0, 0));
  btContactSolverInfo& info = m.world.getSolverInfo();
  info.m_numIterations = s.solver.iterations;
  // Split impulse would move the contact springs' position error out of the velocity solve and
  // so remove their force: off. Warm starting on (impulses carried per tooth pair).
  info.m_splitImpulse = false;
  info.m_solverMode |= SOLVER_USE_WARMSTARTING;
  m.world.setInternalTickCallback(pretick, &m, true);
  for (const PairStiffnessDef& t : s.contact.stiffness_tables)
    if (int row = -1; !contact::stiffness_table_problem(t.table, &row).empty())
      throw InputError("scenario: stiffness table " + t.table.source + " of gears '" + t.body_a + "' and '" + t.body_b +
                       "': " + (row >= 0 ? "row " + std::to_string(row + 1) + ": " : "") +
                       contact::stiffness_table_problem(t.table));

  for (const BodyDef& def : s.bodies) {
    if (m.body_index.count(def.name)) throw InputError("scenario: duplicate body name '" + def.name + "'");
    m.body_index[def.name] = static_cast<int>(m.bodies.size());
    m.bodies.push_back(build_body(def, s.contact));
    BuiltBody& b = m.bodies.back();
    // Bodies of the same gear (the planets of a set) share one flank table: less memory, and
    // the tables probing reads stay in the cache.
    for (std::size_t e = 0; b.flanks && e + 1 < m.bodies.size(); ++e)
      if (m.bodies[e].flanks && m.bodies[e].flanks->same_as(*b.flanks)) {
        b.flanks = m.bodies[e].flanks;
        break;
      }
    const bool gear = b.flanks != nullptr;
    const bool shapeless = b.shape->getShapeType() == EMPTY_SHAPE_PROXYTYPE;
    if (shapeless) m.world.addRigidBody(b.rigid.get(), kShapelessGroup, 0);
    else m.world.addRigidBody(b.rigid.get(), gear ? kGearGroup : kOtherGroup, gear ? kOtherGroup : (kGearGroup | kOtherGroup));
    m.states.push_back({def.name, 0, 0, Eigen::Vector3d::Zero()});
  }
  auto body_of = [&](const std::string& name, const std::string& who) {
    auto it = m.body_index.find(name);
    if (it == m.body_index.end()) throw InputError("scenario: " + who + ": no body named '" + name + "'");
    return it->second;
  };
  m.joints.reserve(s.joints.size());
  for (const JointDef& jd : s.joints) {
    JointRec j;
    j.def = jd;
    j.body = body_of(jd.body, "joint '" + jd.name + "'");
    j.parent = jd.parent == "ground" ? -1 : body_of(jd.parent, "joint '" + jd.name + "'");
    if (jd.axis.norm() < 1e-12) throw InputError("scenario: joint '" + jd.name + "': axis has zero length");
    j.axis_world = jd.axis.normalized();
    m.joints.push_back(j);
    JointRec& jr = m.joints.back();
    btRigidBody& rb = *m.bodies[jr.body].rigid;
    btRigidBody* parent = jr.parent >= 0 ? m.bodies[jr.parent].rigid.get() : nullptr;
    // Joint frame: origin at the pivot, z along the axis.
    btTransform frame_world;
    frame_world.setOrigin(bt(jd.pivot_m));
    const Eigen::Quaterniond q = Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), jr.axis_world);
    frame_world.setRotation(btQuaternion(q.x(), q.y(), q.z(), q.w()));
    const btTransform in_body = rb.getWorldTransform().inverse() * frame_world;
    if (!jd.bearing) {
      if (parent) {
        const btTransform in_parent = parent->getWorldTransform().inverse() * frame_world;
        jr.hinge = new btHingeConstraint(rb, *parent, in_body, in_parent);
      } else {
        // To Bullet's fixed body with an explicit world frame: the one-body constructor reads the
        // body-local frame's basis as a world basis, which flips the axis of a body whose
        // principal frame is turned (and with it the motor's sense).
        jr.hinge = new btHingeConstraint(rb, btTypedConstraint::getFixedBody(), in_body, frame_world);
      }
      jr.constraint = jr.hinge;
    } else {
      if (parent) {
        const btTransform in_parent = parent->getWorldTransform().inverse() * frame_world;
        jr.spring = new btGeneric6DofSpring2Constraint(*parent, rb, in_parent, in_body);
      } else {
        jr.spring = new btGeneric6DofSpring2Constraint(rb, in_body);
      }
      jr.spring->setLinearLowerLimit(btVector3(1, 1, 0));  // x, y free (lower > upper), z locked
      jr.spring->setLinearUpperLimit(btVector3(-1, -1, 0));
      jr.spring->setAngularLowerLimit(btVector3(0, 0, 1));  // tilts locked, spin free
      jr.spring->setAngularUpperLimit(btVector3(0, 0, -1));
      for (int axis = 0; axis < 2; ++axis) {
        jr.spring->enableSpring(axis, true);
        jr.spring->setStiffness(axis, jd.bearing->radial_stiffness_N_per_m);
        jr.spring->setDamping(axis, jd.bearing->radial_damping_N_s_per_m);
      }
      jr.spring->setEquilibriumPoint();
      jr.constraint = jr.spring;
    }
    jr.constraint->setJointFeedback(&jr.feedback);
    m.world.addConstraint(jr.constraint, true);
  }
  auto joint_of = [&](const std::string& name, const std::string& who) -> JointRec& {
    for (JointRec& j : m.joints)
      if (j.def.name == name) return j;
    throw InputError("scenario: " + who + ": no joint named '" + name + "'");
  };
  for (const MotorDef& md : m.scenario.motors) joint_of(md.joint, "motor").motor = &md;
  for (const LoadDef& ld : m.scenario.loads) joint_of(ld.joint, "load").load = &ld;
  // Meshing gear pairs: every two gears whose toothed zones can reach each other.
  for (std::size_t a = 0; a < m.bodies.size(); ++a)
    for (std::size_t b = a + 1; b < m.bodies.size(); ++b) {
      const BuiltBody &ga = m.bodies[a], &gb = m.bodies[b];
      if (!ga.flanks || !gb.flanks || (ga.flanks->internal() && gb.flanks->internal())) continue;
      if (!gears_can_mesh(ga, gb)) continue;
      PairRec pr;
      // The external gear first, so that tooth_a is always the external one's.
      pr.a = static_cast<int>(ga.flanks->internal() ? b : a);
      pr.b = static_cast<int>(ga.flanks->internal() ? a : b);
      pr.manifold = m.dispatcher.getNewManifold(m.bodies[pr.a].rigid.get(), m.bodies[pr.b].rigid.get());
      pr.manifold->setContactProcessingThreshold(BT_LARGE_FLOAT);
      pr.info = pair_contact(m.bodies[pr.a], m.bodies[pr.b], s.contact);
      for (const PairStiffnessDef& t : m.scenario.contact.stiffness_tables) {
        const std::string &na = m.bodies[pr.a].name, &nb = m.bodies[pr.b].name;
        if (!((t.body_a == na && t.body_b == nb) || (t.body_a == nb && t.body_b == na))) continue;
        if (pr.table) throw InputError("scenario: contact.stiffness_tables: two tables for gears '" + na + "' and '" + nb + "'");
        pr.table = &t.table;
        pr.table_on_a = t.body_a == na;
        pr.body_stiffness_N_per_m = t.body_stiffness_N_per_m;
        pr.info.stiffness_table = t.table.source;
      }
      m.pairs.push_back(std::move(pr));
      m.pair_infos.push_back(m.pairs.back().info);
    }
  // Gears overlapping at the start would be flung apart by a force of k·depth in the first step.
  for (std::size_t i = 0; i < m.bodies.size(); ++i)
    if (m.bodies[i].flanks) m.gear_poses.resize(m.bodies.size()), m.gear_poses[i] = planar_pose(m.bodies[i]);
  for (PairRec& pr : m.pairs) {
    const BuiltBody &a = m.bodies[pr.a], &b = m.bodies[pr.b];
    pr.info.tooth_height_m = std::min(a.flanks->r_max_m() - a.flanks->r_min_m(), b.flanks->r_max_m() - b.flanks->r_min_m());
    m.pair_infos[static_cast<std::size_t>(&pr - m.pairs.data())].tooth_height_m = pr.info.tooth_height_m;
    require_clear_mesh(a, m.gear_poses[pr.a], b, m.gear_poses[pr.b],
                       centre_distance_derived(m.scenario.pair_tables, a.name, b.name));
  }
  // Every table must belong to a meshing pair.
  for (const PairStiffnessDef& t : m.scenario.contact.stiffness_tables) {
    bool used = false;
    for (const PairRec& pr : m.pairs) used = used || pr.table == &t.table;
    if (!used)
      throw InputError("scenario: stiffness table " + t.table.source + ": gears '" + t.body_a + "' and '" + t.body_b +
                       "' do not mesh (no tooth contact between them)");
  }
  m.measure();
}

World::~World() = default;

void World::step() {
  Impl& m = *impl_;
  const auto start = Clock::now();
  m.apply_motors_and_loads();
  m.world.stepSimulation(m.scenario.solver.time_step_s, 0, m.scenario.solver.time_step_s);
  m.time += m.scenario.solver.time_step_s;
  ++m.steps;
  m.measure();
  m.measure_power();
  m.profile.step_total_s += seconds_since(start);
}

const World::Profile& World::profile() const { return impl_->profile; }
const PowerFlows& World::power() const { return impl_->power; }
long World::dropped_contacts() const { return impl_->dropped_points; }
long World::stiffness_table_misses() const { return impl_->table_misses; }

void World::Impl::measure_power() {
  const double dt = scenario.solver.time_step_s;
  PowerFlows pw;
  for (const BuiltBody& b : bodies) {
    const btRigidBody& r = *b.rigid;
    if (r.getInvMass() == 0) continue;
    const btVector3 v = r.getLinearVelocity(), w = r.getAngularVelocity();
    const btMatrix3x3 inertia = r.getInvInertiaTensorWorld().inverse();
    pw.kinetic_J += 0.5 * v.dot(v) / r.getInvMass() + 0.5 * w.dot(inertia * w);
  }
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
      // The joint's own body is Bullet's body A of a hinge and body B of a bearing constraint.
      const btVector3& t = j.hinge ? j.feedback.m_appliedTorqueBodyA : j.feedback.m_appliedTorqueBodyB;
      return eig(t).dot(j.axis_world);
    }
  throw InputError("no joint named '" + joint + "'");
}

}  // namespace gearsim::physics

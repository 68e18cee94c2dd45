#include <cmath>

#include "core/errors.hpp"
#include "physics/world_impl.hpp"

// World's construction: the Bullet world from a scenario — bodies, joints (hinges or bearing
// springs), motors and loads, the meshing gear pairs — and the checks it refuses a scenario by.
// Stepping is world_step.cpp.
namespace gearsim::physics {
namespace {

void pretick(btDynamicsWorld* w, btScalar) { static_cast<World::Impl*>(w->getWorldUserInfo())->generate_contacts(); }

// The Bullet constraint of a joint: a hinge, or (with a bearing) a 6-dof spring constraint whose
// radial directions are springs, the axial one locked and the spin free. Owned by the JointRec.
void make_constraint(JointRec& jr, btRigidBody& rb, btRigidBody* parent) {
  const JointDef& jd = jr.def;
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
    return;
  }
  if (parent) {
    const btTransform in_parent = parent->getWorldTransform().inverse() * frame_world;
    jr.spring = new btGeneric6DofSpring2Constraint(*parent, rb, in_parent, in_body);
  } else {
    jr.spring = new btGeneric6DofSpring2Constraint(rb, in_body);
  }
  jr.constraint = jr.spring;
  jr.spring->setLinearLowerLimit(btVector3(1, 1, 0));  // x, y free (lower > upper), z locked
  jr.spring->setLinearUpperLimit(btVector3(-1, -1, 0));
  jr.spring->setAngularLowerLimit(btVector3(0, 0, 1));  // tilts locked, spin free
  jr.spring->setAngularUpperLimit(btVector3(0, 0, -1));
  for (int axis = 0; axis < 2; ++axis) {
    jr.spring->enableSpring(axis, true);
    jr.spring->setStiffness(axis, jd.bearing->radial_stiffness_N_per_m);
    jr.spring->setDamping(axis, jd.bearing->radial_damping_N_s_per_m);
  }
  if (jd.bearing->torsional_stiffness_N_m_per_rad > 0 || jd.bearing->torsional_damping_N_m_s_per_rad > 0) {
    // The spin (axis 5) held by a torsional spring about the start angle, not locked.
    jr.spring->enableSpring(5, true);
    jr.spring->setStiffness(5, jd.bearing->torsional_stiffness_N_m_per_rad);
    jr.spring->setDamping(5, jd.bearing->torsional_damping_N_m_s_per_rad);
  }
  jr.spring->setEquilibriumPoint();
}

}  // namespace

World::Impl::~Impl() {
  for (JointRec& j : joints) {
    if (!j.constraint) continue;
    world.removeConstraint(j.constraint);
    delete j.constraint;
  }
  for (PairRec& p : pairs)
    if (p.manifold) dispatcher.releaseManifold(p.manifold);
  for (BuiltBody& b : bodies)
    if (b.rigid && b.rigid->getBroadphaseHandle()) world.removeRigidBody(b.rigid.get());
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
    if (const Check c = contact::check_stiffness_table(t.table); !c)
      throw InputError("scenario: stiffness table " + t.table.source + " of gears '" + t.body_a + "' and '" + t.body_b +
                       "': " + (c.refusal().index >= 0 ? "row " + std::to_string(c.refusal().index + 1) + ": " : "") +
                       c.reason());
  m.add_bodies();
  m.add_joints();
  m.attach_drives();
  m.find_pairs();
  m.check_start();
  if (s.solver.engine == SolverEngine::multibody) m.build_multibody();
  m.measure();
}

World::~World() = default;

void World::Impl::add_bodies() {
  for (const BodyDef& def : scenario.bodies) {
    if (body_index.count(def.name)) throw InputError("scenario: duplicate body name '" + def.name + "'");
    body_index[def.name] = static_cast<int>(bodies.size());
    bodies.push_back(build_body(def, scenario.contact));
    BuiltBody& b = bodies.back();
    // Bodies of the same gear (the planets of a set) share one flank table: less memory, and
    // the tables probing reads stay in the cache.
    for (std::size_t e = 0; b.flanks && e + 1 < bodies.size(); ++e)
      if (bodies[e].flanks && bodies[e].flanks->same_as(*b.flanks)) {
        b.flanks = bodies[e].flanks;
        break;
      }
    const bool gear = b.flanks != nullptr;
    const bool shapeless = b.shape->getShapeType() == EMPTY_SHAPE_PROXYTYPE;
    states.push_back({def.name, 0, 0, Eigen::Vector3d::Zero()});
    // The multibody engine keeps the rigid bodies out of Bullet's world: they only carry the
    // poses and velocities its tree computes, for measuring and rendering.
    if (scenario.solver.engine == SolverEngine::multibody) continue;
    if (shapeless) world.addRigidBody(b.rigid.get(), kShapelessGroup, 0);
    else world.addRigidBody(b.rigid.get(), gear ? kGearGroup : kOtherGroup, gear ? kOtherGroup : (kGearGroup | kOtherGroup));
  }
}

void World::Impl::add_joints() {
  auto body_of = [&](const std::string& name, const std::string& who) {
    auto it = body_index.find(name);
    if (it == body_index.end()) throw InputError("scenario: " + who + ": no body named '" + name + "'");
    return it->second;
  };
  joints.reserve(scenario.joints.size());
  for (const JointDef& jd : scenario.joints) {
    JointRec j;
    j.def = jd;
    j.body = body_of(jd.body, "joint '" + jd.name + "'");
    j.parent = jd.parent == "ground" ? -1 : body_of(jd.parent, "joint '" + jd.name + "'");
    if (jd.axis.norm() < 1e-12) throw InputError("scenario: joint '" + jd.name + "': axis has zero length");
    j.axis_world = jd.axis.normalized();
    joints.push_back(j);
    JointRec& jr = joints.back();
    if (scenario.solver.engine == SolverEngine::multibody) continue;  // joints of the tree (world_multibody.cpp)
    make_constraint(jr, *bodies[jr.body].rigid, jr.parent >= 0 ? bodies[jr.parent].rigid.get() : nullptr);
    jr.constraint->setJointFeedback(&jr.feedback);
    world.addConstraint(jr.constraint, true);
  }
}

void World::Impl::attach_drives() {
  auto joint_of = [&](const std::string& name, const std::string& who) -> JointRec& {
    for (JointRec& j : joints)
      if (j.def.name == name) return j;
    throw InputError("scenario: " + who + ": no joint named '" + name + "'");
  };
  for (const MotorDef& md : scenario.motors) joint_of(md.joint, "motor").motor = &md;
  for (const LoadDef& ld : scenario.loads) joint_of(ld.joint, "load").load = &ld;
}

// Meshing gear pairs: every two gears whose toothed zones can reach each other, with their
// stiffness table if the scenario gives one.
void World::Impl::find_pairs() {
  for (std::size_t a = 0; a < bodies.size(); ++a)
    for (std::size_t b = a + 1; b < bodies.size(); ++b) {
      const BuiltBody &ga = bodies[a], &gb = bodies[b];
      if (!ga.flanks || !gb.flanks || (ga.flanks->internal() && gb.flanks->internal())) continue;
      if (!gears_can_mesh(ga, gb)) continue;
      PairRec pr;
      // The external gear first, so that tooth_a is always the external one's.
      pr.a = static_cast<int>(ga.flanks->internal() ? b : a);
      pr.b = static_cast<int>(ga.flanks->internal() ? a : b);
      if (scenario.solver.engine == SolverEngine::rigid_bodies) {
        pr.manifold = dispatcher.getNewManifold(bodies[pr.a].rigid.get(), bodies[pr.b].rigid.get());
        pr.manifold->setContactProcessingThreshold(BT_LARGE_FLOAT);
      }
      pr.info = pair_contact(bodies[pr.a], bodies[pr.b], scenario.contact);
      pr.stiffness.pair_stiffness_N_per_m = pr.info.stiffness_N_per_m;
      pr.stiffness.face_width_m = pr.info.face_width_m;
      for (const PairStiffnessDef& t : scenario.contact.stiffness_tables) {
        const std::string &na = bodies[pr.a].name, &nb = bodies[pr.b].name;
        if (!((t.body_a == na && t.body_b == nb) || (t.body_a == nb && t.body_b == na))) continue;
        if (pr.stiffness.table) throw InputError("scenario: contact.stiffness_tables: two tables for gears '" + na + "' and '" + nb + "'");
        pr.stiffness.table = &t.table;
        pr.stiffness.table_on_a = t.body_a == na;
        pr.stiffness.body_stiffness_N_per_m = t.body_stiffness_N_per_m;
        pr.info.stiffness_table = t.table.source;
      }
      for (const PairMeshStiffnessDef& k : scenario.contact.mesh_stiffnesses) {
        const std::string &na = bodies[pr.a].name, &nb = bodies[pr.b].name;
        if (!((k.body_a == na && k.body_b == nb) || (k.body_a == nb && k.body_b == na))) continue;
        if (pr.stiffness.table || pr.stiffness.mesh_stiffness_N_per_m > 0)
          throw InputError("scenario: contact.mesh_stiffnesses: gears '" + na + "' and '" + nb + "' have a stiffness table or mesh stiffness already");
        pr.stiffness.mesh_stiffness_N_per_m = pr.info.mesh_stiffness_N_per_m = k.stiffness_N_per_m;
      }
      pairs.push_back(std::move(pr));
      pair_infos.push_back(pairs.back().info);
    }
}

// Gears overlapping at the start would be flung apart by a force of k·depth in the first step;
// every stiffness table must belong to a meshing pair.
void World::Impl::check_start() {
  for (std::size_t i = 0; i < bodies.size(); ++i)
    if (bodies[i].flanks) gear_poses.resize(bodies.size()), gear_poses[i] = planar_pose(bodies[i]);
  for (PairRec& pr : pairs) {
    const BuiltBody &a = bodies[pr.a], &b = bodies[pr.b];
    pr.info.tooth_height_m = std::min(a.flanks->r_max_m() - a.flanks->r_min_m(), b.flanks->r_max_m() - b.flanks->r_min_m());
    pair_infos[static_cast<std::size_t>(&pr - pairs.data())].tooth_height_m = pr.info.tooth_height_m;
    require_clear_mesh(a, gear_poses[pr.a], b, gear_poses[pr.b], centre_distance_derived(scenario.pair_tables, a.name, b.name));
  }
  for (const PairStiffnessDef& t : scenario.contact.stiffness_tables) {
    bool used = false;
    for (const PairRec& pr : pairs) used = used || pr.stiffness.table == &t.table;
    if (!used)
      throw InputError("scenario: stiffness table " + t.table.source + ": gears '" + t.body_a + "' and '" + t.body_b +
                       "' do not mesh (no tooth contact between them)");
  }
  for (const PairMeshStiffnessDef& k : scenario.contact.mesh_stiffnesses) {
    bool used = false;
    for (const PairRec& pr : pairs)
      used = used || (pr.stiffness.mesh_stiffness_N_per_m > 0 && ((bodies[pr.a].name == k.body_a && bodies[pr.b].name == k.body_b) ||
                                                        (bodies[pr.a].name == k.body_b && bodies[pr.b].name == k.body_a)));
    if (!used)
      throw InputError("scenario: contact.mesh_stiffnesses: gears '" + k.body_a + "' and '" + k.body_b + "' do not mesh (no tooth contact between them)");
  }
}

}  // namespace gearsim::physics

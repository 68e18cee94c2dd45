#include <algorithm>
#include <cmath>
#include <limits>
#include <mutex>

#include "core/errors.hpp"
#include "physics/world_impl.hpp"

// The `multibody` engine (solver.engine: multibody). The joints form a tree: every body that is
// neither fixed nor free turns in one joint about its parent (the ground, a fixed body, or
// another body). Bullet's btMultiBody holds that tree in reduced coordinates (Featherstone's
// articulated-body algorithm): a rigid hinge is one coordinate, a bearing a planar joint (spin
// and two translations). Joints are then exact by construction: nothing to iterate.
//
// Everything else that acts between bodies is one row of a small system solved directly each
// step (Bullet's Dantzig LCP solver, the one its MLCP solvers use), with row Jacobians J and the
// inverse mass matrix M⁻¹ from the btMultiBody:
//   tooth contact, normal    unilateral implicit spring–damper (k, c): impulse λ ≥ 0 with
//                            λ/h = k·δ⁺ + c·δ̇⁺ at the end of the step (δ⁺ = δ − h·J·v⁺)
//   tooth contact, friction  in-plane tangent: μ·λ_n against the slip, shared at its reversal
//                            (contact.friction_model sliding, world_friction.cpp), or sticking
//                            unless |λ_t| would exceed μ·λ_n (stick_slip)
//   bearing, radial          two bilateral implicit springs (k_r, c_r) on the bearing centre's
//                            displacement from its housing
//   bearing, torsional       one on the spin coordinate, about its start angle
//   motor                    the spin coordinate's speed equals the target, |torque| ≤ limit
// (J·M⁻¹·Jᵀ + Γ)·λ = b + w with Γ = diag(1/(h·(h·k + c))) for the springs: the same implicit
// spring–damper Bullet's rigid-body solver makes of a contact's stiffness and damping (ERP and
// CFM), here solved exactly, whatever solver.iterations says.
namespace gearsim::physics {
namespace {

void set_joint_velocities(btMultiBody& t, const std::vector<double>& v) {
  for (int l = 0; l < t.getNumLinks(); ++l) t.setJointVelMultiDof(l, v.data() + t.getLink(l).m_dofOffset);
}

}  // namespace

// Bullet's Dantzig solver reports failure through one global flag (btDantzigLCP.cpp, s_error):
// worlds stepped in parallel threads (the Python module releases the GIL) take turns.
std::mutex& dantzig_flag() {
  static std::mutex m;
  return m;
}

namespace {

const char* const kWho = "scenario: solver.engine multibody: ";

// The joint each body turns in (−1: none), checked: one joint per body, none turning a fixed
// body, every movable body in one, no shapes but teeth.
std::vector<int> joints_of_bodies(const std::vector<BuiltBody>& bodies, const std::vector<JointRec>& joints) {
  const std::string who = kWho;
  std::vector<int> joint_of(bodies.size(), -1);
  for (std::size_t j = 0; j < joints.size(); ++j) {
    const int b = joints[j].body;
    if (joint_of[static_cast<std::size_t>(b)] >= 0)
      throw InputError(who + "body '" + bodies[static_cast<std::size_t>(b)].name + "' turns in two joints (the joints must form a tree)");
    if (bodies[static_cast<std::size_t>(b)].fixed)
      throw InputError(who + "joint '" + joints[j].def.name + "' turns the fixed body '" + bodies[static_cast<std::size_t>(b)].name + "'");
    joint_of[static_cast<std::size_t>(b)] = static_cast<int>(j);
  }
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    const BuiltBody& b = bodies[i];
    if (!b.fixed && joint_of[i] < 0)
      throw InputError(who + "body '" + b.name + "' has no joint; a free body needs solver.engine rigid_bodies");
    if (!b.flanks && b.shape->getShapeType() != EMPTY_SHAPE_PROXYTYPE)
      throw InputError(who + "body '" + b.name + "' has a shape but no teeth; bodies touch only through tooth contact in this engine (solver.engine rigid_bodies collides shapes)");
  }
  return joint_of;
}

// The movable bodies as links, in an order where every parent comes before its children
// (link_of_body: each body's link, −1 for fixed ones); InputError for a loop of joints.
std::vector<int> link_order(const std::vector<BuiltBody>& bodies, const std::vector<JointRec>& joints, const std::vector<int>& joint_of,
                            std::vector<int>& link_of_body) {
  link_of_body.assign(bodies.size(), -1);
  std::vector<int> order;
  for (bool grew = true; grew;) {
    grew = false;
    for (std::size_t i = 0; i < bodies.size(); ++i) {
      if (bodies[i].fixed || link_of_body[i] >= 0) continue;
      const int p = joints[static_cast<std::size_t>(joint_of[i])].parent;
      if (p >= 0 && !bodies[static_cast<std::size_t>(p)].fixed && link_of_body[static_cast<std::size_t>(p)] < 0) continue;
      link_of_body[i] = static_cast<int>(order.size());
      order.push_back(static_cast<int>(i));
      grew = true;
    }
  }
  for (std::size_t i = 0; i < bodies.size(); ++i)
    if (!bodies[i].fixed && link_of_body[i] < 0)
      throw InputError(std::string(kWho) + "body '" + bodies[i].name + "' is in a loop of joints (the joints must form a tree)");
  return order;
}

// The engine's integrator, row solver and friction as the scenario sets them, and whether every
// joint turns about z (the planar path).
void set_engine_options(MultibodyEngine& e, const Scenario& scenario, const std::vector<JointRec>& joints) {
  e.bdf2 = scenario.solver.integrator == SolverDef::Integrator::bdf2;
  e.trapezoid_closed = scenario.solver.integrator == SolverDef::Integrator::trapezoid_closed;
  e.theta = e.bdf2 ? 1.0 : e.trapezoid_closed ? 0.5 : scenario.solver.theta;
  e.h_eff = e.h_step = scenario.solver.time_step_s;
  e.locate_onset = scenario.solver.locate_contact_onset && !e.bdf2;  // BDF2's history assumes equal steps
  e.active_set = scenario.solver.row_solver == SolverDef::RowSolver::active_set;
  e.sliding_friction = scenario.contact.friction_model == ContactDef::FrictionModel::sliding;
  e.planar = true;
  for (const JointRec& jr : joints) e.planar = e.planar && std::abs(std::abs(jr.axis_world.z()) - 1) < 1e-12;
}

}  // namespace

void World::Impl::build_multibody() {
  mb = std::make_unique<MultibodyEngine>();
  MultibodyEngine& e = *mb;
  const std::string who = kWho;
  const std::vector<int> joint_of = joints_of_bodies(bodies, joints);
  const std::vector<int> order = link_order(bodies, joints, joint_of, e.link_of_body);

  e.tree = std::make_unique<btMultiBody>(static_cast<int>(order.size()), 0, btVector3(0, 0, 0), true, false);
  e.dof_of_joint.assign(joints.size(), -1);
  e.pivot_in_body.assign(joints.size(), btVector3(0, 0, 0));
  e.pivot_in_parent.assign(joints.size(), btVector3(0, 0, 0));
  e.motor_torque_N_m.assign(joints.size(), 0);
  for (std::size_t l = 0; l < order.size(); ++l) {
    const std::size_t i = static_cast<std::size_t>(order[l]);
    const BuiltBody& b = bodies[i];
    const std::size_t j = static_cast<std::size_t>(joint_of[i]);
    const JointRec& jr = joints[j];
    const bool on_body = jr.parent >= 0 && !bodies[static_cast<std::size_t>(jr.parent)].fixed;
    const int parent_link = on_body ? e.link_of_body[static_cast<std::size_t>(jr.parent)] : -1;
    // Link frames are the bodies' centre-of-mass principal frames at t = 0; the base is the world.
    const btTransform ti = b.rigid->getWorldTransform();
    const btTransform tp = on_body ? bodies[static_cast<std::size_t>(jr.parent)].rigid->getWorldTransform() : btTransform::getIdentity();
    const btQuaternion parent_to_this = ti.getRotation().inverse() * tp.getRotation();
    const btVector3 inv = b.rigid->getInvInertiaDiagLocal();
    if (!(inv.x() > 0 && inv.y() > 0 && inv.z() > 0 && b.mass_kg > 0))
      throw InputError(who + "body '" + b.name + "' needs a positive mass and principal moments of inertia");
    const btVector3 inertia(1 / inv.x(), 1 / inv.y(), 1 / inv.z());
    const btVector3 pivot = bt(jr.def.pivot_m);
    const btVector3 axis_here = quatRotate(ti.getRotation().inverse(), bt(jr.axis_world));
    if (jr.def.bearing)
      e.tree->setupPlanar(static_cast<int>(l), b.mass_kg, inertia, parent_link, parent_to_this, axis_here, tp.invXform(ti.getOrigin()), false);
    else
      e.tree->setupRevolute(static_cast<int>(l), b.mass_kg, inertia, parent_link, parent_to_this, axis_here, tp.invXform(pivot),
                            quatRotate(ti.getRotation().inverse(), ti.getOrigin() - pivot), false);
    e.pivot_in_body[j] = ti.invXform(pivot);
    e.pivot_in_parent[j] = tp.invXform(pivot);
  }
  btMultiBody& t = *e.tree;
  t.finalizeMultiDof();
  t.setLinearDamping(0);
  t.setAngularDamping(0);
  t.setMaxCoordinateVelocity(std::numeric_limits<double>::max());
  t.setCanSleep(false);
  t.setUseGyroTerm(true);
  t.setHasSelfCollision(false);
  for (std::size_t l = 0; l < order.size(); ++l)
    e.dof_of_joint[static_cast<std::size_t>(joint_of[static_cast<std::size_t>(order[l])])] = t.getLink(static_cast<int>(l)).m_dofOffset;
  e.dofs = t.getNumDofs();
  e.buf.assign(static_cast<std::size_t>(6 + e.dofs), 0);
  e.v_mid.assign(static_cast<std::size_t>(e.dofs), 0);
  set_engine_options(e, scenario, joints);
  e.out.assign(static_cast<std::size_t>(6 + e.dofs), 0);
  e.omega.assign(order.size() + 1, btVector3(0, 0, 0));
  e.vel.assign(order.size() + 1, btVector3(0, 0, 0));
  e.inverse_mass.resize(e.dofs, e.dofs);
  // The tree at q = 0 reproduces the bodies' poses.
  t.forwardKinematics(e.world_to_local, e.local_origin);
  for (std::size_t l = 0; l < order.size(); ++l) {
    const btTransform& tl = t.getLink(static_cast<int>(l)).m_cachedWorldTransform;
    const btTransform& tb = bodies[static_cast<std::size_t>(order[l])].rigid->getWorldTransform();
    GEARSIM_CHECK((tl.getOrigin() - tb.getOrigin()).length() < 1e-12 && (tl.getBasis().getColumn(0) - tb.getBasis().getColumn(0)).length() < 1e-12,
                  "a multibody link must start at its body's pose");
  }
  e.planar_mass = e.planar && scenario.solver.mass_matrix == SolverDef::MassMatrix::planar;
  if (e.planar_mass) {
    build_planar_mass();
    build_planar_kinematics();
  }
}

namespace {

// The loads' torques and the impulses' forces of this time onto the tree's links.
void apply_loads_and_impulses(World::Impl& w) {
  MultibodyEngine& e = *w.mb;
  btMultiBody& t = *e.tree;
  for (std::size_t j = 0; j < w.joints.size(); ++j) {
    const JointRec& jr = w.joints[j];
    if (!jr.load) continue;
    const int link = e.link_of_body[static_cast<std::size_t>(jr.body)];
    t.addJointTorqueMultiDof(link, 0, load_torque_N_m(*jr.load, w.time, w.states[static_cast<std::size_t>(jr.body)].speed_rad_s));
  }
  for (const ImpulseDef& i : w.scenario.impulses) {
    const double share = impulse_shape(i, w.time);
    const int link = e.link_of_body[static_cast<std::size_t>(w.body_index.at(i.body))];
    if (share == 0 || link < 0) continue;
    t.addLinkForce(link, bt(i.force_N * share));
    t.addLinkTorque(link, bt(i.torque_N_m * share));
  }
}

// Bullet's position step of the tree (moved with e.v_mid where `mid`, else with its velocities),
// then the links' poses and velocities onto the rigid bodies, which measuring and rendering read.
void bullet_step_positions(World::Impl& w, double h, bool mid) {
  MultibodyEngine& e = *w.mb;
  btMultiBody& t = *e.tree;
  if (mid) {
    set_joint_velocities(t, e.v_mid);
    t.stepPositionsMultiDof(h);
    set_joint_velocities(t, e.v_end);
  } else {
    t.stepPositionsMultiDof(h);
  }
  t.clearForcesAndTorques();
  t.forwardKinematics(e.world_to_local, e.local_origin);
  t.compTreeLinkVelocities(e.omega.data(), e.vel.data());
  for (std::size_t i = 0; i < w.bodies.size(); ++i) {
    const int l = e.link_of_body[i];
    if (l < 0) continue;
    const btTransform& tl = t.getLink(l).m_cachedWorldTransform;
    btRigidBody& r = *w.bodies[i].rigid;
    r.setCenterOfMassTransform(tl);
    r.updateInertiaTensor();
    r.setAngularVelocity(tl.getBasis() * e.omega[static_cast<std::size_t>(l) + 1]);
    r.setLinearVelocity(tl.getBasis() * e.vel[static_cast<std::size_t>(l) + 1]);
  }
}

}  // namespace

// One step (or sub-step) of length h from the contacts generate_contacts() found at its start.
void World::Impl::advance_multibody(double h) {
  MultibodyEngine& e = *mb;
  btMultiBody& t = *e.tree;
  const bool two_step = e.bdf2 && e.has_history;
  e.h_step = h;
  e.h_eff = two_step ? 2 * h / 3 : h;
  apply_loads_and_impulses(*this);
  e.v_start.assign(t.getVelocityVector() + 6, t.getVelocityVector() + 6 + e.dofs);
  if (two_step) {  // BDF2 starts from v̂ = (4v − v_prev)/3
    for (int k = 0; k < e.dofs; ++k)
      e.v_mid[static_cast<std::size_t>(k)] = (4 * e.v_start[static_cast<std::size_t>(k)] - e.v_prev[static_cast<std::size_t>(k)]) / 3;
    set_joint_velocities(t, e.v_mid);
  }
  // Velocities after the external and gyroscopic forces alone: for a planar tree with the planar
  // mass matrix from it (which the rows then use), else by Bullet's articulated-body pass.
  if (e.planar_mass) planar_free_velocities(e.h_eff);
  else t.computeAccelerationsArticulatedBodyAlgorithmMultiDof(e.h_eff, e.scratch_r, e.scratch_v, e.scratch_m, false, false, false);
  if (e.planar_mass && e.check_mass) {  // check_planar_kinematics() steps Bullet from here
    e.check_q_start.clear();
    for (int l = 0; l < t.getNumLinks(); ++l)
      for (int k = 0; k < t.getLink(l).m_posVarCount; ++k) e.check_q_start.push_back(t.getJointPosMultiDof(l)[k]);
    e.check_h = h;
  }
  const std::uint64_t solve_start = clock.now();
  multibody_rows();
  solve_multibody_rows();
  row_solve_ticks += clock.now() - solve_start;
  // The positions move with v_move (BDF2), the θ-weighted mean of the start and end velocities,
  // or v⁺; the velocities stay v⁺. On the planar path by its own kinematics (which also set the
  // links' and bodies' poses and velocities), else by Bullet's.
  const double* v_end = t.getVelocityVector() + 6;
  const double* v_positions = v_end;
  if (e.bdf2) {
    // x⁺ = (4x − x_prev)/3 + h_eff·v⁺ = x + h·v_move, v_move = (v_move_prev + 2v⁺)/3.
    e.v_end.assign(v_end, v_end + e.dofs);
    for (int k = 0; k < e.dofs; ++k) {
      const std::size_t u = static_cast<std::size_t>(k);
      e.v_mid[u] = two_step ? (e.v_move[u] + 2 * e.v_end[u]) / 3 : e.v_end[u];
    }
    v_positions = e.v_mid.data();
    e.v_prev = e.v_start;
    e.v_move = e.v_mid;
    e.has_history = true;
  } else if (e.theta < 1) {
    e.v_end.assign(v_end, v_end + e.dofs);
    for (int k = 0; k < e.dofs; ++k)
      e.v_mid[static_cast<std::size_t>(k)] = (1 - e.theta) * e.v_start[static_cast<std::size_t>(k)] + e.theta * e.v_end[static_cast<std::size_t>(k)];
    v_positions = e.v_mid.data();
  }
  if (e.planar_mass) {
    if (e.check_mass) e.check_v_positions.assign(v_positions, v_positions + e.dofs);
    planar_step_positions(h, v_positions);
    t.clearForcesAndTorques();
    planar_finish_step();
  } else {
    bullet_step_positions(*this, h, v_positions != v_end);
  }
  time += h;
  measure_joints();
  multibody_results();
}

}  // namespace gearsim::physics

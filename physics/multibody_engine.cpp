#include <algorithm>
#include <cmath>
#include <limits>
#include <mutex>

#include "core/errors.hpp"
#include "physics/measure.hpp"
#include "physics/tooth_contacts.hpp"
#include "physics/multibody_engine.hpp"

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
//                            (verify.friction_model sliding, slip_friction.hpp), or sticking
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

void set_joint_velocities(btMultiBody& t, const double* v) {
  for (int l = 0; l < t.getNumLinks(); ++l) t.setJointVelMultiDof(l, v + t.getLink(l).m_dofOffset);
}

const char* const kWho = "scenario: solver.engine multibody: ";

// The joint each body turns in (−1: none). input/ has checked the tree (one joint per body, none
// turning a welded body, every other body in one, no shapes but teeth:
// require_multibody_tree in scenario_file.cpp).
std::vector<int> joints_of_bodies(const std::vector<BuiltBody>& bodies, const std::vector<ModelJoint>& joints) {
  std::vector<int> joint_of(bodies.size(), -1);
  for (std::size_t j = 0; j < joints.size(); ++j) {
    const std::size_t b = static_cast<std::size_t>(joints[j].body);
    GEARSIM_CHECK(joint_of[b] < 0 && !bodies[b].fixed, "body '" + bodies[b].name + "': one joint per body, none on a welded one");
    joint_of[b] = static_cast<int>(j);
  }
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    const BuiltBody& b = bodies[i];
    GEARSIM_CHECK(b.fixed || joint_of[i] >= 0, "body '" + b.name + "': every movable body turns in a joint");
    GEARSIM_CHECK(b.flanks || b.shape->getShapeType() == EMPTY_SHAPE_PROXYTYPE, "body '" + b.name + "': no shape but teeth");
  }
  return joint_of;
}

// The movable bodies as links, in an order where every parent comes before its children
// (link_of_body: each body's link, −1 for fixed ones); the joints form a tree (input/ checked).
std::vector<int> link_order(const std::vector<BuiltBody>& bodies, const std::vector<ModelJoint>& joints, const std::vector<int>& joint_of,
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
    GEARSIM_CHECK(bodies[i].fixed || link_of_body[i] >= 0, "body '" + bodies[i].name + "': the joints form a tree");
  return order;
}

}  // namespace

// The engine's integrator, row solver and friction as the scenario sets them, and whether every
// joint turns about z (the planar path).
void MultibodyEngine::set_options() {
  const Scenario& scenario = model_.scenario;
  integ_ = Integrator(scenario.solver, dofs_);
  onset_ = OnsetSplit(scenario.solver.locate_contact_onset && !integ_.bdf2());  // BDF2's history assumes equal steps
  active_ = ActiveSetSolve(scenario.solver.row_solver == SolverDef::RowSolver::active_set);
  slip_ = SlipFriction(scenario.contact.friction_model == ContactDef::FrictionModel::sliding);
  planar_ = true;
  for (const ModelJoint& jr : model_.joints) planar_ = planar_ && std::abs(std::abs(jr.axis_world.z()) - 1) < 1e-12;
}

MultibodyEngine::MultibodyEngine(const Model& model, State& state) : model_(model), state_(state) {
  build_tree();
  measure_joints();
}

void MultibodyEngine::build_tree() {
  const std::string who = kWho;
  const std::vector<int> joint_of = joints_of_bodies(model_.bodies, model_.joints);
  const std::vector<int> order = link_order(model_.bodies, model_.joints, joint_of, link_of_body_);

  tree_ = std::make_unique<btMultiBody>(static_cast<int>(order.size()), 0, btVector3(0, 0, 0), true, false);
  dof_of_joint_.assign(model_.joints.size(), -1);
  pivot_in_body_.assign(model_.joints.size(), btVector3(0, 0, 0));
  pivot_in_parent_.assign(model_.joints.size(), btVector3(0, 0, 0));
  motor_torque_.assign(model_.joints.size(), 0);
  for (std::size_t l = 0; l < order.size(); ++l) {
    const std::size_t i = static_cast<std::size_t>(order[l]);
    const BuiltBody& b = model_.bodies[i];
    const std::size_t j = static_cast<std::size_t>(joint_of[i]);
    const ModelJoint& jr = model_.joints[j];
    const bool on_body = jr.parent >= 0 && !model_.bodies[static_cast<std::size_t>(jr.parent)].fixed;
    const int parent_link = on_body ? link_of_body_[static_cast<std::size_t>(jr.parent)] : -1;
    // Link frames are the bodies' centre-of-mass principal frames at t = 0; the base is the world.
    const btTransform ti = b.rigid->getWorldTransform();
    const btTransform tp =
        on_body ? model_.bodies[static_cast<std::size_t>(jr.parent)].rigid->getWorldTransform() : btTransform::getIdentity();
    const btQuaternion parent_to_this = ti.getRotation().inverse() * tp.getRotation();
    const btVector3 inv = b.rigid->getInvInertiaDiagLocal();
    if (!(inv.x() > 0 && inv.y() > 0 && inv.z() > 0 && b.mass_kg > 0))
      throw InputError(who + "body '" + b.name + "' needs a positive mass and principal moments of inertia");
    const btVector3 inertia(1 / inv.x(), 1 / inv.y(), 1 / inv.z());
    const btVector3 pivot = bt(jr.def.pivot_m);
    const btVector3 axis_here = quatRotate(ti.getRotation().inverse(), bt(jr.axis_world));
    if (jr.def.bearing && !jr.def.bearing->radially_rigid)
      tree_->setupPlanar(static_cast<int>(l), b.mass_kg, inertia, parent_link, parent_to_this, axis_here, tp.invXform(ti.getOrigin()),
                         false);
    else
      tree_->setupRevolute(static_cast<int>(l), b.mass_kg, inertia, parent_link, parent_to_this, axis_here, tp.invXform(pivot),
                           quatRotate(ti.getRotation().inverse(), ti.getOrigin() - pivot), false);
    pivot_in_body_[j] = ti.invXform(pivot);
    pivot_in_parent_[j] = tp.invXform(pivot);
  }
  btMultiBody& t = *tree_;
  t.finalizeMultiDof();
  t.setLinearDamping(0);
  t.setAngularDamping(0);
  t.setMaxCoordinateVelocity(std::numeric_limits<double>::max());
  t.setCanSleep(false);
  t.setUseGyroTerm(true);
  t.setHasSelfCollision(false);
  for (std::size_t l = 0; l < order.size(); ++l)
    dof_of_joint_[static_cast<std::size_t>(joint_of[static_cast<std::size_t>(order[l])])] = t.getLink(static_cast<int>(l)).m_dofOffset;
  dofs_ = t.getNumDofs();
  rows_.dofs = static_cast<std::size_t>(dofs_);
  buf_.assign(static_cast<std::size_t>(6 + dofs_), 0);
  set_options();
  out_.assign(static_cast<std::size_t>(6 + dofs_), 0);
  scratch_.omega.assign(order.size() + 1, btVector3(0, 0, 0));
  scratch_.vel.assign(order.size() + 1, btVector3(0, 0, 0));
  rows_.inverse_mass.resize(dofs_, dofs_);
  // The tree at q = 0 reproduces the bodies' poses.
  t.forwardKinematics(scratch_.world_to_local, scratch_.local_origin);
  for (std::size_t l = 0; l < order.size(); ++l) {
    const btTransform& tl = t.getLink(static_cast<int>(l)).m_cachedWorldTransform;
    const btTransform& tb = model_.bodies[static_cast<std::size_t>(order[l])].rigid->getWorldTransform();
    GEARSIM_CHECK(
        (tl.getOrigin() - tb.getOrigin()).length() < 1e-12 && (tl.getBasis().getColumn(0) - tb.getBasis().getColumn(0)).length() < 1e-12,
        "a multibody link must start at its body's pose");
  }
  planar_mass_ = planar_ && model_.scenario.solver.mass_matrix == SolverDef::MassMatrix::planar;
  if (planar_mass_) {
    mass_.build(*tree_);  // before the kinematics rewrite the links' cached poses
    kin_.build(model_, *tree_, link_of_body_);
  }
}

// The loads' torques and the impulses' forces of this time onto the tree's links.
void MultibodyEngine::apply_loads_and_impulses() {
  btMultiBody& t = *tree_;
  for (std::size_t j = 0; j < model_.joints.size(); ++j) {
    const ModelJoint& jr = model_.joints[j];
    if (!jr.load) continue;
    const int link = link_of_body_[static_cast<std::size_t>(jr.body)];
    t.addJointTorqueMultiDof(link, 0, load_torque_N_m(*jr.load, state_.time, state_.bodies[static_cast<std::size_t>(jr.body)].speed_rad_s));
  }
  for (const ImpulseDef& i : model_.scenario.impulses) {
    const double share = impulse_shape(i, state_.time);
    const int link = link_of_body_[static_cast<std::size_t>(model_.body_index.at(i.body))];
    if (share == 0 || link < 0) continue;
    t.addLinkForce(link, bt(i.force_N * share));
    t.addLinkTorque(link, bt(i.torque_N_m * share));
  }
}

// Bullet's position step of the tree (moved with the integrator's v_mid where `mid`, else with its velocities),
// then the links' poses and velocities onto the rigid bodies, which measuring and rendering read.
void MultibodyEngine::bullet_step_positions(double h, bool mid) {
  btMultiBody& t = *tree_;
  if (mid) {
    set_joint_velocities(t, integ_.v_mid().data());
    t.stepPositionsMultiDof(h);
    set_joint_velocities(t, integ_.v_end().data());
  } else {
    t.stepPositionsMultiDof(h);
  }
  t.clearForcesAndTorques();
  t.forwardKinematics(scratch_.world_to_local, scratch_.local_origin);
  t.compTreeLinkVelocities(scratch_.omega.data(), scratch_.vel.data());
  for (std::size_t i = 0; i < model_.bodies.size(); ++i) {
    const int l = link_of_body_[i];
    if (l < 0) continue;
    const btTransform& tl = t.getLink(l).m_cachedWorldTransform;
    btRigidBody& r = *model_.bodies[i].rigid;
    r.setCenterOfMassTransform(tl);
    r.updateInertiaTensor();
    r.setAngularVelocity(tl.getBasis() * scratch_.omega[static_cast<std::size_t>(l) + 1]);
    r.setLinearVelocity(tl.getBasis() * scratch_.vel[static_cast<std::size_t>(l) + 1]);
  }
}

// One step (or sub-step) of length h from the contacts generate_contacts() found at its start.
void MultibodyEngine::advance(double h) {
  btMultiBody& t = *tree_;
  const double* v_hat = integ_.start(h, t.getVelocityVector() + 6);
  apply_loads_and_impulses();
  if (v_hat) set_joint_velocities(t, v_hat);  // BDF2 starts from v̂
  // Velocities after the external and gyroscopic forces alone: for a planar tree with the planar
  // mass matrix from it (which the rows then use), else by Bullet's articulated-body pass.
  const double h_eff = integ_.h_eff();
  if (planar_mass_)
    mass_.free_velocities(kin_, h_eff, buf_, scratch_, check_mass_ ? &mass_check_ : nullptr);
  else
    t.computeAccelerationsArticulatedBodyAlgorithmMultiDof(h_eff, scratch_.r, scratch_.v, scratch_.m, false, false, false);
  if (planar_mass_ && check_mass_) kin_.keep_step_start(h);  // the check steps Bullet from here
  const std::uint64_t solve_start = state_.clock.now();
  build_rows();
  solve_rows();
  state_.row_solve_ticks += state_.clock.now() - solve_start;
  // The positions move with the integrator's velocities (v⁺ itself for implicit Euler); the
  // velocities stay v⁺. On the planar path by its own kinematics (which also set the links' and
  // bodies' poses and velocities), else by Bullet's.
  const double* v_end = t.getVelocityVector() + 6;
  const double* v_positions = integ_.position_velocities(v_end);
  if (planar_mass_) {
    if (check_mass_) kin_.keep_position_velocities(v_positions);
    kin_.step_positions(h, v_positions);
    t.clearForcesAndTorques();
    kin_.finish_step(scratch_, check_mass_ ? &mass_check_ : nullptr);
  } else {
    bullet_step_positions(h, v_positions != v_end);
  }
  state_.time += h;
  measure_joints();
  results();
}

// One step: split where a near tooth pair touches (verify.locate_contact_onset), else whole.
void MultibodyEngine::step() {
  const double h = model_.scenario.solver.time_step_s;
  generate_contacts();
  double onset = onset_.on() ? onset_.onset_s(model_, state_, h) : h;
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
    onset_.accumulate(state_, motor_torque_, sub, split == 0);
    done += sub;
    if (!cut) break;  // the step's last piece
    ++state_.profile.onset_splits;
    generate_contacts();
    deepest = std::max(deepest, state_.max_penetration);
    onset = split + 1 < kMaxOnsetSplits ? onset_.onset_s(model_, state_, h - done) : h;
  }
  state_.max_penetration = deepest;
  state_.time = start + h;
  onset_.finish(state_, motor_torque_, h);
  ++state_.steps;
}

// This step's tooth contacts at the gears' poses: on the planar path from the links' turns, else
// from the bodies' transforms; the near pairs too where the step may split at an onset.
void MultibodyEngine::generate_contacts() {
  const std::uint64_t start = state_.clock.now();
  if (planar_mass_) {
    state_.gear_poses.resize(model_.bodies.size());
    for (std::size_t i = 0; i < model_.bodies.size(); ++i)
      if (model_.bodies[i].flanks) state_.gear_poses[i] = kin_.gear_pose(i);
  } else {
    gear_poses_from_bodies(model_, state_);
  }
  find_tooth_contacts(model_, state_, {0, onset_.on()});
  state_.tooth_contact_ticks += state_.clock.now() - start;
}

// Joint angles and speeds: on the planar path from the links' turns, else from the bodies.
void MultibodyEngine::measure_joints() {
  if (planar_mass_)
    kin_.measure_joints(state_);
  else
    measure_joints_from_bodies(model_, state_);
}

double MultibodyEngine::kinetic_energy_J() const {
  return planar_mass_ ? mass_.kinetic_energy_J(kin_) : kinetic_energy_of_bodies_J(model_);
}

}  // namespace gearsim::physics

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

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Bullet's Dantzig solver reports failure through one global flag (btDantzigLCP.cpp, s_error):
// worlds stepped in parallel threads (the Python module releases the GIL) take turns.

void set_joint_velocities(btMultiBody& t, const std::vector<double>& v) {
  for (int l = 0; l < t.getNumLinks(); ++l) t.setJointVelMultiDof(l, v.data() + t.getLink(l).m_dofOffset);
}

btVector3 unit_perpendicular(const btVector3& a) {
  const btVector3 t = std::abs(a.x()) < 0.9 ? btVector3(1, 0, 0) : btVector3(0, 1, 0);
  return (t - a * t.dot(a)).normalized();
}

}  // namespace

// Bullet's Dantzig solver reports failure through one global flag (btDantzigLCP.cpp, s_error):
// worlds stepped in parallel threads (the Python module releases the GIL) take turns.
std::mutex& dantzig_flag() {
  static std::mutex m;
  return m;
}

void World::Impl::build_multibody() {
  mb = std::make_unique<MultibodyEngine>();
  MultibodyEngine& e = *mb;
  const std::string who = "scenario: solver.engine multibody: ";
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
  // Links in an order where every parent comes before its children.
  e.link_of_body.assign(bodies.size(), -1);
  std::vector<int> order;
  for (bool grew = true; grew;) {
    grew = false;
    for (std::size_t i = 0; i < bodies.size(); ++i) {
      if (bodies[i].fixed || e.link_of_body[i] >= 0) continue;
      const int p = joints[static_cast<std::size_t>(joint_of[i])].parent;
      if (p >= 0 && !bodies[static_cast<std::size_t>(p)].fixed && e.link_of_body[static_cast<std::size_t>(p)] < 0) continue;
      e.link_of_body[i] = static_cast<int>(order.size());
      order.push_back(static_cast<int>(i));
      grew = true;
    }
  }
  for (std::size_t i = 0; i < bodies.size(); ++i)
    if (!bodies[i].fixed && e.link_of_body[i] < 0)
      throw InputError(who + "body '" + bodies[i].name + "' is in a loop of joints (the joints must form a tree)");

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
  e.bdf2 = scenario.solver.integrator == SolverDef::Integrator::bdf2;
  e.trapezoid_closed = scenario.solver.integrator == SolverDef::Integrator::trapezoid_closed;
  e.theta = e.bdf2 ? 1.0 : e.trapezoid_closed ? 0.5 : scenario.solver.theta;
  e.h_eff = e.h_step = scenario.solver.time_step_s;
  e.locate_onset = scenario.solver.locate_contact_onset && !e.bdf2;  // BDF2's history assumes equal steps
  e.active_set = scenario.solver.row_solver == SolverDef::RowSolver::active_set;
  e.sliding_friction = scenario.contact.friction_model == ContactDef::FrictionModel::sliding;
  e.planar = true;
  for (const JointRec& jr : joints) e.planar = e.planar && std::abs(std::abs(jr.axis_world.z()) - 1) < 1e-12;
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

// One step (or sub-step) of length h from the contacts generate_contacts() found at its start.
void World::Impl::advance_multibody(double h) {
  MultibodyEngine& e = *mb;
  btMultiBody& t = *e.tree;
  const bool two_step = e.bdf2 && e.has_history;
  e.h_step = h;
  e.h_eff = two_step ? 2 * h / 3 : h;
  for (std::size_t j = 0; j < joints.size(); ++j) {
    const JointRec& jr = joints[j];
    if (!jr.load) continue;
    const int link = e.link_of_body[static_cast<std::size_t>(jr.body)];
    t.addJointTorqueMultiDof(link, 0, load_torque_N_m(*jr.load, time, states[static_cast<std::size_t>(jr.body)].speed_rad_s));
  }
  for (const ImpulseDef& i : scenario.impulses) {
    const double share = impulse_shape(i, time);
    const int link = e.link_of_body[static_cast<std::size_t>(body_index.at(i.body))];
    if (share == 0 || link < 0) continue;
    t.addLinkForce(link, bt(i.force_N * share));
    t.addLinkTorque(link, bt(i.torque_N_m * share));
  }
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
    if (v_positions != v_end) {
      set_joint_velocities(t, e.v_mid);
      t.stepPositionsMultiDof(h);
      set_joint_velocities(t, e.v_end);
    } else {
      t.stepPositionsMultiDof(h);
    }
    t.clearForcesAndTorques();
    // The links' poses and velocities onto the rigid bodies, which measuring and rendering read.
    t.forwardKinematics(e.world_to_local, e.local_origin);
    t.compTreeLinkVelocities(e.omega.data(), e.vel.data());
    for (std::size_t i = 0; i < bodies.size(); ++i) {
      const int l = e.link_of_body[i];
      if (l < 0) continue;
      const btTransform& tl = t.getLink(l).m_cachedWorldTransform;
      btRigidBody& r = *bodies[i].rigid;
      r.setCenterOfMassTransform(tl);
      r.updateInertiaTensor();
      r.setAngularVelocity(tl.getBasis() * e.omega[static_cast<std::size_t>(l) + 1]);
      r.setLinearVelocity(tl.getBasis() * e.vel[static_cast<std::size_t>(l) + 1]);
    }
  }
  time += h;
  measure_joints();
  multibody_results();
}

// The rows of this step: their Jacobians (e.jrows), compliances, targets and bounds.
void World::Impl::multibody_rows() {
  MultibodyEngine& e = *mb;
  btMultiBody& t = *e.tree;
  const int dofs = e.dofs;
  e.rows.clear();
  if (e.trapezoid_closed) e.theta = trapezoid_closed_theta();
  contacts.clear();
  std::vector<double>& jrows = e.jrows;  // grown row by row
  jrows.clear();
  // A planar tree (every joint axis along z): each link's spin rate and centre velocity as rows
  // over the coordinates, once per step; a point's velocity along an in-plane direction is then
  // a combination of the three (v_p = v_c + ω × r), without walking the tree per row.
  const std::size_t links = static_cast<std::size_t>(t.getNumLinks()), ud = static_cast<std::size_t>(dofs);
  if (e.planar_mass) {
    // e.link_jac of this pose: planar_free_velocities() built it.
  } else if (e.planar) {
    e.link_jac.assign(links * 3 * ud, 0.0);
    // ω_z as the y velocity of a point 1 m along x from the centre less the centre's (Bullet's
    // angular Jacobian of a planar joint leaves out the spin: fillConstraintJacobianMultiDof).
    const btVector3 ex(1, 0, 0), ey(0, 1, 0);
    for (std::size_t l = 0; l < links; ++l) {
      const btVector3 centre = t.getLink(static_cast<int>(l)).m_cachedWorldTransform.getOrigin();
      const btVector3 points[3] = {centre + ex, centre, centre}, dirs[3] = {ey, ex, ey};
      for (std::size_t c = 0; c < 3; ++c) {
        t.fillContactJacobianMultiDof(static_cast<int>(l), points[c], dirs[c], e.buf.data(), e.scratch_r, e.scratch_v, e.scratch_m);
        std::copy(e.buf.begin() + 6, e.buf.end(), e.link_jac.begin() + static_cast<std::ptrdiff_t>((l * 3 + c) * ud));
      }
      double* jl = e.link_jac.data() + l * 3 * ud;
      for (std::size_t k = 0; k < ud; ++k) jl[k] -= jl[2 * ud + k];
    }
  }
  // J of the velocity of `point` (world) on the body of link `link`, along `dir`, added × sign.
  auto add_point = [&](std::size_t row, int link, const btVector3& point, const btVector3& dir, double sign) {
    if (link < 0) return;
    double* out = jrows.data() + row * ud;
    if (e.planar) {
      const btVector3 r = point - t.getLink(link).m_cachedWorldTransform.getOrigin();
      const double* jl = e.link_jac.data() + static_cast<std::size_t>(link) * 3 * ud;
      const double w = sign * (r.x() * dir.y() - r.y() * dir.x()), wx = sign * dir.x(), wy = sign * dir.y();
      if (e.planar_mass) {
        // Only the coordinates on the link's chain: planar_link_jacobians() leaves the others 0.
        for (const int d : e.link_dofs[static_cast<std::size_t>(link)]) {
          const std::size_t k = static_cast<std::size_t>(d);
          out[k] += w * jl[k] + wx * jl[ud + k] + wy * jl[2 * ud + k];
        }
        return;
      }
      for (std::size_t k = 0; k < ud; ++k) out[k] += w * jl[k] + wx * jl[ud + k] + wy * jl[2 * ud + k];
      return;
    }
    t.fillContactJacobianMultiDof(link, point, dir, e.buf.data(), e.scratch_r, e.scratch_v, e.scratch_m);
    for (std::size_t k = 0; k < ud; ++k) out[k] += sign * e.buf[6 + k];
  };
  auto new_row = [&](const MultibodyRow& r) {
    e.rows.push_back(r);
    jrows.resize(e.rows.size() * static_cast<std::size_t>(dofs), 0.0);
    return e.rows.size() - 1;
  };
  const double mu = scenario.contact.friction;
  for (std::size_t p = 0; p < pairs.size(); ++p) {
    const PairRec& pr = pairs[p];
    const BuiltBody &a = bodies[static_cast<std::size_t>(pr.a)], &b = bodies[static_cast<std::size_t>(pr.b)];
    const int la = mb->link_of_body[static_cast<std::size_t>(pr.a)], lb = mb->link_of_body[static_cast<std::size_t>(pr.b)];
    // The contact plane's height: a planar tree's rows use the points' x and y only.
    const double z = e.planar ? 0.0
                              : 0.5 * ((a.rigid->getWorldTransform() * a.com_from_gear).getOrigin().z() +
                                       (b.rigid->getWorldTransform() * b.com_from_gear).getOrigin().z());
    for (std::size_t i = 0; i < pr.found.size(); ++i) {
      if (!pr.active[i]) continue;
      const contact::ToothContact& c = pr.found[i];
      ContactSample cs;
      cs.pair = static_cast<int>(p);
      cs.geometry = c;
      cs.stiffness_N_per_m = pr.pair_stiffness[i];
      contacts.push_back(cs);
      const btVector3 n(c.normal_on_b.x(), c.normal_on_b.y(), 0);
      const btVector3 mid(c.point_m.x(), c.point_m.y(), z);
      const btVector3 on_b = mid + n * (0.5 * c.depth_m), on_a = mid - n * (0.5 * c.depth_m);
      const double k = cs.stiffness_N_per_m;
      MultibodyRow r = spring_row(k, contact_damping(pr, k), k * c.depth_m);
      r.kind = MultibodyRow::contact_normal;
      r.owner = static_cast<int>(contacts.size() - 1);
      r.lo = 0;
      r.hi = kInfinity;
      const std::size_t normal = new_row(r);
      add_point(normal, la, on_a, n, 1);
      add_point(normal, lb, on_b, n, -1);
      if (mu <= 0) continue;
      const btVector3 tangent(-n.y(), n.x(), 0);
      MultibodyRow f;
      f.kind = MultibodyRow::contact_friction;
      f.owner = r.owner;
      f.lo = -mu;
      f.hi = mu;
      f.friction_of = static_cast<int>(normal);
      const std::size_t fr = new_row(f);
      add_point(fr, la, on_a, tangent, 1);
      add_point(fr, lb, on_b, tangent, -1);
    }
  }
  for (std::size_t j = 0; j < joints.size(); ++j) {
    const JointRec& jr = joints[j];
    const int link = e.link_of_body[static_cast<std::size_t>(jr.body)];
    const int dof = e.dof_of_joint[j];
    if (jr.def.bearing) {
      const BearingDef& bd = *jr.def.bearing;
      const bool on_body = jr.parent >= 0 && e.link_of_body[static_cast<std::size_t>(jr.parent)] >= 0;
      const int parent_link = on_body ? e.link_of_body[static_cast<std::size_t>(jr.parent)] : -1;
      const btVector3 centre = bodies[static_cast<std::size_t>(jr.body)].rigid->getWorldTransform() * e.pivot_in_body[j];
      const btVector3 housing = on_body ? bodies[static_cast<std::size_t>(jr.parent)].rigid->getWorldTransform() * e.pivot_in_parent[j] : e.pivot_in_parent[j];
      const btVector3 axis = bt(jr.axis_world);
      const btVector3 e1 = unit_perpendicular(axis), e2 = axis.cross(e1);
      for (const btVector3& d : {e1, e2}) {
        if (!(bd.radial_stiffness_N_per_m > 0 || bd.radial_damping_N_s_per_m > 0)) break;
        MultibodyRow r = spring_row(bd.radial_stiffness_N_per_m, bd.radial_damping_N_s_per_m, -bd.radial_stiffness_N_per_m * (centre - housing).dot(d));
        r.kind = MultibodyRow::bearing;
        r.owner = static_cast<int>(j);
        r.lo = -kInfinity;
        r.hi = kInfinity;
        const std::size_t row = new_row(r);
        add_point(row, link, centre, d, 1);
        add_point(row, parent_link, housing, d, -1);
      }
      if (bd.torsional_stiffness_N_m_per_rad > 0 || bd.torsional_damping_N_m_s_per_rad > 0) {
        MultibodyRow r = spring_row(bd.torsional_stiffness_N_m_per_rad, bd.torsional_damping_N_m_s_per_rad,
                                    -bd.torsional_stiffness_N_m_per_rad * e.tree->getJointPosMultiDof(link)[0]);
        r.kind = MultibodyRow::torsion;
        r.owner = static_cast<int>(j);
        r.lo = -kInfinity;
        r.hi = kInfinity;
        jrows[new_row(r) * static_cast<std::size_t>(dofs) + static_cast<std::size_t>(dof)] = 1;
      }
    }
    if (jr.motor) {
      MultibodyRow r;
      r.kind = MultibodyRow::motor;
      r.owner = static_cast<int>(j);
      r.target = motor_target_rad_s(*jr.motor, time + e.h_step);  // the speed at the (sub)step's end
      r.lo = -jr.motor->max_torque_N_m * e.h_eff;  // impulses are force × h_eff
      r.hi = jr.motor->max_torque_N_m * e.h_eff;
      jrows[new_row(r) * static_cast<std::size_t>(dofs) + static_cast<std::size_t>(dof)] = 1;
    }
  }
  if (!e.planar_mass)  // the articulated path's products with M⁻¹ (solve_multibody_rows)
    e.jac = Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(jrows.data(), static_cast<Eigen::Index>(e.rows.size()), dofs);
}

// Forces, motor torques and power flows of the step just taken (velocities after it).
void World::Impl::multibody_results() {
  MultibodyEngine& e = *mb;
  const double h = e.h_step;
  // Work of a row over the step: its force times its travel, h·J·v_θ (positions moved with v_θ).
  const Eigen::Map<const Eigen::VectorXd> v_end(e.tree->getVelocityVector() + 6, e.dofs), v_start(e.v_start.data(), e.dofs);
  if (e.bdf2) e.v_theta = Eigen::Map<const Eigen::VectorXd>(e.v_move.data(), e.dofs);  // BDF2: positions moved with v_move
  else e.v_theta.noalias() = (1 - e.theta) * v_start + e.theta * v_end;
  const Eigen::VectorXd& v = e.v_theta;
  PowerFlows pw;
  std::fill(e.motor_torque_N_m.begin(), e.motor_torque_N_m.end(), 0.0);
  for (std::size_t r = 0; r < e.rows.size(); ++r) {
    const MultibodyRow& row = e.rows[r];
    const double force = e.x[r] / e.h_eff, rate = e.row_dot(r, v.data());
    switch (row.kind) {
      case MultibodyRow::contact_normal:
        contacts[static_cast<std::size_t>(row.owner)].normal_force_N = force;
        pw.contact_W += force * rate;
        break;
      case MultibodyRow::contact_friction:
        contacts[static_cast<std::size_t>(row.owner)].friction_force_N = std::abs(force);
        pw.contact_W += force * rate;
        break;
      case MultibodyRow::bearing:
      case MultibodyRow::torsion:
        pw.joint_W += force * rate;
        break;
      case MultibodyRow::motor:
        e.motor_torque_N_m[static_cast<std::size_t>(row.owner)] = force;
        pw.motor_W += force * rate;
        break;
    }
  }
  for (const JointRec& j : joints)
    if (j.load) {
      const double speed = states[static_cast<std::size_t>(j.body)].speed_rad_s;
      pw.load_W += load_torque_N_m(*j.load, time - h, speed) * speed;
    }
  pw.kinetic_J = kinetic_energy_J();
  pw.impulse_W = impulse_power_W(h);
  power = pw;
}

}  // namespace gearsim::physics

#include "physics/planar_kinematics.hpp"

#include <algorithm>
#include <cmath>

#include "core/errors.hpp"
#include "physics/measure.hpp"

// verify.mass_matrix planar (docs/solver.md, "The planar kinematics"): on a tree whose joints all
// turn about z, each step's positions, the links' poses and velocities and the bodies' states
// from the joint coordinates in closed form — every link's turn is the sum of the angles on its
// chain, one sine and cosine per link — in place of Bullet's stepPositionsMultiDof(),
// forwardKinematics() and compTreeLinkVelocities() and of measuring the bodies' transforms back
// by atan2. Bullet still holds the coordinates (its joint positions and velocities, in its own
// conventions) and the tree; World::set_mass_matrix_check runs its three passes from the same
// coordinates at every step and compares (check()).
namespace gearsim::physics {
namespace {

// Turns v (world) about z by the angle whose cosine and sine are c and s.
btVector3 turn_z(const btVector3& v, double c, double s) { return {c * v.x() - s * v.y(), s * v.x() + c * v.y(), v.z()}; }

}  // namespace

// Per link: its parent, the sign of its joint's turn about world z, and its joint's vectors at
// q = 0 in world terms (the tree's pose then is the bodies' start poses: MultibodyEngine::build_tree()).
// In Bullet's conventions (btMultibodyLink::updateCacheMultiDof, btMultiBody::forwardKinematics)
// a link l below parent p turns as R_l = R_p·Z⁻¹·Rot(a, q), Z its zero rotation from the parent
// and a its axis in its own frame; with R_l0 = R_p0·Z⁻¹ at q = 0 and R_l0·a = σ·ẑ that is
// R_l = Rz(φ_p + σ·q)·R_l0 — the link's turn φ_l = φ_p + σ·q. Its centre:
//   revolute  c_l = c_p + R_p·e + R_l·d   (e: parent's centre to the pivot, parent frame; d: pivot to
//                                          the centre, own frame)
//   planar    c_l = c_p + R_p·Z⁻¹·(q₁·b₁ + q₂·b₂) + R_p·e   (b₁, b₂ its two translation axes)
// so with E = R_p0·e, D = R_l0·d, B_i = R_l0·b_i (world, at q = 0):
//   revolute  c_l = c_p + Rz(φ_p)·E + Rz(φ_l)·D,   planar  c_l = c_p + Rz(φ_p)·(q₁·B₁ + q₂·B₂ + E).
void PlanarKinematics::build(const Model& model, btMultiBody& tree, const std::vector<int>& link_of_body) {
  model_ = &model;
  tree_ = &tree;
  link_of_body_ = link_of_body;
  dofs_ = static_cast<std::size_t>(tree.getNumDofs());
  const btMultiBody& t = tree;
  const std::size_t links = static_cast<std::size_t>(t.getNumLinks());
  // Per link its chain to the ground and the coordinates that move it.
  link_chain_.assign(links, {});
  link_dofs_.assign(links, {});
  for (std::size_t l = 0; l < links; ++l)
    for (int i = static_cast<int>(l); i >= 0; i = t.getParent(i)) {
      link_chain_[l].push_back(i);
      for (int d = 0; d < t.getLink(i).m_dofCount; ++d) link_dofs_[l].push_back(t.getLink(i).m_dofOffset + d);
    }
  build_links();
  link_phi_.assign(links, 0.0);
  link_cos_.assign(links, 1.0);
  link_sin_.assign(links, 0.0);
  std::vector<btTransform> bullet(links);
  for (std::size_t l = 0; l < links; ++l) bullet[l] = t.getLink(static_cast<int>(l)).m_cachedWorldTransform;
  forward_kinematics();
  link_velocities(t.getVelocityVector() + 6);  // at rest: the tree starts with q̇ = 0
  // The closed form reproduces Bullet's start pose (its forward kinematics at q = 0).
  for (std::size_t l = 0; l < links; ++l) {
    const btTransform& tl = t.getLink(static_cast<int>(l)).m_cachedWorldTransform;
    GEARSIM_CHECK((tl.getOrigin() - bullet[l].getOrigin()).length() < 1e-12 &&
                      (tl.getBasis().getColumn(0) - bullet[l].getBasis().getColumn(0)).length() < 1e-12,
                  "the planar kinematics must start at Bullet's pose");
  }
  build_gears();
}

// Per link its parent, the sign of its joint's turn and its joint's vectors at q = 0 (world).
void PlanarKinematics::build_links() {
  const btMultiBody& t = *tree_;
  const std::size_t links = static_cast<std::size_t>(t.getNumLinks());
  links_.assign(links, {});
  for (std::size_t l = 0; l < links; ++l) {
    const btMultibodyLink& link = t.getLink(static_cast<int>(l));
    Link& p = links_[l];
    p.parent = link.m_parent;
    GEARSIM_CHECK(p.parent < static_cast<int>(l), "a multibody link's parent must come before it");
    GEARSIM_CHECK(link.m_jointType == btMultibodyLink::eRevolute || link.m_jointType == btMultibodyLink::ePlanar,
                  "the planar kinematics know revolute and planar joints only");
    p.planar_joint = link.m_jointType == btMultibodyLink::ePlanar;
    p.basis0 = link.m_cachedWorldTransform.getBasis();
    const btMatrix3x3 parent_basis0 = p.parent >= 0 ? t.getLink(p.parent).m_cachedWorldTransform.getBasis() : btMatrix3x3::getIdentity();
    const double z = (p.basis0 * link.getAxisTop(0)).z();
    GEARSIM_CHECK(std::abs(std::abs(z) - 1) < 1e-12, "a planar tree's joint axes must lie along z");
    p.sigma = z > 0 ? 1.0 : -1.0;
    p.e0 = parent_basis0 * link.m_eVector;
    p.d0 = p.basis0 * link.m_dVector;
    if (p.planar_joint) {
      p.b1 = p.basis0 * link.getAxisBottom(1);
      p.b2 = p.basis0 * link.getAxisBottom(2);
      // Bullet's planar position step projects the turned velocity on b₁ and b₂, which are
      // orthogonal, both ⟂ a and of the same length (b₂ = b₁ × a): their length squared scales it.
      p.axis_length2 = link.getAxisBottom(1).length2();
    }
  }
}

// Per joint its angle at q = 0; per gear its frame's x axis in the plane at q = 0 (unit) and
// that axis' angle; the fixed gears' poses once.
void PlanarKinematics::build_gears() {
  const Model& model = *model_;
  angle_at_zero_.resize(model.joints.size());
  for (std::size_t k = 0; k < model.joints.size(); ++k) angle_at_zero_[k] = joint_raw_angle(model, model.joints[k]);
  gear_x0_.assign(model.bodies.size(), {1.0, 0.0});
  gear_angle0_.assign(model.bodies.size(), 0.0);
  fixed_pose_.assign(model.bodies.size(), {});
  for (std::size_t i = 0; i < model.bodies.size(); ++i) {
    const BuiltBody& b = model.bodies[i];
    if (!b.flanks) continue;
    const contact::PlanarPose p = planar_pose(b);
    if (link_of_body_[i] < 0) {
      fixed_pose_[i] = p;
      continue;
    }
    gear_x0_[i] = {p.cos_angle, p.sin_angle};
    gear_angle0_[i] = p.angle_rad;
  }
}

// Joint positions q⁺ = q + h·v as Bullet's stepPositionsMultiDof() takes them: a revolute joint's
// angle by h·v; a planar joint's angle likewise, its translations by its in-plane velocity (along
// b₁, b₂ in its turned frame) turned by the new angle about its axis — Rot(a, q₀)·(v₁·b₁ + v₂·b₂) =
// (c·v₁ + s·v₂)·b₁ + (c·v₂ − s·v₁)·b₂ — and projected on b₁ and b₂ again. v: one entry per
// coordinate. Then the poses (forward_kinematics()).
void PlanarKinematics::step_positions(double h, const double* v) {
  btMultiBody& t = *tree_;
  for (std::size_t l = 0; l < links_.size(); ++l) {
    const Link& p = links_[l];
    btScalar* q = t.getJointPosMultiDof(static_cast<int>(l));
    const double* u = v + t.getLink(static_cast<int>(l)).m_dofOffset;
    q[0] += h * u[0];
    if (!p.planar_joint) continue;
    const double c = std::cos(q[0]), s = std::sin(q[0]), scale = h * p.axis_length2;
    q[1] += scale * (c * u[1] + s * u[2]);
    q[2] += scale * (c * u[2] - s * u[1]);
  }
  forward_kinematics();
}

// Each link's turn φ (its cosine and sine) and world transform from the joint positions (the
// closed form of build()), into Bullet's link cache (which the rows and the
// link Jacobians read) and the bodies' transforms. The links' Jacobians at this pose follow
// (link_jacobians(); the next step's PlanarMass::free_velocities() and rows take them as they are).
void PlanarKinematics::forward_kinematics() {
  const Model& model = *model_;
  btMultiBody& t = *tree_;
  for (std::size_t l = 0; l < links_.size(); ++l) {
    const Link& p = links_[l];
    const btScalar* q = t.getJointPosMultiDof(static_cast<int>(l));
    const bool grounded = p.parent < 0;
    const std::size_t up = grounded ? 0 : static_cast<std::size_t>(p.parent);
    const double phi_p = grounded ? 0.0 : link_phi_[up], cp = grounded ? 1.0 : link_cos_[up], sp = grounded ? 0.0 : link_sin_[up];
    const btVector3 origin_p = grounded ? btVector3(0, 0, 0) : t.getLink(p.parent).m_cachedWorldTransform.getOrigin();
    const double phi = phi_p + p.sigma * q[0], c = std::cos(phi), s = std::sin(phi);
    link_phi_[l] = phi, link_cos_[l] = c, link_sin_[l] = s;
    btTransform& tl = t.getLink(static_cast<int>(l)).m_cachedWorldTransform;
    const btMatrix3x3& b0 = p.basis0;
    tl.getBasis().setValue(c * b0[0][0] - s * b0[1][0], c * b0[0][1] - s * b0[1][1], c * b0[0][2] - s * b0[1][2],
                           s * b0[0][0] + c * b0[1][0], s * b0[0][1] + c * b0[1][1], s * b0[0][2] + c * b0[1][2], b0[2][0], b0[2][1],
                           b0[2][2]);
    tl.setOrigin(p.planar_joint ? origin_p + turn_z(q[1] * p.b1 + q[2] * p.b2 + p.e0, cp, sp)
                                : origin_p + turn_z(p.e0, cp, sp) + turn_z(p.d0, c, s));
  }
  for (std::size_t i = 0; i < model.bodies.size(); ++i) {
    const int l = link_of_body_[i];
    if (l >= 0) model.bodies[i].rigid->setWorldTransform(t.getLink(l).m_cachedWorldTransform);
  }
  link_jacobians();
}

// link_jac() (rows ω_z, v_x, v_y of each link's centre over the coordinates) at this step's pose.
// Each coordinate d of a link i on the chain from the ground to link l turns l's centre c_l about
// i's centre c_i with rate s_d (its axis' z component, world) and moves it by b_d (its axis'
// linear part, world): ω_l = Σ s_d·q̇_d, v_l = Σ (s_d·ẑ × (c_l − c_i) + b_d)·q̇_d — Bullet's own
// joint axes (btMultibodyLink::getAxisTop/Bottom, in i's frame) and convention
// (fillConstraintJacobianMultiDof, compTreeLinkVelocities), without walking the tree per row.
// s_d and b_d are kept per coordinate (PlanarMass::free_velocities() differentiates them).
void PlanarKinematics::link_jacobians() {
  const btMultiBody& t = *tree_;
  const std::size_t links = static_cast<std::size_t>(t.getNumLinks()), ud = dofs_;
  dof_s_.resize(ud);
  dof_bx_.resize(ud);
  dof_by_.resize(ud);
  dof_link_.resize(ud);
  for (std::size_t i = 0; i < links; ++i) {
    const btMultibodyLink& li = t.getLink(static_cast<int>(i));
    const btMatrix3x3& basis = li.m_cachedWorldTransform.getBasis();
    for (int k = 0; k < li.m_dofCount; ++k) {
      const std::size_t dof = static_cast<std::size_t>(li.m_dofOffset + k);
      const btVector3 b_d = basis * li.getAxisBottom(k);
      dof_s_[dof] = basis.getRow(2).dot(li.getAxisTop(k));
      dof_bx_[dof] = b_d.x();
      dof_by_[dof] = b_d.y();
      dof_link_[dof] = static_cast<int>(i);
    }
  }
  link_jac_.assign(links * 3 * ud, 0.0);
  for (std::size_t l = 0; l < links; ++l) {
    double* jl = link_jac_.data() + l * 3 * ud;
    const btVector3 c_l = t.getLink(static_cast<int>(l)).m_cachedWorldTransform.getOrigin();
    for (const int i : link_chain_[l]) {
      const btMultibodyLink& li = t.getLink(i);
      const btVector3 d = c_l - li.m_cachedWorldTransform.getOrigin();
      for (int k = 0; k < li.m_dofCount; ++k) {
        const std::size_t dof = static_cast<std::size_t>(li.m_dofOffset + k);
        const double s_d = dof_s_[dof];
        jl[dof] = s_d;
        jl[ud + dof] = dof_bx_[dof] - s_d * d.y();
        jl[2 * ud + dof] = dof_by_[dof] + s_d * d.x();
      }
    }
  }
}

// Each link's spin rate and centre velocity (world) from the coordinates' velocities u through
// this pose's link Jacobians.
void PlanarKinematics::link_velocities(const double* u) {
  const std::size_t links = links_.size(), ud = dofs_;
  link_w_.resize(links);
  link_vx_.resize(links);
  link_vy_.resize(links);
  for (std::size_t l = 0; l < links; ++l) {
    const double* jw = link_jac_.data() + l * 3 * ud;
    const double *jx = jw + ud, *jy = jw + 2 * ud;
    double w = 0, vx = 0, vy = 0;
    for (const int d : link_dofs_[l]) {
      const std::size_t k = static_cast<std::size_t>(d);
      w += jw[k] * u[k], vx += jx[k] * u[k], vy += jy[k] * u[k];
    }
    link_w_[l] = w, link_vx_[l] = vx, link_vy_[l] = vy;
  }
}

// The end of a step on the planar path: the links' velocities at the new pose onto the bodies,
// then (World::set_mass_matrix_check) Bullet's own passes from the same coordinates compared.
void PlanarKinematics::finish_step(BulletScratch& scratch, World::MassMatrixCheck* check_into) {
  const Model& model = *model_;
  link_velocities(tree_->getVelocityVector() + 6);
  for (std::size_t i = 0; i < model.bodies.size(); ++i) {
    const int l = link_of_body_[i];
    if (l < 0) continue;
    const std::size_t u = static_cast<std::size_t>(l);
    btRigidBody& r = *model.bodies[i].rigid;
    r.setAngularVelocity(btVector3(0, 0, link_w_[u]));
    r.setLinearVelocity(btVector3(link_vx_[u], link_vy_[u], 0));
  }
  if (check_into) check(scratch, *check_into);
}

// World::set_mass_matrix_check: the step's start coordinates and length (before its rows).
void PlanarKinematics::keep_step_start(double h) {
  btMultiBody& t = *tree_;
  check_q_start_.clear();
  for (int l = 0; l < t.getNumLinks(); ++l)
    for (int k = 0; k < t.getLink(l).m_posVarCount; ++k) check_q_start_.push_back(t.getJointPosMultiDof(l)[k]);
  check_h_ = h;
}

void PlanarKinematics::keep_position_velocities(const double* v) { check_v_positions_.assign(v, v + dofs_); }

// Joint angles and speeds from the links' turns and spin rates: a joint's angle about its axis is
// its angle at q = 0 plus the turn of its body less its parent's (a fixed parent or the ground does
// not turn), seen along the axis.
void PlanarKinematics::measure_joints(State& state) const {
  const Model& model = *model_;
  for (std::size_t k = 0; k < model.joints.size(); ++k) {
    const ModelJoint& j = model.joints[k];
    const std::size_t l = static_cast<std::size_t>(link_of_body_[static_cast<std::size_t>(j.body)]);
    const int p = j.parent >= 0 ? link_of_body_[static_cast<std::size_t>(j.parent)] : -1;
    const double phi_p = p >= 0 ? link_phi_[static_cast<std::size_t>(p)] : 0.0, w_p = p >= 0 ? link_w_[static_cast<std::size_t>(p)] : 0.0;
    const double az = j.axis_world.z();
    BodyState& s = state.bodies[static_cast<std::size_t>(j.body)];
    s.angle_rad = angle_at_zero_[k] + (az > 0 ? 1.0 : -1.0) * (link_phi_[l] - phi_p);
    s.speed_rad_s = (link_w_[l] - w_p) * az;
  }
  for (std::size_t i = 0; i < model.bodies.size(); ++i)
    state.bodies[i].position_m = eig(model.bodies[i].rigid->getWorldTransform() * model.bodies[i].com_from_gear.getOrigin());
}

// A gear's planar pose from its link's turn: its frame's x axis at q = 0 turned by φ (cosine and
// sine without a libm call), its angle that axis' angle at q = 0 plus φ — not wrapped to a turn
// (the contact search takes differences of angles and windows modulo the teeth).
contact::PlanarPose PlanarKinematics::gear_pose(std::size_t body) const {
  const Model& model = *model_;
  const int l = link_of_body_[body];
  if (l < 0) return fixed_pose_[body];
  const std::size_t u = static_cast<std::size_t>(l);
  const BuiltBody& b = model.bodies[body];
  const btVector3 o = b.rigid->getWorldTransform() * b.com_from_gear.getOrigin();
  const double c = link_cos_[u], s = link_sin_[u];
  const Eigen::Vector2d& x0 = gear_x0_[body];
  contact::PlanarPose p{{o.x(), o.y()}, gear_angle0_[body] + link_phi_[u]};
  p.cos_angle = c * x0.x() - s * x0.y();
  p.sin_angle = s * x0.x() + c * x0.y();
  p.rotation_of_rad = p.angle_rad;
  return p;
}

// World::set_mass_matrix_check: Bullet's position step from the step's start coordinates (kept
// by keep_step_start() in check_q_start_) and the velocities the positions moved with, its link
// caches, forward kinematics and link velocities from this step's coordinates, against the planar
// path's: the largest coordinate difference, link centre distance (m), basis difference and
// velocity difference (rad/s, m/s) over the steps. Bullet's caches are left as its passes made
// them (its articulated-body pass, which the check also runs, reads them); the links' transforms
// as the planar path made them.
void PlanarKinematics::check(BulletScratch& scratch, World::MassMatrixCheck& c) {
  btMultiBody& t = *tree_;
  const int links = t.getNumLinks();
  const std::size_t ud = dofs_;
  // Bullet's position step on copies: base (quaternion, position) then the links' coordinates.
  std::vector<double> pq(7 + ud, 0.0), pqd(6 + ud, 0.0);
  pq[3] = 1;
  std::copy(check_q_start_.begin(), check_q_start_.end(), pq.begin() + 7);
  std::copy(check_v_positions_.begin(), check_v_positions_.end(), pqd.begin() + 6);
  // (Its planar joints' case reads the tree's own velocities, not pqd: they are set to the same.)
  const std::vector<double> v_end(t.getVelocityVector() + 6, t.getVelocityVector() + 6 + static_cast<std::ptrdiff_t>(dofs_));
  for (int l = 0; l < links; ++l) t.setJointVelMultiDof(l, check_v_positions_.data() + t.getLink(l).m_dofOffset);
  t.stepPositionsMultiDof(check_h_, pq.data(), pqd.data());
  for (int l = 0; l < links; ++l) t.setJointVelMultiDof(l, v_end.data() + t.getLink(l).m_dofOffset);
  double dq = 0;
  for (int l = 0; l < links; ++l) {
    const btMultibodyLink& link = t.getLink(l);
    for (int k = 0; k < link.m_posVarCount; ++k)
      dq = std::max(dq, std::abs(pq[7 + static_cast<std::size_t>(link.m_dofOffset + k)] - t.getJointPosMultiDof(l)[k]));
  }
  std::vector<btTransform> ours(static_cast<std::size_t>(links));
  for (int l = 0; l < links; ++l) {
    ours[static_cast<std::size_t>(l)] = t.getLink(l).m_cachedWorldTransform;
    t.getLink(l).updateCacheMultiDof();
  }
  t.forwardKinematics(scratch.world_to_local, scratch.local_origin);
  t.compTreeLinkVelocities(scratch.omega.data(), scratch.vel.data());
  double dc = 0, db = 0, dv = 0;
  for (int l = 0; l < links; ++l) {
    const std::size_t u = static_cast<std::size_t>(l);
    const btTransform& tb = t.getLink(l).m_cachedWorldTransform;
    dc = std::max(dc, (tb.getOrigin() - ours[u].getOrigin()).length());
    for (int r = 0; r < 3; ++r) db = std::max(db, (tb.getBasis()[r] - ours[u].getBasis()[r]).length());
    const btVector3 w = tb.getBasis() * scratch.omega[u + 1], v = tb.getBasis() * scratch.vel[u + 1];
    dv = std::max({dv, (w - btVector3(0, 0, link_w_[u])).length(), (v - btVector3(link_vx_[u], link_vy_[u], 0)).length()});
    t.getLink(l).m_cachedWorldTransform = ours[u];
  }
  ++c.kinematics_steps;
  c.coordinate_difference = std::max(c.coordinate_difference, dq);
  c.centre_difference_m = std::max(c.centre_difference_m, dc);
  c.basis_difference = std::max(c.basis_difference, db);
  c.link_velocity_difference = std::max(c.link_velocity_difference, dv);
}

}  // namespace gearsim::physics

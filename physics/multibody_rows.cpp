#include <algorithm>
#include <cmath>
#include <limits>

#include "physics/multibody_engine.hpp"
#include "physics/measure.hpp"

// The rows of the `multibody` engine's step (multibody_engine.cpp steps the tree): one per tooth
// contact's normal and friction, bearing direction, torsional support and motor, each with its
// Jacobian over the tree's coordinates, compliance, target and bounds; and what the solved rows
// did (forces, motor torques, power flows).
namespace gearsim::physics {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

btVector3 unit_perpendicular(const btVector3& a) {
  const btVector3 t = std::abs(a.x()) < 0.9 ? btVector3(1, 0, 0) : btVector3(0, 1, 0);
  return (t - a * t.dot(a)).normalized();
}

// A planar tree without the planar mass matrix: each link's spin rate and centre velocity as rows
// over the coordinates (link_jac_), from Bullet's Jacobians of this pose.
}  // namespace

void MultibodyEngine::bullet_link_jacobians() {
  btMultiBody& t = *tree_;
  const std::size_t links = static_cast<std::size_t>(t.getNumLinks()), ud = static_cast<std::size_t>(dofs_);
  link_jac_.assign(links * 3 * ud, 0.0);
  // ω_z as the y velocity of a point 1 m along x from the centre less the centre's (Bullet's
  // angular Jacobian of a planar joint leaves out the spin: fillConstraintJacobianMultiDof).
  const btVector3 ex(1, 0, 0), ey(0, 1, 0);
  for (std::size_t l = 0; l < links; ++l) {
    const btVector3 centre = t.getLink(static_cast<int>(l)).m_cachedWorldTransform.getOrigin();
    const btVector3 points[3] = {centre + ex, centre, centre}, dirs[3] = {ey, ex, ey};
    for (std::size_t c = 0; c < 3; ++c) {
      t.fillContactJacobianMultiDof(static_cast<int>(l), points[c], dirs[c], buf_.data(), scratch_.r, scratch_.v, scratch_.m);
      std::copy(buf_.begin() + 6, buf_.end(), link_jac_.begin() + static_cast<std::ptrdiff_t>((l * 3 + c) * ud));
    }
    double* jl = link_jac_.data() + l * 3 * ud;
    for (std::size_t k = 0; k < ud; ++k) jl[k] -= jl[2 * ud + k];
  }
}

namespace {

// Appends rows to rows.rows with their Jacobians in rows.jrows (grown row by row).
struct RowBuilder {
  RowSystem& rows;
  btMultiBody& tree;
  std::vector<double>& buf;  // the tree's 6 + dofs scratch
  BulletScratch& scratch;
  bool planar;  // a planar tree: rows from link_jac
  const PlanarKinematics* kin;  // the planar kinematics' links (verify.mass_matrix planar), else nullptr
  const double* link_jac;  // per link: rows ω_z, v_x, v_y over the coordinates (planar trees)
  std::size_t ud;
  // J of the velocity of `point` (world) on the body of link `link`, along `dir`, added × sign.
  void add_point(std::size_t row, int link, const btVector3& point, const btVector3& dir, double sign) {
    if (link < 0) return;
    btMultiBody& t = tree;
    double* out = rows.jrows.data() + row * ud;
    if (planar) {
      const btVector3 r = point - t.getLink(link).m_cachedWorldTransform.getOrigin();
      const double* jl = link_jac + static_cast<std::size_t>(link) * 3 * ud;
      const double w = sign * (r.x() * dir.y() - r.y() * dir.x()), wx = sign * dir.x(), wy = sign * dir.y();
      if (kin) {
        // Only the coordinates on the link's chain: PlanarKinematics::link_jacobians() leaves the others 0.
        for (const int d : kin->link_dofs(static_cast<std::size_t>(link))) {
          const std::size_t k = static_cast<std::size_t>(d);
          out[k] += w * jl[k] + wx * jl[ud + k] + wy * jl[2 * ud + k];
        }
        return;
      }
      for (std::size_t k = 0; k < ud; ++k) out[k] += w * jl[k] + wx * jl[ud + k] + wy * jl[2 * ud + k];
      return;
    }
    t.fillContactJacobianMultiDof(link, point, dir, buf.data(), scratch.r, scratch.v, scratch.m);
    for (std::size_t k = 0; k < ud; ++k) out[k] += sign * buf[6 + k];
  }
  std::size_t new_row(const MultibodyRow& r) {
    rows.rows.push_back(r);
    rows.jrows.resize(rows.rows.size() * ud, 0.0);
    return rows.rows.size() - 1;
  }
};

// A row per kept tooth contact's normal (a unilateral spring) and, with friction, one along its
// tangent; each contact also recorded in state.contacts.
void contact_rows(RowBuilder& rb, const Model& model, State& state, const std::vector<int>& link_of_body, const Integrator& integ) {
  const double mu = model.scenario.contact.friction;
  for (std::size_t p = 0; p < model.pairs.size(); ++p) {
    const ModelPair& pr = model.pairs[p];
    const PairContacts& pc = state.pairs[p];
    const BuiltBody &a = model.bodies[static_cast<std::size_t>(pr.a)], &b = model.bodies[static_cast<std::size_t>(pr.b)];
    const int la = link_of_body[static_cast<std::size_t>(pr.a)], lb = link_of_body[static_cast<std::size_t>(pr.b)];
    // The contact plane's height: a planar tree's rows use the points' x and y only.
    const double z = rb.planar ? 0.0
                               : 0.5 * ((a.rigid->getWorldTransform() * a.com_from_gear).getOrigin().z() +
                                        (b.rigid->getWorldTransform() * b.com_from_gear).getOrigin().z());
    for (std::size_t i = 0; i < pc.found.size(); ++i) {
      if (!pc.active[i]) continue;
      const contact::ToothContact& c = pc.found[i];
      ContactSample cs;
      cs.pair = static_cast<int>(p);
      cs.geometry = c;
      cs.stiffness_N_per_m = pc.pair_stiffness[i];
      state.contacts.push_back(cs);
      const btVector3 n(c.normal_on_b.x(), c.normal_on_b.y(), 0);
      const btVector3 mid(c.point_m.x(), c.point_m.y(), z);
      const btVector3 on_b = mid + n * (0.5 * c.depth_m), on_a = mid - n * (0.5 * c.depth_m);
      const double k = cs.stiffness_N_per_m;
      MultibodyRow r = integ.spring_row(k, contact_damping(model, pr, k), k * c.depth_m);
      r.kind = MultibodyRow::contact_normal;
      r.owner = static_cast<int>(state.contacts.size() - 1);
      r.lo = 0;
      r.hi = kInfinity;
      const std::size_t normal = rb.new_row(r);
      rb.add_point(normal, la, on_a, n, 1);
      rb.add_point(normal, lb, on_b, n, -1);
      if (mu <= 0) continue;
      const btVector3 tangent(-n.y(), n.x(), 0);
      MultibodyRow f;
      f.kind = MultibodyRow::contact_friction;
      f.owner = r.owner;
      f.lo = -mu;
      f.hi = mu;
      f.friction_of = static_cast<int>(normal);
      const std::size_t fr = rb.new_row(f);
      rb.add_point(fr, la, on_a, tangent, 1);
      rb.add_point(fr, lb, on_b, tangent, -1);
    }
  }
}

// A bearing's rows: two radial springs on its centre's displacement from the housing, and a
// torsional one on its spin coordinate where it has one.
void bearing_rows(RowBuilder& rb, const Model& model, const Integrator& integ, std::size_t j, const std::vector<int>& link_of_body,
                  const std::vector<int>& dof_of_joint, const std::vector<btVector3>& pivot_in_body,
                  const std::vector<btVector3>& pivot_in_parent) {
  const ModelJoint& jr = model.joints[j];
  const BearingDef& bd = *jr.def.bearing;
  const int link = link_of_body[static_cast<std::size_t>(jr.body)];
  const bool on_body = jr.parent >= 0 && link_of_body[static_cast<std::size_t>(jr.parent)] >= 0;
  const int parent_link = on_body ? link_of_body[static_cast<std::size_t>(jr.parent)] : -1;
  const btVector3 centre = model.bodies[static_cast<std::size_t>(jr.body)].rigid->getWorldTransform() * pivot_in_body[j];
  const btVector3 housing =
      on_body ? model.bodies[static_cast<std::size_t>(jr.parent)].rigid->getWorldTransform() * pivot_in_parent[j] : pivot_in_parent[j];
  const btVector3 axis = bt(jr.axis_world);
  const btVector3 e1 = unit_perpendicular(axis), e2 = axis.cross(e1);
  for (const btVector3& d : {e1, e2}) {
    if (bd.radially_rigid || !(bd.radial_stiffness_N_per_m > 0 || bd.radial_damping_N_s_per_m > 0)) break;
    MultibodyRow r = integ.spring_row(bd.radial_stiffness_N_per_m, bd.radial_damping_N_s_per_m,
                                      -bd.radial_stiffness_N_per_m * (centre - housing).dot(d));
    r.kind = MultibodyRow::bearing;
    r.owner = static_cast<int>(j);
    r.lo = -kInfinity;
    r.hi = kInfinity;
    const std::size_t row = rb.new_row(r);
    rb.add_point(row, link, centre, d, 1);
    rb.add_point(row, parent_link, housing, d, -1);
  }
  if (bd.torsional_stiffness_N_m_per_rad > 0 || bd.torsional_damping_N_m_s_per_rad > 0) {
    MultibodyRow r = integ.spring_row(bd.torsional_stiffness_N_m_per_rad, bd.torsional_damping_N_m_s_per_rad,
                                      -bd.torsional_stiffness_N_m_per_rad * rb.tree.getJointPosMultiDof(link)[0]);
    r.kind = MultibodyRow::torsion;
    r.owner = static_cast<int>(j);
    r.lo = -kInfinity;
    r.hi = kInfinity;
    rb.rows.jrows[rb.new_row(r) * rb.ud + static_cast<std::size_t>(dof_of_joint[j])] = 1;
  }
}

}  // namespace

// The rows of this step: their Jacobians (rows_.jrows), compliances, targets and bounds.
void MultibodyEngine::build_rows() {
  const int dofs = dofs_;
  rows_.rows.clear();
  integ_.choose_theta(model_, state_);
  state_.contacts.clear();
  rows_.jrows.clear();
  // A planar tree (every joint axis along z): each link's spin rate and centre velocity as rows
  // over the coordinates, once per step; a point's velocity along an in-plane direction is then
  // a combination of the three (v_p = v_c + ω × r), without walking the tree per row. With the
  // planar mass matrix, the planar kinematics built them for this pose.
  if (!planar_mass_ && planar_) bullet_link_jacobians();
  RowBuilder rb{rows_,
                *tree_,
                buf_,
                scratch_,
                planar_,
                planar_mass_ ? &kin_ : nullptr,
                planar_mass_ ? kin_.link_jac().data() : link_jac_.data(),
                static_cast<std::size_t>(dofs)};
  contact_rows(rb, model_, state_, link_of_body_, integ_);
  for (std::size_t j = 0; j < model_.joints.size(); ++j) {
    const ModelJoint& jr = model_.joints[j];
    const int dof = dof_of_joint_[j];
    if (jr.def.bearing) bearing_rows(rb, model_, integ_, j, link_of_body_, dof_of_joint_, pivot_in_body_, pivot_in_parent_);
    if (jr.motor) {
      MultibodyRow r;
      r.kind = MultibodyRow::motor;
      r.owner = static_cast<int>(j);
      r.target = motor_target_rad_s(*jr.motor, state_.time + integ_.h_step());  // the speed at the (sub)step's end
      r.lo = -jr.motor->max_torque_N_m * integ_.h_eff();  // impulses are force × h_eff
      r.hi = jr.motor->max_torque_N_m * integ_.h_eff();
      rows_.jrows[rb.new_row(r) * static_cast<std::size_t>(dofs) + static_cast<std::size_t>(dof)] = 1;
    }
  }
  if (!planar_mass_)  // the articulated path's products with M⁻¹ (solve_rows)
    rows_.jac = Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
        rows_.jrows.data(), static_cast<Eigen::Index>(rows_.rows.size()), dofs);
}

// Forces, motor torques and power flows of the step just taken (velocities after it).
void MultibodyEngine::results() {
  const double h = integ_.h_step(), h_eff = integ_.h_eff();
  // Work of a row over the step: its force times its travel, h·J·v_θ (positions moved with v_θ).
  const Eigen::VectorXd& v = integ_.work_velocities(tree_->getVelocityVector() + 6);
  PowerFlows pw;
  std::fill(motor_torque_.begin(), motor_torque_.end(), 0.0);
  for (std::size_t r = 0; r < rows_.rows.size(); ++r) {
    const MultibodyRow& row = rows_.rows[r];
    const double force = rows_.x[r] / h_eff, rate = rows_.row_dot(r, v.data());
    switch (row.kind) {
      case MultibodyRow::contact_normal:
        state_.contacts[static_cast<std::size_t>(row.owner)].normal_force_N = force;
        pw.contact_W += force * rate;
        break;
      case MultibodyRow::contact_friction:
        state_.contacts[static_cast<std::size_t>(row.owner)].friction_force_N = std::abs(force);
        pw.contact_W += force * rate;
        break;
      case MultibodyRow::bearing:
      case MultibodyRow::torsion:
        pw.joint_W += force * rate;
        break;
      case MultibodyRow::motor:
        motor_torque_[static_cast<std::size_t>(row.owner)] = force;
        pw.motor_W += force * rate;
        break;
    }
  }
  for (const ModelJoint& j : model_.joints)
    if (j.load) {
      const double speed = state_.bodies[static_cast<std::size_t>(j.body)].speed_rad_s;
      pw.load_W += load_torque_N_m(*j.load, state_.time - h, speed) * speed;
    }
  pw.kinetic_J = kinetic_energy_J();
  pw.impulse_W = impulse_power_W(model_, state_, h);
  state_.power = pw;
}

}  // namespace gearsim::physics

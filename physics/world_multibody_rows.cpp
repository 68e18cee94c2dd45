#include <algorithm>
#include <cmath>
#include <limits>

#include "physics/world_impl.hpp"

// The rows of the `multibody` engine's step (world_multibody.cpp steps the tree): one per tooth
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
// over the coordinates (e.link_jac), from Bullet's Jacobians of this pose.
void bullet_link_jacobians(MultibodyEngine& e) {
  btMultiBody& t = *e.tree;
  const std::size_t links = static_cast<std::size_t>(t.getNumLinks()), ud = static_cast<std::size_t>(e.dofs);
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

// Appends rows to e.rows with their Jacobians in e.jrows (grown row by row).
struct RowBuilder {
  MultibodyEngine& e;
  std::size_t ud;
  // J of the velocity of `point` (world) on the body of link `link`, along `dir`, added × sign.
  void add_point(std::size_t row, int link, const btVector3& point, const btVector3& dir, double sign) {
    if (link < 0) return;
    btMultiBody& t = *e.tree;
    double* out = e.jrows.data() + row * ud;
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
  }
  std::size_t new_row(const MultibodyRow& r) {
    e.rows.push_back(r);
    e.jrows.resize(e.rows.size() * ud, 0.0);
    return e.rows.size() - 1;
  }
};

// A row per kept tooth contact's normal (a unilateral spring) and, with friction, one along its
// tangent; each contact also recorded in w.contacts.
void contact_rows(World::Impl& w, RowBuilder& rb) {
  MultibodyEngine& e = *w.mb;
  const double mu = w.scenario.contact.friction;
  for (std::size_t p = 0; p < w.pairs.size(); ++p) {
    const PairRec& pr = w.pairs[p];
    const BuiltBody &a = w.bodies[static_cast<std::size_t>(pr.a)], &b = w.bodies[static_cast<std::size_t>(pr.b)];
    const int la = e.link_of_body[static_cast<std::size_t>(pr.a)], lb = e.link_of_body[static_cast<std::size_t>(pr.b)];
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
      w.contacts.push_back(cs);
      const btVector3 n(c.normal_on_b.x(), c.normal_on_b.y(), 0);
      const btVector3 mid(c.point_m.x(), c.point_m.y(), z);
      const btVector3 on_b = mid + n * (0.5 * c.depth_m), on_a = mid - n * (0.5 * c.depth_m);
      const double k = cs.stiffness_N_per_m;
      MultibodyRow r = w.spring_row(k, w.contact_damping(pr, k), k * c.depth_m);
      r.kind = MultibodyRow::contact_normal;
      r.owner = static_cast<int>(w.contacts.size() - 1);
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
void bearing_rows(World::Impl& w, RowBuilder& rb, std::size_t j) {
  MultibodyEngine& e = *w.mb;
  const JointRec& jr = w.joints[j];
  const BearingDef& bd = *jr.def.bearing;
  const int link = e.link_of_body[static_cast<std::size_t>(jr.body)];
  const bool on_body = jr.parent >= 0 && e.link_of_body[static_cast<std::size_t>(jr.parent)] >= 0;
  const int parent_link = on_body ? e.link_of_body[static_cast<std::size_t>(jr.parent)] : -1;
  const btVector3 centre = w.bodies[static_cast<std::size_t>(jr.body)].rigid->getWorldTransform() * e.pivot_in_body[j];
  const btVector3 housing = on_body ? w.bodies[static_cast<std::size_t>(jr.parent)].rigid->getWorldTransform() * e.pivot_in_parent[j] : e.pivot_in_parent[j];
  const btVector3 axis = bt(jr.axis_world);
  const btVector3 e1 = unit_perpendicular(axis), e2 = axis.cross(e1);
  for (const btVector3& d : {e1, e2}) {
    if (!(bd.radial_stiffness_N_per_m > 0 || bd.radial_damping_N_s_per_m > 0)) break;
    MultibodyRow r = w.spring_row(bd.radial_stiffness_N_per_m, bd.radial_damping_N_s_per_m, -bd.radial_stiffness_N_per_m * (centre - housing).dot(d));
    r.kind = MultibodyRow::bearing;
    r.owner = static_cast<int>(j);
    r.lo = -kInfinity;
    r.hi = kInfinity;
    const std::size_t row = rb.new_row(r);
    rb.add_point(row, link, centre, d, 1);
    rb.add_point(row, parent_link, housing, d, -1);
  }
  if (bd.torsional_stiffness_N_m_per_rad > 0 || bd.torsional_damping_N_m_s_per_rad > 0) {
    MultibodyRow r = w.spring_row(bd.torsional_stiffness_N_m_per_rad, bd.torsional_damping_N_m_s_per_rad,
                                  -bd.torsional_stiffness_N_m_per_rad * e.tree->getJointPosMultiDof(link)[0]);
    r.kind = MultibodyRow::torsion;
    r.owner = static_cast<int>(j);
    r.lo = -kInfinity;
    r.hi = kInfinity;
    e.jrows[rb.new_row(r) * rb.ud + static_cast<std::size_t>(e.dof_of_joint[j])] = 1;
  }
}

}  // namespace

// The rows of this step: their Jacobians (e.jrows), compliances, targets and bounds.
void World::Impl::multibody_rows() {
  MultibodyEngine& e = *mb;
  const int dofs = e.dofs;
  e.rows.clear();
  if (e.trapezoid_closed) e.theta = trapezoid_closed_theta();
  contacts.clear();
  e.jrows.clear();
  // A planar tree (every joint axis along z): each link's spin rate and centre velocity as rows
  // over the coordinates, once per step; a point's velocity along an in-plane direction is then
  // a combination of the three (v_p = v_c + ω × r), without walking the tree per row. With the
  // planar mass matrix, planar_free_velocities() built them for this pose.
  if (!e.planar_mass && e.planar) bullet_link_jacobians(e);
  RowBuilder rb{e, static_cast<std::size_t>(dofs)};
  contact_rows(*this, rb);
  for (std::size_t j = 0; j < joints.size(); ++j) {
    const JointRec& jr = joints[j];
    const int dof = e.dof_of_joint[j];
    if (jr.def.bearing) bearing_rows(*this, rb, j);
    if (jr.motor) {
      MultibodyRow r;
      r.kind = MultibodyRow::motor;
      r.owner = static_cast<int>(j);
      r.target = motor_target_rad_s(*jr.motor, time + e.h_step);  // the speed at the (sub)step's end
      r.lo = -jr.motor->max_torque_N_m * e.h_eff;  // impulses are force × h_eff
      r.hi = jr.motor->max_torque_N_m * e.h_eff;
      e.jrows[rb.new_row(r) * static_cast<std::size_t>(dofs) + static_cast<std::size_t>(dof)] = 1;
    }
  }
  if (!e.planar_mass)  // the articulated path's products with M⁻¹ (solve_multibody_rows)
    e.jac = Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(e.jrows.data(), static_cast<Eigen::Index>(e.rows.size()), dofs);
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

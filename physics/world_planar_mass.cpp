#include <algorithm>
#include <cmath>
#include <vector>

#include "core/errors.hpp"
#include "physics/world_impl.hpp"

// solver.mass_matrix planar (docs/solver.md, "The planar mass matrix"): for a tree whose joints
// all turn about z, the links' Jacobians from their joint axes, the mass matrix from them and its
// Cholesky factor, in place of Bullet's Jacobian tree walks and articulated-body solves
// (world_multibody.cpp, solver.mass_matrix articulated).
namespace gearsim::physics {

// Per link: mass, moment about z, its chain to the ground and the coordinates that move it.
void World::Impl::build_planar_mass() {
  MultibodyEngine& e = *mb;
  const btMultiBody& t = *e.tree;
  const std::size_t links = static_cast<std::size_t>(t.getNumLinks());
  e.link_mass_kg.assign(links, 0);
  e.link_izz_kg_m2.assign(links, 0);
  e.link_chain.assign(links, {});
  e.link_dofs.assign(links, {});
  for (std::size_t l = 0; l < links; ++l) {
    const btMultibodyLink& link = t.getLink(static_cast<int>(l));
    // The moment about world z of the principal moments: the link turns about z only, so the
    // local axis that points along z, and this moment, stay as they are at the start.
    const btMatrix3x3& basis = link.m_cachedWorldTransform.getBasis();
    const btVector3 inertia = t.getLinkInertia(static_cast<int>(l));
    e.link_mass_kg[l] = t.getLinkMass(static_cast<int>(l));
    e.link_izz_kg_m2[l] = basis[2][0] * basis[2][0] * inertia.x() + basis[2][1] * basis[2][1] * inertia.y() + basis[2][2] * basis[2][2] * inertia.z();
    for (int i = static_cast<int>(l); i >= 0; i = t.getParent(i)) {
      e.link_chain[l].push_back(i);
      for (int d = 0; d < t.getLink(i).m_dofCount; ++d) e.link_dofs[l].push_back(t.getLink(i).m_dofOffset + d);
    }
  }
  e.chol.assign(static_cast<std::size_t>(e.dofs) * static_cast<std::size_t>(e.dofs), 0);
  e.g_lambda.assign(static_cast<std::size_t>(e.dofs), 0);
}

// e.link_jac (rows ω_z, v_x, v_y of each link's centre over the coordinates) at this step's pose.
// Each coordinate d of a link i on the chain from the ground to link l turns l's centre c_l about
// i's centre c_i with rate s_d (its axis' z component, world) and moves it by b_d (its axis'
// linear part, world): ω_l = Σ s_d·q̇_d, v_l = Σ (s_d·ẑ × (c_l − c_i) + b_d)·q̇_d — Bullet's own
// joint axes (btMultibodyLink::getAxisTop/Bottom, in i's frame) and convention
// (fillConstraintJacobianMultiDof, compTreeLinkVelocities), without walking the tree per row.
// s_d and b_d are kept per coordinate (planar_free_velocities() differentiates them).
void World::Impl::planar_link_jacobians() {
  MultibodyEngine& e = *mb;
  const btMultiBody& t = *e.tree;
  const std::size_t links = static_cast<std::size_t>(t.getNumLinks()), ud = static_cast<std::size_t>(e.dofs);
  e.dof_s.resize(ud);
  e.dof_bx.resize(ud);
  e.dof_by.resize(ud);
  e.dof_link.resize(ud);
  for (std::size_t i = 0; i < links; ++i) {
    const btMultibodyLink& li = t.getLink(static_cast<int>(i));
    const btMatrix3x3& basis = li.m_cachedWorldTransform.getBasis();
    for (int k = 0; k < li.m_dofCount; ++k) {
      const std::size_t dof = static_cast<std::size_t>(li.m_dofOffset + k);
      const btVector3 b_d = basis * li.getAxisBottom(k);
      e.dof_s[dof] = basis.getRow(2).dot(li.getAxisTop(k));
      e.dof_bx[dof] = b_d.x();
      e.dof_by[dof] = b_d.y();
      e.dof_link[dof] = static_cast<int>(i);
    }
  }
  e.link_jac.assign(links * 3 * ud, 0.0);
  for (std::size_t l = 0; l < links; ++l) {
    double* jl = e.link_jac.data() + l * 3 * ud;
    const btVector3 c_l = t.getLink(static_cast<int>(l)).m_cachedWorldTransform.getOrigin();
    for (const int i : e.link_chain[l]) {
      const btMultibodyLink& li = t.getLink(i);
      const btVector3 d = c_l - li.m_cachedWorldTransform.getOrigin();
      for (int k = 0; k < li.m_dofCount; ++k) {
        const std::size_t dof = static_cast<std::size_t>(li.m_dofOffset + k);
        const double s_d = e.dof_s[dof];
        jl[dof] = s_d;
        jl[ud + dof] = e.dof_bx[dof] - s_d * d.y();
        jl[2 * ud + dof] = e.dof_by[dof] + s_d * d.x();
      }
    }
  }
}

// M of this step from the links' Jacobians and its Cholesky factor L (e.chol, lower triangle;
// e.chol_inv_diag). M is positive definite for links with positive masses and moments
// (build_multibody requires them).
void World::Impl::planar_mass_factor() {
  MultibodyEngine& e = *mb;
  const std::size_t ud = static_cast<std::size_t>(e.dofs);
  double* m = e.chol.data();
  std::fill(e.chol.begin(), e.chol.end(), 0.0);
  for (std::size_t l = 0; l < e.link_dofs.size(); ++l) {
    const double* jw = e.link_jac.data() + l * 3 * ud;
    const double *jx = jw + ud, *jy = jw + 2 * ud;
    const double mass = e.link_mass_kg[l], izz = e.link_izz_kg_m2[l];
    for (const int a : e.link_dofs[l])
      for (const int b : e.link_dofs[l]) {
        if (b > a) continue;
        const std::size_t ua = static_cast<std::size_t>(a), ub = static_cast<std::size_t>(b);
        m[ua * ud + ub] += mass * (jx[ua] * jx[ub] + jy[ua] * jy[ub]) + izz * jw[ua] * jw[ub];
      }
  }
  if (e.check_mass) check_planar_mass(m);
  e.mass.assign(m, m + ud * ud);  // M itself, for the dof-space solve (solve_rows_primal)
  e.chol_inv_diag.resize(ud);
  for (std::size_t j = 0; j < ud; ++j) {
    double s = m[j * ud + j];
    for (std::size_t k = 0; k < j; ++k) s -= m[j * ud + k] * m[j * ud + k];
    GEARSIM_CHECK(s > 0, "the planar mass matrix must be positive definite");
    const double d = std::sqrt(s), inv = 1 / d;
    m[j * ud + j] = d;
    e.chol_inv_diag[j] = inv;
    for (std::size_t i = j + 1; i < ud; ++i) {
      double v = m[i * ud + j];
      for (std::size_t k = 0; k < j; ++k) v -= m[i * ud + k] * m[j * ud + k];
      m[i * ud + j] = v * inv;
    }
  }
}

// The velocities the applied forces alone would reach, v* = v + h·q̈ with M·q̈ = Q − c (Kane's
// equations of the planar tree), in place of Bullet's articulated-body pass over the same tree:
// Q the joint torques (addJointTorqueMultiDof) and the links' applied forces and torques
// (addLinkForce/Torque, at their centres) through the links' Jacobians; c = Σ_l m_l·J_lᵀ·a_l
// with a_l the acceleration of l's centre at q̈ = 0: differentiating v_l above with q̇ fixed,
// a_l = Σ_d q̇_d·(ω_i·ẑ × b_d + s_d·ẑ × (v_l − v_i)) over the coordinates d of the links i on l's
// chain (b_d turns with its link i). Spins need no term: s_d is constant, and a link turning
// about z has no gyroscopic torque about z. Bullet's pass is the reference
// (World::set_mass_matrix_check: Multibody.ThePlanarMassMatrixLinkJacobiansAndFreeMotionAreBulletsAtEveryStep).
void World::Impl::planar_free_velocities(double h) {
  MultibodyEngine& e = *mb;
  btMultiBody& t = *e.tree;
  if (e.check_mass) {
    // Bullet's pass at the same state without a step (dt 0): its q̈ in scratch_r[dofs + 6…]
    // (and the articulated inertias that check_planar_mass() solves with).
    t.computeAccelerationsArticulatedBodyAlgorithmMultiDof(0, e.scratch_r, e.scratch_v, e.scratch_m, false, false, false);
    e.bullet_qdd.assign(&e.scratch_r[e.dofs] + 6, &e.scratch_r[e.dofs] + 6 + e.dofs);
  }
  // The link Jacobians of this pose: the last step's end made them (planar_forward_kinematics()).
  if (!e.link_jac_current) planar_link_jacobians();
  planar_mass_factor();
  const std::size_t links = static_cast<std::size_t>(t.getNumLinks()), ud = static_cast<std::size_t>(e.dofs);
  const double* u = t.getVelocityVector() + 6;
  planar_link_velocities(u);
  e.gen_force.assign(ud, 0.0);
  double* q = e.gen_force.data();
  for (std::size_t l = 0; l < links; ++l) {
    const btMultibodyLink& link = t.getLink(static_cast<int>(l));
    const btScalar* tau = t.getJointTorqueMultiDof(static_cast<int>(l));
    for (int k = 0; k < link.m_dofCount; ++k) q[link.m_dofOffset + k] += tau[k];
    double ax = 0, ay = 0;
    for (const int d : e.link_dofs[l]) {
      const std::size_t k = static_cast<std::size_t>(d);
      const std::size_t i = static_cast<std::size_t>(e.dof_link[k]);
      const double w_i = e.link_w[i], s_d = e.dof_s[k];
      ax += u[k] * (-w_i * e.dof_by[k] - s_d * (e.link_vy[l] - e.link_vy[i]));
      ay += u[k] * (w_i * e.dof_bx[k] + s_d * (e.link_vx[l] - e.link_vx[i]));
    }
    const btVector3 f = t.getLinkForce(static_cast<int>(l)), torque = t.getLinkTorque(static_cast<int>(l));
    const double mass = e.link_mass_kg[l];
    const double fx = f.x() - mass * ax, fy = f.y() - mass * ay, tz = torque.z();
    const double* jw = e.link_jac.data() + l * 3 * ud;
    const double *jx = jw + ud, *jy = jw + 2 * ud;
    for (const int d : e.link_dofs[l]) {
      const std::size_t k = static_cast<std::size_t>(d);
      q[k] += jx[k] * fx + jy[k] * fy + jw[k] * tz;
    }
  }
  // q̈ = L⁻ᵀ·L⁻¹·(Q − c), into e.buf[6…] (the base, fixed, stays at rest).
  const double* m = e.chol.data();
  for (std::size_t i = 0; i < ud; ++i) {
    double v = q[i];
    for (std::size_t k = 0; k < i; ++k) v -= m[i * ud + k] * q[k];
    q[i] = v * e.chol_inv_diag[i];
  }
  std::fill(e.buf.begin(), e.buf.end(), 0.0);
  double* qdd = e.buf.data() + 6;
  for (std::size_t i = ud; i-- > 0;) {
    double v = q[i];
    for (std::size_t k = i + 1; k < ud; ++k) v -= m[k * ud + i] * qdd[k];
    qdd[i] = v * e.chol_inv_diag[i];
  }
  if (e.check_mass) {
    const double* bullet = e.bullet_qdd.data();
    double scale = 0, difference = 0;
    for (std::size_t k = 0; k < ud; ++k) scale = std::max(scale, std::abs(bullet[k])), difference = std::max(difference, std::abs(qdd[k] - bullet[k]));
    if (scale > 0) e.mass_check.free_velocity_difference = std::max(e.mass_check.free_velocity_difference, difference / scale);
  }
  t.applyDeltaVeeMultiDof(e.buf.data(), h);
}

// World::set_mass_matrix_check: this step's M (lower triangle, before its factorisation) against
// the articulated-body solves' M⁻¹, and e.link_jac against Bullet's tree walks, at the same pose.
void World::Impl::check_planar_mass(const double* m_lower) {
  MultibodyEngine& e = *mb;
  btMultiBody& t = *e.tree;
  const std::size_t ud = static_cast<std::size_t>(e.dofs), links = static_cast<std::size_t>(t.getNumLinks());
  std::vector<double> minv(ud * ud), buf(6 + ud), out(6 + ud);
  for (std::size_t k = 0; k < ud; ++k) {
    std::fill(buf.begin(), buf.end(), 0.0);
    buf[6 + k] = 1;
    t.calcAccelerationDeltasMultiDof(buf.data(), out.data(), e.scratch_r, e.scratch_v);
    for (std::size_t r = 0; r < ud; ++r) minv[r * ud + k] = out[6 + r];
  }
  double residual = 0;
  for (std::size_t i = 0; i < ud; ++i)
    for (std::size_t j = 0; j < ud; ++j) {
      double v = 0;
      for (std::size_t k = 0; k < ud; ++k) v += (k <= i ? m_lower[i * ud + k] : m_lower[k * ud + i]) * minv[k * ud + j];
      residual = std::max(residual, std::abs(v - (i == j ? 1.0 : 0.0)));
    }
  // ω_z as the y velocity of a point 1 m along x from the centre less the centre's (Bullet's
  // angular Jacobian of a planar joint leaves out the spin), v_x and v_y of the centre.
  double difference = 0;
  const btVector3 ex(1, 0, 0), ey(0, 1, 0);
  std::vector<double> rows(3 * ud);
  for (std::size_t l = 0; l < links; ++l) {
    const btVector3 centre = t.getLink(static_cast<int>(l)).m_cachedWorldTransform.getOrigin();
    const btVector3 points[3] = {centre + ex, centre, centre}, dirs[3] = {ey, ex, ey};
    for (std::size_t c = 0; c < 3; ++c) {
      t.fillContactJacobianMultiDof(static_cast<int>(l), points[c], dirs[c], buf.data(), e.scratch_r, e.scratch_v, e.scratch_m);
      std::copy(buf.begin() + 6, buf.end(), rows.begin() + static_cast<std::ptrdiff_t>(c * ud));
    }
    for (std::size_t k = 0; k < ud; ++k) rows[k] -= rows[2 * ud + k];
    for (std::size_t i = 0; i < 3 * ud; ++i) difference = std::max(difference, std::abs(rows[i] - e.link_jac[l * 3 * ud + i]));
  }
  ++e.mass_check.steps;
  e.mass_check.identity_residual = std::max(e.mass_check.identity_residual, residual);
  e.mass_check.jacobian_difference = std::max(e.mass_check.jacobian_difference, difference);
}

void World::set_mass_matrix_check(bool on) {
  if (impl_->mb) impl_->mb->check_mass = on;
}

const World::MassMatrixCheck& World::mass_matrix_check() const {
  static const MassMatrixCheck kNone;
  return impl_->mb ? impl_->mb->mass_check : kNone;
}

}  // namespace gearsim::physics

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/errors.hpp"
#include "physics/multibody_engine.hpp"

// solver.mass_matrix planar (docs/solver.md, "The planar mass matrix"): for a tree whose joints
// all turn about z, the links' Jacobians from their joint axes, the mass matrix from them and its
// Cholesky factor, in place of Bullet's Jacobian tree walks and articulated-body solves
// (world_multibody.cpp, solver.mass_matrix articulated).
namespace gearsim::physics {

// Per link: mass, moment about z, its chain to the ground and the coordinates that move it.
void MultibodyEngine::build_planar_mass() {
  const btMultiBody& t = *tree_;
  const std::size_t links = static_cast<std::size_t>(t.getNumLinks());
  mass_.link_mass_kg.assign(links, 0);
  mass_.link_izz_kg_m2.assign(links, 0);
  mass_.link_chain.assign(links, {});
  mass_.link_dofs.assign(links, {});
  for (std::size_t l = 0; l < links; ++l) {
    const btMultibodyLink& link = t.getLink(static_cast<int>(l));
    // The moment about world z of the principal moments: the link turns about z only, so the
    // local axis that points along z, and this moment, stay as they are at the start.
    const btMatrix3x3& basis = link.m_cachedWorldTransform.getBasis();
    const btVector3 inertia = t.getLinkInertia(static_cast<int>(l));
    mass_.link_mass_kg[l] = t.getLinkMass(static_cast<int>(l));
    mass_.link_izz_kg_m2[l] = basis[2][0] * basis[2][0] * inertia.x() + basis[2][1] * basis[2][1] * inertia.y() + basis[2][2] * basis[2][2] * inertia.z();
    for (int i = static_cast<int>(l); i >= 0; i = t.getParent(i)) {
      mass_.link_chain[l].push_back(i);
      for (int d = 0; d < t.getLink(i).m_dofCount; ++d) mass_.link_dofs[l].push_back(t.getLink(i).m_dofOffset + d);
    }
  }
  mass_.chol.assign(static_cast<std::size_t>(dofs_) * static_cast<std::size_t>(dofs_), 0);
  mass_.g_lambda.assign(static_cast<std::size_t>(dofs_), 0);
}

// link_jac_ (rows ω_z, v_x, v_y of each link's centre over the coordinates) at this step's pose.
// Each coordinate d of a link i on the chain from the ground to link l turns l's centre c_l about
// i's centre c_i with rate s_d (its axis' z component, world) and moves it by b_d (its axis'
// linear part, world): ω_l = Σ s_d·q̇_d, v_l = Σ (s_d·ẑ × (c_l − c_i) + b_d)·q̇_d — Bullet's own
// joint axes (btMultibodyLink::getAxisTop/Bottom, in i's frame) and convention
// (fillConstraintJacobianMultiDof, compTreeLinkVelocities), without walking the tree per row.
// s_d and b_d are kept per coordinate (planar_free_velocities() differentiates them).
void MultibodyEngine::planar_link_jacobians() {
  const btMultiBody& t = *tree_;
  const std::size_t links = static_cast<std::size_t>(t.getNumLinks()), ud = static_cast<std::size_t>(dofs_);
  mass_.dof_s.resize(ud);
  mass_.dof_bx.resize(ud);
  mass_.dof_by.resize(ud);
  mass_.dof_link.resize(ud);
  for (std::size_t i = 0; i < links; ++i) {
    const btMultibodyLink& li = t.getLink(static_cast<int>(i));
    const btMatrix3x3& basis = li.m_cachedWorldTransform.getBasis();
    for (int k = 0; k < li.m_dofCount; ++k) {
      const std::size_t dof = static_cast<std::size_t>(li.m_dofOffset + k);
      const btVector3 b_d = basis * li.getAxisBottom(k);
      mass_.dof_s[dof] = basis.getRow(2).dot(li.getAxisTop(k));
      mass_.dof_bx[dof] = b_d.x();
      mass_.dof_by[dof] = b_d.y();
      mass_.dof_link[dof] = static_cast<int>(i);
    }
  }
  link_jac_.assign(links * 3 * ud, 0.0);
  for (std::size_t l = 0; l < links; ++l) {
    double* jl = link_jac_.data() + l * 3 * ud;
    const btVector3 c_l = t.getLink(static_cast<int>(l)).m_cachedWorldTransform.getOrigin();
    for (const int i : mass_.link_chain[l]) {
      const btMultibodyLink& li = t.getLink(i);
      const btVector3 d = c_l - li.m_cachedWorldTransform.getOrigin();
      for (int k = 0; k < li.m_dofCount; ++k) {
        const std::size_t dof = static_cast<std::size_t>(li.m_dofOffset + k);
        const double s_d = mass_.dof_s[dof];
        jl[dof] = s_d;
        jl[ud + dof] = mass_.dof_bx[dof] - s_d * d.y();
        jl[2 * ud + dof] = mass_.dof_by[dof] + s_d * d.x();
      }
    }
  }
}

// M of this step from the links' Jacobians and its Cholesky factor L (mass_.chol, lower triangle;
// mass_.chol_inv_diag). M is positive definite for links with positive masses and moments
// (build_multibody requires them).
void MultibodyEngine::planar_mass_factor() {
  const std::size_t ud = static_cast<std::size_t>(dofs_);
  double* m = mass_.chol.data();
  std::fill(mass_.chol.begin(), mass_.chol.end(), 0.0);
  for (std::size_t l = 0; l < mass_.link_dofs.size(); ++l) {
    const double* jw = link_jac_.data() + l * 3 * ud;
    const double *jx = jw + ud, *jy = jw + 2 * ud;
    const double mass = mass_.link_mass_kg[l], izz = mass_.link_izz_kg_m2[l];
    for (const int a : mass_.link_dofs[l])
      for (const int b : mass_.link_dofs[l]) {
        if (b > a) continue;
        const std::size_t ua = static_cast<std::size_t>(a), ub = static_cast<std::size_t>(b);
        m[ua * ud + ub] += mass * (jx[ua] * jx[ub] + jy[ua] * jy[ub]) + izz * jw[ua] * jw[ub];
      }
  }
  if (check_mass_) check_planar_mass(m);
  mass_.mass.assign(m, m + ud * ud);  // M itself, for the dof-space solve (solve_rows_primal)
  mass_.chol_inv_diag.resize(ud);
  for (std::size_t j = 0; j < ud; ++j) {
    double s = m[j * ud + j];
    for (std::size_t k = 0; k < j; ++k) s -= m[j * ud + k] * m[j * ud + k];
    GEARSIM_CHECK(s > 0, "the planar mass matrix must be positive definite");
    const double d = std::sqrt(s), inv = 1 / d;
    m[j * ud + j] = d;
    mass_.chol_inv_diag[j] = inv;
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
void MultibodyEngine::planar_free_velocities(double h) {
  btMultiBody& t = *tree_;
  if (check_mass_) {
    // Bullet's pass at the same state without a step (dt 0): its q̈ in scratch_r[dofs + 6…]
    // (and the articulated inertias that check_planar_mass() solves with).
    t.computeAccelerationsArticulatedBodyAlgorithmMultiDof(0, scratch_r_, scratch_v_, scratch_m_, false, false, false);
    mass_.bullet_qdd.assign(&scratch_r_[dofs_] + 6, &scratch_r_[dofs_] + 6 + dofs_);
  }
  // The link Jacobians of this pose: the last step's end made them (planar_forward_kinematics()).
  if (!kin_.link_jac_current) planar_link_jacobians();
  planar_mass_factor();
  const std::size_t links = static_cast<std::size_t>(t.getNumLinks()), ud = static_cast<std::size_t>(dofs_);
  const double* u = t.getVelocityVector() + 6;
  planar_link_velocities(u);
  mass_.gen_force.assign(ud, 0.0);
  double* q = mass_.gen_force.data();
  for (std::size_t l = 0; l < links; ++l) {
    const btMultibodyLink& link = t.getLink(static_cast<int>(l));
    const btScalar* tau = t.getJointTorqueMultiDof(static_cast<int>(l));
    for (int k = 0; k < link.m_dofCount; ++k) q[link.m_dofOffset + k] += tau[k];
    double ax = 0, ay = 0;
    for (const int d : mass_.link_dofs[l]) {
      const std::size_t k = static_cast<std::size_t>(d);
      const std::size_t i = static_cast<std::size_t>(mass_.dof_link[k]);
      const double w_i = mass_.link_w[i], s_d = mass_.dof_s[k];
      ax += u[k] * (-w_i * mass_.dof_by[k] - s_d * (mass_.link_vy[l] - mass_.link_vy[i]));
      ay += u[k] * (w_i * mass_.dof_bx[k] + s_d * (mass_.link_vx[l] - mass_.link_vx[i]));
    }
    const btVector3 f = t.getLinkForce(static_cast<int>(l)), torque = t.getLinkTorque(static_cast<int>(l));
    const double mass = mass_.link_mass_kg[l];
    const double fx = f.x() - mass * ax, fy = f.y() - mass * ay, tz = torque.z();
    const double* jw = link_jac_.data() + l * 3 * ud;
    const double *jx = jw + ud, *jy = jw + 2 * ud;
    for (const int d : mass_.link_dofs[l]) {
      const std::size_t k = static_cast<std::size_t>(d);
      q[k] += jx[k] * fx + jy[k] * fy + jw[k] * tz;
    }
  }
  // q̈ = L⁻ᵀ·L⁻¹·(Q − c), into buf_[6…] (the base, fixed, stays at rest).
  const double* m = mass_.chol.data();
  for (std::size_t i = 0; i < ud; ++i) {
    double v = q[i];
    for (std::size_t k = 0; k < i; ++k) v -= m[i * ud + k] * q[k];
    q[i] = v * mass_.chol_inv_diag[i];
  }
  std::fill(buf_.begin(), buf_.end(), 0.0);
  double* qdd = buf_.data() + 6;
  for (std::size_t i = ud; i-- > 0;) {
    double v = q[i];
    for (std::size_t k = i + 1; k < ud; ++k) v -= m[k * ud + i] * qdd[k];
    qdd[i] = v * mass_.chol_inv_diag[i];
  }
  if (check_mass_) {
    const double* bullet = mass_.bullet_qdd.data();
    double scale = 0, difference = 0;
    for (std::size_t k = 0; k < ud; ++k) scale = std::max(scale, std::abs(bullet[k])), difference = std::max(difference, std::abs(qdd[k] - bullet[k]));
    if (scale > 0) mass_check_.free_velocity_difference = std::max(mass_check_.free_velocity_difference, difference / scale);
  }
  t.applyDeltaVeeMultiDof(buf_.data(), h);
}

// World::set_mass_matrix_check: this step's M (lower triangle, before its factorisation) against
// the articulated-body solves' M⁻¹, and link_jac_ against Bullet's tree walks, at the same pose.
void MultibodyEngine::check_planar_mass(const double* m_lower) {
  btMultiBody& t = *tree_;
  const std::size_t ud = static_cast<std::size_t>(dofs_), links = static_cast<std::size_t>(t.getNumLinks());
  std::vector<double> minv(ud * ud), buf(6 + ud), out(6 + ud);
  for (std::size_t k = 0; k < ud; ++k) {
    std::fill(buf.begin(), buf.end(), 0.0);
    buf[6 + k] = 1;
    t.calcAccelerationDeltasMultiDof(buf.data(), out.data(), scratch_r_, scratch_v_);
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
      t.fillContactJacobianMultiDof(static_cast<int>(l), points[c], dirs[c], buf.data(), scratch_r_, scratch_v_, scratch_m_);
      std::copy(buf.begin() + 6, buf.end(), rows.begin() + static_cast<std::ptrdiff_t>(c * ud));
    }
    for (std::size_t k = 0; k < ud; ++k) rows[k] -= rows[2 * ud + k];
    for (std::size_t i = 0; i < 3 * ud; ++i) difference = std::max(difference, std::abs(rows[i] - link_jac_[l * 3 * ud + i]));
  }
  ++mass_check_.steps;
  mass_check_.identity_residual = std::max(mass_check_.identity_residual, residual);
  mass_check_.jacobian_difference = std::max(mass_check_.jacobian_difference, difference);
}

}  // namespace gearsim::physics

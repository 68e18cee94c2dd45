#include "physics/planar_mass.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/errors.hpp"

// verify.mass_matrix planar (docs/solver.md, "The planar mass matrix"): for a tree whose joints
// all turn about z, the links' Jacobians from their joint axes, the mass matrix from them and its
// Cholesky factor, in place of Bullet's Jacobian tree walks and articulated-body solves
// (the multibody engine's articulated path, verify.mass_matrix articulated).
namespace gearsim::physics {

// Per link: mass and moment about z.
void PlanarMass::build(btMultiBody& tree) {
  tree_ = &tree;
  dofs_ = static_cast<std::size_t>(tree.getNumDofs());
  const btMultiBody& t = tree;
  const std::size_t links = static_cast<std::size_t>(t.getNumLinks());
  link_mass_kg_.assign(links, 0);
  link_izz_kg_m2_.assign(links, 0);
  for (std::size_t l = 0; l < links; ++l) {
    const btMultibodyLink& link = t.getLink(static_cast<int>(l));
    // The moment about world z of the principal moments: the link turns about z only, so the
    // local axis that points along z, and this moment, stay as they are at the start.
    const btMatrix3x3& basis = link.m_cachedWorldTransform.getBasis();
    const btVector3 inertia = t.getLinkInertia(static_cast<int>(l));
    link_mass_kg_[l] = t.getLinkMass(static_cast<int>(l));
    link_izz_kg_m2_[l] =
        basis[2][0] * basis[2][0] * inertia.x() + basis[2][1] * basis[2][1] * inertia.y() + basis[2][2] * basis[2][2] * inertia.z();
  }
  chol_.assign(dofs_ * dofs_, 0);
  g_lambda_.assign(dofs_, 0);
}

// M of this step from the links' Jacobians and its Cholesky factor L (chol_, lower triangle;
// chol_inv_diag_). M is positive definite for links with positive masses and moments
// (MultibodyEngine::build_tree requires them).
void PlanarMass::factor(const PlanarKinematics& kin, BulletScratch& scratch, World::MassMatrixCheck* check) {
  const std::size_t ud = dofs_;
  double* m = chol_.data();
  std::fill(chol_.begin(), chol_.end(), 0.0);
  for (std::size_t l = 0; l < kin.links(); ++l) {
    const double* jw = kin.link_jac().data() + l * 3 * ud;
    const double *jx = jw + ud, *jy = jw + 2 * ud;
    const double mass = link_mass_kg_[l], izz = link_izz_kg_m2_[l];
    for (const int a : kin.link_dofs(l))
      for (const int b : kin.link_dofs(l)) {
        if (b > a) continue;
        const std::size_t ua = static_cast<std::size_t>(a), ub = static_cast<std::size_t>(b);
        m[ua * ud + ub] += mass * (jx[ua] * jx[ub] + jy[ua] * jy[ub]) + izz * jw[ua] * jw[ub];
      }
  }
  if (check) check_against_bullet(m, kin, scratch, *check);
  mass_.assign(m, m + ud * ud);  // M itself, for the dof-space solve (PrimalSolve)
  chol_inv_diag_.resize(ud);
  for (std::size_t j = 0; j < ud; ++j) {
    double s = m[j * ud + j];
    for (std::size_t k = 0; k < j; ++k) s -= m[j * ud + k] * m[j * ud + k];
    GEARSIM_CHECK(s > 0, "the planar mass matrix must be positive definite");
    const double d = std::sqrt(s), inv = 1 / d;
    m[j * ud + j] = d;
    chol_inv_diag_[j] = inv;
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
void PlanarMass::free_velocities(PlanarKinematics& kin, double h, std::vector<double>& buf, BulletScratch& scratch,
                                 World::MassMatrixCheck* check) {
  btMultiBody& t = *tree_;
  if (check) {
    // Bullet's pass at the same state without a step (dt 0): its q̈ in scratch_r[dofs + 6…]
    // (and the articulated inertias that check_against_bullet() solves with).
    t.computeAccelerationsArticulatedBodyAlgorithmMultiDof(0, scratch.r, scratch.v, scratch.m, false, false, false);
    bullet_qdd_.assign(&scratch.r[static_cast<int>(dofs_)] + 6, &scratch.r[static_cast<int>(dofs_)] + 6 + dofs_);
  }
  // The link Jacobians of this pose: the last step's end made them (PlanarKinematics::forward_kinematics()).
  factor(kin, scratch, check);
  const std::size_t links = static_cast<std::size_t>(t.getNumLinks()), ud = dofs_;
  const double* u = t.getVelocityVector() + 6;
  kin.link_velocities(u);
  gen_force_.assign(ud, 0.0);
  double* q = gen_force_.data();
  for (std::size_t l = 0; l < links; ++l) {
    const btMultibodyLink& link = t.getLink(static_cast<int>(l));
    const btScalar* tau = t.getJointTorqueMultiDof(static_cast<int>(l));
    for (int k = 0; k < link.m_dofCount; ++k) q[link.m_dofOffset + k] += tau[k];
    double ax = 0, ay = 0;
    for (const int d : kin.link_dofs(l)) {
      const std::size_t k = static_cast<std::size_t>(d);
      const std::size_t i = static_cast<std::size_t>(kin.dof_link()[k]);
      const double w_i = kin.link_w()[i], s_d = kin.dof_s()[k];
      ax += u[k] * (-w_i * kin.dof_by()[k] - s_d * (kin.link_vy()[l] - kin.link_vy()[i]));
      ay += u[k] * (w_i * kin.dof_bx()[k] + s_d * (kin.link_vx()[l] - kin.link_vx()[i]));
    }
    const btVector3 f = t.getLinkForce(static_cast<int>(l)), torque = t.getLinkTorque(static_cast<int>(l));
    const double mass = link_mass_kg_[l];
    const double fx = f.x() - mass * ax, fy = f.y() - mass * ay, tz = torque.z();
    const double* jw = kin.link_jac().data() + l * 3 * ud;
    const double *jx = jw + ud, *jy = jw + 2 * ud;
    for (const int d : kin.link_dofs(l)) {
      const std::size_t k = static_cast<std::size_t>(d);
      q[k] += jx[k] * fx + jy[k] * fy + jw[k] * tz;
    }
  }
  // q̈ = L⁻ᵀ·L⁻¹·(Q − c), into buf_[6…] (the base, fixed, stays at rest).
  const double* m = chol_.data();
  for (std::size_t i = 0; i < ud; ++i) {
    double v = q[i];
    for (std::size_t k = 0; k < i; ++k) v -= m[i * ud + k] * q[k];
    q[i] = v * chol_inv_diag_[i];
  }
  std::fill(buf.begin(), buf.end(), 0.0);
  double* qdd = buf.data() + 6;
  for (std::size_t i = ud; i-- > 0;) {
    double v = q[i];
    for (std::size_t k = i + 1; k < ud; ++k) v -= m[k * ud + i] * qdd[k];
    qdd[i] = v * chol_inv_diag_[i];
  }
  if (check) {
    const double* bullet = bullet_qdd_.data();
    double scale = 0, difference = 0;
    for (std::size_t k = 0; k < ud; ++k)
      scale = std::max(scale, std::abs(bullet[k])), difference = std::max(difference, std::abs(qdd[k] - bullet[k]));
    if (scale > 0) check->free_velocity_difference = std::max(check->free_velocity_difference, difference / scale);
  }
  t.applyDeltaVeeMultiDof(buf.data(), h);
}

// World::set_mass_matrix_check: this step's M (lower triangle, before its factorisation) against
// the articulated-body solves' M⁻¹, and link_jac_ against Bullet's tree walks, at the same pose.
void PlanarMass::check_against_bullet(const double* m_lower, const PlanarKinematics& kin, BulletScratch& scratch,
                                      World::MassMatrixCheck& check) {
  btMultiBody& t = *tree_;
  const std::size_t ud = dofs_, links = static_cast<std::size_t>(t.getNumLinks());
  std::vector<double> minv(ud * ud), buf(6 + ud), out(6 + ud);
  for (std::size_t k = 0; k < ud; ++k) {
    std::fill(buf.begin(), buf.end(), 0.0);
    buf[6 + k] = 1;
    t.calcAccelerationDeltasMultiDof(buf.data(), out.data(), scratch.r, scratch.v);
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
      t.fillContactJacobianMultiDof(static_cast<int>(l), points[c], dirs[c], buf.data(), scratch.r, scratch.v, scratch.m);
      std::copy(buf.begin() + 6, buf.end(), rows.begin() + static_cast<std::ptrdiff_t>(c * ud));
    }
    for (std::size_t k = 0; k < ud; ++k) rows[k] -= rows[2 * ud + k];
    for (std::size_t i = 0; i < 3 * ud; ++i) difference = std::max(difference, std::abs(rows[i] - kin.link_jac()[l * 3 * ud + i]));
  }
  ++check.steps;
  check.identity_residual = std::max(check.identity_residual, residual);
  check.jacobian_difference = std::max(check.jacobian_difference, difference);
}

}  // namespace gearsim::physics

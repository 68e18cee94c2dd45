// verify.mass_matrix planar on a tree whose joints all turn about z (docs/solver.md, "The planar
// mass matrix"): M = Σ m·(J_xᵀ·J_x + J_yᵀ·J_y) + I_zz·J_ωᵀ·J_ω over the links (their Jacobians from
// planar_kinematics.hpp), factored M = L·Lᵀ (Cholesky); per row g_i = L⁻¹·J_iᵀ, so that A = Gᵀ·G
// and M⁻¹·Jᵀ·λ = L⁻ᵀ·(G·λ), without M⁻¹; the free motion v* = v + h·M⁻¹·(Q − c). In place of
// Bullet's articulated-body solves (the multibody engine's articulated path). Internal to physics/.
#pragma once

#include <BulletDynamics/Featherstone/btMultiBody.h>

#include <cstddef>
#include <vector>

#include "physics/bullet_scratch.hpp"
#include "physics/multibody_rows.hpp"
#include "physics/planar_kinematics.hpp"
#include "physics/world.hpp"

namespace gearsim::physics {

class PlanarMass {
 public:
  // Per link of the tree (as built): mass and moment about z.
  void build(btMultiBody& tree);
  // A new step's rows: G and the dense A are formed again where needed.
  void new_rows() { g_formed_ = a_formed_ = false; }
  // The velocities the applied forces alone would reach, v* = v + h·q̈ with M·q̈ = Q − c, onto the
  // tree (M and L of this pose formed on the way); buf: the tree's 6 + dofs scratch. With a
  // check, Bullet's articulated-body pass and M⁻¹ compared into it.
  void free_velocities(PlanarKinematics& kin, double h, std::vector<double>& buf, BulletScratch& scratch, World::MassMatrixCheck* check);
  // Row r's diagonal of A = J·M⁻¹·Jᵀ, |L⁻¹·J_rᵀ|².
  double diag_a(const RowSystem& rows, std::size_t r);
  // G = L⁻¹·Jᵀ of this step's rows (dofs × rows), formed once per step.
  const std::vector<double>& g(const RowSystem& rows);
  // The dense A = Gᵀ·G + diag(compliance) into rows.a, formed once per step.
  void full_a(RowSystem& rows);
  // dv = M⁻¹·Jᵀ·λ over this step's rows.
  void velocity_change(const RowSystem& rows, const double* lambda, double* dv);
  // ½·m·|v|² + ½·I_zz·ω² over the links, J.
  double kinetic_energy_J(const PlanarKinematics& kin) const;

  const std::vector<double>& chol() const { return chol_; }  // L, dofs × dofs row-major (lower triangle)
  const std::vector<double>& chol_inv_diag() const { return chol_inv_diag_; }  // 1 / L's diagonal
  const std::vector<double>& mass() const { return mass_; }  // M, dofs × dofs row-major (lower triangle)
  std::vector<double>& scratch() { return g_lambda_; }  // dofs entries, for a caller's substitutions

 private:
  void factor(const PlanarKinematics& kin, BulletScratch& scratch, World::MassMatrixCheck* check);
  void check_against_bullet(const double* m_lower, const PlanarKinematics& kin, BulletScratch& scratch, World::MassMatrixCheck& check);

  btMultiBody* tree_ = nullptr;  // the engine's
  std::size_t dofs_ = 0;
  std::vector<double> link_mass_kg_, link_izz_kg_m2_;  // per link: mass, moment about z
  std::vector<double> gen_force_;  // dofs: Q − c of free_velocities()
  std::vector<double> bullet_qdd_;  // dofs: Bullet's q̈ at the same state (the check)
  std::vector<double> chol_;  // dofs × dofs, row-major: L (lower triangle)
  std::vector<double> chol_inv_diag_;  // dofs: 1 / L's diagonal
  std::vector<double> mass_;  // dofs × dofs, row-major: M (lower triangle)
  std::vector<double> g_;  // dofs × rows: G = L⁻¹·Jᵀ
  std::vector<double> g_lambda_;  // dofs: scratch (Jᵀ·λ and its substitutions; a row's L⁻¹·Jᵀ)
  bool g_formed_ = false;  // g_ holds this step's G
  bool a_formed_ = false;  // the rows' a holds this step's dense A
};

}  // namespace gearsim::physics

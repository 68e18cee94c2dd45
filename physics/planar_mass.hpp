// solver.mass_matrix planar on a tree whose joints all turn about z (docs/solver.md, "The planar
// mass matrix"): the links' Jacobians from their joints' axes (no tree walks); M = Σ m·(J_xᵀ·J_x +
// J_yᵀ·J_y) + I_zz·J_ωᵀ·J_ω over the links, factored M = L·Lᵀ (Cholesky); per row g_i = L⁻¹·J_iᵀ,
// so that A = Gᵀ·G and M⁻¹·Jᵀ·λ = L⁻ᵀ·(G·λ), without M⁻¹. The multibody engine's working data for
// it; the articulated path (Bullet's articulated-body solves) is the engine's own. Internal to
// physics/.
#pragma once

#include <vector>

namespace gearsim::physics {

struct PlanarMass {
  std::vector<double> link_mass_kg, link_izz_kg_m2;  // per link: mass, moment about z
  std::vector<std::vector<int>> link_chain;          // per link: it and its ancestors
  std::vector<std::vector<int>> link_dofs;           // per link: the coordinates that move it
  // Per coordinate: the z component of its joint's angular axis s_d, its linear axis b_d (world)
  // and the link it belongs to; per link, this step's spin rate and centre velocity (world).
  std::vector<double> dof_s, dof_bx, dof_by;
  std::vector<int> dof_link;
  std::vector<double> link_w, link_vx, link_vy;
  std::vector<double> gen_force;      // dofs: Q − c of free_velocities()
  std::vector<double> bullet_qdd;     // dofs: Bullet's q̈ at the same state (World::set_mass_matrix_check)
  std::vector<double> chol;           // dofs × dofs, row-major: L (lower triangle)
  std::vector<double> chol_inv_diag;  // dofs: 1 / L's diagonal
  std::vector<double> mass;           // dofs × dofs, row-major: M (lower triangle)
  std::vector<double> g;              // dofs × rows: G = L⁻¹·Jᵀ (formed when needed)
  bool g_formed = false;              // g holds this step's G
  std::vector<double> g_lambda;       // dofs: scratch (Jᵀ·λ and its substitutions; a row's L⁻¹·Jᵀ)
};

}  // namespace gearsim::physics

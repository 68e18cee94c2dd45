#include <algorithm>
#include <cmath>
#include <vector>

#include "physics/planar_mass.hpp"

// verify.mass_matrix planar, the rows' side of PlanarMass: the diagonal of A = J·M⁻¹·Jᵀ, G = L⁻¹·Jᵀ
// and the dense A for the row-space solves (the folded solve's and Dantzig's), the velocity
// change of given impulses, the links' kinetic energy (planar_mass.cpp forms M and its factor L;
// primal_solve.cpp solves the rows in the coordinates' space).
namespace gearsim::physics {

// verify.mass_matrix planar: row r's diagonal of A = J·M⁻¹·Jᵀ, |L⁻¹·J_rᵀ|² (L of
// free_velocities(), this step's pose), where its compliance is taken relative to it (a
// row without a spring: a motor, sticking friction). The rows themselves are solved in the
// coordinates' space (PrimalSolve), without G = L⁻¹·Jᵀ; g() forms G for the
// row-space solves (the fallbacks).
double PlanarMass::diag_a(const RowSystem& rows, std::size_t r) {
  const std::size_t ud = dofs_;
  const double* m = chol_.data();
  const double* jr = rows.jrows.data() + r * ud;
  double* g = g_lambda_.data();
  double sum = 0;
  for (std::size_t i = 0; i < ud; ++i) {
    double v = jr[i];
    for (std::size_t k = 0; k < i; ++k) v -= m[i * ud + k] * g[k];
    g[i] = v * chol_inv_diag_[i];
    sum += g[i] * g[i];
  }
  return sum;
}

// G = L⁻¹·Jᵀ of this step's rows, for the row-space solves (FoldedSolve, full_a()).
// Kept by coordinate (dofs × rows): the substitutions run over all rows at once, one coordinate
// after the other, instead of one row's chain of dependent divisions after the other's.
const std::vector<double>& PlanarMass::g(const RowSystem& rows) {
  if (g_formed_) return g_;
  const std::size_t n = rows.rows.size(), ud = dofs_;
  const double* m = chol_.data();
  g_.resize(ud * n);
  double* g = g_.data();
  const double* jrows = rows.jrows.data();
  for (std::size_t i = 0; i < ud; ++i) {
    double* gi = g + i * n;
    for (std::size_t r = 0; r < n; ++r) gi[r] = jrows[r * ud + i];
    for (std::size_t k = 0; k < i; ++k) {
      const double lik = m[i * ud + k];
      if (lik == 0) continue;
      const double* gk = g + k * n;
      for (std::size_t r = 0; r < n; ++r) gi[r] -= lik * gk[r];
    }
    const double inv = chol_inv_diag_[i];
    for (std::size_t r = 0; r < n; ++r) gi[r] *= inv;
  }
  g_formed_ = true;
  return g_;
}

// The dense A = Gᵀ·G + diag(compliance), n × n, for Bullet's Dantzig solver (the active set's
// fallback): the upper triangle summed coordinate by coordinate, then mirrored.
void PlanarMass::full_a(RowSystem& rows) {
  if (a_formed_) return;
  g(rows);
  const std::size_t n = rows.rows.size(), ud = dofs_;
  rows.a.resize(n * n);
  double* a = rows.a.data();
  const double* g = g_.data();
  for (std::size_t r = 0; r < n; ++r) std::fill(a + r * n + r, a + r * n + n, 0.0);
  for (std::size_t k = 0; k < ud; ++k) {
    const double* gk = g + k * n;
    for (std::size_t r = 0; r < n; ++r) {
      const double gkr = gk[r];
      if (gkr == 0) continue;
      double* ar = a + r * n;
      for (std::size_t c = r; c < n; ++c) ar[c] += gkr * gk[c];
    }
  }
  for (std::size_t r = 0; r < n; ++r) {
    a[r * n + r] += rows.compliance[r];
    for (std::size_t c = r + 1; c < n; ++c) a[c * n + r] = a[r * n + c];
  }
  a_formed_ = true;
}

void PlanarMass::velocity_change(const RowSystem& rows, const double* lambda, double* dv) {
  const std::size_t n = rows.rows.size(), ud = dofs_;
  // dv = L⁻ᵀ·L⁻¹·(Jᵀ·λ)
  const double* m = chol_.data();
  const double* jrows = rows.jrows.data();
  double* y = g_lambda_.data();
  std::fill(g_lambda_.begin(), g_lambda_.end(), 0.0);
  for (std::size_t r = 0; r < n; ++r) {
    const double l = lambda[r];
    if (l == 0) continue;
    for (std::size_t i = 0; i < ud; ++i) y[i] += jrows[r * ud + i] * l;
  }
  for (std::size_t i = 0; i < ud; ++i) {
    double v = y[i];
    for (std::size_t k = 0; k < i; ++k) v -= m[i * ud + k] * y[k];
    y[i] = v * chol_inv_diag_[i];
  }
  for (std::size_t i = ud; i-- > 0;) {
    double v = g_lambda_[i];
    for (std::size_t k = i + 1; k < ud; ++k) v -= m[k * ud + i] * dv[k];
    dv[i] = v * chol_inv_diag_[i];
  }
}

// ½·m·|v|² + ½·I_zz·ω² over the links, from this pose's link velocities (the planar path holds no
// world inertia tensors of the bodies).
double PlanarMass::kinetic_energy_J(const PlanarKinematics& kin) const {
  const std::vector<double>&w = kin.link_w(), &vx = kin.link_vx(), &vy = kin.link_vy();
  double kinetic = 0;
  for (std::size_t l = 0; l < w.size(); ++l)
    kinetic += 0.5 * link_mass_kg_[l] * (vx[l] * vx[l] + vy[l] * vy[l]) + 0.5 * link_izz_kg_m2_[l] * w[l] * w[l];
  return kinetic;
}

}  // namespace gearsim::physics

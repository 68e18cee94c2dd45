#include <algorithm>
#include <cmath>
#include <vector>

#include "physics/world_impl.hpp"

// solver.mass_matrix planar, the rows' side: the diagonal of A = J·M⁻¹·Jᵀ, G = L⁻¹·Jᵀ and the
// dense A for the row-space solves (the active set's and Dantzig's fallbacks), the folded
// row-space solve, and the velocity change of given impulses (world_planar_mass.cpp forms M and
// its factor L; world_primal_solve.cpp solves the rows in the coordinates' space).
namespace gearsim::physics {

// solver.mass_matrix planar: row r's diagonal of A = J·M⁻¹·Jᵀ, |L⁻¹·J_rᵀ|² (L of
// planar_free_velocities(), this step's pose), where its compliance is taken relative to it (a
// row without a spring: a motor, sticking friction). The rows themselves are solved in the
// coordinates' space (solve_rows_primal), without G = L⁻¹·Jᵀ; planar_g() forms G for the
// row-space solves (the fallbacks).
double World::Impl::planar_diag_a(std::size_t r) {
  MultibodyEngine& e = *mb;
  const std::size_t ud = static_cast<std::size_t>(e.dofs);
  const double* m = e.chol.data();
  const double* jr = e.jrows.data() + r * ud;
  double* g = e.g_lambda.data();
  double sum = 0;
  for (std::size_t i = 0; i < ud; ++i) {
    double v = jr[i];
    for (std::size_t k = 0; k < i; ++k) v -= m[i * ud + k] * g[k];
    g[i] = v * e.chol_inv_diag[i];
    sum += g[i] * g[i];
  }
  return sum;
}

// G = L⁻¹·Jᵀ of this step's rows, for the row-space solves (solve_rows_folded, planar_full_a).
// Kept by coordinate (dofs × rows): the substitutions run over all rows at once, one coordinate
// after the other, instead of one row's chain of dependent divisions after the other's.
void World::Impl::planar_g() {
  MultibodyEngine& e = *mb;
  if (e.g_formed) return;
  const std::size_t n = e.rows.size(), ud = static_cast<std::size_t>(e.dofs);
  const double* m = e.chol.data();
  e.g.resize(ud * n);
  double* g = e.g.data();
  const double* jrows = e.jrows.data();
  for (std::size_t i = 0; i < ud; ++i) {
    double* gi = g + i * n;
    for (std::size_t r = 0; r < n; ++r) gi[r] = jrows[r * ud + i];
    for (std::size_t k = 0; k < i; ++k) {
      const double lik = m[i * ud + k];
      if (lik == 0) continue;
      const double* gk = g + k * n;
      for (std::size_t r = 0; r < n; ++r) gi[r] -= lik * gk[r];
    }
    const double inv = e.chol_inv_diag[i];
    for (std::size_t r = 0; r < n; ++r) gi[r] *= inv;
  }
  e.g_formed = true;
}

// The dense A = Gᵀ·G + diag(compliance), n × n, for Bullet's Dantzig solver (the active set's
// fallback): the upper triangle summed coordinate by coordinate, then mirrored.
void World::Impl::planar_full_a() {
  MultibodyEngine& e = *mb;
  if (e.a_formed) return;
  planar_g();
  const std::size_t n = e.rows.size(), ud = static_cast<std::size_t>(e.dofs);
  e.a.resize(n * n);
  double* a = e.a.data();
  const double* g = e.g.data();
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
    a[r * n + r] += e.compliance[r];
    for (std::size_t c = r + 1; c < n; ++c) a[c * n + r] = a[r * n + c];
  }
  e.a_formed = true;
}

// The active set on the folded rows (docs/solver.md, "The planar mass matrix"): a friction row
// held at a fixed multiple c of its normal's impulse (lo = hi: sliding friction) is no unknown and
// has no condition, so it leaves the problem, its impulse folded into its normal's column —
// A'_iu = g_i·(g_u + Σ c_t·g_t) over the held rows t of normal u — and restored after the solve
// (c·λ_u; 0 where the normal carries nothing). The same solution as the full rows' (the active set
// there does the same folding, row by row); n² dot products of the full A become (n − held)².
// Returns the linear solves it took, 0 where it did not settle.
int World::Impl::solve_rows_folded() {
  MultibodyEngine& e = *mb;
  planar_g();
  const std::size_t n = e.rows.size(), ud = static_cast<std::size_t>(e.dofs);
  const double* g = e.g.data();
  e.fold_index.assign(n, -1);
  e.fold_kept.clear();
  for (std::size_t i = 0; i < n; ++i)
    if (!e.held_friction(i)) e.fold_index[i] = static_cast<int>(e.fold_kept.size()), e.fold_kept.push_back(static_cast<int>(i));
  const std::size_t m = e.fold_kept.size();
  // Per kept row its g and its column's h = g plus its held friction rows' c·g, by row.
  e.fold_g.resize(m * ud);
  e.fold_h.resize(m * ud);
  for (std::size_t r = 0; r < m; ++r)
    for (std::size_t k = 0; k < ud; ++k) e.fold_h[r * ud + k] = e.fold_g[r * ud + k] = g[k * n + static_cast<std::size_t>(e.fold_kept[r])];
  for (std::size_t t = 0; t < n; ++t) {
    if (e.fold_index[t] >= 0) continue;
    double* h = e.fold_h.data() + static_cast<std::size_t>(e.fold_index[static_cast<std::size_t>(e.findex[t])]) * ud;
    for (std::size_t k = 0; k < ud; ++k) h[k] += e.lo[t] * g[k * n + t];
  }
  e.fold_a.resize(m * m);
  e.fold_b.resize(m);
  e.fold_lo.resize(m);
  e.fold_hi.resize(m);
  e.fold_x.resize(m);
  e.fold_findex.resize(m);
  e.fold_states.resize(m);
  for (std::size_t r = 0; r < m; ++r) {
    const std::size_t i = static_cast<std::size_t>(e.fold_kept[r]);
    const double* gr = e.fold_g.data() + r * ud;
    for (std::size_t c = 0; c < m; ++c) {
      const double* hc = e.fold_h.data() + c * ud;
      double v = 0;
      for (std::size_t k = 0; k < ud; ++k) v += gr[k] * hc[k];
      e.fold_a[r * m + c] = v;
    }
    e.fold_a[r * m + r] += e.compliance[i];
    e.fold_b[r] = e.b[i];
    e.fold_lo[r] = e.lo[i];
    e.fold_hi[r] = e.hi[i];
    e.fold_findex[r] = e.findex[i] >= 0 ? e.fold_index[static_cast<std::size_t>(e.findex[i])] : -1;
    e.fold_states[r] = e.row_states[i];
  }
  const int solves = solve_row_lcp(static_cast<int>(m), e.fold_a.data(), e.fold_b.data(), e.fold_lo.data(), e.fold_hi.data(),
                                   e.fold_findex.data(), e.fold_x.data(), e.fold_states.data(), e.lcp);
  if (solves == 0) return 0;
  for (std::size_t r = 0; r < m; ++r) {
    const std::size_t i = static_cast<std::size_t>(e.fold_kept[r]);
    e.x[i] = e.fold_x[r];
    e.row_states[i] = e.fold_states[r];
  }
  for (std::size_t t = 0; t < n; ++t) {
    if (e.fold_index[t] >= 0) continue;
    const double normal = e.x[static_cast<std::size_t>(e.findex[t])];
    e.x[t] = normal == 0 ? 0.0 : e.lo[t] * normal;
    e.row_states[t] = RowBound::lower;
  }
  return solves;
}

void World::Impl::velocity_change(const double* lambda, double* dv) {
  MultibodyEngine& e = *mb;
  const std::size_t n = e.rows.size(), ud = static_cast<std::size_t>(e.dofs);
  if (!e.planar_mass) {
    Eigen::Map<Eigen::VectorXd>(dv, e.dofs).noalias() = e.minv_jt * Eigen::Map<const Eigen::VectorXd>(lambda, static_cast<Eigen::Index>(n));
    return;
  }
  // dv = L⁻ᵀ·L⁻¹·(Jᵀ·λ)
  const double* m = e.chol.data();
  const double* jrows = e.jrows.data();
  double* y = e.g_lambda.data();
  std::fill(e.g_lambda.begin(), e.g_lambda.end(), 0.0);
  for (std::size_t r = 0; r < n; ++r) {
    const double l = lambda[r];
    if (l == 0) continue;
    for (std::size_t i = 0; i < ud; ++i) y[i] += jrows[r * ud + i] * l;
  }
  for (std::size_t i = 0; i < ud; ++i) {
    double v = y[i];
    for (std::size_t k = 0; k < i; ++k) v -= m[i * ud + k] * y[k];
    y[i] = v * e.chol_inv_diag[i];
  }
  for (std::size_t i = ud; i-- > 0;) {
    double v = e.g_lambda[i];
    for (std::size_t k = i + 1; k < ud; ++k) v -= m[k * ud + i] * dv[k];
    dv[i] = v * e.chol_inv_diag[i];
  }
}

// The velocity change of this step's impulses e.x. Where the dof-space solve found them
// (solve_rows_planar), the dv it solved them with: M·dv = Jᵀ·x to rounding, so M⁻¹·Jᵀ·x need
// not be formed again (World::set_mass_matrix_check compares the two).
void World::Impl::velocity_change_of_x(double* dv) {
  MultibodyEngine& e = *mb;
  if (!(e.planar_mass && e.primal_dv_of_x)) {
    velocity_change(e.x.data(), dv);
    return;
  }
  std::copy(e.primal_dv.begin(), e.primal_dv.end(), dv);
  if (!e.check_mass) return;
  std::vector<double> reference(e.primal_dv.size());
  velocity_change(e.x.data(), reference.data());
  double scale = 0, difference = 0;
  for (std::size_t k = 0; k < reference.size(); ++k) {
    scale = std::max(scale, std::abs(reference[k]));
    difference = std::max(difference, std::abs(reference[k] - dv[k]));
  }
  ++e.mass_check.velocity_changes_compared;
  if (scale > 0) e.mass_check.velocity_change_difference = std::max(e.mass_check.velocity_change_difference, difference / scale);
}

}  // namespace gearsim::physics

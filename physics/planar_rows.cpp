#include <algorithm>
#include <cmath>
#include <vector>

#include "physics/multibody_engine.hpp"

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
double MultibodyEngine::planar_diag_a(std::size_t r) {
  const std::size_t ud = static_cast<std::size_t>(dofs_);
  const double* m = mass_.chol.data();
  const double* jr = rows_.jrows.data() + r * ud;
  double* g = mass_.g_lambda.data();
  double sum = 0;
  for (std::size_t i = 0; i < ud; ++i) {
    double v = jr[i];
    for (std::size_t k = 0; k < i; ++k) v -= m[i * ud + k] * g[k];
    g[i] = v * mass_.chol_inv_diag[i];
    sum += g[i] * g[i];
  }
  return sum;
}

// G = L⁻¹·Jᵀ of this step's rows, for the row-space solves (solve_rows_folded, planar_full_a).
// Kept by coordinate (dofs × rows): the substitutions run over all rows at once, one coordinate
// after the other, instead of one row's chain of dependent divisions after the other's.
void MultibodyEngine::planar_g() {
  if (mass_.g_formed) return;
  const std::size_t n = rows_.rows.size(), ud = static_cast<std::size_t>(dofs_);
  const double* m = mass_.chol.data();
  mass_.g.resize(ud * n);
  double* g = mass_.g.data();
  const double* jrows = rows_.jrows.data();
  for (std::size_t i = 0; i < ud; ++i) {
    double* gi = g + i * n;
    for (std::size_t r = 0; r < n; ++r) gi[r] = jrows[r * ud + i];
    for (std::size_t k = 0; k < i; ++k) {
      const double lik = m[i * ud + k];
      if (lik == 0) continue;
      const double* gk = g + k * n;
      for (std::size_t r = 0; r < n; ++r) gi[r] -= lik * gk[r];
    }
    const double inv = mass_.chol_inv_diag[i];
    for (std::size_t r = 0; r < n; ++r) gi[r] *= inv;
  }
  mass_.g_formed = true;
}

// The dense A = Gᵀ·G + diag(compliance), n × n, for Bullet's Dantzig solver (the active set's
// fallback): the upper triangle summed coordinate by coordinate, then mirrored.
void MultibodyEngine::planar_full_a() {
  if (rows_.a_formed) return;
  planar_g();
  const std::size_t n = rows_.rows.size(), ud = static_cast<std::size_t>(dofs_);
  rows_.a.resize(n * n);
  double* a = rows_.a.data();
  const double* g = mass_.g.data();
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
    a[r * n + r] += rows_.compliance[r];
    for (std::size_t c = r + 1; c < n; ++c) a[c * n + r] = a[r * n + c];
  }
  rows_.a_formed = true;
}

// The active set on the folded rows (docs/solver.md, "The planar mass matrix"): a friction row
// held at a fixed multiple c of its normal's impulse (lo = hi: sliding friction) is no unknown and
// has no condition, so it leaves the problem, its impulse folded into its normal's column —
// A'_iu = g_i·(g_u + Σ c_t·g_t) over the held rows t of normal u — and restored after the solve
// (c·λ_u; 0 where the normal carries nothing). The same solution as the full rows' (the active set
// there does the same folding, row by row); n² dot products of the full A become (n − held)².
// Returns the linear solves it took, 0 where it did not settle.
int MultibodyEngine::solve_rows_folded() {
  planar_g();
  const std::size_t n = rows_.rows.size(), ud = static_cast<std::size_t>(dofs_);
  const double* g = mass_.g.data();
  folded_.index.assign(n, -1);
  folded_.kept.clear();
  for (std::size_t i = 0; i < n; ++i)
    if (!rows_.held_friction(i)) folded_.index[i] = static_cast<int>(folded_.kept.size()), folded_.kept.push_back(static_cast<int>(i));
  const std::size_t m = folded_.kept.size();
  // Per kept row its g and its column's h = g plus its held friction rows' c·g, by row.
  folded_.g.resize(m * ud);
  folded_.h.resize(m * ud);
  for (std::size_t r = 0; r < m; ++r)
    for (std::size_t k = 0; k < ud; ++k) folded_.h[r * ud + k] = folded_.g[r * ud + k] = g[k * n + static_cast<std::size_t>(folded_.kept[r])];
  for (std::size_t t = 0; t < n; ++t) {
    if (folded_.index[t] >= 0) continue;
    double* h = folded_.h.data() + static_cast<std::size_t>(folded_.index[static_cast<std::size_t>(rows_.findex[t])]) * ud;
    for (std::size_t k = 0; k < ud; ++k) h[k] += rows_.lo[t] * g[k * n + t];
  }
  folded_.a.resize(m * m);
  folded_.b.resize(m);
  folded_.lo.resize(m);
  folded_.hi.resize(m);
  folded_.x.resize(m);
  folded_.findex.resize(m);
  folded_.states.resize(m);
  for (std::size_t r = 0; r < m; ++r) {
    const std::size_t i = static_cast<std::size_t>(folded_.kept[r]);
    const double* gr = folded_.g.data() + r * ud;
    for (std::size_t c = 0; c < m; ++c) {
      const double* hc = folded_.h.data() + c * ud;
      double v = 0;
      for (std::size_t k = 0; k < ud; ++k) v += gr[k] * hc[k];
      folded_.a[r * m + c] = v;
    }
    folded_.a[r * m + r] += rows_.compliance[i];
    folded_.b[r] = rows_.b[i];
    folded_.lo[r] = rows_.lo[i];
    folded_.hi[r] = rows_.hi[i];
    folded_.findex[r] = rows_.findex[i] >= 0 ? folded_.index[static_cast<std::size_t>(rows_.findex[i])] : -1;
    folded_.states[r] = active_.row_states[i];
  }
  const int solves = solve_row_lcp(static_cast<int>(m), folded_.a.data(), folded_.b.data(), folded_.lo.data(), folded_.hi.data(),
                                   folded_.findex.data(), folded_.x.data(), folded_.states.data(), active_.lcp);
  if (solves == 0) return 0;
  for (std::size_t r = 0; r < m; ++r) {
    const std::size_t i = static_cast<std::size_t>(folded_.kept[r]);
    rows_.x[i] = folded_.x[r];
    active_.row_states[i] = folded_.states[r];
  }
  for (std::size_t t = 0; t < n; ++t) {
    if (folded_.index[t] >= 0) continue;
    const double normal = rows_.x[static_cast<std::size_t>(rows_.findex[t])];
    rows_.x[t] = normal == 0 ? 0.0 : rows_.lo[t] * normal;
    active_.row_states[t] = RowBound::lower;
  }
  return solves;
}

void MultibodyEngine::velocity_change(const double* lambda, double* dv) {
  const std::size_t n = rows_.rows.size(), ud = static_cast<std::size_t>(dofs_);
  if (!planar_mass_) {
    Eigen::Map<Eigen::VectorXd>(dv, dofs_).noalias() = rows_.minv_jt * Eigen::Map<const Eigen::VectorXd>(lambda, static_cast<Eigen::Index>(n));
    return;
  }
  // dv = L⁻ᵀ·L⁻¹·(Jᵀ·λ)
  const double* m = mass_.chol.data();
  const double* jrows = rows_.jrows.data();
  double* y = mass_.g_lambda.data();
  std::fill(mass_.g_lambda.begin(), mass_.g_lambda.end(), 0.0);
  for (std::size_t r = 0; r < n; ++r) {
    const double l = lambda[r];
    if (l == 0) continue;
    for (std::size_t i = 0; i < ud; ++i) y[i] += jrows[r * ud + i] * l;
  }
  for (std::size_t i = 0; i < ud; ++i) {
    double v = y[i];
    for (std::size_t k = 0; k < i; ++k) v -= m[i * ud + k] * y[k];
    y[i] = v * mass_.chol_inv_diag[i];
  }
  for (std::size_t i = ud; i-- > 0;) {
    double v = mass_.g_lambda[i];
    for (std::size_t k = i + 1; k < ud; ++k) v -= m[k * ud + i] * dv[k];
    dv[i] = v * mass_.chol_inv_diag[i];
  }
}

// The velocity change of this step's impulses rows_.x. Where the dof-space solve found them
// (solve_rows_planar), the dv it solved them with: M·dv = Jᵀ·x to rounding, so M⁻¹·Jᵀ·x need
// not be formed again (World::set_mass_matrix_check compares the two).
void MultibodyEngine::velocity_change_of_x(double* dv) {
  if (!(planar_mass_ && primal_.dv_of_x)) {
    velocity_change(rows_.x.data(), dv);
    return;
  }
  std::copy(primal_.dv.begin(), primal_.dv.end(), dv);
  if (!check_mass_) return;
  std::vector<double> reference(primal_.dv.size());
  velocity_change(rows_.x.data(), reference.data());
  double scale = 0, difference = 0;
  for (std::size_t k = 0; k < reference.size(); ++k) {
    scale = std::max(scale, std::abs(reference[k]));
    difference = std::max(difference, std::abs(reference[k] - dv[k]));
  }
  ++mass_check_.velocity_changes_compared;
  if (scale > 0) mass_check_.velocity_change_difference = std::max(mass_check_.velocity_change_difference, difference / scale);
}

}  // namespace gearsim::physics

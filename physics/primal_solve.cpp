#include "physics/primal_solve.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "physics/dense_lu.hpp"
#include "physics/dof_dispatch.hpp"
#include "physics/row_lcp.hpp"

// The rows of a planar tree solved in the space of its coordinates (docs/solver.md, "The row
// solve in the coordinates' space"): the same mixed LCP as solve_row_lcp() on the folded rows,
// from the same bound states and to the same conditions, with one factorisation of a dofs × dofs
// matrix per solve instead of one of the rows' (n × n, n ≈ 2 × the coordinates on a gear set).
namespace gearsim::physics {
namespace {

constexpr double kPrimalRelativeTolerance = 1e-9;  // as solve_row_lcp()
constexpr int kMaxPrimalSolves = 8;  // as solve_row_lcp()'s default
// A spring row whose compliance is below this times its diagonal A_ii = J_i·M⁻¹·J_iᵀ (a spring
// far stiffer than the step resolves) is solved as a stiff row: in K its 1/D would raise the
// condition number by up to A_ii/D.
constexpr double kSoftSpring = 1e-4;

double dot(const double* a, const double* b, std::size_t n) {
  double s = 0;
  for (std::size_t i = 0; i < n; ++i) s += a[i] * b[i];
  return s;
}

}  // namespace

// Which of this step's rows enter K (soft springs) and which the Schur system of
// the dof-space solve (the rest): once per step, after the rows' compliances (the rows and
// their compliances stay the step's through the slip reversals' solves again). A_ii ≤
// trace(M⁻¹)·|J_i|² (M⁻¹ is positive definite), trace(M⁻¹) = ‖L⁻¹‖²_F: the exact A_ii only where
// that bound leaves the question open.
void PrimalSolve::classify_rows(const RowSystem& rows, PlanarMass& mass, int dofs) {
  with_dof_count(dofs, [&](auto count) { classify_rows_n<decltype(count)::value>(rows, mass, dofs); });
}

template <int N>
void PrimalSolve::classify_rows_n(const RowSystem& rows, PlanarMass& mass, int dofs) {
  const std::size_t n = rows.rows.size(), ud = N > 0 ? static_cast<std::size_t>(N) : static_cast<std::size_t>(dofs);
  const double* jrows = rows.jrows.data();
  const auto j = [&](std::size_t i) { return jrows + i * ud; };
  const double* d = rows.compliance.data();
  double trace_minv = 0;
  {
    const double* l = mass.chol().data();
    std::vector<double>& col = mass.scratch();  // scratch: column c of L⁻¹
    // Column c of L⁻¹ is zero above its diagonal (L lower triangular): only rows i ≥ c are
    // formed and summed (the zeros added nothing to the trace).
    for (std::size_t c = 0; c < ud; ++c) {
      for (std::size_t i = c; i < ud; ++i) {
        double v = i == c ? 1.0 : 0.0;
        for (std::size_t k = c; k < i; ++k) v -= l[i * ud + k] * col[k];
        col[i] = v * mass.chol_inv_diag()[i];
        trace_minv += col[i] * col[i];
      }
    }
  }
  w_.soft.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    bool soft = rows.rows[i].cfm > 0;
    if (soft && !(d[i] >= kSoftSpring * trace_minv * dot(j(i), j(i), ud))) soft = d[i] >= kSoftSpring * mass.diag_a(rows, i);
    w_.soft[i] = soft;
  }
}

// The step's rows as primal_solve() reads them: Jacobians, bounds, right-hand sides,
// compliances, friction links, bound states and impulses.
namespace {

template <int N>
struct PrimalRows {
  PrimalRows(RowSystem& rs, RowBound* states, const double* mass_lower, int dofs)
      : n(rs.rows.size()),
        ud(N > 0 ? static_cast<std::size_t>(N) : static_cast<std::size_t>(dofs)),
        jrows(rs.jrows.data()),
        state(states),
        lo(rs.lo.data()),
        hi(rs.hi.data()),
        b(rs.b.data()),
        d(rs.compliance.data()),
        findex(rs.findex.data()),
        x(rs.x.data()),
        mass(mass_lower) {}
  const double* j(std::size_t i) const { return jrows + i * ud; }
  // Friction whose normal sits at a zero lower bound: its impulse is 0.
  bool pinned(std::size_t i) const { return findex[i] >= 0 && state[findex[i]] == RowBound::lower && lo[findex[i]] == 0; }
  // Friction held at a multiple of its normal's impulse (an empty box).
  bool held(std::size_t i) const { return findex[i] >= 0 && !(hi[i] > lo[i]); }
  std::size_t n, ud;
  const double* jrows;
  RowBound* state;
  const double *lo, *hi, *b, *d;
  const int* findex;
  double* x;
  const double* mass;  // M, lower triangle, ud × ud row-major
};

// Unknowns: the free rows (not pinned, not held), the stiff ones among them apart.
template <int N>
void primal_unknowns(PrimalWork& e, const PrimalRows<N>& r) {
  e.rows.clear();
  e.stiff.clear();
  for (std::size_t i = 0; i < r.n; ++i) {
    e.unknown[i] = -1;
    if (r.state[i] == RowBound::free && !r.pinned(i) && !r.held(i)) {
      e.unknown[i] = static_cast<int>(e.rows.size());
      e.rows.push_back(static_cast<int>(i));
      if (!e.soft[i]) e.stiff.push_back(static_cast<int>(i));
    }
  }
}

// Columns: each unknown's J, with the friction held at a multiple c of it (held rows, box
// friction on a bound) folded in; the constants' impulses into f₀ (e.constant).
template <int N>
void primal_columns(PrimalWork& e, const PrimalRows<N>& r) {
  const std::size_t m = e.rows.size(), ud = r.ud;
  double* x = r.x;
  e.cols.resize(m * ud);
  for (std::size_t u = 0; u < m; ++u)
    std::copy(r.j(static_cast<std::size_t>(e.rows[u])), r.j(static_cast<std::size_t>(e.rows[u])) + ud,
              e.cols.begin() + static_cast<std::ptrdiff_t>(u * ud));
  double* f0 = e.constant.data();
  std::fill(f0, f0 + ud, 0.0);
  for (std::size_t i = 0; i < r.n; ++i) {
    if (e.unknown[i] >= 0 || r.findex[i] >= 0) continue;
    x[i] = r.state[i] == RowBound::lower ? r.lo[i] : r.hi[i];  // a row on a bound
    if (x[i] != 0)
      for (std::size_t k = 0; k < ud; ++k) f0[k] += r.j(i)[k] * x[i];
  }
  for (std::size_t i = 0; i < r.n; ++i) {
    if (e.unknown[i] >= 0 || r.findex[i] < 0) continue;
    if (r.pinned(i)) {
      x[i] = 0;
      continue;
    }
    const double c = r.held(i) || r.state[i] == RowBound::lower ? r.lo[i] : r.hi[i];
    const std::size_t f = static_cast<std::size_t>(r.findex[i]);
    if (e.unknown[f] >= 0) {
      double* col = e.cols.data() + static_cast<std::size_t>(e.unknown[f]) * ud;
      for (std::size_t k = 0; k < ud; ++k) col[k] += c * r.j(i)[k];
    } else {
      x[i] = c * x[f];
      if (x[i] != 0)
        for (std::size_t k = 0; k < ud; ++k) f0[k] += r.j(i)[k] * x[i];
    }
  }
}

// K = M + Σ_springs J_f,u·J_uᵀ/D_u (e.k) and its right-hand side f₀ + Σ_springs
// J_f,u·b_u/D_u (e.rhs).
template <int N>
void primal_k(PrimalWork& e, const PrimalRows<N>& r) {
  const std::size_t m = e.rows.size(), ud = r.ud;
  double* kk = e.k.data();
  double* rhs = e.rhs.data();
  for (std::size_t a = 0; a < ud; ++a)
    for (std::size_t c = 0; c < ud; ++c) kk[a * ud + c] = c <= a ? r.mass[a * ud + c] : r.mass[c * ud + a];
  std::copy(e.constant.data(), e.constant.data() + ud, rhs);
  for (std::size_t u = 0; u < m; ++u) {
    const std::size_t i = static_cast<std::size_t>(e.rows[u]);
    if (!e.soft[i]) continue;
    const double inv_d = 1 / r.d[i];
    const double* col = e.cols.data() + u * ud;
    const double* ji = r.j(i);
    for (std::size_t a = 0; a < ud; ++a) {
      const double ca = col[a] * inv_d;
      if (ca == 0) continue;
      rhs[a] += ca * r.b[i];
      double* row = kk + a * ud;
      for (std::size_t c = 0; c < ud; ++c) row[c] += ca * ji[c];
    }
  }
}

// The stiff rows, with K factorised and dv₀ in e.dv: Y = K⁻¹·J_f,R, then
// (D_R + J_R·Y)·λ_R = b_R − J_R·dv₀; λ_R into x and Y·λ_R added to dv. False where the Schur
// matrix does not factorise.
template <int N>
bool primal_stiff_rows(PrimalWork& e, const PrimalRows<N>& r) {
  const std::size_t ms = e.stiff.size(), ud = r.ud;
  const int dofs = static_cast<int>(ud);
  double* dv = e.dv.data();
  e.y.resize(ms * ud);
  e.s.resize(ms * ms);
  e.t.resize(ms);
  for (std::size_t q = 0; q < ms; ++q) {
    const std::size_t i = static_cast<std::size_t>(e.stiff[q]);
    double* y = e.y.data() + q * ud;
    const double* col = e.cols.data() + static_cast<std::size_t>(e.unknown[i]) * ud;
    std::copy(col, col + ud, y);
    lu_solve<N>(dofs, e.k.data(), e.pivots.data(), y);
  }
  for (std::size_t q = 0; q < ms; ++q) {
    const std::size_t i = static_cast<std::size_t>(e.stiff[q]);
    for (std::size_t c = 0; c < ms; ++c) e.s[q * ms + c] = dot(r.j(i), e.y.data() + c * ud, ud) + (q == c ? r.d[i] : 0.0);
    e.t[q] = r.b[i] - dot(r.j(i), dv, ud);
  }
  std::vector<int>& piv = e.stiff_pivots;
  piv.resize(ms);
  if (!lu_factor(static_cast<int>(ms), e.s.data(), piv.data())) return false;
  lu_solve(static_cast<int>(ms), e.s.data(), piv.data(), e.t.data());
  for (std::size_t q = 0; q < ms; ++q) {
    r.x[static_cast<std::size_t>(e.stiff[q])] = e.t[q];
    const double* y = e.y.data() + q * ud;
    for (std::size_t k = 0; k < ud; ++k) dv[k] += y[k] * e.t[q];
  }
  return true;
}

// The springs' impulses from dv, then the folded friction from its normal. True when a row has
// conditions on w (one on a bound, not held).
template <int N>
bool primal_impulses(PrimalWork& e, const PrimalRows<N>& r) {
  const double* dv = e.dv.data();
  double* x = r.x;
  for (std::size_t u = 0; u < e.rows.size(); ++u) {
    const std::size_t i = static_cast<std::size_t>(e.rows[u]);
    if (e.soft[i]) x[i] = (r.b[i] - dot(r.j(i), dv, r.ud)) / r.d[i];
  }
  bool on_bound = false;
  for (std::size_t i = 0; i < r.n; ++i) {
    if (e.unknown[i] >= 0) continue;
    if (!r.held(i) && !r.pinned(i)) on_bound = true;
    if (r.findex[i] < 0 || r.pinned(i)) continue;
    const std::size_t f = static_cast<std::size_t>(r.findex[i]);
    if (e.unknown[f] >= 0) x[i] = (r.held(i) || r.state[i] == RowBound::lower ? r.lo[i] : r.hi[i]) * x[f];
  }
  return on_bound;
}

// The conditions' scales over the rows that have conditions (held friction has none: it is not
// a row of the folded problem); w = A·x − b = J·dv + D·x − b where a row sits on a bound (a free
// row's w is 0: it has none to meet) into e.w. False where a value is not finite.
template <int N>
bool primal_scales(PrimalWork& e, const PrimalRows<N>& r, bool on_bound, double& x_scale, double& w_scale) {
  const double* dv = e.dv.data();
  x_scale = 0, w_scale = 0;
  for (std::size_t i = 0; i < r.n; ++i) {
    if (!std::isfinite(r.x[i])) return false;
    if (r.held(i)) continue;
    x_scale = std::max(x_scale, std::abs(r.x[i]));
  }
  if (on_bound) {
    for (std::size_t i = 0; i < r.n; ++i) {
      const double ax = dot(r.j(i), dv, r.ud) + r.d[i] * r.x[i];
      e.w[i] = ax - r.b[i];
      if (!std::isfinite(ax)) return false;
      if (r.held(i)) continue;
      w_scale = std::max({w_scale, std::abs(r.b[i]), std::abs(ax)});
    }
  }
  return true;
}

template <int N>
int primal_solve(PrimalWork& e, RowSystem& rows, RowBound* states, const double* mass, int tree_dofs) {
  const PrimalRows<N> r(rows, states, mass, tree_dofs);
  const std::size_t n = r.n, ud = r.ud;
  const int dofs = static_cast<int>(ud);
  e.unknown.resize(n);
  e.w.resize(n);
  e.dv.resize(ud);
  e.constant.resize(ud);
  e.rhs.resize(ud);
  e.k.resize(ud * ud);
  e.pivots.resize(ud);
  for (int solves = 1; solves <= kMaxPrimalSolves; ++solves) {
    primal_unknowns(e, r);
    primal_columns(e, r);
    primal_k(e, r);
    double* kk = e.k.data();
    double* rhs = e.rhs.data();
    if (!lu_factor<N>(dofs, kk, e.pivots.data())) return 0;
    lu_solve<N>(dofs, kk, e.pivots.data(), rhs);  // dv of the springs and constants alone
    std::copy(rhs, rhs + ud, e.dv.data());
    if (!e.stiff.empty() && !primal_stiff_rows(e, r)) return 0;
    const bool on_bound = primal_impulses(e, r);
    double x_scale, w_scale;
    if (!primal_scales(e, r, on_bound, x_scale, w_scale)) return 0;
    if (settle_row_states(static_cast<int>(n), r.x, on_bound ? e.w.data() : nullptr, r.lo, r.hi, r.findex, r.state, solves,
                          kPrimalRelativeTolerance * x_scale, kPrimalRelativeTolerance * w_scale)) {
      for (std::size_t i = 0; i < n; ++i)
        if (r.held(i)) r.state[i] = RowBound::lower;
      return solves;
    }
  }
  return 0;
}

}  // namespace

int PrimalSolve::solve(RowSystem& rows, std::vector<RowBound>& states, const std::vector<double>& mass, int dofs) {
  w_.dv_of_x = false;
  const int solves = with_dof_count(dofs, [&](auto n) {
    constexpr int N = decltype(n)::value;
    return primal_solve<N>(w_, rows, states.data(), mass.data(), dofs);
  });
  w_.dv_of_x = solves > 0;
  return solves;
}

}  // namespace gearsim::physics

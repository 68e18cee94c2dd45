// The active-set solve of the multibody rows (physics/row_lcp.hpp) against Bullet's Dantzig LCP
// solver on systems built as the engine builds them: A = J·M⁻¹·Jᵀ + compliances, rows of tooth
// contacts (normal λ ≥ 0 with a spring's compliance, friction within ±μ·λ_n), a bilateral bearing
// spring and a torque-limited motor. Where both solve, they give the same impulses; the solution
// satisfies every complementarity condition; a warm start from the solution settles in one solve.
#include <gtest/gtest.h>

#include <BulletDynamics/MLCPSolvers/btDantzigLCP.h>

#include <Eigen/Dense>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "physics/row_lcp.hpp"

namespace gearsim::physics {
namespace test_row_lcp {

constexpr double kInf = std::numeric_limits<double>::infinity();

struct Problem {
  int n = 0;
  std::vector<double> A, b, lo, hi;
  std::vector<int> findex;
};

// `contacts` tooth contacts on a tree of `dofs` coordinates, then a bearing row and a motor row.
// Right-hand sides as a step makes them: springs pressed by up to a micrometre, bodies moving.
Problem make_problem(std::mt19937_64& rng, int contacts, int dofs, double mu) {
  std::uniform_real_distribution<double> u(-1, 1);
  Problem p;
  p.n = 2 * contacts + 2;
  Eigen::MatrixXd J(p.n, dofs), L(dofs, dofs);
  for (int i = 0; i < p.n; ++i)
    for (int j = 0; j < dofs; ++j) J(i, j) = u(rng) * 0.03;  // lever arms of ~30 mm
  for (int i = 0; i < dofs; ++i)
    for (int j = 0; j < dofs; ++j) L(i, j) = u(rng);
  const Eigen::MatrixXd minv = (L * L.transpose() + dofs * Eigen::MatrixXd::Identity(dofs, dofs)) * 1e2;  // ~1e2–1e3 per kg·m²
  Eigen::MatrixXd A = J * minv * J.transpose();
  const double h = 1e-5, k = 1.4e8, c = 400;
  p.b.assign(static_cast<std::size_t>(p.n), 0.0);
  p.lo.assign(static_cast<std::size_t>(p.n), 0.0);
  p.hi.assign(static_cast<std::size_t>(p.n), 0.0);
  p.findex.assign(static_cast<std::size_t>(p.n), -1);
  for (int i = 0; i < contacts; ++i) {
    const int nrow = 2 * i, frow = 2 * i + 1;
    const double sigma = h * k + c;
    A(nrow, nrow) += 1 / (h * sigma);
    p.b[static_cast<std::size_t>(nrow)] = k * 1e-6 * (u(rng) + 0.3) / sigma + 0.02 * u(rng);  // pressed or just apart, approaching or not
    p.lo[static_cast<std::size_t>(nrow)] = 0, p.hi[static_cast<std::size_t>(nrow)] = kInf;
    A(frow, frow) *= 1 + 1e-8;  // the engine's compliance of rows without a spring
    p.b[static_cast<std::size_t>(frow)] = 0.5 * u(rng);  // sliding speed to stop
    p.lo[static_cast<std::size_t>(frow)] = -mu, p.hi[static_cast<std::size_t>(frow)] = mu;
    p.findex[static_cast<std::size_t>(frow)] = nrow;
  }
  const int bearing = 2 * contacts, motor = bearing + 1;
  A(bearing, bearing) += 1 / (h * (h * 5e7 + 50));
  p.b[static_cast<std::size_t>(bearing)] = 0.01 * u(rng);
  p.lo[static_cast<std::size_t>(bearing)] = -kInf, p.hi[static_cast<std::size_t>(bearing)] = kInf;
  A(motor, motor) *= 1 + 1e-8;
  p.b[static_cast<std::size_t>(motor)] = u(rng);
  p.lo[static_cast<std::size_t>(motor)] = -50 * h, p.hi[static_cast<std::size_t>(motor)] = 50 * h;
  p.A.assign(static_cast<std::size_t>(p.n) * static_cast<std::size_t>(p.n), 0.0);
  for (int i = 0; i < p.n; ++i)
    for (int j = 0; j < p.n; ++j) p.A[static_cast<std::size_t>(i * p.n + j)] = A(i, j);
  return p;
}

std::vector<double> dantzig(Problem p) {  // a copy: Dantzig works in place
  std::vector<double> x(static_cast<std::size_t>(p.n), 0.0), w(static_cast<std::size_t>(p.n), 0.0);
  btDantzigScratchMemory scratch;
  EXPECT_TRUE(btSolveDantzigLCP(p.n, p.A.data(), x.data(), p.b.data(), w.data(), 0, p.lo.data(), p.hi.data(), p.findex.data(), scratch));
  return x;
}

// Largest breach of the conditions, relative to the problem's impulses and rates.
double breach(const Problem& p, const std::vector<double>& x) {
  double xs = 0, ws = 0, worst = 0;
  std::vector<double> w(static_cast<std::size_t>(p.n));
  for (int i = 0; i < p.n; ++i) {
    double ax = 0;
    for (int j = 0; j < p.n; ++j) ax += p.A[static_cast<std::size_t>(i * p.n + j)] * x[static_cast<std::size_t>(j)];
    w[static_cast<std::size_t>(i)] = ax - p.b[static_cast<std::size_t>(i)];
    xs = std::max(xs, std::abs(x[static_cast<std::size_t>(i)]));
    ws = std::max({ws, std::abs(ax), std::abs(p.b[static_cast<std::size_t>(i)])});
  }
  for (int i = 0; i < p.n; ++i) {
    const std::size_t u = static_cast<std::size_t>(i);
    const double f = p.findex[u] >= 0 ? x[static_cast<std::size_t>(p.findex[u])] : 1;
    const double l = p.findex[u] >= 0 ? p.lo[u] * f : p.lo[u], h = p.findex[u] >= 0 ? p.hi[u] * f : p.hi[u];
    const double below = (l - x[u]) / xs, above = (x[u] - h) / xs;
    worst = std::max({worst, below, above});
    // On a bound or between: w's sign (inside, w = 0).
    const double gap_lo = (x[u] - l) / xs, gap_hi = (h - x[u]) / xs;
    if (gap_lo > 1e-7 && gap_hi > 1e-7)
      worst = std::max(worst, std::abs(w[u]) / ws);
    else if (gap_lo <= 1e-7 && gap_hi > 1e-7)
      worst = std::max(worst, -w[u] / ws);
    else if (gap_hi <= 1e-7 && gap_lo > 1e-7)
      worst = std::max(worst, w[u] / ws);
  }
  return worst;
}

TEST(RowLcp, GivesDantzigsImpulsesOnTheEnginesKindOfSystem) {
  std::mt19937_64 rng(18);
  int cold_solves = 0, cases = 0;
  double worst_dantzig = 0, worst_diff = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const int contacts = 1 + trial % 12, dofs = 3 + trial % 7;
    const Problem p = make_problem(rng, contacts, dofs, trial % 3 == 0 ? 0.0 : 0.05);
    std::vector<double> x(static_cast<std::size_t>(p.n), 0.0);
    std::vector<RowBound> state(static_cast<std::size_t>(p.n), RowBound::free);
    RowLcpScratch scratch;
    const int solves =
        solve_row_lcp(p.n, p.A.data(), p.b.data(), p.lo.data(), p.hi.data(), p.findex.data(), x.data(), state.data(), scratch, 30);
    ASSERT_GT(solves, 0) << "trial " << trial << ": no settled active set from a cold start";
    cold_solves += solves, ++cases;
    EXPECT_LT(breach(p, x), 1e-8) << "trial " << trial;
    // Dantzig sets each friction row's bounds from its normal's impulse when it reaches that row,
    // and does not revise them when a later pivot changes the normal: on the systems with friction
    // its answer breaks the coupled conditions by up to ~1e-5 of the impulses. The frictionless
    // ones must agree to the solves' precision; all within the friction coupling's reach.
    const std::vector<double> d = dantzig(p);
    double scale = 0, diff = 0;
    for (std::size_t i = 0; i < x.size(); ++i) scale = std::max(scale, std::abs(d[i])), diff = std::max(diff, std::abs(x[i] - d[i]));
    const double dantzig_breach = breach(p, d);
    worst_dantzig = std::max(worst_dantzig, dantzig_breach);
    worst_diff = std::max(worst_diff, diff / scale);
    if (trial % 3 == 0)
      EXPECT_LE(diff, 1e-9 * scale) << "trial " << trial << " (" << contacts << " contacts, frictionless)";
    else
      EXPECT_LE(diff, 10 * std::max(dantzig_breach, 1e-9) * scale) << "trial " << trial << " (" << contacts << " contacts)";
    // Warm: the same problem from its own solution's states takes one solve.
    std::vector<double> x2(static_cast<std::size_t>(p.n), 0.0);
    EXPECT_EQ(solve_row_lcp(p.n, p.A.data(), p.b.data(), p.lo.data(), p.hi.data(), p.findex.data(), x2.data(), state.data(), scratch), 1);
  }
  std::printf(
      "  %d systems, %.2f solves each from a cold start; Dantzig's largest breach of the conditions %.2g, largest difference %.2g of the "
      "impulses\n",
      cases, static_cast<double>(cold_solves) / cases, worst_dantzig, worst_diff);
}

TEST(RowLcp, ARowHeldAtOneValueStaysThereWhateverItsRate) {
  // A motor row whose torque limit is zero (lo = hi = 0) next to a contact: its impulse is 0 and
  // its w may have either sign; the solve settles instead of cycling between the two bounds.
  std::mt19937_64 rng(7);
  Problem p = make_problem(rng, 3, 5, 0.05);
  const int motor = p.n - 1;
  p.lo[static_cast<std::size_t>(motor)] = 0, p.hi[static_cast<std::size_t>(motor)] = 0;
  for (double sign : {1.0, -1.0}) {
    p.b[static_cast<std::size_t>(motor)] = sign * 0.5;
    std::vector<double> x(static_cast<std::size_t>(p.n), 0.0);
    std::vector<RowBound> state(static_cast<std::size_t>(p.n), RowBound::free);
    RowLcpScratch scratch;
    ASSERT_GT(solve_row_lcp(p.n, p.A.data(), p.b.data(), p.lo.data(), p.hi.data(), p.findex.data(), x.data(), state.data(), scratch, 30),
              0);
    EXPECT_EQ(x[static_cast<std::size_t>(motor)], 0.0);
    EXPECT_LT(breach(p, x), 1e-8);
  }
}

}  // namespace test_row_lcp
}  // namespace gearsim::physics

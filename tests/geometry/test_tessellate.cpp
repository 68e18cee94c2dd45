// Adaptive tessellation: the chordal deviation bound holds, measured against the true curve.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "geometry/tessellate.hpp"

namespace gearsim {
namespace test_tessellate {

using Eigen::Vector2d;

double max_deviation(const Curve2& c, double t0, double t1, const std::vector<Vector2d>& pts) {
  // Distance of 20 000 true-curve points to the polyline (closed by c(t1)).
  std::vector<Vector2d> poly = pts;
  poly.push_back(c(t1));
  double worst = 0;
  for (int i = 0; i <= 20000; ++i) {
    const Vector2d p = c(t0 + (t1 - t0) * i / 20000.0);
    double d = 1e300;
    for (std::size_t k = 0; k + 1 < poly.size(); ++k) d = std::min(d, distance_to_segment(p, poly[k], poly[k + 1]));
    worst = std::max(worst, d);
  }
  return worst;
}

TEST(Tessellate, ArcSagittaStaysWithinTheBound) {
  const double r = 0.05, tol = 0.5e-6;
  std::vector<Vector2d> pts;
  tessellate_arc(Vector2d::Zero(), r, 0.0, 1.0, tol, pts);
  const int n = static_cast<int>(pts.size());
  // Sagitta of n equal chords over 1 rad, and one chord fewer would break the bound.
  EXPECT_LE(r * (1 - std::cos(0.5 / n)), tol);
  EXPECT_GT(r * (1 - std::cos(0.5 / (n - 1))), tol);
}

TEST(Tessellate, InvoluteDeviationIsBelowHalfAMicrometre) {
  const double rb = 0.016914;  // the paper planet's base radius, m
  const Curve2 inv = [rb](double t) { return Vector2d(rb * (std::cos(t) + t * std::sin(t)), rb * (std::sin(t) - t * std::cos(t))); };
  std::vector<Vector2d> pts;
  tessellate_curve(inv, 0.05, 0.6, 0.5e-6, pts);
  const double dev = max_deviation(inv, 0.05, 0.6, pts);
  EXPECT_LE(dev, 0.5e-6);
  // And not absurdly over-refined: the worst chord uses at least a fifth of the allowance.
  EXPECT_GT(dev, 0.1e-6);
}

TEST(Tessellate, SBendIsRefinedEvenWhenItsMidpointLiesOnTheChord) {
  // y = 1e-3·sin(2πt): the midpoint of the whole span is on the chord.
  const Curve2 s = [](double t) { return Vector2d(t * 0.01, 1e-3 * std::sin(2 * std::numbers::pi * t)); };
  std::vector<Vector2d> pts;
  tessellate_curve(s, 0.0, 1.0, 0.5e-6, pts);
  EXPECT_LE(max_deviation(s, 0.0, 1.0, pts), 0.5e-6);
}

}  // namespace test_tessellate
}  // namespace gearsim

// Suite named outline_resample so `ctest -R outline_resample` selects it.
// Boundary nodes resampled along a polygon: on a circle the sagitta limit sets the spacing
// √(8 R s) and the chords stay within the limit; without it the spacing is the given one.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "fe/constants.hpp"
#include "fe/outline_resample.hpp"

namespace gearsim::fe {
namespace test_outline_resample {

// A circle of radius r as a polygon of n exact points.
ArcPolygon circle(double r, int n) {
  Polygon2 p;
  for (int i = 0; i < n; ++i) {
    const double a = 2.0 * std::numbers::pi * i / n;
    p.points.emplace_back(r * std::cos(a), r * std::sin(a));
  }
  return make_arc_polygon(p);
}

TEST(outline_resample, SagittaLimitSetsTheSpacingOnACircle) {
  // R = 5 mm, s = 1 µm: spacing √(8 R s) = 0.2 mm < the 0.4 mm asked, 157 edges round the loop;
  // each chord's sagitta c²/(8R) = 1 µm (vertices 2π·5 mm/20000 = 1.6 µm apart, so snapping
  // moves nodes by < 1 %).
  const double r = 5e-3, s = 1e-6;
  const ArcPolygon poly = circle(r, 20000);
  const ResampledLoop loop = resample_loop(poly, 0.4e-3, s);
  const double expected = 2.0 * std::numbers::pi * r / std::sqrt(8.0 * r * s);
  EXPECT_NEAR(static_cast<double>(loop.points.size()), expected, 2.0);
  EXPECT_LT(max_edge_sagitta(poly, loop), 1.05 * s);
  EXPECT_GT(max_edge_sagitta(poly, loop), 0.9 * s);
  for (double h : local_spacing(poly, 0.4e-3, s)) EXPECT_NEAR(h, std::sqrt(8.0 * r * s), 1e-9);
}

TEST(outline_resample, WithoutALimitTheSpacingIsTheGivenOne) {
  const double r = 5e-3;
  const ArcPolygon poly = circle(r, 20000);
  const ResampledLoop loop = resample_loop(poly, 0.4e-3);
  // 2π·5/0.4 = 78.54 → 79 edges, made even: 80; each chord's sagitta R(1 − cos(π/80)) = 3.85 µm.
  EXPECT_EQ(loop.points.size(), 80u);
  EXPECT_NEAR(max_edge_sagitta(poly, loop), r * (1.0 - std::cos(std::numbers::pi / 80)), 0.05e-6);
}

TEST(outline_resample, SpacingIsGradedAwayFromACurve) {
  // A long straight run ending in a tight 0.4 mm-radius semicircle (a stadium): the spacing is
  // √(8 ρ s) = 0.126 mm on the arcs and grows by at most kSpacingGrading per unit length along
  // the straights, up to the 0.4 mm asked.
  const double rho = 0.4e-3, len = 10e-3, s = 5e-6;
  Polygon2 p;
  const int arc_n = 400, line_n = 2000;
  auto arc = [&](double cx, double a0) {
    for (int i = 0; i <= arc_n; ++i) {
      const double a = a0 + std::numbers::pi * i / arc_n;
      p.points.emplace_back(cx + rho * std::cos(a), rho * std::sin(a));
    }
  };
  for (int i = 0; i < line_n; ++i) p.points.emplace_back(len * i / line_n, -rho);
  arc(len, -std::numbers::pi / 2);
  for (int i = 1; i < line_n; ++i) p.points.emplace_back(len - len * i / line_n, rho);
  arc(0.0, std::numbers::pi / 2);
  const ArcPolygon poly = make_arc_polygon(p);
  const std::vector<double> h = local_spacing(poly, 0.4e-3, s);
  double lo = 1, hi = 0;
  for (double v : h) {
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  EXPECT_NEAR(lo, std::sqrt(8.0 * rho * s), 1e-6);
  EXPECT_NEAR(hi, 0.4e-3, 1e-12);
  for (std::size_t i = 0; i + 1 < h.size(); ++i)
    EXPECT_LE(std::abs(h[i + 1] - h[i]), kSpacingGrading * (poly.s_m[i + 1] - poly.s_m[i]) + 1e-12);
  const ResampledLoop loop = resample_loop(poly, 0.4e-3, s);
  EXPECT_EQ(loop.points.size() % 2, 0u);
  EXPECT_LT(max_edge_sagitta(poly, loop), 1.5 * s);
}

}  // namespace test_outline_resample
}  // namespace gearsim::fe

// Gear outlines measured like a gear on a metrology bench: tooth thickness, span, chordal
// deviation, and where each manufacturing error lands.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "geometry/gear_profile.hpp"
#include "tests/support/gear_specs.hpp"
#include "tests/support/outline_probe.hpp"
#include "geometry/constants.hpp"

namespace gearsim {
namespace test_gear_profile {

using Eigen::Vector2d;
using gearsim::constants::kPi;
constexpr double kChord = 0.5e-6;  // the specs' chordal deviation, m

const Polygon2& toothed(const GearOutline& g, const GearSpec& s) {
  return s.kind == GearKind::External ? g.outline.outer : g.outline.holes.front();
}

// Arc length on circle r between the two crossings bounding polar angle 0 (tooth 0's centre).
double arc_across_angle_zero(const Polygon2& loop, double r) {
  double lo = -kPi, hi = kPi;
  for (const Vector2d& p : test::circle_crossings(loop, r)) {
    const double a = test::polar(p);
    if (a < 0)
      lo = std::max(lo, a);
    else
      hi = std::min(hi, a);
  }
  return (hi - lo) * r;
}

TEST(GearProfile, ExternalToothThicknessOnTheReferenceCircleIsHalfAPitch) {
  const GearSpec s = test::external_gear(36);
  const GearOutline g = make_gear_outline(s);
  // Crossings lie on chords within 0.5 µm of the flanks; two flanks → 1 µm.
  EXPECT_NEAR(arc_across_angle_zero(g.outline.outer, 18e-3), kPi * 1e-3 / 2, 2 * kChord);
}

TEST(GearProfile, ThinnedToothLosesTwiceTheThinningOverCosAlpha) {
  GearSpec s = test::external_gear(24);
  s.thinning_per_flank_m = 25e-6;
  const GearOutline g = make_gear_outline(s);
  const double expected = kPi * 1e-3 / 2 - 2 * 25e-6 / std::cos(s.pressure_angle_rad);
  EXPECT_NEAR(arc_across_angle_zero(g.outline.outer, 12e-3), expected, 2 * kChord);
}

TEST(GearProfile, InternalToothThicknessOnTheReferenceCircleIsHalfAPitch) {
  const GearSpec s = test::internal_gear(96);
  const GearOutline g = make_gear_outline(s);
  EXPECT_NEAR(arc_across_angle_zero(toothed(g, s), 48e-3), kPi * 1e-3 / 2, 2 * kChord);
}

TEST(GearProfile, SpanOverKTeethMeasuredOnTheOutlineMatchesTheFormula) {
  const GearSpec s = test::external_gear(36);
  const GearOutline g = make_gear_outline(s);
  const int k = g.dims.span_teeth;
  // The measuring line is tangent to the base circle, perpendicular to the middle of teeth 0..k−1.
  const double mid = (k - 1) * kPi / s.teeth;
  const Vector2d t = g.dims.base_radius_m * Vector2d(std::cos(mid), std::sin(mid));
  const Vector2d dir(-std::sin(mid), std::cos(mid));
  double s_cw = 0, s_ccw = 0;
  const auto& v = g.outline.outer.points;
  for (std::size_t i = 0; i < v.size(); ++i) {
    // Crossings of the line with each edge; keep those on tooth 0's Cw flank and on the Ccw
    // flank of tooth k−1 (by polar angle).
    const Vector2d a = v[i], b = v[(i + 1) % v.size()];
    const double da = (a - t).dot(Vector2d(dir.y(), -dir.x())), db = (b - t).dot(Vector2d(dir.y(), -dir.x()));
    if ((da < 0) == (db < 0)) continue;
    const Vector2d p = a + (b - a) * (da / (da - db));
    const double ang = test::polar(p), pitch = 2 * kPi / s.teeth;
    if (ang > -pitch / 2 && ang < 0) s_cw = (p - t).dot(dir);
    if (std::abs(ang - ((k - 1) * pitch + pitch / 4)) < pitch / 4) s_ccw = (p - t).dot(dir);
  }
  EXPECT_NEAR(s_ccw - s_cw, g.dims.span_m, 2 * kChord);
}

TEST(GearProfile, FlanksAreTessellatedWithinTheChordalDeviation) {
  for (const GearSpec& s : {test::external_gear(24), test::external_gear(36), test::internal_gear(96)}) {
    const GearOutline g = make_gear_outline(s);
    double worst = 0;
    for (Flank f : {Flank::Ccw, Flank::Cw})
      for (int i = 0; i <= 400; ++i) {
        const double r = g.dims.form_radius_m + (g.dims.tip_radius_m - g.dims.form_radius_m) * i / 400.0;
        worst = std::max(worst, test::distance_to_boundary(toothed(g, s), flank_point(s, g.dims, 0, f, r)));
      }
    // 1e-12 m: the floating-point noise of evaluating the curve twice.
    EXPECT_LE(worst, kChord + 1e-12) << s.name;
  }
}

TEST(GearProfile, RootFilletReachesTheRootCircle) {
  const GearSpec s = test::external_gear(24);
  const GearOutline g = make_gear_outline(s);
  double rmin = 1, rmax = 0;
  for (const Vector2d& p : g.outline.outer.points) {
    rmin = std::min(rmin, p.norm());
    rmax = std::max(rmax, p.norm());
  }
  EXPECT_NEAR(rmin, g.dims.root_radius_m, 1e-12);
  EXPECT_NEAR(rmax, g.dims.tip_radius_m, 1e-12);
}

TEST(GearProfile, ConstantFlankOffsetIsARotationByOffsetOverBaseRadius) {
  // The defining property of the involute: rotating it by e/r_b moves it e along its normal,
  // everywhere from the form circle to the tip.
  GearSpec s = test::external_gear(36);
  const GearDimensions d = gear_dimensions(s);
  GearSpec faulty = s;
  faulty.errors.flank_offsets.push_back({0, Flank::Ccw, -43e-6});
  for (double r : {d.form_radius_m, d.reference_radius_m, d.tip_radius_m}) {
    const Vector2d q = flank_point(faulty, d, 0, Flank::Ccw, r);
    // Distance to the nominal involute (extended 0.2 mm past form and tip circles so the foot
    // of the normal is always inside the search): dense search, 200 000 steps of ~15 nm.
    double best = 1;
    const double r0 = d.form_radius_m - 0.2e-3, r1 = d.tip_radius_m + 0.2e-3;
    for (int i = 0; i <= 200000; ++i) {
      const double rr = r0 + (r1 - r0) * (i / 200000.0);
      best = std::min(best, (q - flank_point(s, d, 0, Flank::Ccw, rr)).norm());
    }
    // A 15 nm step misses the foot of the normal by ≤ 7.5 nm along the curve; at a 43 µm
    // distance that changes the distance by (7.5e-9)²/(2·43e-6) ≈ 1e-12 m.
    EXPECT_NEAR(best, 43e-6, 1e-9) << "r = " << r;
  }
}

TEST(GearProfile, SingleFlankErrorLandsOnlyOnItsFlank) {
  // A 10 nm chordal deviation here so that the outline itself, not just the analytic flank, is
  // measured to the issue's ±0.1 µm.
  GearSpec s = test::external_gear(36);
  s.chordal_deviation_m = 10e-9;
  GearSpec faulty = s;
  faulty.errors.flank_offsets.push_back({0, Flank::Ccw, -43e-6});
  const GearOutline g0 = make_gear_outline(s), g1 = make_gear_outline(faulty);
  const double r = g0.dims.reference_radius_m;
  for (Flank f : {Flank::Ccw, Flank::Cw}) {
    const Vector2d p = flank_point(s, g0.dims, 0, f, r);
    const Vector2d n = flank_normal(s, g0.dims, 0, f, r);
    const auto hit = test::line_hit(g1.outline.outer, p, n, 200e-6);
    ASSERT_TRUE(hit.has_value());
    // Along the outward normal: −43 µm on the faulty flank, 0 on the other, ±0.1 µm (the issue's
    // acceptance; the tessellation contributes at most 0.01 µm).
    EXPECT_NEAR(*hit, f == Flank::Ccw ? -43e-6 : 0.0, 0.1e-6) << (f == Flank::Ccw ? "ccw" : "cw");
  }
  // Every other tooth is untouched: outside tooth 0 and the root arc it shares with tooth 1,
  // the two outlines have the very same vertices.
  const double half_pitch = kPi / s.teeth;
  auto outside_tooth0 = [&](const Polygon2& loop) {
    std::vector<Vector2d> kept;
    for (const Vector2d& p : loop.points) {
      const double a = test::polar(p);
      if (a < -half_pitch || a > 1.2 * half_pitch) kept.push_back(p);
    }
    return kept;
  };
  const std::vector<Vector2d> v0 = outside_tooth0(g0.outline.outer), v1 = outside_tooth0(g1.outline.outer);
  ASSERT_EQ(v0.size(), v1.size());
  double worst = 0;
  for (std::size_t i = 0; i < v0.size(); ++i) worst = std::max(worst, (v0[i] - v1[i]).norm());
  EXPECT_EQ(worst, 0.0);
}

TEST(GearProfile, PitchErrorMovesBothFlanksAlongTheReferenceCircle) {
  GearSpec s = test::external_gear(24);
  s.errors.pitch_errors.push_back({0, 20e-6});
  const GearOutline g = make_gear_outline(s);
  double lo = -kPi, hi = kPi;
  for (const Vector2d& p : test::circle_crossings(g.outline.outer, 12e-3)) {
    const double a = test::polar(p);
    if (a < 0)
      lo = std::max(lo, a);
    else
      hi = std::min(hi, a);
  }
  const double half = kPi / 2 / s.teeth;  // nominal half-thickness angle at the reference circle
  EXPECT_NEAR(hi * 12e-3, half * 12e-3 + 20e-6, kChord);
  EXPECT_NEAR(lo * 12e-3, -half * 12e-3 + 20e-6, kChord);
}

TEST(GearProfile, ProfileSlopeGrowsLinearlyWithRollLength) {
  const GearSpec s = test::external_gear(36);
  GearSpec sloped = s;
  sloped.errors.profile_slopes.push_back({0, Flank::Cw, 10e-6});
  const GearDimensions d = gear_dimensions(s);
  const GearOutline g = make_gear_outline(sloped);
  const double l0 = std::sqrt(d.form_radius_m * d.form_radius_m - d.base_radius_m * d.base_radius_m);
  const double l1 = std::sqrt(d.tip_radius_m * d.tip_radius_m - d.base_radius_m * d.base_radius_m);
  for (double share : {0.0, 0.5, 0.98}) {
    const double L = l0 + share * (l1 - l0);
    const double r = std::hypot(d.base_radius_m, L);
    const auto hit = test::line_hit(g.outline.outer, flank_point(s, d, 0, Flank::Cw, r), flank_normal(s, d, 0, Flank::Cw, r), 100e-6);
    ASSERT_TRUE(hit.has_value());
    EXPECT_NEAR(*hit, 10e-6 * share, kChord) << "share " << share;
  }
}

TEST(GearProfile, EccentricityGivesARunoutOfTwiceTheOffset) {
  GearSpec s = test::external_gear(36);
  s.errors.eccentricity = {30e-6, 0.3};
  const GearOutline g = make_gear_outline(s);
  // Radius of each tooth's tip centre point: varies by ±e around the tip radius.
  double rmin = 1, rmax = 0;
  for (const Vector2d& p : g.outline.outer.points) {
    rmin = std::min(rmin, std::abs(p.norm() - g.dims.tip_radius_m) < 60e-6 ? p.norm() : 1.0);
    rmax = std::max(rmax, p.norm());
  }
  // 36 teeth sample the sinusoid every 10°: the extreme tooth is within cos(5°) of the peak.
  EXPECT_NEAR(rmax - rmin, 2 * 30e-6, 30e-6 * (1 - std::cos(5 * kPi / 180)) * 2 + 1e-9);
}

}  // namespace test_gear_profile
}  // namespace gearsim

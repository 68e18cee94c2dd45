// Gear recognition against gears whose generating parameters are known: gearsim's own outlines
// (exact involutes, vertices on the curve within the 0.5 µm chordal deviation), moved, turned,
// thinned, shifted, damaged, and shapes that are not gears.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "geometry/gear_dimensions.hpp"
#include "geometry/gear_profile.hpp"
#include "geometry/gear_recognition.hpp"
#include "tests/support/asymmetric_gear.hpp"
#include "tests/support/gear_specs.hpp"
#include "geometry/constants.hpp"

namespace gearsim {
namespace test_gear_recognition {

using gearsim::constants::kPi;
using gearsim::constants::kRadPerDeg;
// The outlines' vertices lie on the exact flanks to rounding; their chords stray up to 0.5 µm.
// Base radius: a least-squares fit through hundreds of exact vertices, 0.1 µm.
constexpr double kBaseRadiusTol_m = 0.1e-6;
// Tooth 0 from mid-depth crossings of the chords, averaged over the teeth: within a chordal
// deviation over the radius, 1e-5 rad at these sizes.
constexpr double kAngleTol_rad = 1e-5;

// Angle difference modulo the pitch, in (−pitch/2, pitch/2].
double pitch_residue(double a, double b, int z) { return std::remainder(a - b, 2 * kPi / z); }

RecognisedGear recognise_ok(const Outline2& o) {
  const Result<RecognisedGear> r = recognise_gear(o);
  EXPECT_TRUE(r.ok()) << r.reason();
  return r.optional().value_or(RecognisedGear{});
}

struct Case {
  int z;
  double module_m, alpha_deg, tooth0_deg;
  double shift;  // profile shift x: enough to keep the rack from undercutting small tooth counts
};

class ExternalGear : public ::testing::TestWithParam<Case> {};

TEST_P(ExternalGear, CountToothZeroBaseRadiusModuleAndPressureAngle) {
  const Case c = GetParam();
  GearSpec s = test::external_gear(c.z, 0.0);
  s.module_m = c.module_m;
  s.face_width_m = 6 * c.module_m;
  s.pressure_angle_rad = c.alpha_deg * kRadPerDeg;
  if (c.alpha_deg > 22) s.root_fillet_coeff = 0.25;  // ρ* 0.38 does not fit the 25° rack
  s.tooth0_angle_rad = c.tooth0_deg * kRadPerDeg;
  s.profile_shift = c.shift;
  const GearOutline go = make_gear_outline(s);
  const RecognisedGear g = recognise_ok(go.outline);
  EXPECT_EQ(g.teeth, c.z);
  EXPECT_FALSE(g.internal);
  EXPECT_EQ(g.loop, -1);
  EXPECT_NEAR(pitch_residue(g.tooth0_angle_rad, s.tooth0_angle_rad, c.z), 0.0, kAngleTol_rad);
  EXPECT_NEAR(g.axis_m.norm(), 0.0, 1e-9);
  EXPECT_TRUE(g.involute) << "ccw rms " << g.ccw.rms_m << " cw rms " << g.cw.rms_m;
  EXPECT_NEAR(g.ccw.base_radius_m, go.dims.base_radius_m, kBaseRadiusTol_m);
  EXPECT_NEAR(g.cw.base_radius_m, go.dims.base_radius_m, kBaseRadiusTol_m);
  EXPECT_TRUE(g.standard);
  EXPECT_DOUBLE_EQ(g.module_m, c.module_m);
  EXPECT_NEAR(g.pressure_angle_rad, s.pressure_angle_rad, 1e-12);
  // Thickness at the reference circle, and the profile shift it implies (0.2 µm: the chords'
  // crossings aside, the fit through exact vertices is exact to well under that).
  EXPECT_NEAR(g.reference_thickness_m, go.dims.tooth_thickness_m, 0.2e-6);
  EXPECT_NEAR(g.profile_shift, c.shift, 1e-3);
  // Tip and root circles: the envelope's extremes, within the chordal deviation.
  EXPECT_NEAR(g.tip_radius_m, go.dims.tip_radius_m, 0.5e-6);
  EXPECT_NEAR(g.root_radius_m, go.dims.root_radius_m, 0.5e-6);
  // The involute runs from the form circle to the tip.
  EXPECT_NEAR(g.ccw.active_to_m, go.dims.tip_radius_m, 1e-6);
  EXPECT_LT(g.ccw.active_from_m, go.dims.form_radius_m + 0.02 * c.module_m);
}

INSTANTIATE_TEST_SUITE_P(Grid, ExternalGear,
                         ::testing::Values(Case{12, 1e-3, 20, 0, 0.4}, Case{24, 1e-3, 14.5, 3.0, 0.3}, Case{36, 1e-3, 20, -4.0, 0},
                                           Case{80, 4e-3, 25, 1.0, 0}, Case{17, 4e-3, 20, 10.0, 0.1}, Case{55, 2.5e-3, 25, 0.5, -0.2}));

TEST(GearRecognition, InternalGearIsTheToothedHole) {
  GearSpec s = test::internal_gear(96);
  s.tooth0_angle_rad = kPi / 96;
  const GearOutline go = make_gear_outline(s);
  const RecognisedGear g = recognise_ok(go.outline);
  EXPECT_EQ(g.teeth, 96);
  EXPECT_TRUE(g.internal);
  EXPECT_EQ(g.loop, 0);
  EXPECT_NEAR(pitch_residue(g.tooth0_angle_rad, s.tooth0_angle_rad, 96), 0.0, kAngleTol_rad);
  EXPECT_TRUE(g.involute);
  EXPECT_NEAR(g.base_radius_m, go.dims.base_radius_m, kBaseRadiusTol_m);
  EXPECT_DOUBLE_EQ(g.module_m, 1e-3);
  EXPECT_NEAR(g.pressure_angle_rad, 20 * kRadPerDeg, 1e-12);
  EXPECT_NEAR(g.tip_radius_m, go.dims.tip_radius_m, 0.5e-6);
  EXPECT_NEAR(g.root_radius_m, go.dims.root_radius_m, 0.5e-6);
  EXPECT_NEAR(g.reference_thickness_m, go.dims.tooth_thickness_m, 0.2e-6);
}

TEST(GearRecognition, ProfileShiftAndThinningReadAsTheShiftOfTheThickness) {
  GearSpec s = test::external_gear(20, 0.0);
  s.profile_shift = 0.3;
  s.thinning_per_flank_m = 25e-6;
  const GearOutline go = make_gear_outline(s);
  const RecognisedGear g = recognise_ok(go.outline);
  // Thinning t per flank (normal) takes 2t/cos α of arc thickness: x drops by t/(m·sin α).
  const double expected = 0.3 - 25e-6 / (1e-3 * std::sin(20 * kRadPerDeg));
  EXPECT_NEAR(g.profile_shift, expected, 1e-3);
  EXPECT_NEAR(g.reference_thickness_m, go.dims.tooth_thickness_m, 0.2e-6);
  EXPECT_DOUBLE_EQ(g.module_m, 1e-3);
}

TEST(GearRecognition, OffOriginGearFindsItsAxis) {
  const GearOutline go = make_gear_outline(test::external_gear(31));
  Outline2 moved = go.outline;
  const Eigen::Vector2d offset(0.050, -0.0213);
  for (Eigen::Vector2d& v : moved.outer.points) v += offset;
  for (Polygon2& h : moved.holes)
    for (Eigen::Vector2d& v : h.points) v += offset;
  const RecognisedGear g = recognise_ok(moved);
  EXPECT_EQ(g.teeth, 31);
  EXPECT_NEAR((g.axis_m - offset).norm(), 0.0, 1e-9);
  EXPECT_NEAR(pitch_residue(g.tooth0_angle_rad, 0.0, 31), 0.0, kAngleTol_rad);
  EXPECT_NEAR(g.base_radius_m, gear_dimensions(test::external_gear(31)).base_radius_m, kBaseRadiusTol_m);
  // Moved back, the same gear about the origin.
  EXPECT_NEAR(recognise_ok(recentred(moved, g.axis_m)).axis_m.norm(), 0.0, 1e-9);
}

TEST(GearRecognition, ADamagedFlankIsAnOutlierOfItsToothNotAWrongFit) {
  GearSpec s = test::external_gear(36);
  s.errors.flank_offsets.push_back({5, Flank::Ccw, 43e-6});
  const GearOutline go = make_gear_outline(s);
  const RecognisedGear g = recognise_ok(go.outline);
  ASSERT_EQ(g.ccw.outlier_teeth, std::vector<int>{5});
  EXPECT_NEAR(g.ccw.largest_outlier_m, 43e-6, 0.5e-6);
  EXPECT_TRUE(g.cw.outlier_teeth.empty());
  EXPECT_NEAR(g.base_radius_m, go.dims.base_radius_m, kBaseRadiusTol_m);
}

// A square hole with a keyway (CW) of half-width w and depth d above the bore radius r.
Polygon2 keyed_bore(double r, double w, double d) {
  Polygon2 p;
  const double a = std::asin(w / r);
  for (int i = 0; i <= 64; ++i) {
    const double t = a + (2 * kPi - 2 * a) * i / 64;
    p.points.emplace_back(r * std::cos(t), r * std::sin(t));
  }
  p.points.emplace_back(r + d, -w);
  p.points.emplace_back(r + d, w);
  std::reverse(p.points.begin(), p.points.end());
  return p;
}

TEST(GearRecognition, AKeyedBoreIsNotTheToothedLoop) {
  GearOutline go = make_gear_outline(test::external_gear(24, 0.0));
  go.outline.holes.push_back(keyed_bore(4e-3, 1e-3, 1.5e-3));
  const RecognisedGear g = recognise_ok(go.outline);
  EXPECT_EQ(g.loop, -1);
  EXPECT_EQ(g.teeth, 24);
}

TEST(GearRecognition, ShapesWithoutTeethAreNotGears) {
  Outline2 disc;
  for (int i = 0; i < 128; ++i) disc.outer.points.emplace_back(0.02 * std::cos(2 * kPi * i / 128), 0.02 * std::sin(2 * kPi * i / 128));
  disc.holes.push_back(keyed_bore(4e-3, 1e-3, 1.5e-3));
  const Result<RecognisedGear> a = recognise_gear(disc);
  EXPECT_FALSE(a.ok());
  EXPECT_NE(a.reason().find("outer loop: a circle"), std::string::npos) << a.reason();
  // A square (four sides of eight points): below the fewest teeth looked for.
  Outline2 square;
  square.outer.points = {{-0.01, -0.01}, {0, -0.01}, {0.01, -0.01}, {0.01, 0}, {0.01, 0.01}, {0, 0.01}, {-0.01, 0.01}, {-0.01, 0}};
  EXPECT_FALSE(recognise_gear(square).ok());
}

// m·cos α alone cannot tell m and α apart: a 60-tooth ring of module 1 mm at 25° with a stub
// tooth (addendum 0.8 m: depth 2.05 m) also reads as module 0.95 mm at 17.5°, whose depth
// (2.16 of its modules) is nearer the standard 2.25 — but only with a profile shift of 1.9.
// The reading with the least shift wins (seen on a ring cut from OpenSCAD's MCAD gear shape).
TEST(GearRecognition, AStubToothRingReadsAsItsModuleNotAShiftedOne) {
  GearSpec s = test::internal_gear(60, 0.080);
  s.pressure_angle_rad = 25 * kRadPerDeg;
  s.addendum_coeff = 0.8;
  s.root_fillet_coeff = 0.25;
  const RecognisedGear g = recognise_ok(make_gear_outline(s).outline);
  EXPECT_EQ(g.teeth, 60);
  EXPECT_TRUE(g.standard);
  EXPECT_DOUBLE_EQ(g.module_m, 1e-3);
  EXPECT_NEAR(g.pressure_angle_rad, 25 * kRadPerDeg, 1e-12);
}

// Asymmetric teeth (counter-clockwise sides on a 20° base circle, clockwise on a 25° one): each
// side's fit keeps its own base circle, and the gear claims no single base circle, module or
// pressure angle.
TEST(GearRecognition, AsymmetricTeethKeepEachSidesBaseCircle) {
  const test::AsymmetricGear a;
  const RecognisedGear g = recognise_ok(Outline2{a.outline(), {}});
  EXPECT_EQ(g.teeth, 20);
  // Tooth 0's centre line is taken at mid-depth, where this lopsided tooth's middle lies off +x.
  const double r_mid = 0.5 * (a.r_root_m + a.r_tip_m);
  const double mid = 0.5 * (a.side_angle(a.rb_ccw_m, r_mid) - a.side_angle(a.rb_cw_m, r_mid));  // 1.2e-3 rad
  EXPECT_NEAR(pitch_residue(g.tooth0_angle_rad, mid, 20), 0.0, kAngleTol_rad);
  ASSERT_TRUE(g.ccw.involute && g.cw.involute);
  EXPECT_NEAR(g.ccw.base_radius_m, a.rb_ccw_m, 0.5e-6);  // vertices on the exact involutes
  EXPECT_NEAR(g.cw.base_radius_m, a.rb_cw_m, 0.5e-6);
  EXPECT_TRUE(g.asymmetric);
  EXPECT_FALSE(g.involute);
  EXPECT_EQ(g.base_radius_m, 0.0);
}

}  // namespace test_gear_recognition
}  // namespace gearsim

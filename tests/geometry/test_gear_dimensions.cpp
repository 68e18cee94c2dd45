// Gear-table numbers from first principles, and the specs that must be refused.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/errors.hpp"
#include "geometry/gear_dimensions.hpp"
#include "geometry/involute.hpp"
#include "tests/support/gear_specs.hpp"
#include "geometry/constants.hpp"

namespace gearsim {
namespace test_gear_dimensions {

using gearsim::constants::kPi;
const double kAlpha = 20.0 * kPi / 180.0;

TEST(GearDimensions, BaseRadiusIsReferenceRadiusTimesCosAlpha) {
  for (int z : {24, 36, 96}) {
    const GearDimensions d = gear_dimensions(test::external_gear(z));
    EXPECT_DOUBLE_EQ(d.reference_radius_m, 0.5e-3 * z);
    EXPECT_NEAR(d.base_radius_m, 0.5e-3 * z * std::cos(kAlpha), 1e-15);
  }
}

TEST(GearDimensions, PaperSunPlanetRingDiametersFromTheStandardRack) {
  // d_a = m(z + 2), d_f = m(z − 2.5) external; internal d_a = m(z − 2), d_f = m(z + 2.5).
  const GearDimensions sun = gear_dimensions(test::external_gear(24));
  const GearDimensions planet = gear_dimensions(test::external_gear(36));
  const GearDimensions ring = gear_dimensions(test::internal_gear(96));
  EXPECT_NEAR(2 * sun.tip_radius_m, 26e-3, 1e-15);
  EXPECT_NEAR(2 * sun.root_radius_m, 21.5e-3, 1e-15);
  EXPECT_NEAR(2 * planet.tip_radius_m, 38e-3, 1e-15);
  EXPECT_NEAR(2 * planet.root_radius_m, 33.5e-3, 1e-15);  // the paper's Table 1 says 36.75
  EXPECT_NEAR(2 * ring.reference_radius_m, 96e-3, 1e-15);  // the paper's Table 1 says 98.5
  EXPECT_NEAR(2 * ring.tip_radius_m, 94e-3, 1e-15);
  EXPECT_NEAR(2 * ring.root_radius_m, 98.5e-3, 1e-15);
}

TEST(GearDimensions, ToothThicknessIsHalfAPitchLessTheThinning) {
  GearSpec s = test::external_gear(36);
  EXPECT_NEAR(gear_dimensions(s).tooth_thickness_m, kPi * 1e-3 / 2, 1e-15);
  s.thinning_per_flank_m = 20e-6;
  // A normal offset t moves the flank t/cos α along the reference circle, on both flanks.
  EXPECT_NEAR(gear_dimensions(s).tooth_thickness_m, kPi * 1e-3 / 2 - 2 * 20e-6 / std::cos(kAlpha), 1e-15);
  s.thinning_per_flank_m = 0;
  s.profile_shift = 0.4;
  EXPECT_NEAR(gear_dimensions(s).tooth_thickness_m, kPi * 1e-3 / 2 + 2 * 0.4e-3 * std::tan(kAlpha), 1e-15);
}

TEST(GearDimensions, SpanMeasurementMatchesTheTabulatedValue) {
  // DIN 3960 / textbook tables for m = 1, α = 20°: z = 24 → k = 3, W = 7.7165 mm;
  // z = 36 → k = 5, W = 13.7888 mm (W* = cos α [π(k − ½) + z inv α]).
  const GearDimensions sun = gear_dimensions(test::external_gear(24));
  EXPECT_EQ(sun.span_teeth, 3);
  EXPECT_NEAR(sun.span_m, 7.7165e-3, 0.05e-6);  // tables give 4 decimals in mm
  const GearDimensions planet = gear_dimensions(test::external_gear(36));
  EXPECT_EQ(planet.span_teeth, 5);
  EXPECT_NEAR(planet.span_m, 13.7888e-3, 0.05e-6);
}

TEST(GearDimensions, FormCircleOfRackGenerationLiesAboveTheBaseCircle) {
  // Roll length at the form circle: r sin α − (h_f − ρ(1 − sin α) − x)m / sin α.
  const GearDimensions planet = gear_dimensions(test::external_gear(36));
  const double roll = 18e-3 * std::sin(kAlpha) - (1.25e-3 - 0.38e-3 * (1 - std::sin(kAlpha))) / std::sin(kAlpha);
  EXPECT_NEAR(planet.form_radius_m, std::hypot(planet.base_radius_m, roll), 1e-15);
  EXPECT_GT(planet.form_radius_m, planet.base_radius_m);
}

TEST(GearDimensions, UndercutIsRefusedWithTheReason) {
  try {
    gear_dimensions(test::external_gear(10, 0.0));
    FAIL() << "a 10-tooth unshifted gear is undercut";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("undercut"), std::string::npos) << e.what();
  }
}

TEST(GearDimensions, ImpossibleSpecsNameTheirField) {
  auto expect_field = [](GearSpec s, const std::string& field) {
    try {
      gear_dimensions(s);
      FAIL() << "expected an error naming " << field;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
    }
  };
  GearSpec s = test::external_gear(36);
  s.module_m = -1e-3;
  expect_field(s, "module_m");
  s = test::external_gear(36);
  s.teeth = 2;
  expect_field(s, "teeth");
  s = test::external_gear(36, 0.040);
  expect_field(s, "bore_diameter_m");
  s = test::internal_gear(96, 0.0);
  expect_field(s, "rim_diameter_m");
  s = test::external_gear(36);
  s.errors.flank_offsets.push_back({36, Flank::Ccw, -43e-6});
  expect_field(s, "tooth index 36");
}

}  // namespace test_gear_dimensions
}  // namespace gearsim

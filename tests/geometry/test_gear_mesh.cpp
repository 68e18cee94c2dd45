// Meshing geometry: centre distance, contact ratio, conjugate backlash, interference.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/errors.hpp"
#include "geometry/gear_dimensions.hpp"
#include "geometry/gear_mesh.hpp"
#include "geometry/involute.hpp"
#include "tests/support/gear_specs.hpp"

namespace gearsim {
namespace test_gear_mesh {

const double kAlpha = 20.0 * std::numbers::pi / 180.0;

TEST(GearMesh, UnshiftedCentreDistanceIsTheSumOfReferenceRadii) {
  EXPECT_NEAR(zero_backlash_centre_distance(test::external_gear(24), test::external_gear(36)), 30e-3, 1e-15);
  EXPECT_NEAR(zero_backlash_centre_distance(test::external_gear(36), test::internal_gear(96)), 30e-3, 1e-15);
}

TEST(GearMesh, ShiftedPairHasZeroBacklashOnTheWorkingPitchCircles) {
  GearSpec a = test::external_gear(13, 0.0), b = test::external_gear(40);
  a.profile_shift = 0.3;
  b.profile_shift = 0.1;
  const double aw = zero_backlash_centre_distance(a, b);
  const MeshGeometry m = analyse_mesh(a, b, aw);
  // Tooth thickness on the working circle: s_w = d_w (s/d + inv α − inv α_w); s_w1 + s_w2 = p_w.
  const double dw1 = 2 * aw * 13 / 53.0, dw2 = 2 * aw * 40 / 53.0;
  auto sw = [&](const GearSpec& g, double dw) {
    const GearDimensions d = gear_dimensions(g);
    return dw * (d.tooth_thickness_m / (2 * d.reference_radius_m) + involute(kAlpha) - involute(m.working_pressure_angle_rad));
  };
  EXPECT_NEAR(sw(a, dw1) + sw(b, dw2), std::numbers::pi * dw1 / 13, 1e-12);
}

TEST(GearMesh, PaperSunPlanetContactRatioFromThePathOfContact) {
  // ε = [√(ra1² − rb1²) + √(ra2² − rb2²) − a sin α] / (π m cos α), radii in mm.
  const double rb1 = 12 * std::cos(kAlpha), rb2 = 18 * std::cos(kAlpha);
  const double eps =
      (std::sqrt(13 * 13 - rb1 * rb1) + std::sqrt(19 * 19 - rb2 * rb2) - 30 * std::sin(kAlpha)) / (std::numbers::pi * std::cos(kAlpha));
  const MeshGeometry m = analyse_mesh(test::external_gear(24), test::external_gear(36), 30e-3);
  EXPECT_NEAR(m.contact_ratio, eps, 1e-12);
  EXPECT_TRUE(m.problems.empty()) << m.problems.front();
}

TEST(GearMesh, PaperPlanetRingReportsTheRingTipReachingThePlanetFillet) {
  // Internal: ε = [√(ra1² − rb1²) − √(ra2² − rb2²) + a sin α] / p_b. The ring tip (d_a = 94 mm)
  // starts contact at roll length √(47² − rb2²) − 30 sin α = 2.95 mm on the planet, below its
  // form circle (3.23 mm): the standard-addendum ring reaches the planet's fillet.
  const double rb1 = 18 * std::cos(kAlpha), rb2 = 48 * std::cos(kAlpha);
  const double eps =
      (std::sqrt(19 * 19 - rb1 * rb1) - std::sqrt(47 * 47 - rb2 * rb2) + 30 * std::sin(kAlpha)) / (std::numbers::pi * std::cos(kAlpha));
  const MeshGeometry m = analyse_mesh(test::external_gear(36), test::internal_gear(96), 30e-3);
  EXPECT_NEAR(m.contact_ratio, eps, 1e-12);
  EXPECT_NEAR(m.active_start_roll_a_m, std::sqrt(47 * 47 - rb2 * rb2) * 1e-3 - 30e-3 * std::sin(kAlpha), 1e-15);
  EXPECT_LT(m.active_start_roll_a_m, m.form_roll_a_m);
  EXPECT_LT(m.effective_contact_ratio, m.contact_ratio);
  EXPECT_FALSE(m.problems.empty());
}

TEST(GearMesh, ShorterRingAddendumClearsThePlanetFillet) {
  GearSpec ring = test::internal_gear(96);
  ring.addendum_coeff = 0.8;
  const MeshGeometry m = analyse_mesh(test::external_gear(36), ring, 30e-3);
  EXPECT_GE(m.active_start_roll_a_m, m.form_roll_a_m);
  EXPECT_LE(m.tip_interference_a_m, 0.5e-6);  // only the tessellation's chord noise
}

TEST(GearMesh, MismatchedModulesCannotMesh) {
  GearSpec b = test::external_gear(36);
  b.module_m = 1.25e-3;
  EXPECT_THROW(analyse_mesh(test::external_gear(24), b, 30e-3), InputError);
}

}  // namespace test_gear_mesh
}  // namespace gearsim

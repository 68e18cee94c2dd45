// Planetary sets: Willis ratio, assembly condition, and placement that really meshes.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>

#include "core/errors.hpp"
#include "geometry/gear_profile.hpp"
#include "geometry/planetary.hpp"
#include "tests/support/gear_specs.hpp"
#include "tests/support/outline_probe.hpp"

namespace gearsim {
namespace test_planetary {

using Eigen::Vector2d;

PlanetarySpec paper_set(int planets = 3) {
  return {test::external_gear(24), test::external_gear(36, 0.010), test::internal_gear(96), planets};
}

TEST(Planetary, WillisRatioIsOnePlusRingOverSun) {
  const PlanetaryGeometry g = analyse_planetary(paper_set());
  EXPECT_DOUBLE_EQ(g.ratio_sun_to_carrier, 1.0 + 96.0 / 24.0);
  EXPECT_NEAR(g.centre_distance_m, 30e-3, 1e-15);
}

TEST(Planetary, ThreePlanetsAssembleEquallySpacedSevenDoNot) {
  const PlanetaryGeometry three = analyse_planetary(paper_set(3));
  EXPECT_TRUE(three.equally_spaced_assembly);
  EXPECT_DOUBLE_EQ(three.assembly_quotient, 40.0);
  EXPECT_LT(three.phase_mismatch_teeth, 1e-9);
  const PlanetaryGeometry seven = analyse_planetary(paper_set(7));
  EXPECT_FALSE(seven.equally_spaced_assembly);
  // (24 + 96)/7 = 17.142857: the planets' demands on the ring differ by a fraction of a tooth.
  EXPECT_GT(seven.phase_mismatch_teeth, 0.1);
}

// Gap (> 0) or overlap (< 0) between two placed toothed loops: the polyline distance is the
// smaller of the vertex-to-polyline distances both ways; a vertex inside the other body's
// material is an overlap. `b_material_inside` is false for a ring (material outside its loop).
double clearance(const Polygon2& a, const Polygon2& b, bool b_material_inside) {
  double gap = 1;
  for (const Vector2d& p : a.points) {
    const double sd = test::signed_distance(b, p);
    gap = std::min(gap, b_material_inside ? -sd : sd);
  }
  for (const Vector2d& p : b.points) gap = std::min(gap, -test::signed_distance(a, p));
  return gap;
}

TEST(Planetary, PlacedPlanetsTouchSunAndRingWithoutOverlap) {
  PlanetarySpec s = paper_set();
  // The paper's standard ring (h_a* = 1) cuts ~6 µm into the planet's fillet during part of the
  // mesh (GearMesh tests); a shortened ring addendum isolates what this test checks: placement.
  s.ring.addendum_coeff = 0.8;
  const PlanetaryGeometry g = analyse_planetary(s);
  const GearOutline sun = make_gear_outline(s.sun), planet = make_gear_outline(s.planet), ring = make_gear_outline(s.ring);
  Polygon2 ring_teeth = ring.outline.holes.front();
  for (Vector2d& p : ring_teeth.points) p = Eigen::Rotation2Dd(g.ring_angle_rad) * p;
  for (const PlanetPlacement& pl : g.placements) {
    const Vector2d c = g.centre_distance_m * Vector2d(std::cos(pl.carrier_angle_rad), std::sin(pl.carrier_angle_rad));
    Polygon2 placed = planet.outline.outer;
    for (Vector2d& p : placed.points) p = c + Eigen::Rotation2Dd(pl.spin_angle_rad) * p;
    // Zero backlash: the flanks touch. Chords sit within 0.5 µm of each curve (inside a convex
    // flank, outside the ring's concave one), so contact reads as |gap| ≤ 1 µm.
    const double gap_sun = clearance(placed, sun.outline.outer, true);
    const double gap_ring = clearance(placed, ring_teeth, false);
    EXPECT_NEAR(gap_sun, 0.0, 1e-6) << "planet at " << pl.carrier_angle_rad;
    EXPECT_NEAR(gap_ring, 0.0, 1e-6) << "planet at " << pl.carrier_angle_rad;
  }
}

TEST(Planetary, RingThatCannotCloseTheTrainIsRefused) {
  PlanetarySpec s = paper_set();
  s.ring = test::internal_gear(98);
  EXPECT_THROW(analyse_planetary(s), InputError);
}

}  // namespace test_planetary
}  // namespace gearsim

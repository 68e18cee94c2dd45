// Kinematic poses of the paper's set: Willis' ratio between sun and carrier, planets that keep
// meshing with sun and ring as the carrier turns, the tooth-at-sun angle, and the scene built
// from them (names, highlight, refusal of a pose for another set).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/errors.hpp"
#include "geometry/gear_profile.hpp"
#include "render/planetary_pose.hpp"
#include "tests/render/paper_scene.hpp"
#include "tests/support/outline_probe.hpp"
#include "geometry/constants.hpp"

namespace gearsim::render {
namespace test_planetary_pose {

using Eigen::Vector2d;
using gearsim::constants::kPi;

// Angle of the body's x axis about z.
double angle_of(const Eigen::Isometry3d& t) { return std::atan2(t.linear()(1, 0), t.linear()(0, 0)); }

TEST(PlanetaryPose, SunTurnsOnePlusZrOverZsTimesTheCarrier) {
  const PlanetarySpec& s = test::paper_set().spec;
  const PlanetaryGeometry& g = test::paper_set().geometry;
  const PlanetaryPose p = kinematic_planetary_pose(s, g, 0.1);
  EXPECT_DOUBLE_EQ(p.sun_angle_rad, 0.1 * (1 + 96.0 / 24.0));
  EXPECT_NEAR(angle_of(p.sun), 0.5, 1e-12);
  EXPECT_NEAR(angle_of(p.ring), g.ring_angle_rad, 1e-12);  // the ring stays fixed
  const PlanetaryPose q = kinematic_planetary_pose_from_sun(s, g, 0.5);
  EXPECT_NEAR(q.carrier_angle_rad, 0.1, 1e-15);
  // Planet 0's centre on the carrier arm at 0.1 rad, 30 mm out.
  EXPECT_NEAR(p.planets[0].translation().x(), 0.030 * std::cos(0.1), 1e-15);
  EXPECT_NEAR(p.planets[0].translation().y(), 0.030 * std::sin(0.1), 1e-15);
}

// Gap (> 0) or overlap (< 0) between a placed planet's toothed loop and another toothed loop
// (material inside it for the sun, outside it for the ring), as in geometry's planetary test;
// only vertices within 4 mm of the mesh point are probed (the teeth in mesh, and fast).
double clearance(const Polygon2& planet, const Polygon2& other, bool other_material_inside, const Vector2d& at) {
  constexpr double kProbeRadius_m = 4e-3;
  double gap = 1;
  for (const Vector2d& q : planet.points) {
    if ((q - at).norm() > kProbeRadius_m) continue;
    const double sd = test::signed_distance(other, q);
    gap = std::min(gap, other_material_inside ? -sd : sd);
  }
  for (const Vector2d& q : other.points)
    if ((q - at).norm() <= kProbeRadius_m) gap = std::min(gap, -test::signed_distance(planet, q));
  return gap;
}

Polygon2 placed(Polygon2 loop, const Eigen::Isometry3d& t) {
  for (Vector2d& q : loop.points) q = (t * Eigen::Vector3d(q.x(), q.y(), 0)).head<2>();
  return loop;
}

TEST(PlanetaryPose, PlanetsKeepMeshingAsTheCarrierTurns) {
  PlanetarySpec s = test::paper_planetary();
  s.ring.addendum_coeff = 0.8;  // clear of the paper's 6 µm tip/fillet interference (README)
  const PlanetaryGeometry g = analyse_planetary(s);
  const Polygon2 sun = make_gear_outline(s.sun).outline.outer, planet = make_gear_outline(s.planet).outline.outer,
                 ring = make_gear_outline(s.ring).outline.holes.front();
  for (double carrier : {0.05, 0.37, 1.0}) {
    const PlanetaryPose p = kinematic_planetary_pose(s, g, carrier);
    for (int k = 0; k < s.planets; ++k) {
      const Polygon2 pl = placed(planet, p.planets[k]);
      const Vector2d at_sun = sun_mesh_point(s, g, p, k).head<2>(), at_ring = ring_mesh_point(s, g, p, k).head<2>();
      // Zero backlash: the flanks touch within the tessellation (chords within 0.5 µm of curves).
      EXPECT_NEAR(clearance(pl, placed(sun, p.sun), true, at_sun), 0.0, 1e-6) << "carrier " << carrier << " planet " << k;
      EXPECT_NEAR(clearance(pl, placed(ring, p.ring), false, at_ring), 0.0, 1e-6) << "carrier " << carrier << " planet " << k;
    }
  }
}

TEST(PlanetaryPose, ToothAtSunPointsAtTheSun) {
  const PlanetarySpec& s = test::paper_set().spec;
  const PlanetaryGeometry& g = test::paper_set().geometry;
  for (int tooth : {0, 7}) {
    const double carrier = carrier_angle_tooth_at_sun(s, g, 1, tooth);
    EXPECT_GE(carrier, 0.0);
    EXPECT_LT(carrier, 2 * kPi * 36 / 96);  // the tooth comes back to the sun after this
    const PlanetaryPose p = kinematic_planetary_pose(s, g, carrier);
    const double tooth_angle = angle_of(p.planets[1]) + s.planet.tooth0_angle_rad + tooth * 2 * kPi / 36;
    const Eigen::Vector3d to_sun = -p.planets[1].translation();
    const double d = std::remainder(tooth_angle - std::atan2(to_sun.y(), to_sun.x()), 2 * kPi);
    EXPECT_NEAR(d, 0.0, 1e-12) << "tooth " << tooth;
  }
}

TEST(PlanetaryPose, MeshPointsLieOnThePitchCircles) {
  const PlanetarySpec& s = test::paper_set().spec;
  const PlanetaryGeometry& g = test::paper_set().geometry;
  const PlanetaryPose p = kinematic_planetary_pose(s, g, 0.2);
  EXPECT_NEAR(sun_mesh_point(s, g, p, 2).head<2>().norm(), 0.012, 1e-15);  // sun pitch radius
  EXPECT_NEAR(ring_mesh_point(s, g, p, 2).head<2>().norm(), 0.048, 1e-15);  // ring pitch radius
  EXPECT_THROW(sun_mesh_point(s, g, p, 3), InputError);
}

TEST(PlanetaryScene, BodiesAreNamedAndTheFaultyToothHighlighted) {
  const PlanetarySpec& s = test::paper_set().spec;
  const PlanetaryGeometry& g = test::paper_set().geometry;
  const PlanetaryMeshes& m = test::paper_set().meshes;
  const Scene scene = planetary_scene(m, kinematic_planetary_pose(s, g, 0));
  ASSERT_EQ(scene.bodies.size(), 5u);
  EXPECT_EQ(scene.bodies[2].name, "planet 0");
  ASSERT_TRUE(scene.bodies[2].highlight);
  EXPECT_FALSE(scene.bodies[3].highlight);
  EXPECT_NO_THROW(validate_scene(scene));
}

TEST(PlanetaryScene, PoseForAnotherSetIsRefused) {
  const PlanetarySpec& s = test::paper_set().spec;
  const PlanetaryGeometry& g = test::paper_set().geometry;
  PlanetaryPose pose = kinematic_planetary_pose(s, g, 0);
  pose.planets.pop_back();
  EXPECT_THROW(planetary_scene(test::paper_set().meshes, pose), InputError);
  pose.planets.clear();  // no poses at all
  EXPECT_THROW(planetary_scene(test::paper_set().meshes, pose), InputError);
  EXPECT_THROW(kinematic_planetary_pose(s, g, std::nan("")), InputError);
}

}  // namespace test_planetary_pose
}  // namespace gearsim::render

// Tooth contact geometry against the involute's exact properties: a rotation Δθ of the driver
// presses each loaded flank pair by r_b·Δθ along the line of action; the number of loaded pairs
// follows the contact ratio; a flank error shows up as exactly its size.
#include <gtest/gtest.h>

#include <cmath>
#include <Eigen/Geometry>
#include <numbers>

#include "geometry/gear_profile.hpp"
#include "geometry/planetary.hpp"
#include "contact/tooth_contact.hpp"
#include "tests/support/gear_specs.hpp"
#include "geometry/constants.hpp"

namespace gearsim::contact {
namespace {

using gearsim::constants::kPi;
constexpr double kChord = 0.5e-6;  // the outline's default chordal deviation, m: flank knots lie on the curve
constexpr int kSamples = 4096;  // flank-table radii

GearSpec fine(GearSpec s) {
  s.chordal_deviation_m = kChord;
  return s;
}

FlankTable table_of(const GearSpec& s) {
  const GearOutline o = make_gear_outline(s);
  const Polygon2& loop = s.kind == GearKind::External ? o.outline.outer : o.outline.holes.front();
  return FlankTable(loop, {s.teeth, s.tooth0_angle_rad}, s.kind == GearKind::Internal, kSamples);
}

// Distance from a contact point to the nearer of the sun–planet pair's two lines of action:
// through the pitch point (12 mm, 0) at ±20° from the y axis.
double off_line_of_action(const Eigen::Vector2d& p) {
  const Eigen::Vector2d pitch(12e-3, 0.0);
  double best = 1;
  for (double sgn : {-1.0, 1.0}) {
    const Eigen::Vector2d dir(sgn * std::sin(20.0 * kPi / 180), std::cos(20.0 * kPi / 180));
    const Eigen::Vector2d d = p - pitch;
    best = std::min(best, std::abs(d.x() * dir.y() - d.y() * dir.x()));
  }
  return best;
}

// The paper's sun and planet 0 at their assembly pose (zero backlash: flanks touch).
struct SunPlanet {
  GearSpec sun = fine(test::external_gear(24)), planet = fine(test::external_gear(36, 0.010));
  FlankTable ts = table_of(sun), tp = table_of(planet);
  // Placement does not depend on the tessellation: analyse the default (coarse) specs.
  PlanetaryGeometry g = analyse_planetary({test::external_gear(24), test::external_gear(36, 0.010), test::internal_gear(96), 3});
  PlanarPose sun_pose{}, planet_pose{{g.centre_distance_m, 0.0}, g.placements[0].spin_angle_rad};
};

TEST(ToothContact, AssembledPairTouchesWithoutPenetration) {
  SunPlanet s;
  for (const ToothContact& c : find_tooth_contacts(s.ts, s.sun_pose, s.tp, s.planet_pose))
    EXPECT_LT(c.depth_m, 0.02e-6) << "tooth " << c.tooth_a;  // the tables' accuracy
}

TEST(ToothContact, DriverRotationPressesEachLoadedPairByBaseRadiusTimesAngle) {
  SunPlanet s;
  const double dtheta = 2e-6 / 11.2763e-3;  // 2 µm on the sun's base circle
  for (double phase : {0.0, 0.1, 0.37, 0.62, 0.9}) {
    // Roll the pair through part of a pitch, then press the sun forward by dθ.
    const double roll = phase * 2 * kPi / 24;
    PlanarPose sun{{0, 0}, roll + dtheta};
    PlanarPose planet = s.planet_pose;
    planet.angle_rad -= roll * 24.0 / 36.0;
    int loaded = 0;
    for (const ToothContact& c : find_tooth_contacts(s.ts, sun, s.tp, planet)) {
      // Conjugate contact lies on the line of action (to the depth's order); tip-corner contact
      // just outside the path of contact does not, and is pressed less.
      if (off_line_of_action(c.point_m) > 1e-6) continue;
      ++loaded;
      // r_b·Δθ = 2 µm; 0.02 µm covers the flank tables (10 nm chords, linear in r).
      EXPECT_NEAR(c.depth_m, 2e-6, 0.02e-6) << "phase " << phase;
      // The normal is the line of action: the pressure angle off the y axis here.
      EXPECT_NEAR(std::abs(std::atan2(c.normal_on_b.x(), std::abs(c.normal_on_b.y()))), 20.0 * kPi / 180, 1e-4);
    }
    EXPECT_GE(loaded, 1);
    EXPECT_LE(loaded, 2);
  }
}

// A pose may carry its rotation (with_rotation(), what the World passes: one sincos per gear per
// step). The search then gives the same contacts bit for bit as from the angle alone; and a pose
// turned after its rotation was taken (PlanarPose is a plain aggregate callers do turn) is
// searched at its new angle, not at the stale rotation.
TEST(ToothContact, APoseCarryingItsRotationIsSearchedAtItsAngle) {
  SunPlanet s;
  const double dtheta = 2e-6 / 11.2763e-3;  // presses the loaded flanks by 2 µm
  auto same = [](const std::vector<ToothContact>& u, const std::vector<ToothContact>& v) {
    if (u.size() != v.size()) return false;
    for (std::size_t i = 0; i < u.size(); ++i)
      if (u[i].tooth_a != v[i].tooth_a || u[i].tooth_b != v[i].tooth_b || u[i].flank_a != v[i].flank_a || u[i].depth_m != v[i].depth_m ||
          u[i].point_m != v[i].point_m || u[i].normal_on_b != v[i].normal_on_b)
        return false;
    return true;
  };
  const PlanarPose pressed{{0, 0}, dtheta};
  const std::vector<ToothContact> plain = find_tooth_contacts(s.ts, pressed, s.tp, s.planet_pose);
  ASSERT_FALSE(plain.empty());
  EXPECT_TRUE(same(find_tooth_contacts(s.ts, with_rotation(pressed), s.tp, with_rotation(s.planet_pose)), plain));
  // Rotation taken at the assembly angle (no contact), then the sun pressed: the new angle counts.
  PlanarPose turned = with_rotation(PlanarPose{{0, 0}, 0.0});
  turned.angle_rad = dtheta;
  EXPECT_FALSE(turned.has_rotation());
  EXPECT_TRUE(same(find_tooth_contacts(s.ts, turned, s.tp, s.planet_pose), plain));
  // The stale rotation would have found the assembly pose's contacts: none 2 µm deep.
  for (const ToothContact& c : find_tooth_contacts(s.ts, PlanarPose{{0, 0}, 0.0}, s.tp, s.planet_pose)) EXPECT_LT(c.depth_m, 0.1e-6);
  for (const ToothContact& c : plain) {
    if (off_line_of_action(c.point_m) < 1e-6) {
      EXPECT_NEAR(c.depth_m, 2e-6, 0.02e-6);
    }
  }
}

// A module-4 pair at 25° (17 and 24 teeth): its flanks are 4× longer than the paper's and the
// contact depth along them 4× more sharply peaked between the 16 probe samples. At every phase
// of a pitch the pinion pressed by 1.2 µm on its base circle must load a flank pair by 1.2 µm
// (the coarse-to-fine sampling once skipped the deepest sample here and saw no contact at all).
TEST(ToothContact, Module4PairIsFoundPressedAtEveryPhaseOfAPitch) {
  auto spec = [](int z) {
    GearSpec g = fine(test::external_gear(z, 0.02));
    g.module_m = 4e-3;
    g.face_width_m = 0.024;
    g.pressure_angle_rad = 25.0 * kPi / 180;
    g.root_fillet_coeff = 0.25;  // the standard rack's 0.38 does not fit at 25°
    return g;
  };
  const GearSpec a = spec(17), b = spec(24);
  const FlankTable ta = table_of(a), tb = table_of(b);
  const double c = 0.5 * 4e-3 * (17 + 24), r_b = 0.5 * 4e-3 * 17 * std::cos(25.0 * kPi / 180);
  const double press = 1.2e-6;
  for (int i = 0; i < 200; ++i) {
    const double roll = (i / 200.0) * 2 * kPi / 17;
    // b's tooth space faces a's tooth 0 at the start: zero backlash on both flanks.
    const PlanarPose pa{{0, 0}, roll + press / r_b}, pb{{c, 0.0}, kPi + kPi / 24 - roll * 17.0 / 24.0};
    double deepest = 0;
    for (const ToothContact& t : find_tooth_contacts(ta, pa, tb, pb)) deepest = std::max(deepest, t.depth_m);
    // r_b·Δθ on the line of action; 0.05 µm covers the tables (0.5 µm chords at module 4).
    EXPECT_NEAR(deepest, press, 0.05e-6) << "phase " << i << "/200 of a pitch";
  }
}

TEST(ToothContact, TwoPairsShareTheLoadForContactRatioMinusOneOfAPitch) {
  // A light press (0.2 µm) so that tip-corner contact, which widens the loaded zone by roughly
  // √(press), stays small; pairs pressed by more than half of it count as loaded.
  SunPlanet s;
  const double dtheta = 0.2e-6 / 11.2763e-3;
  constexpr int kSteps = 200;
  int two = 0;
  for (int i = 0; i < kSteps; ++i) {
    const double roll = (i + 0.5) / kSteps * 2 * kPi / 24;
    PlanarPose sun{{0, 0}, roll + dtheta};
    PlanarPose planet = s.planet_pose;
    planet.angle_rad -= roll * 24.0 / 36.0;
    int loaded = 0;
    for (const ToothContact& c : find_tooth_contacts(s.ts, sun, s.tp, planet)) loaded += c.depth_m > 0.1e-6;
    two += loaded == 2;
  }
  // ε_α = 1.6472: two pairs over 64.7 % of a pitch. Measured with a 2 µm press the share was
  // 0.74 (corner contact); at 0.2 µm the widening is ~√0.1 of that: ≤ 3 %.
  EXPECT_NEAR(two / double(kSteps), 1.6472 - 1.0, 0.03);
}

TEST(ToothContact, PlanetRingPairIsPressedByPlanetBaseRadiusTimesAngle) {
  const GearSpec planet = fine(test::external_gear(36, 0.010));
  GearSpec ring = fine(test::internal_gear(96));
  ring.addendum_coeff = 0.8;  // keeps the ring tip off the planet fillet (see GearMesh tests)
  GearSpec coarse_ring = test::internal_gear(96);
  coarse_ring.addendum_coeff = 0.8;
  const PlanetaryGeometry g = analyse_planetary({test::external_gear(24), test::external_gear(36, 0.010), coarse_ring, 3});
  const FlankTable tp = table_of(planet), tr = table_of(ring);
  const double dtheta = 2e-6 / 16.9145e-3;
  PlanarPose pp{{g.centre_distance_m, 0.0}, g.placements[0].spin_angle_rad + dtheta};
  PlanarPose pr{{0, 0}, g.ring_angle_rad};
  int loaded = 0;
  for (const ToothContact& c : find_tooth_contacts(tp, pp, tr, pr)) {
    if (c.depth_m < 0.5e-6) continue;
    ++loaded;
    EXPECT_NEAR(c.depth_m, 2e-6, 0.02e-6);
  }
  EXPECT_GE(loaded, 1);
}

TEST(ToothContact, SingleFlankErrorOpensAGapOfItsSize) {
  // Planet tooth 0's Ccw flank loses 43 µm. With the sun pressed 50 µm forward (on its base
  // circle) so that the faulty pair still touches, every pair is as deep as with a healthy
  // planet, except the faulty flank's pair: 43 µm shallower.
  SunPlanet s;
  GearSpec faulty = s.planet;
  faulty.errors.flank_offsets.push_back({0, Flank::Ccw, -43e-6});
  const FlankTable tf = table_of(faulty);
  const double dtheta = 50e-6 / 11.2763e-3;
  int faulty_seen = 0, healthy_seen = 0;
  for (int i = 0; i < 60; ++i) {
    const double roll = -0.5 * 2 * kPi / 24 + i / 60.0 * 2 * 2 * kPi / 24;
    PlanarPose sun{{0, 0}, roll + dtheta};
    PlanarPose planet = s.planet_pose;
    planet.angle_rad -= roll * 24.0 / 36.0;
    const std::vector<ToothContact> healthy = find_tooth_contacts(s.ts, sun, s.tp, planet);
    for (const ToothContact& c : find_tooth_contacts(s.ts, sun, tf, planet)) {
      // Conjugate contact only, away from the ends of the path of contact (which runs from
      // −2.50 to +2.37 mm about the pitch point): near the ends a 50 µm press reaches past the
      // tip corner, where the depth is no longer the flank offset.
      if (off_line_of_action(c.point_m) > 1e-6 || (c.point_m - Eigen::Vector2d(12e-3, 0)).norm() > 1.5e-3) continue;
      for (const ToothContact& h : healthy) {
        if (h.tooth_a != c.tooth_a || h.tooth_b != c.tooth_b || h.flank_a != c.flank_a) continue;
        const bool faulty_pair = c.tooth_b == 0;
        (faulty_pair ? faulty_seen : healthy_seen)++;
        // Same tables elsewhere: identical depths. The faulty pair: 43 µm less, to the tables'
        // accuracy (a few nm).
        EXPECT_NEAR(h.depth_m - c.depth_m, faulty_pair ? 43e-6 : 0.0, 0.01e-6) << "tooth_b " << c.tooth_b;
      }
    }
  }
  EXPECT_GT(faulty_seen, 0) << "the faulty tooth never came into mesh";
  EXPECT_GT(healthy_seen, 0);
}

}  // namespace
}  // namespace gearsim::contact

namespace gearsim::contact {
namespace {

TEST(FlankTable, IdenticalTeethShareOneShapeAndAnErrorKeepsItsOwn) {
  // A generated gear's teeth are rotated copies of one tooth: one shape in the table. A flank
  // error on tooth 0 makes that tooth a second shape; probing it still sees the error.
  const GearSpec healthy = fine(test::external_gear(36, 0.010));
  GearSpec faulty = healthy;
  faulty.errors.flank_offsets.push_back({0, Flank::Ccw, -43e-6});
  const FlankTable th = table_of(healthy), tf = table_of(faulty);
  EXPECT_EQ(th.distinct_teeth(), 1);
  EXPECT_EQ(tf.distinct_teeth(), 2);
  const double r = 18e-3;  // reference radius: on the involute
  const double arc = r * (th.flank_angle(0, Flank::Ccw, r) - tf.flank_angle(0, Flank::Ccw, r));
  // 43 µm along the normal is 43/cos(20°) µm along the reference circle (normal = arc·cos α there).
  EXPECT_NEAR(arc, 43e-6 / std::cos(20.0 * kPi / 180), 0.05e-6);
  EXPECT_NEAR(th.flank_angle(5, Flank::Ccw, r), tf.flank_angle(5, Flank::Ccw, r), 1e-12);
}

}  // namespace
}  // namespace gearsim::contact

namespace gearsim::contact {
namespace {

TEST(FlankTable, FirstOrderProbeAgreesWithTheExactOne) {
  // Points across the planet's working flanks (the involute, from above the base circle
  // 16.91 mm to the tip; the fillet below meets no tooth in a mesh without interference): the
  // trigonometry-free probe picks the same tooth and flank as the exact one. Within the window where tooth contact refines a maximum (5 µm of
  // overlap or gap) its depth is within 0.2 µm of the exact depth: its error is second order in
  // the depth, d²/ρ with ρ down to ~0.2 mm where the flank turns toward the tangential (fillet),
  // and 0.2 µm keeps the coarse search's error budget (1.2 µm sampling rise + this) inside 5 µm.
  const FlankTable t = table_of(fine(test::external_gear(36, 0.010)));
  int compared = 0;
  for (int i = 0; i < 20000; ++i) {
    const double a = i * 7.3e-4, r = 17.0e-3 + (i % 997) / 997.0 * (t.r_max_m() - 17.0e-3);
    const Eigen::Vector2d p(r * std::cos(a), r * std::sin(a));
    const FlankTable::Probe fast = t.probe_depth(p), exact = t.probe(p);
    ASSERT_EQ(fast.has_flank, exact.has_flank) << i;
    if (!exact.has_flank || std::abs(exact.depth_m) > 5e-6) continue;
    EXPECT_EQ(fast.inside, exact.inside) << i;
    EXPECT_EQ(fast.tooth, exact.tooth) << i;
    EXPECT_EQ(fast.flank, exact.flank) << i;
    EXPECT_NEAR(fast.depth_m, exact.depth_m, 0.2e-6) << i;
    ++compared;
  }
  EXPECT_GT(compared, 100);
}

}  // namespace
}  // namespace gearsim::contact

namespace gearsim::contact {
namespace {

TEST(ToothContact, TipCornerOfTheSecondGearIsFound) {
  // Pressed 20 µm along the line of action, the planet's tip corners cut into the sun's flanks
  // where a tooth pair enters and leaves mesh. Probing the planet only at its tips must still
  // report every such contact at least as deep as the corner itself sits in the sun (measured
  // exactly, point by point).
  SunPlanet s;
  const double press = 20e-6 / 11.2763e-3;
  int corners = 0;
  for (int i = 0; i < 240; ++i) {
    const double roll = i / 240.0 * 2 * 2 * kPi / 24;
    const PlanarPose sun{{0, 0}, roll + press};
    PlanarPose planet = s.planet_pose;
    planet.angle_rad -= roll * 24.0 / 36.0;
    const std::vector<ToothContact> found = find_tooth_contacts(s.ts, sun, s.tp, planet);
    const Eigen::Rotation2Dd to_world(planet.angle_rad), to_sun(-sun.angle_rad);
    for (int k = 0; k < s.tp.teeth(); ++k)
      for (Flank f : {Flank::Ccw, Flank::Cw}) {
        const Eigen::Vector2d corner_world = planet.centre_m + to_world * s.tp.probe_point(k, f, FlankTable::kProbeRadii - 1);
        const FlankTable::Probe p = s.ts.probe(to_sun * corner_world);
        if (!p.inside || !p.has_flank || p.depth_m < 0.1e-6) continue;
        ++corners;
        double reported = 0;
        for (const ToothContact& c : found)
          if (c.tooth_a == p.tooth && c.tooth_b == k) reported = std::max(reported, c.depth_m);
        EXPECT_GE(reported, p.depth_m - 0.01e-6) << "planet tooth " << k << " at roll step " << i;
      }
  }
  EXPECT_GT(corners, 10);  // the sweep does produce corner contacts
}

}  // namespace
}  // namespace gearsim::contact

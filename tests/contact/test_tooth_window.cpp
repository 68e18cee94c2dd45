// The searches' tooth window (contact/flank_search_impl.hpp, tooth_window() and for_each_tooth()):
// every tooth whose bounding circle reaches the other gear's toothed annulus (tooth_near()) lies
// in the window, each tooth is visited once and in increasing order — over random poses of an
// external pair, an internal pair, gears far apart and gears turned many times.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "geometry/gear_profile.hpp"
#include "tests/support/gear_specs.hpp"

// The search internals (an anonymous namespace: this file gets its own copy); some are unused here.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#include "contact/flank_search_impl.hpp"
#pragma GCC diagnostic pop

namespace gearsim::contact {
namespace {

FlankTable window_table(const GearSpec& s) {
  const GearOutline o = make_gear_outline(s);
  const Polygon2& loop = s.kind == GearKind::External ? o.outline.outer : o.outline.holes.front();
  return FlankTable(loop, {s.teeth, s.tooth0_angle_rad}, s.kind == GearKind::Internal, 256);
}

// Over `poses` random placements of x about y at centre distances in [d_lo, d_hi] and any angles
// (up to ±1000 rad: a gear turned many times), the teeth tooth_near() accepts against those the
// window visits. Returns how many teeth the window visited that tooth_near() rejected.
long check_window(const FlankTable& x_table, const FlankTable& y_table, double d_lo, double d_hi, int poses) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> dist(d_lo, d_hi), dir(-3.2, 3.2), angle(-1000, 1000);
  long extra = 0;
  for (int i = 0; i < poses; ++i) {
    const double d = dist(rng), phi = dir(rng);
    const PlanarPose px{{d * std::cos(phi), d * std::sin(phi)}, angle(rng)}, py{{0, 0}, angle(rng)};
    const Frame x{x_table, px}, y{y_table, py};
    std::vector<int> visited, visited_from_y;
    for_each_tooth(tooth_window(x, y), x_table.teeth(), [&](int k) { visited.push_back(k); });
    // As CoherentToothSearch's second pass takes it: the distance and direction measured from
    // y's centre to x's, the direction turned by π.
    const Vector2d y_to_x = px.centre_m - py.centre_m;
    for_each_tooth(tooth_window(x, y, y_to_x.norm(), rough_atan2(y_to_x.y(), y_to_x.x()) + 3.141592653589793), x_table.teeth(),
                   [&](int k) { visited_from_y.push_back(k); });
    for (std::size_t j = 1; j < visited.size(); ++j) EXPECT_LT(visited[j - 1], visited[j]) << "pose " << i;
    for (std::size_t j = 1; j < visited_from_y.size(); ++j) EXPECT_LT(visited_from_y[j - 1], visited_from_y[j]) << "pose " << i;
    for (int k = 0; k < x_table.teeth(); ++k) {
      const bool in_window = std::find(visited.begin(), visited.end(), k) != visited.end();
      const bool in_window_from_y = std::find(visited_from_y.begin(), visited_from_y.end(), k) != visited_from_y.end();
      if (tooth_near(x, k, y)) {
        EXPECT_TRUE(in_window) << "pose " << i << ": tooth " << k << " reaches y but lies outside the window";
        EXPECT_TRUE(in_window_from_y) << "pose " << i << ": tooth " << k << " reaches y but lies outside the window taken from y";
      } else if (in_window) {
        ++extra;
      }
    }
  }
  return extra;
}

TEST(ToothWindow, HoldsEveryToothThatReachesTheOtherGear) {
  const FlankTable sun = window_table(test::external_gear(24)), planet = window_table(test::external_gear(36, 0.010));
  const FlankTable ring = window_table(test::internal_gear(96));
  // Sun–planet around their 30 mm centre distance (overlapping, meshing, apart).
  check_window(sun, planet, 20e-3, 40e-3, 4000);
  check_window(planet, sun, 20e-3, 40e-3, 4000);
  // A planet inside the ring (its centre 30 mm from the ring's), both ways round.
  check_window(planet, ring, 25e-3, 35e-3, 4000);
  check_window(ring, planet, 25e-3, 35e-3, 4000);
}

TEST(ToothWindow, HoldsNoMoreTeethThanReachTheOtherGearNearTheMesh) {
  // Within 0.5 mm of the meshing distance tooth_near() is the window's own test (one circle of
  // the two binds): only the margin (1e-4 rad; 2.3e-4 rad about the opposite direction, of
  // pitches of 0.065–0.26 rad) can add a tooth, in well under 1 % of the poses.
  const FlankTable sun = window_table(test::external_gear(24)), planet = window_table(test::external_gear(36, 0.010));
  EXPECT_LE(check_window(sun, planet, 29.5e-3, 30.5e-3, 4000), 40);
  EXPECT_LE(check_window(planet, sun, 29.5e-3, 30.5e-3, 4000), 40);
  // A planet inside the ring: every planet tooth lies within the ring's tip circle plus its
  // reach, so the window is the one about the direction away from the ring's centre (the teeth
  // beyond the ring's root circle less the reach), about a quarter of the planet's 36 teeth.
  const FlankTable ring = window_table(test::internal_gear(96));
  EXPECT_LE(check_window(planet, ring, 29.5e-3, 30.5e-3, 4000), 40);
  EXPECT_LE(check_window(ring, planet, 29.5e-3, 30.5e-3, 4000), 40);
}

}  // namespace
}  // namespace gearsim::contact

// FlankTable's bounds the coherent search rests on (contact/flank_table.hpp): how far the
// first-order depth can rise with a move (first_order_rise()), and how far a point can move and
// still face the same flank (face()'s margin) — on the paper's sun, ring and faulty planet.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "contact/flank_table.hpp"
#include "tests/support/paper_flank_tables.hpp"

namespace gearsim::contact {
namespace {

using test::Gear;
using test::named;
using test::paper_gears;

TEST(FirstOrderRise, BoundsHowFarTheFirstOrderDepthMovesWithThePoint) {
  // The bound the coherent search rests on (FlankTable::first_order_rise): for points anywhere in
  // the teeth of the paper's sun and ring moved by up to 20 µm in any direction (staying clear of
  // the root and tip circles), the first-order depth after the move stays below the bound from
  // the depth before it. 200 000 random moves per gear.
  const std::vector<Gear>& g = paper_gears();
  for (const char* name : {"sun", "ring", "planet_0"}) {
    const FlankTable& t = *named(g, name).table;
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> unit(0, 1);
    long checked = 0, above = 0;
    for (int i = 0; i < 200000; ++i) {
      const double delta = 20e-6 * unit(rng), r = t.r_min_m() + delta + unit(rng) * (t.r_max_m() - t.r_min_m() - 2 * delta);
      const double at = 2 * M_PI * unit(rng), dir = 2 * M_PI * unit(rng);
      const Eigen::Vector2d q0 = r * Eigen::Vector2d(std::cos(at), std::sin(at));
      const Eigen::Vector2d q1 = q0 + delta * unit(rng) * Eigen::Vector2d(std::cos(dir), std::sin(dir));
      int h0 = -1, h1 = -1;
      const double d0 = t.first_order_depth(q0, h0), d1 = t.first_order_depth(q1, h1);
      const FlankTable::FirstOrderRise rise = t.first_order_rise(r - delta, r + delta);
      if (d0 <= FlankTable::kNoDepth || d1 <= FlankTable::kNoDepth || !(rise.slope < FlankTable::kInfinity) || rise.growth * delta >= 0.5 ||
          rise.jump >= 1)
        continue;
      const double top = d0 < 0 ? d0 * (1 - rise.jump) : d0;
      const double f = top + delta * (rise.slope + rise.growth * (std::abs(top) + rise.slope * delta) / (1 - rise.growth * delta));
      above += d1 > (f > 0 ? f * (1 + rise.jump) : f);
      ++checked;
    }
    EXPECT_GT(checked, 100000) << name;
    EXPECT_EQ(above, 0) << name << ": moves whose depth rose beyond the bound, of " << checked;
  }
}

TEST(FlankTable, AMoveWithinTheFacingMarginFacesTheSameFlank) {
  const std::vector<Gear>& g = paper_gears();
  for (const char* name : {"sun", "ring", "planet_0"}) test::expect_facing_margin_holds(*named(g, name).table, name, 100000);
}

}  // namespace
}  // namespace gearsim::contact

// Outline helpers: signed area and the area of an outline with a hole.
#include <gtest/gtest.h>

#include <algorithm>

#include "geometry/outline.hpp"

namespace gearsim {
namespace test_outline {

TEST(Outline, UnitSquareAreaIsOneAndSignFollowsOrientation) {
  Polygon2 sq{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
  EXPECT_DOUBLE_EQ(signed_area(sq), 1.0);
  std::reverse(sq.points.begin(), sq.points.end());
  EXPECT_DOUBLE_EQ(signed_area(sq), -1.0);
}

TEST(Outline, HoleIsSubtracted) {
  Outline2 o;
  o.outer = Polygon2{{{0, 0}, {4, 0}, {4, 4}, {0, 4}}};
  o.holes.push_back(Polygon2{{{1, 1}, {1, 2}, {2, 2}, {2, 1}}});  // clockwise
  EXPECT_DOUBLE_EQ(area(o), 15.0);
}

}  // namespace test_outline
}  // namespace gearsim

// The involute function and its inverse.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "geometry/involute.hpp"

namespace gearsim {
namespace test_involute {

TEST(Involute, TwentyDegreesMatchesTheTabulatedValue) {
  // inv 20° = 0.014904383867336 (tables of the involute function); exact double arithmetic.
  EXPECT_NEAR(involute(20.0 * std::numbers::pi / 180.0), 0.014904383867336, 1e-15);
}

TEST(Involute, InverseRecoversTheAngleOverTheWholeRange) {
  for (double deg = 0.5; deg < 80.0; deg += 0.5) {
    const double a = deg * std::numbers::pi / 180.0;
    // Newton on tan a − a converges to machine precision; 1e-12 rad leaves room for the
    // conditioning of tan near 80°.
    EXPECT_NEAR(inverse_involute(involute(a)), a, 1e-12) << deg << "°";
  }
}

TEST(Involute, RollLengthIsThePythagoreanTangent) {
  // A 3-4-5 triangle: base radius 3, radius 5 → roll length 4, pressure angle acos(3/5).
  EXPECT_DOUBLE_EQ(roll_length_at(3.0, 5.0), 4.0);
  EXPECT_DOUBLE_EQ(pressure_angle_at(3.0, 5.0), std::acos(0.6));
}

}  // namespace test_involute
}  // namespace gearsim

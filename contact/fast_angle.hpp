// Internal to contact/: angle functions without a libm call, for choosing teeth (never for a
// contact's geometry, which is exact).
#pragma once

#include <cmath>

namespace gearsim::contact {

// atan2 to about 1e-5 rad (Abramowitz & Stegun 4.4.49 on [0, 1], reduced by octant): enough to
// pick the tooth a point faces; the angle within the tooth is then exact.
inline double rough_atan2(double y, double x) {
  const double ax = std::abs(x), ay = std::abs(y);
  const bool steep = ay > ax;
  const double z = steep ? ax / ay : (ax > 0 ? ay / ax : 0.0);
  const double z2 = z * z;
  double a = z * (0.9998660 + z2 * (-0.3302995 + z2 * (0.1801410 + z2 * (-0.0851330 + z2 * 0.0208351))));
  if (steep) a = 1.5707963267948966 - a;
  if (x < 0) a = 3.141592653589793 - a;
  return y < 0 ? -a : a;
}

// An upper bound on acos(x) for x in [−1, 1], at most 1e-4 rad above it (Abramowitz & Stegun
// 4.4.45, |error| ≤ 6.7e-5 rad on [0, 1], plus that error): for windows that must not be too narrow.
inline double acos_above(double x) {
  constexpr double kError = 6.7e-5;
  const double ax = std::abs(x);
  const double a = std::sqrt(1 - ax) * (1.5707288 + ax * (-0.2121144 + ax * (0.0742610 + ax * -0.0187293)));
  return x >= 0 ? a + kError : 3.141592653589793 - a + kError;
}

}  // namespace gearsim::contact

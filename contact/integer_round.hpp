// Internal to contact/: rounding a double to an integer value without a libm call (on x86-64
// without SSE4.1, which the portable build targets, std::floor, std::ceil and std::nearbyint are
// calls into libm). Each gives libm's value, except that a zero result is always +0.
#pragma once

namespace gearsim::contact {

// std::floor(x) for |x| < 2^52 (the truncation toward zero is exact there).
inline double floor_small(double x) {
  const double t = static_cast<double>(static_cast<long long>(x));
  return t > x ? t - 1 : t;
}

// std::ceil(x) for |x| < 2^52.
inline double ceil_small(double x) {
  const double t = static_cast<double>(static_cast<long long>(x));
  return t < x ? t + 1 : t;
}

// std::nearbyint(x) in the default rounding mode (to nearest, ties to even) for |x| < 2^51:
// adding and subtracting 1.5·2^52 rounds to an integer.
inline double round_to_even(double x) {
  constexpr double kShift = 6755399441055744.0;  // 1.5·2^52
  return (x + kShift) - kShift;
}

// Below this magnitude the functions above hold (2^51).
constexpr double kIntegerRoundLimit = 2251799813685248.0;

}  // namespace gearsim::contact

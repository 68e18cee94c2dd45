// Linear resampling: exact on straight lines, within h²·max|y''|/8 on a sine, and strict about
// its input.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "analysis/resample.hpp"
#include "core/errors.hpp"
#include "tests/analysis/synthetic_signals.hpp"

namespace gearsim {
namespace test_resample {

using test::kTwoPi;

// Jittered sample times: nominal step dt, each moved by up to ±0.4·dt (strictly increasing).
std::vector<double> jittered_times(std::size_t n, double dt, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-0.4, 0.4);
  std::vector<double> t(n);
  for (std::size_t i = 0; i < n; ++i) t[i] = (static_cast<double>(i) + (i == 0 ? 0.0 : u(rng))) * dt;
  return t;
}

TEST(Resample, StraightLineIsExact) {
  const std::vector<double> t = jittered_times(1000, 1e-3, 1);
  std::vector<double> y(t.size());
  for (std::size_t i = 0; i < t.size(); ++i) y[i] = 3.0 - 2.0 * t[i];
  const UniformSignal u = resample_uniform(t, y, 750.0);
  ASSERT_GT(u.values.size(), 700u);
  for (std::size_t k = 0; k < u.values.size(); ++k)
    EXPECT_NEAR(u.values[k], 3.0 - 2.0 * (u.start_time_s + static_cast<double>(k) / 750.0), 1e-12);
}

TEST(Resample, SineWithinTheLinearInterpolationBound) {
  // |error| ≤ h²·(2πf)²·A/8 with h the largest input step (≤ 1.8 ms here).
  constexpr double kF = 7.0, kA = 1.5;
  const std::vector<double> t = jittered_times(2000, 1e-3, 2);
  std::vector<double> y(t.size());
  double h = 0.0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    y[i] = kA * std::sin(kTwoPi * kF * t[i]);
    if (i > 0) h = std::max(h, t[i] - t[i - 1]);
  }
  const double bound = h * h * std::pow(kTwoPi * kF, 2) * kA / 8.0;
  const UniformSignal u = resample_uniform(t, y, 1000.0);
  double worst = 0.0;
  for (std::size_t k = 0; k < u.values.size(); ++k) {
    const double tk = u.start_time_s + static_cast<double>(k) / u.sample_rate_hz;
    worst = std::max(worst, std::abs(u.values[k] - kA * std::sin(kTwoPi * kF * tk)));
  }
  EXPECT_LE(worst, bound);
  EXPECT_GT(worst, 0.0);  // it is an approximation, and says so
}

TEST(Resample, UniformRateIsMeasuredAndJitterIsRefused) {
  std::vector<double> t(101);
  for (std::size_t i = 0; i < t.size(); ++i) t[i] = 0.5 + static_cast<double>(i) / 400.0;
  EXPECT_NEAR(uniform_sample_rate_hz(t), 400.0, 1e-9);
  EXPECT_THROW(uniform_sample_rate_hz(jittered_times(100, 1e-3, 3)), InputError);
}

TEST(Resample, BadInputIsRejected) {
  EXPECT_THROW(resample_uniform({0.0, 0.0, 1.0}, {1, 2, 3}, 10.0), InputError);  // repeated time
  EXPECT_THROW(resample_uniform({0.0, 1.0}, {1, 2}, -1.0), InputError);
  EXPECT_THROW(interpolate_linear({0.0, 1.0}, {1, 2}, {1.5}), InputError);  // outside
}

}  // namespace test_resample
}  // namespace gearsim

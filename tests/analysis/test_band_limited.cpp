// Extremes of a band-limited signal between its samples: the same whatever the samples' phase,
// where the samples' own max − min read low.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "analysis/band_limited.hpp"
#include "core/errors.hpp"
#include "tests/analysis/synthetic_signals.hpp"

namespace gearsim {
namespace test_band_limited {

using test::kTwoPi;

constexpr double kRate = 2000;  // the paper runs' output rate, Hz

// A mesh-like signal: the paper's harmonics 320 / 640 / 960 Hz (960 Hz is 0.48 of the rate, the
// anti-aliasing filter's passband edge), amplitudes and phases of no special kind.
double tones(double t) {
  return 1.0 * std::sin(kTwoPi * 320 * t + 0.3) + 0.7 * std::sin(kTwoPi * 640 * t + 1.1) + 0.9 * std::sin(kTwoPi * 960 * t + 2.0);
}

// A dip like a fault event's in the TE: a Gaussian of σ = 1 ms (its spectrum e^{−(2π·f·σ)²/2} is
// 3e-9 of its peak at 1 kHz: band-limited to double precision's scale) on a slope.
double dip(double t) { return 2e-4 * t - 4e-4 * std::exp(-0.5 * std::pow((t - 0.2371) / 1e-3, 2)); }

// The continuous signal's extremes over [t0, t1], evaluated every 0.1 µs.
Extremes dense(double (*f)(double), double t0, double t1) {
  Extremes e{std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
  for (double t = t0; t <= t1; t += 1e-7) e.min = std::min(e.min, f(t)), e.max = std::max(e.max, f(t));
  return e;
}

std::vector<double> sampled(double (*f)(double), double t0, std::size_t n) {
  std::vector<double> x(n);
  for (std::size_t k = 0; k < n; ++k) x[k] = f(t0 + static_cast<double>(k) / kRate);
  return x;
}

TEST(BandLimited, TonesPeakToPeakDoesNotDependOnWhereTheSamplesFall) {
  for (int offset = 0; offset < 8; ++offset) {
    const double t0 = 0.05 + offset / (8 * kRate);
    const std::size_t n = 1000;
    const std::vector<double> x = sampled(tones, t0, n);
    // Where the kernel has samples on both sides (the ends count by their samples only, which
    // here lie below the interior's extremes: the tones repeat every 25 samples).
    const double interior0 = t0 + static_cast<double>(kBandLimitedHalfTaps - 1) / kRate,
                 interior1 = t0 + static_cast<double>(n - kBandLimitedHalfTaps - 1) / kRate;
    const Extremes truth = dense(tones, interior0, interior1);
    const Extremes e = band_limited_extremes(x);
    // The kernel is flat to 3e-5 up to 0.485 of the rate: each tone within 3e-5 of its amplitude,
    // 1e-4 of the peak-to-peak with room for the parabola's last step.
    EXPECT_NEAR(e.max, truth.max, 1e-4 * (truth.max - truth.min)) << offset;
    EXPECT_NEAR(e.min, truth.min, 1e-4 * (truth.max - truth.min)) << offset;
  }
}

TEST(BandLimited, APulseBetweenSamplesIsFoundAtItsFullDepth) {
  double worst_samples = 0;
  for (int offset = 0; offset < 8; ++offset) {
    const double t0 = 0.2 + offset / (8 * kRate);
    const std::vector<double> x = sampled(dip, t0 - 0.06, 400);  // the dip 120 samples in: inside the interior
    const Extremes truth = dense(dip, t0 - 0.06, t0 - 0.06 + 399 / kRate);
    const Extremes e = band_limited_extremes(x);
    EXPECT_NEAR(e.min, truth.min, 1e-6 * (truth.max - truth.min)) << offset;
    EXPECT_NEAR(e.max - e.min, truth.max - truth.min, 1e-6 * (truth.max - truth.min)) << offset;
    double lo = x[0];
    for (double v : x) lo = std::min(lo, v);
    worst_samples = std::max(worst_samples, (lo - truth.min) / (truth.max - truth.min));
  }
  // The samples alone miss part of the dip: a quarter of a millisecond off its centre they read
  // e^{−(0.25/1)²/2} = 97 % of its 4e-4 depth, the rest of the p2p being the slope's 4e-5.
  EXPECT_GT(worst_samples, 0.02);
}

TEST(BandLimited, ShortRecordsGiveTheirSamplesAndBadInputIsRefused) {
  const std::vector<double> few = {1, 3, -2, 0.5};
  const Extremes e = band_limited_extremes(few);
  EXPECT_EQ(e.min, -2);
  EXPECT_EQ(e.max, 3);
  EXPECT_THROW(band_limited_extremes({}), InputError);
  EXPECT_THROW(band_limited_extremes({1, std::nan(""), 2}), InputError);
}

}  // namespace test_band_limited
}  // namespace gearsim

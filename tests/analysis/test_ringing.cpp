// Ringing estimate: a damped sinusoid on an offset gives back its frequency and damping ratio
// (the closed form it was made from); anything else shows in the residual or is refused.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "analysis/ringing.hpp"
#include "core/errors.hpp"
#include "tests/analysis/synthetic_signals.hpp"

namespace gearsim {
namespace test_ringing {

using test::kTwoPi;

constexpr double kFs = 50000.0;  // the paper's step rate, Hz

// offset + a·exp(−ζ·ω_n·t)·cos(ω_d·t + φ), ω_d = ω_n·√(1 − ζ²), t = k/fs.
std::vector<double> ringing(std::size_t n, double fn_hz, double zeta, double offset) {
  const double wn = kTwoPi * fn_hz, wd = wn * std::sqrt(1.0 - zeta * zeta);
  std::vector<double> x(n);
  for (std::size_t k = 0; k < n; ++k) {
    const double t = static_cast<double>(k) / kFs;
    x[k] = offset + 30.0 * std::exp(-zeta * wn * t) * std::cos(wd * t + 0.4);
  }
  return x;
}

TEST(Ringing, DampedSineGivesItsFrequencyAndDamping) {
  // A contact ringing at 6 kHz, ζ = 2 %, on a 120 N mean force; 20 ms (5 time constants).
  // Two-pole prediction is exact for this signal: the tolerances are rounding (~1e-14 over 1000
  // samples) with a margin.
  const double fn = 6000.0, zeta = 0.02;
  const RingingEstimate e = estimate_ringing(ringing(1000, fn, zeta, 120.0), kFs);
  EXPECT_NEAR(e.frequency_hz, fn * std::sqrt(1.0 - zeta * zeta), 1e-10 * fn);
  EXPECT_NEAR(e.damping_ratio, zeta, 1e-10);
  EXPECT_NEAR(e.decay_rate_per_s, zeta * kTwoPi * fn, 1e-10 * zeta * kTwoPi * fn);
  EXPECT_LT(e.relative_residual, 1e-9);
}

TEST(Ringing, AnUndampedToneHasZeroDamping) {
  const RingingEstimate e = estimate_ringing(test::tone(5000, kFs, 1234.5, 2.0, 1.0), kFs);
  EXPECT_NEAR(e.frequency_hz, 1234.5, 1e-10 * 1234.5);
  EXPECT_NEAR(e.damping_ratio, 0.0, 1e-10);
}

TEST(Ringing, ASecondComponentShowsInTheResidual) {
  // A 320 Hz mesh-frequency component of 10 % beside the ringing: one mode no longer explains
  // the record, and the residual rises from rounding to at least 1 %.
  std::vector<double> x = ringing(1000, 6000.0, 0.02, 120.0);
  test::add(x, test::tone(x.size(), kFs, 320.0, 3.0));
  EXPECT_GT(estimate_ringing(x, kFs).relative_residual, 0.01);
}

TEST(Ringing, RecordsWithoutOscillationAreRefused) {
  std::vector<double> decay(500);
  for (std::size_t k = 0; k < decay.size(); ++k) decay[k] = 5.0 * std::exp(-static_cast<double>(k) / 80.0);
  try {
    estimate_ringing(decay, kFs);
    ADD_FAILURE() << "a plain exponential decay was fitted as a ringing";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("not an oscillation"), std::string::npos) << e.what();
  }
  EXPECT_THROW(estimate_ringing(std::vector<double>(100, 3.0), kFs), InputError);
  EXPECT_THROW(estimate_ringing({1, 2, 3}, kFs), InputError);
  std::vector<double> bad = ringing(100, 6000.0, 0.02, 0.0);
  bad[7] = NAN;
  EXPECT_THROW(estimate_ringing(bad, kFs), InputError);
  EXPECT_THROW(estimate_ringing(ringing(100, 6000.0, 0.02, 0.0), 0.0), InputError);
}

}  // namespace test_ringing
}  // namespace gearsim

// Welch averaging: the PSD level of white noise, and a steady tone's amplitude.
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/spectrum.hpp"
#include "core/errors.hpp"
#include "tests/analysis/synthetic_signals.hpp"

namespace gearsim {
namespace test_welch {

TEST(Welch, WhiteNoiseHasSingleSidedDensitySigmaSquaredOverHalfTheRate) {
  // σ² spread over 0 … fs/2: PSD = σ²/(fs/2). Mean over the 511 interior bins of K = 255 Hann
  // segments of L = 1024, 50 % overlap. Its relative variance is 2·Σ_n c_n²/(K·S2)², where
  // c_n = Σ_k w²(n − s_k) ≤ 1 (sin⁴ + cos⁴ ≤ 1) and S2 = Σw² = 3L/8, so at most
  // 2/(K·S2) = 16/(3·K·L) = 2.0e-5: a standard deviation ≤ 0.45 %. Tolerance 2 % (> 4σ).
  // No mean removal: subtracting a segment's mean biases bin 1 of a Hann spectrum.
  constexpr double kFs = 1000.0, kSigma = 0.7;
  const std::vector<double> x = test::white_noise(131072, kSigma, 42);
  WelchOptions o;
  o.segment_length = 1024;
  o.remove_mean = false;
  const Spectrum s = welch_spectrum(x, kFs, o);
  EXPECT_EQ(s.averages, 255);
  double level = 0.0;
  for (std::size_t k = 1; k + 1 < s.psd_per_hz.size(); ++k) level += s.psd_per_hz[k];
  level /= static_cast<double>(s.psd_per_hz.size() - 2);
  const double expected = kSigma * kSigma / (kFs / 2.0);
  EXPECT_NEAR(level, expected, 0.02 * expected);
  EXPECT_DOUBLE_EQ(s.resolution_hz, kFs / 1024.0);  // a segment's 1/T, not the record's
}

TEST(Welch, SteadyOnBinToneReadsItsAmplitudeInEverySegment) {
  // 125 Hz is on a bin of 1024-sample segments at 1024 Hz: each segment reads exactly A whatever
  // its phase, so the RMS over segments is A to rounding (1e-9 relative).
  constexpr double kFs = 1024.0, kA = 3.0;
  WelchOptions o;
  o.segment_length = 1024;
  o.overlap_fraction = 0.25;
  const Spectrum s = welch_spectrum(test::tone(16384, kFs, 125.0, kA, 0.4), kFs, o);
  EXPECT_NEAR(s.amplitude[125], kA, 1e-9 * kA);
  EXPECT_EQ(s.averages, 21);  // (16384 − 1024)/768 + 1
}

TEST(Welch, BadSegmentingIsRejected) {
  const std::vector<double> x(100, 1.0);
  WelchOptions o;
  o.segment_length = 101;
  EXPECT_THROW(welch_spectrum(x, 100.0, o), InputError);
  o.segment_length = 50;
  o.overlap_fraction = 1.0;
  EXPECT_THROW(welch_spectrum(x, 100.0, o), InputError);
}

}  // namespace test_welch
}  // namespace gearsim

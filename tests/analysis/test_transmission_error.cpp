// Transmission error of a synthetic train whose input leads by c + a·sin(2πft): statistics in
// every unit, and the spectrum.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "analysis/peaks.hpp"
#include "analysis/transmission_error.hpp"
#include "core/errors.hpp"
#include "tests/analysis/synthetic_signals.hpp"

namespace gearsim {
namespace test_transmission_error {

using test::kTwoPi;

constexpr double kRatio = 5.0;  // the paper's sun → carrier ratio, 1 + 96/24
constexpr double kCarrier = 20.94;  // rad/s (104.7/5)
constexpr double kA = 100e-6;  // rad: TE amplitude
constexpr double kC = 20e-6;  // rad: TE mean
constexpr double kF = 320.0;  // Hz: at the mesh frequency
constexpr double kFs = 64.0 * kF;  // Hz: 64 samples per period, one on each crest and trough
constexpr double kSunBase = 0.012 * std::cos(20.0 * std::numbers::pi / 180.0);  // m: z 24, m 1 mm

TransmissionError synthetic_te() {
  const std::size_t n = static_cast<std::size_t>(kFs);  // 1 s = 320 whole periods
  std::vector<double> t(n), in(n), out(n);
  for (std::size_t i = 0; i < n; ++i) {
    t[i] = static_cast<double>(i) / kFs;
    out[i] = kCarrier * t[i];
    in[i] = kRatio * out[i] + kC + kA * std::sin(kTwoPi * kF * t[i]);
  }
  return transmission_error(t, in, out, kRatio);
}

TEST(TransmissionError, StatisticsOfASineAreItsAmplitudeAndMean) {
  // TE = c + a·sin: min c − a, max c + a, p-p 2a, RMS about the mean a/√2 (whole periods, 64
  // samples each: exact). Tolerance 1e-12 rad: θ_in reaches 105 rad, and 105·2.2e-16 ≈ 2e-14 rad
  // is lost when i·θ_out is subtracted from it.
  const TransmissionErrorStats s = te_stats(synthetic_te(), kSunBase);
  EXPECT_NEAR(s.rad.mean, kC, 1e-12);
  EXPECT_NEAR(s.rad.min, kC - kA, 1e-12);
  EXPECT_NEAR(s.rad.max, kC + kA, 1e-12);
  EXPECT_NEAR(s.rad.peak_to_peak, 2 * kA, 1e-12);
  EXPECT_NEAR(s.rad.rms, kA / std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(s.urad.peak_to_peak, 200.0, 1e-6);
  EXPECT_NEAR(s.deg.peak_to_peak, 2 * kA * 180.0 / std::numbers::pi, 1e-10);
  ASSERT_TRUE(s.um);
  EXPECT_NEAR(s.um->peak_to_peak, 2 * kA * kSunBase * 1e6, 1e-9);  // 2.255 µm along the line of action
}

TEST(TransmissionError, SpectrumShowsTheTeAmplitudeAtItsFrequency) {
  // Flat-top, 320 Hz on a bin of the 1 s record: exactly a (1e-9 relative, rounding).
  const Spectrum s = te_spectrum(synthetic_te(), {WindowKind::FlatTop});
  EXPECT_NEAR(s.amplitude[nearest_bin(s, kF)], kA, 1e-9 * kA);
}

TEST(TransmissionError, VariableStepLogNeedsAResampleRate) {
  TransmissionError te = synthetic_te();
  te.time_s[10] += 0.3 / kFs;  // one jittered step
  EXPECT_THROW(te_spectrum(te), InputError);
  const Spectrum s = te_spectrum(te, {WindowKind::FlatTop}, kFs);
  // One sample moved by 0.3 of a step perturbs the resampled series at one point only.
  EXPECT_NEAR(s.amplitude[nearest_bin(s, kF)], kA, 1e-3 * kA);
}

TEST(TransmissionError, BadInputIsRejected) {
  EXPECT_THROW(transmission_error({0, 1}, {0, 1}, {0}, 5.0), InputError);
  EXPECT_THROW(transmission_error({0, 1}, {0, 1}, {0, 1}, 0.0), InputError);
  EXPECT_THROW(te_stats(synthetic_te(), -1.0), InputError);
}

}  // namespace test_transmission_error
}  // namespace gearsim

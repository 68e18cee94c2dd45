// Single-record spectra: amplitudes in the signal's unit, scalloping, Parseval, zero padding and
// what the two resolutions (bin width, 1/T) mean.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "analysis/peaks.hpp"
#include "analysis/spectrum.hpp"
#include "core/errors.hpp"
#include "tests/analysis/synthetic_signals.hpp"

namespace gearsim {
namespace test_spectrum {

using test::tone;

constexpr double kFs = 1024.0;  // Hz
constexpr std::size_t kN = 1024;  // 1 s record: 1 Hz resolution, on-bin tones at integer Hz
constexpr double kA = 2.5;  // tone amplitude, signal unit

double max_amplitude(const Spectrum& s, double lo_hz, double hi_hz) {
  double m = 0.0;
  for (std::size_t k = 0; k < s.frequency_hz.size(); ++k)
    if (s.frequency_hz[k] >= lo_hz && s.frequency_hz[k] <= hi_hz) m = std::max(m, s.amplitude[k]);
  return m;
}

TEST(Spectrum, FlatTopRecoversAmplitudeWithinOneThousandthEvenHalfABinOff) {
  // 100.5 Hz lies halfway between bins: the worst case. HFT95's flatness is ±0.05 %, and its
  // −95 dB sidelobes keep the image at −100.5 Hz out, so 0.1 % holds.
  for (const double f_hz : {100.0, 100.25, 100.5}) {
    const Spectrum s = amplitude_spectrum(tone(kN, kFs, f_hz, kA, 0.3), kFs, {WindowKind::FlatTop});
    EXPECT_NEAR(max_amplitude(s, 95, 106), kA, 1e-3 * kA) << f_hz << " Hz";
  }
}

TEST(Spectrum, HannOffBinReadsTheScallopedAmplitudeWithinTheBound) {
  // A tone δ bins off a bin reads A·sinc(δ)/(1 − δ²) at the nearest bin (Hann's transform); at
  // δ = ½ that is 0.8488·A, Hann's worst scalloping (−1.42 dB). Tolerance 1e-4·A: leakage of the
  // negative-frequency image 200 bins away (Hann falls as 1/k³).
  for (const double delta : {0.0, 0.3, 0.5}) {
    const Spectrum s = amplitude_spectrum(tone(kN, kFs, 100.0 + delta, kA), kFs, {WindowKind::Hann});
    const double sinc = delta == 0.0 ? 1.0 : std::sin(std::numbers::pi * delta) / (std::numbers::pi * delta);
    const double expected = kA * sinc / (1.0 - delta * delta);
    const double measured = max_amplitude(s, 95, 106);
    EXPECT_NEAR(measured, expected, 1e-4 * kA) << delta;
    EXPECT_GE(measured, 0.8488 * kA) << "below Hann's scalloping bound";
    EXPECT_LE(measured, kA * (1 + 1e-4));
  }
}

TEST(Spectrum, ParsevalHoldsForTheRectangularWindow) {
  // Σ psd·Δf = mean(x²) exactly (rounding only: 1e-10 relative), for even (Nyquist bin) and odd
  // (no Nyquist bin) lengths, without mean removal.
  for (const std::size_t n : {std::size_t{1000}, std::size_t{999}}) {
    std::vector<double> x = test::white_noise(n, 1.3, 7);
    test::add(x, tone(n, kFs, 123.4, 0.8));
    for (double& v : x) v += 0.25;  // a DC offset, kept
    double mean_square = 0.0;
    for (const double v : x) mean_square += v * v / static_cast<double>(n);
    const Spectrum s = amplitude_spectrum(x, kFs, {WindowKind::Rectangular, 0, false});
    EXPECT_NEAR(spectrum_power(s), mean_square, 1e-10 * mean_square) << n << " samples";
  }
}

TEST(Spectrum, ZeroPaddingKeepsTheAmplitudeOfAnOnBinTone) {
  // 50 Hz is on a bin of every padded grid; padding evaluates the same transform at more
  // frequencies, so the peak is unchanged to rounding (1e-9·A).
  const std::vector<double> x = tone(kN, kFs, 50.0, kA, 1.1);
  const Spectrum plain = amplitude_spectrum(x, kFs, {WindowKind::FlatTop});
  const Spectrum padded = amplitude_spectrum(x, kFs, {WindowKind::FlatTop, 4 * kN});
  EXPECT_NEAR(plain.amplitude[nearest_bin(plain, 50.0)], kA, 1e-9 * kA);
  EXPECT_NEAR(padded.amplitude[nearest_bin(padded, 50.0)], kA, 1e-9 * kA);
  EXPECT_DOUBLE_EQ(padded.bin_width_hz, 0.25);
  EXPECT_DOUBLE_EQ(padded.resolution_hz, 1.0);  // still a 1 s record
}

TEST(Spectrum, PaddingDoesNotResolveTonesCloserThanOneOverT) {
  // Two tones 0.5 Hz apart: a 1 s record (1 Hz resolution) padded 16× to 1/16 Hz bins still
  // shows one peak; a 10 s record (0.1 Hz resolution) shows two. Rectangular window.
  auto peaks_near_100 = [](double seconds, std::size_t pad) {
    const auto n = static_cast<std::size_t>(seconds * kFs);
    std::vector<double> x = tone(n, kFs, 100.0, 1.0);
    test::add(x, tone(n, kFs, 100.5, 1.0));
    const Spectrum s = amplitude_spectrum(x, kFs, {WindowKind::Rectangular, pad * n});
    return local_maxima(s, 98.0, 102.5, 0.5).size();
  };
  EXPECT_EQ(peaks_near_100(1.0, 16), 1u);
  EXPECT_EQ(peaks_near_100(10.0, 1), 2u);
}

TEST(Spectrum, ResultCarriesItsResolutions) {
  const Spectrum s = amplitude_spectrum(tone(kN, kFs, 10.0, 1.0), kFs, {WindowKind::Hann, 8 * kN});
  EXPECT_DOUBLE_EQ(s.resolution_hz, 1.0);
  EXPECT_DOUBLE_EQ(s.bin_width_hz, 0.125);
  EXPECT_DOUBLE_EQ(s.mainlobe_halfwidth_hz, 2.0);
  EXPECT_DOUBLE_EQ(s.enbw_hz, 1.5);  // Hann: 1.5 bins of 1/T
  EXPECT_EQ(s.frequency_hz.size(), 4 * kN + 1);
}

TEST(Spectrum, BadInputIsRejected) {
  EXPECT_THROW(amplitude_spectrum({1.0}, kFs), InputError);
  EXPECT_THROW(amplitude_spectrum({1.0, 2.0}, 0.0), InputError);
  EXPECT_THROW(amplitude_spectrum({1.0, NAN}, kFs), InputError);
  EXPECT_THROW(amplitude_spectrum({1.0, 2.0, 3.0}, kFs, {WindowKind::Hann, 2}), InputError);
}

}  // namespace test_spectrum
}  // namespace gearsim

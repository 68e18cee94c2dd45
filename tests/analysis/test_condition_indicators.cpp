// Condition indicators and envelope analysis on synthetic signals with known answers: Gaussian
// difference signals (FM4 = 3, M6A = 15), sines (kurtosis 1.5, crest factor √2, M6A 2.5), a pure
// mesh tone (FM0 = 2), an off-mesh order (ER = its amplitude over the mesh's), a planted impulse
// (FM4 as the moments predict), NA4's normalisation by earlier records, the regular / residual /
// difference split, and an amplitude-modulated carrier's envelope line.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "analysis/condition_indicators.hpp"
#include "analysis/envelope.hpp"
#include "analysis/synchronous_teeth.hpp"
#include "synthetic_signals.hpp"

namespace gearsim {
namespace test_condition_indicators {

constexpr double kTwoPi = 2 * std::numbers::pi;

// One revolution of n samples: Σ a·cos(order·θ + phase).
std::vector<double> orders(std::size_t n, const std::vector<std::tuple<int, double, double>>& parts) {
  std::vector<double> x(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    const double th = kTwoPi * static_cast<double>(i) / static_cast<double>(n);
    for (const auto& [k, a, ph] : parts) x[i] += a * std::cos(k * th + ph);
  }
  return x;
}

TEST(ConditionIndicators, OrderAmplitudeReadsACosineOnItsOrder) {
  const auto x = orders(1024, {{36, 0.7, 0.3}, {5, 0.2, 1.1}});
  EXPECT_NEAR(order_amplitude(x, 36), 0.7, 1e-12);
  EXPECT_NEAR(order_amplitude(x, 5), 0.2, 1e-12);
  EXPECT_NEAR(order_amplitude(x, 7), 0.0, 1e-12);
}

TEST(ConditionIndicators, SineStatisticsAreTheTextbookValues) {
  const auto x = orders(4096, {{3, 2.0, 0.0}});
  EXPECT_NEAR(kurtosis(x), 1.5, 1e-9);
  EXPECT_NEAR(crest_factor(x), std::sqrt(2.0), 1e-9);
  EXPECT_NEAR(sixth_moment(x), 2.5, 1e-9);  // E sin⁶ / (E sin²)³ = (5/16)/(1/8)
  EXPECT_NEAR(rms_about_mean(x), 2.0 / std::sqrt(2.0), 1e-12);
}

TEST(ConditionIndicators, RegularResidualAndDifferenceSplitTheOrdersAsDefined) {
  const int z = 36;
  // mesh 1.0 at 36, sideband 0.3 at 37, shaft 0.2 at 1, an off-mesh order 0.1 at 11, mean 5.
  auto x = orders(2048, {{z, 1.0, 0.2}, {z + 1, 0.3, 0.5}, {1, 0.2, 0.0}, {11, 0.1, 0.9}});
  for (double& v : x) v += 5.0;
  const TsaSignals s = tsa_signals(x, z);
  const auto d = orders(2048, {{11, 0.1, 0.9}});
  const auto res = orders(2048, {{z + 1, 0.3, 0.5}, {11, 0.1, 0.9}});
  for (std::size_t i = 0; i < x.size(); ++i) {
    EXPECT_NEAR(s.difference[i], d[i], 1e-12);
    EXPECT_NEAR(s.residual[i], res[i], 1e-12);
    EXPECT_NEAR(s.regular[i] + s.difference[i], x[i] - 5.0, 1e-12);
  }
}

TEST(ConditionIndicators, APureMeshToneHasFm0OfTwoAndNoDifferenceShape) {
  // 2016 = 36·56 samples: crest (θ = 0) and trough (θ = π/36) both fall on samples.
  const ConditionIndicators c = condition_indicators(orders(2016, {{36, 1.5, 0.0}}), 36);
  EXPECT_NEAR(c.fm0, 2.0, 1e-9);  // peak-to-peak 2A over the one mesh amplitude A
  EXPECT_TRUE(std::isnan(c.fm4));
  EXPECT_NEAR(c.er, 0.0, 1e-12);
}

TEST(ConditionIndicators, EnergyRatioIsTheOffMeshAmplitudeOverTheMeshs) {
  const ConditionIndicators c = condition_indicators(orders(2048, {{36, 2.0, 0.0}, {72, 0.5, 0.3}, {11, 0.25, 0.0}}), 36);
  // RMS of the difference (order 11) over the RMS of the mesh orders (36 and 72).
  EXPECT_NEAR(c.er, 0.25 / std::sqrt(2.0 * 2.0 + 0.5 * 0.5), 1e-12);
  EXPECT_NEAR(c.fm4, 1.5, 1e-9);  // the difference is one sine
  EXPECT_NEAR(c.m6a, 2.5, 1e-9);
}

TEST(ConditionIndicators, GaussianDifferenceGivesFm4ThreeAndM6aFifteen) {
  const std::size_t n = 1 << 16;
  auto x = orders(n, {{36, 10.0, 0.0}, {37, 1.0, 0.0}});
  test::add(x, test::white_noise(n, 1.0, 11));
  const ConditionIndicators c = condition_indicators(x, 36);
  // Sampling spread of the estimators at N = 65536: kurtosis √(24/N) = 0.019, sixth moment
  // ≈ √(10170/N) = 0.39; bounds at about four of those.
  EXPECT_NEAR(c.fm4, 3.0, 0.08);
  EXPECT_NEAR(c.m6a, 15.0, 1.6);
  // One record: NA4 is the residual's kurtosis, and the residual keeps the sideband (a sine of
  // variance 0.5 beside noise of variance 1): (1.5·0.5² + 6·0.5·1 + 3·1²)/1.5² = 2.8333.
  EXPECT_NEAR(c.na4, (1.5 * 0.25 + 6 * 0.5 + 3) / (1.5 * 1.5), 0.08);
}

// A planted impulse of height h on Gaussian noise σ: FM4 = N(Σd⁴ + h⁴ + 6h²d₀²…)/(Σd² + h²)²,
// to leading order N(3Nσ⁴ + h⁴)/(Nσ² + h²)² with the noise's own moments. 1000 teeth: the orders
// removed (mesh, sidebands, shaft) hold 0.3 % of the impulse's energy.
TEST(ConditionIndicators, APlantedImpulseRaisesFm4AsTheMomentsPredict) {
  const std::size_t n = 1 << 16;
  const double h = 40.0;
  auto noise = test::white_noise(n, 1.0, 5);
  const double before = condition_indicators(noise, 1000).fm4;
  noise[n / 3] += h;
  const double after = condition_indicators(noise, 1000).fm4;
  const double N = static_cast<double>(n);
  const double predicted = N * (before * N + std::pow(h, 4)) / std::pow(N + h * h, 2);
  EXPECT_GT(after, 8.0 * before);
  EXPECT_NEAR(after, predicted, 0.05 * predicted);
}

TEST(ConditionIndicators, Na4NormalisesByTheMeanVarianceOfEarlierRecords) {
  const std::size_t n = 4096;
  auto x = orders(n, {{36, 3.0, 0.0}});
  test::add(x, test::white_noise(n, 1.0, 3));
  std::vector<double> quiet(x.size());
  const TsaSignals s = tsa_signals(x, 36);
  for (std::size_t i = 0; i < n; ++i) quiet[i] = 0.5 * s.residual[i];  // an earlier record, half the amplitude
  const ConditionIndicators c = condition_indicators(x, 36, {quiet});
  // Mean variance (v + v/4)/2 = 0.625 v: NA4 = kurtosis(residual)/0.625².
  EXPECT_NEAR(c.na4, kurtosis(s.residual) / (0.625 * 0.625), 1e-9);
}

TEST(ConditionIndicators, BadInputIsRefused) {
  EXPECT_THROW(tsa_signals(std::vector<double>(100, 1.0), 36), InputError);  // < 4 samples per tooth
  EXPECT_THROW(kurtosis(std::vector<double>(10, 2.0)), InputError);  // constant
  EXPECT_THROW(order_amplitude(std::vector<double>(10, 0.0), 6), InputError);
}

// The planets' synchronous averages carry the indicators: a force with one tooth losing load
// (a 20 N dip half a pitch wide, once per planet turn) reads FM4 far above a healthy one's.
TEST(ConditionIndicators, ASynchronousAverageOfAToothThatLosesLoadRaisesFm4) {
  const int z = 36;
  const std::size_t n = 200000;  // 20 planet turns at 10 000 samples per turn
  std::vector<double> angle(n), healthy(n), faulty(n);
  const auto noise = test::white_noise(n, 0.1, 9);
  for (std::size_t i = 0; i < n; ++i) {
    angle[i] = kTwoPi * 20.0 * static_cast<double>(i) / static_cast<double>(n);
    healthy[i] = 100 + 10 * std::cos(z * angle[i]) + noise[i];
    const double from_tooth = std::remainder(angle[i], kTwoPi) / (kTwoPi / z);  // in pitches
    faulty[i] = healthy[i] - 20 * std::exp(-0.5 * std::pow(from_tooth / 0.25, 2));
  }
  const PlanetGear planet{"planet_0", z, 0.0};
  const SynchronousTeeth h = synchronous_teeth({"sun", "planet_0"}, planet, healthy, angle);
  const SynchronousTeeth f = synchronous_teeth({"sun", "planet_0"}, planet, faulty, angle);
  EXPECT_NEAR(h.indicators.fm4, 3.0, 0.5);  // the averaged noise: Gaussian
  EXPECT_GT(f.indicators.fm4, 10 * h.indicators.fm4);
  EXPECT_GT(f.indicators.crest_factor, h.indicators.crest_factor);
  EXPECT_NEAR(h.indicators.fm0, 2.0, 0.1);  // a mesh tone of 10 N: peak-to-peak 20 N over 10 N
}

TEST(Envelope, AnAmplitudeModulatedCarrierShowsItsModulationLine) {
  const double fs = 20000, fc = 3000, fa = 40, c = 2.0, m = 0.5;
  const std::size_t n = 20000;  // 1 s: every tone on a bin
  std::vector<double> x(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double t = static_cast<double>(i) / fs;
    x[i] =
        c * (1 + m * std::cos(kTwoPi * fa * t)) * std::cos(kTwoPi * fc * t) + 5.0 * std::cos(kTwoPi * 500 * t);  // 500 Hz: outside the band
  }
  const EnvelopeSpectrum e = envelope_spectrum(x, fs, 2000, 4000);
  EXPECT_NEAR(e.spectrum.amplitude[nearest_bin(e.spectrum, fa)], c * m, 0.01 * c * m);
  EXPECT_LT(e.spectrum.amplitude[nearest_bin(e.spectrum, 500)], 1e-6);
  double mean = 0;
  for (double v : e.envelope) mean += v;
  EXPECT_NEAR(mean / static_cast<double>(n), c, 1e-9);  // the carrier's amplitude
  EXPECT_THROW(envelope_spectrum(x, fs, 4000, 2000), InputError);
}

}  // namespace test_condition_indicators
}  // namespace gearsim

#include "analysis/resonator.hpp"

namespace gearsim {
namespace test_condition_indicators {

// The housing mode: 1/(2ζm) at resonance (prewarped, exactly), 1/m far above it, ~ (f/f_r)²/m
// far below, and the running filter settles to the amplitude its response says.
TEST(Resonator, AnswersAsASpringMountedMassDoes) {
  const double fs = 50000, fr = 4000, zeta = 0.05, m = 2.0;
  const Resonator r(fr, zeta, m, fs);
  EXPECT_NEAR(std::abs(r.response(fr)), 1 / (2 * zeta * m), 1e-9);
  // Below resonance the bilinear map shifts frequencies: digital f answers as the analog mode at
  // K·tan(πf/fs)/2π, K = ω_r/tan(πf_r/fs) (2.1 % lower at 40 Hz for these rates).
  const double K = kTwoPi * fr / std::tan(std::numbers::pi * fr / fs);
  const double f_analog = K * std::tan(std::numbers::pi * 40 / fs) / kTwoPi;
  const std::complex<double> s(0, kTwoPi * f_analog), w2(std::pow(kTwoPi * fr, 2), 0);
  const double analog = std::abs(s * s / (s * s + 2 * zeta * kTwoPi * fr * s + w2)) / m;
  EXPECT_NEAR(std::abs(r.response(40)), analog, 1e-6 * analog);
  EXPECT_NEAR(f_analog, 40 * 0.9786, 0.001 * 40);
  EXPECT_NEAR(std::abs(r.response(20000)), 1 / m, 0.2 / m);  // towards Nyquist the bilinear map bends it
  Resonator run(fr, zeta, m, fs);
  double peak = 0;
  const double f = 1500;
  for (int i = 0; i < 20000; ++i) {
    const double y = run.step(std::cos(kTwoPi * f * i / fs));
    if (i > 10000) peak = std::max(peak, std::abs(y));
  }
  EXPECT_NEAR(peak, std::abs(r.response(f)), 0.002 * std::abs(r.response(f)));
  EXPECT_THROW(Resonator(30000, zeta, m, fs), InputError);  // above Nyquist
}

}  // namespace test_condition_indicators
}  // namespace gearsim

// Modulated mesh signals: amplitude modulation puts sidebands of m·A/2 at f_m ± f_mod; phase
// (frequency) modulation puts sidebands of A·J_k(β) at f_m ± k·f_mod. Found by analyse_sidebands.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>

#include "analysis/sidebands.hpp"
#include "tests/analysis/synthetic_signals.hpp"

namespace gearsim {
namespace test_modulation {

using test::kTwoPi;

constexpr double kFs = 4096.0;  // Hz
constexpr std::size_t kN = 4096;  // 1 s: 1 Hz bins, every tone below on a bin
constexpr double kMesh = 320.0, kMod = 20.0, kA = 2.0;

const std::vector<CharacteristicFrequency> kModulation = {{"modulation", "modulating rate", kMod, "f_mod", FrequencyKind::Fault}};

// The sideband found at offset_hz (± half a bin), or nothing.
std::optional<Sideband> sideband_at(const MeshHarmonic& h, double offset_hz) {
  for (const Sideband& s : h.sidebands)
    if (std::abs(s.offset_hz - offset_hz) < 0.5) return s;
  return std::nullopt;
}

SidebandAnalysis analyse(const std::vector<double>& x) {
  // Flat-top for amplitudes; a little noise (σ = 1e-4·A) gives the floor something to measure.
  std::vector<double> noisy = x;
  test::add(noisy, test::white_noise(kN, 1e-4 * kA, 3));
  const Spectrum s = amplitude_spectrum(noisy, kFs, {WindowKind::FlatTop});
  SidebandOptions o;
  o.harmonics = 1;
  o.span_hz = 70.0;
  return analyse_sidebands(s, kMesh, kModulation, o);
}

TEST(Modulation, AmplitudeModulationGivesSidebandsOfHalfTheDepth) {
  // A(1 + m·cos 2πf_mod t)·cos 2πf_m t = A cos + (mA/2)[cos 2π(f_m − f_mod)t + cos 2π(f_m + f_mod)t].
  // Tolerance 1 % of m·A/2: flat-top reads on-bin tones exactly; noise adds ~1e-5·A per bin.
  constexpr double m = 0.3;
  std::vector<double> x(kN);
  for (std::size_t n = 0; n < kN; ++n) {
    const double t = static_cast<double>(n) / kFs;
    x[n] = kA * (1.0 + m * std::cos(kTwoPi * kMod * t)) * std::cos(kTwoPi * kMesh * t);
  }
  const SidebandAnalysis r = analyse(x);
  const MeshHarmonic& h = r.harmonics.at(0);
  ASSERT_TRUE(h.peak);
  EXPECT_NEAR(h.peak->amplitude, kA, 1e-3 * kA);
  for (const double offset : {-kMod, kMod}) {
    const std::optional<Sideband> sb = sideband_at(h, offset);
    ASSERT_TRUE(sb) << offset;
    EXPECT_NEAR(sb->peak.amplitude, m * kA / 2.0, 0.01 * m * kA / 2.0);
    EXPECT_NEAR(sb->level_db_re_harmonic, 20.0 * std::log10(m / 2.0), 0.1);  // −16.5 dB
    ASSERT_TRUE(sb->match);
    EXPECT_EQ(sb->match->key, "modulation");
    EXPECT_EQ(sb->match->multiple, 1);
  }
}

TEST(Modulation, FrequencyModulationGivesBesselSidebands) {
  // cos(2πf_m t + β sin 2πf_mod t) = Σ_k J_k(β)·cos 2π(f_m + k·f_mod)t: carrier A·J0(β), first
  // sidebands A·J1(β), second A·J2(β) (the lower ones with sign (−1)^k, same amplitude).
  // Tolerance 1 % of each.
  constexpr double beta = 0.5;
  std::vector<double> x(kN);
  for (std::size_t n = 0; n < kN; ++n) {
    const double t = static_cast<double>(n) / kFs;
    x[n] = kA * std::cos(kTwoPi * kMesh * t + beta * std::sin(kTwoPi * kMod * t));
  }
  const SidebandAnalysis r = analyse(x);
  const MeshHarmonic& h = r.harmonics.at(0);
  ASSERT_TRUE(h.peak);
  EXPECT_NEAR(h.peak->amplitude, kA * std::cyl_bessel_j(0.0, beta), 0.01 * kA * std::cyl_bessel_j(0.0, beta));
  for (const int k : {1, 2}) {
    const double expected = kA * std::cyl_bessel_j(static_cast<double>(k), beta);  // J1 = 0.2423, J2 = 0.0306
    for (const double sign : {-1.0, 1.0}) {
      const std::optional<Sideband> sb = sideband_at(h, sign * k * kMod);
      ASSERT_TRUE(sb) << sign * k * kMod << " Hz";
      EXPECT_NEAR(sb->peak.amplitude, expected, 0.01 * expected);
      ASSERT_TRUE(sb->match);
      EXPECT_EQ(sb->match->multiple, k);
    }
  }
}

}  // namespace test_modulation
}  // namespace gearsim

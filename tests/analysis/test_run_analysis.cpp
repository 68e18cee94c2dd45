// The typed run analysis on synthetic runs of a paper-like planetary set (z_s 24, z_p 36, z_r 96,
// three planets, ring fixed) whose sun turns 15 rev/s: f_c = 3 Hz, f_m = z_r·f_c = 288 Hz and the
// planet local-fault frequency f_m/z_p = 8 Hz. Sampled at 2048 Hz for 1 s, every line sits on a
// bin of the record (1 Hz) and of the padded grid (16384 points: 0.125 Hz), so the Hann amplitude
// spectrum reads each tone's amplitude exactly; the tolerances are those of the added noise.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "analysis/run_analysis.hpp"
#include "core/errors.hpp"
#include "tests/analysis/synthetic_signals.hpp"

namespace gearsim {
namespace test_run_analysis {

using test::kTwoPi;

constexpr double kFs = 2048.0;  // Hz
constexpr std::size_t kSamples = 2048;  // 1 s
constexpr double kMesh = 288.0;  // Hz, f_m
constexpr double kFault = 8.0;  // Hz, f_m/z_p
constexpr double kSigma = 0.01;  // N, white noise on every force
// The Hann amplitude of white noise in one bin is Rayleigh with mean square 6σ²/N (coherent gain
// 1/2, Σw² = 3N/8): rms 0.54 mN. A line's amplitude is read to within a few of those: 3 mN.
constexpr double kAmplitudeTolerance = 3e-3;

TrainDescription paper_like_train() {
  PlanetaryTrainSpec spec;
  spec.sun_teeth = 24;
  spec.planet_teeth = 36;
  spec.ring_teeth = 96;
  spec.planets = 3;
  spec.input_speed_rad_s = 15 * kTwoPi;  // f_s = 15 Hz, f_c = 15/5 = 3 Hz
  TrainDescription t;
  t.frequencies = planetary_frequencies(spec);
  t.planetary = true;
  t.sun = "sun";
  t.planets = {{"planet_0", 36, 0.0}};
  t.counted_gears = {{"planet_0", 36}};
  return t;
}

std::vector<double> times() {
  std::vector<double> t(kSamples);
  for (std::size_t n = 0; n < kSamples; ++n) t[n] = static_cast<double>(n) / kFs;
  return t;
}

// A sun–planet force: mean 120 N; harmonics 10, 5, 2 N at f_m, 2f_m, 3f_m; the mesh amplitude
// modulated at the fault frequency (sidebands of 1 N at f_m ± 8 Hz); the fault family's own
// lines, 0.8 N at 8 Hz and 0.4 N at 16 Hz; noise σ.
std::vector<double> sun_planet_force() {
  std::vector<double> f = test::white_noise(kSamples, kSigma, 7);
  for (std::size_t n = 0; n < kSamples; ++n) {
    const double t = static_cast<double>(n) / kFs;
    const double mesh_amplitude = 10.0 + 2.0 * 1.0 * std::cos(kTwoPi * kFault * t);
    f[n] += 120.0 + mesh_amplitude * std::cos(kTwoPi * kMesh * t) + 5.0 * std::cos(kTwoPi * 2 * kMesh * t) +
            2.0 * std::cos(kTwoPi * 3 * kMesh * t) + 0.8 * std::cos(kTwoPi * kFault * t) + 0.4 * std::cos(kTwoPi * 2 * kFault * t);
  }
  return f;
}

RunSignals synthetic_run() {
  RunSignals s;
  s.time_s = times();
  s.pair_forces = {{{"sun", "planet_0"}, sun_planet_force(), {}}, {{"planet_0", "ring"}, test::tone(kSamples, kFs, kMesh, 10.0), {}}};
  for (double& v : s.pair_forces[1].force_N) v += 110.0;
  std::vector<double> angle(kSamples);
  for (std::size_t n = 0; n < kSamples; ++n) angle[n] = -kTwoPi * kFault * s.time_s[n];  // 8 rev/s relative
  s.angles = {{"planet_0", angle}};
  return s;
}

const Sideband* sideband_at(const MeshHarmonic& h, double offset_hz) {
  for (const Sideband& b : h.sidebands)
    if (std::abs(b.offset_hz - offset_hz) < 0.5) return &b;
  return nullptr;
}

TEST(RunAnalysis, MeshHarmonicsReadTheirAmplitudesAtKTimesTheMeshFrequency) {
  const RunAnalysis r = analyze_signals(synthetic_run(), paper_like_train());
  const PairForceAnalysis& p = r.pairs.at(0);
  const double amplitude[] = {10.0, 5.0, 2.0};
  ASSERT_EQ(p.mesh.harmonics.size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) {
    const MeshHarmonic& h = p.mesh.harmonics[k];
    ASSERT_TRUE(h.peak) << "harmonic " << k + 1;
    // On a bin of the padded grid: the peak is the line's own bin.
    EXPECT_NEAR(h.peak->frequency_hz, static_cast<double>(k + 1) * kMesh, 1e-9);
    EXPECT_NEAR(h.peak->amplitude, amplitude[k], kAmplitudeTolerance);
  }
}

TEST(RunAnalysis, HarmonicsStandOverTheNoiseFloorByTheirRatioToIt) {
  // The 0–1000 Hz floor is the median Hann amplitude of the noise: Rayleigh, median
  // √(ln 2 · 6σ²/N) = 0.0451·σ for N = 2048. Its sample median over ~1000 independent bins is
  // good to a few percent: 1 dB.
  const RunAnalysis r = analyze_signals(synthetic_run(), paper_like_train());
  const PairForceAnalysis& p = r.pairs.at(0);
  const double floor = std::sqrt(std::log(2.0) * 6.0 / kSamples) * kSigma;
  EXPECT_NEAR(20 * std::log10(p.floor_N / floor), 0.0, 1.0);
  ASSERT_TRUE(p.harmonic_over_floor_db.at(0));
  EXPECT_NEAR(*p.harmonic_over_floor_db[0], 20 * std::log10(10.0 / p.floor_N), 1e-3);
}

TEST(RunAnalysis, SidebandsOfThePlanetFaultAreMatchedAndRead) {
  // (A + 2B·cos 2πf_f t)·cos 2πf_m t = A·cos 2πf_m t + B·cos 2π(f_m ± f_f)t: both sidebands at
  // B = 1 N, 20·log10(1/10) = −20 dB re the harmonic, matched to 1×planet_fault.
  const RunAnalysis r = analyze_signals(synthetic_run(), paper_like_train());
  const MeshHarmonic& h = r.pairs.at(0).mesh.harmonics.at(0);
  for (const double offset : {-kFault, kFault}) {
    const Sideband* b = sideband_at(h, offset);
    ASSERT_NE(b, nullptr) << "offset " << offset;
    EXPECT_NEAR(b->peak.amplitude, 1.0, kAmplitudeTolerance);
    EXPECT_NEAR(b->level_db_re_harmonic, -20.0, 0.01);  // 3 mN of 1 N and of 10 N: 0.03 dB at most
    ASSERT_TRUE(b->match);
    EXPECT_EQ(b->match->key, "planet_fault");
    EXPECT_EQ(b->match->multiple, 1);
  }
}

TEST(RunAnalysis, PlanetFaultFamilyReadsItsLinesAndNothingWhereThereIsNone) {
  const RunAnalysis r = analyze_signals(synthetic_run(), paper_like_train());
  const std::vector<FaultLine>& family = r.pairs.at(0).planet_fault_family;
  ASSERT_EQ(family.size(), 5u);
  const double amplitude[] = {0.8, 0.4};
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_DOUBLE_EQ(family[k].expected_hz, static_cast<double>(k + 1) * kFault);
    ASSERT_TRUE(family[k].peak) << "multiple " << k + 1;
    EXPECT_NEAR(family[k].peak->amplitude, amplitude[k], kAmplitudeTolerance);
  }
  // 24, 32, 40 Hz hold noise only: at most a noise maximum, ten times under the weakest line.
  for (std::size_t k = 2; k < 5; ++k) {
    if (family[k].peak) {
      EXPECT_LT(family[k].peak->amplitude, 0.04) << "multiple " << k + 1;
    }
  }
}

TEST(RunAnalysis, MeanForceAndZeroShareOfAPairOutOfContactAQuarterOfTheTime) {
  // 2 samples of every 8 carry no force, the others 100 N: share 1/4, mean 75 N, exactly.
  RunSignals s = synthetic_run();
  for (std::size_t n = 0; n < kSamples; ++n) s.pair_forces[1].force_N[n] = n % 8 < 2 ? 0.0 : 100.0;
  const RunAnalysis r = analyze_signals(s, paper_like_train());  // kept: p refers into it
  const PairForceAnalysis& p = r.pairs.at(1);
  EXPECT_EQ(p.zero_force_share, 0.25);
  EXPECT_NEAR(p.mean_force_N, 75.0, 1e-12);
}

TEST(RunAnalysis, DynamicFactorIsPeakOverMeanOfTheWindow) {
  // 100 N with one sample of 180 N inside the window and one of 900 N before it (during the ramp):
  // the peak is the window's 180 N, the mean (100·(n−1) + 180)/n, the factor their ratio.
  RunSignals s = synthetic_run();
  for (std::size_t n = 0; n < kSamples; ++n) s.pair_forces[1].force_N[n] = 100.0;
  s.pair_forces[1].force_N[kSamples / 2] = 180.0;
  s.from_s = s.time_s[1];
  s.pair_forces[1].force_N[0] = 900.0;
  const RunAnalysis r = analyze_signals(s, paper_like_train());  // kept: p refers into it
  const PairForceAnalysis& p = r.pairs.at(1);
  const double n = static_cast<double>(kSamples - 1), mean = (100.0 * (n - 1) + 180.0) / n;
  EXPECT_EQ(p.peak_force_N, 180.0);
  EXPECT_NEAR(p.dynamic_factor_band_limited, 180.0 / mean, 1e-12);
}

// The per-step dynamic factor: the pair's force in each step is the sum of its tooth contacts'
// impulses over dt, its mean over every step of the window (steps without contact count as 0).
// planet_0–ring: steps of 100 N on one tooth pair, one step with two pairs of 60 and 90 N (150 N:
// the peak), one step without contact, and a 900 N step before the window (not counted).
TEST(RunAnalysis, PerStepDynamicFactorIsThePeakStepForceOverItsMean) {
  RunSignals s = synthetic_run();
  s.from_s = s.time_s[1];
  ToothContactLog log;
  log.pairs = {s.pair_forces[0].pair, s.pair_forces[1].pair};
  log.time_step_s = 1.0 / kFs;  // one step per sample here
  const auto contact = [&](std::size_t step, double force_N) {
    log.time_s.push_back(static_cast<double>(step) * log.time_step_s);
    log.pair.push_back(1);
    log.tooth_a.push_back(0);
    log.tooth_b.push_back(0);
    log.normal_impulse_N_s.push_back(force_N * log.time_step_s);
  };
  contact(0, 900.0);  // before the window
  for (std::size_t k = 1; k < kSamples; ++k) {
    if (k == 7) continue;  // no contact in this step
    if (k == kSamples / 2) {
      contact(k, 60.0), contact(k, 90.0);
      continue;
    }
    contact(k, 100.0);
  }
  s.tooth_contacts = log;
  TrainDescription train = paper_like_train();
  train.counted_gears.clear();  // no per-tooth loads in this test
  const RunAnalysis r = analyze_signals(s, train);
  const PairForceAnalysis& p = r.pairs.at(1);
  const double steps = static_cast<double>(kSamples - 1), mean = (100.0 * (steps - 2) + 150.0) / steps;
  ASSERT_TRUE(p.dynamic_factor_per_step);
  EXPECT_NEAR(*p.mean_step_force_N, mean, 1e-9 * mean);
  EXPECT_DOUBLE_EQ(*p.peak_step_force_N, 150.0);
  EXPECT_NEAR(*p.dynamic_factor_per_step, 150.0 / mean, 1e-9);
  // A pair with no contact in the log: mean and peak 0, factor 0 (not a division by zero).
  EXPECT_EQ(*r.pairs.at(0).dynamic_factor_per_step, 0.0);
}

TEST(RunAnalysis, ZeroShareIsCountedOnThePointSamplesWhenTheForceWasFiltered) {
  // An anti-aliased force is never exactly zero; the point samples beside it say when no tooth
  // pair touched: 1 sample in 4 here, while the filtered force stays near its 75 N mean.
  RunSignals s = synthetic_run();
  PairForce& pf = s.pair_forces[1];
  pf.point_force_N.resize(kSamples);
  for (std::size_t n = 0; n < kSamples; ++n) {
    pf.point_force_N[n] = n % 4 == 0 ? 0.0 : 100.0;
    pf.force_N[n] = 75.0 + 1e-3 * std::sin(0.1 * static_cast<double>(n));
  }
  const RunAnalysis r = analyze_signals(s, paper_like_train());  // kept: p refers into it
  const PairForceAnalysis& p = r.pairs.at(1);
  EXPECT_EQ(p.zero_force_share, 0.25);
  EXPECT_NEAR(p.mean_force_N, 75.0, 1e-3);
  pf.point_force_N.pop_back();  // a point series of another length is refused, naming the pair
  try {
    analyze_signals(s, paper_like_train());
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("point-sampled force of pair planet_0–ring"), std::string::npos) << e.what();
  }
}

TEST(RunAnalysis, MeanForceIsTheForceAveragedOverTheWindow) {
  // 120 N plus whole periods of every tone (they average to zero) plus noise of mean σ/√N·ξ.
  const RunAnalysis r = analyze_signals(synthetic_run(), paper_like_train());
  EXPECT_NEAR(r.pairs.at(0).mean_force_N, 120.0, 5 * kSigma / std::sqrt(kSamples));
}

TEST(RunAnalysis, PairsKeepTheirIdentityAndOrder) {
  const RunAnalysis r = analyze_signals(synthetic_run(), paper_like_train());
  ASSERT_EQ(r.pairs.size(), 2u);
  EXPECT_EQ(r.pairs[0].pair, (PairId{"sun", "planet_0"}));
  EXPECT_EQ(r.pairs[1].pair, (PairId{"planet_0", "ring"}));
  ASSERT_TRUE(r.synchronous);
  ASSERT_EQ(r.synchronous->size(), 1u);
  EXPECT_EQ(r.synchronous->at(0).pair, (PairId{"sun", "planet_0"}));
  EXPECT_EQ(r.synchronous->at(0).planet, "planet_0");
}

TEST(RunAnalysis, WindowStartsAtFromAndTheRateIsTheSamples) {
  RunSignals s = synthetic_run();
  s.from_s = 0.25;  // sample 512 exactly
  const RunAnalysis r = analyze_signals(s, paper_like_train());
  EXPECT_EQ(r.from_s, 0.25);
  EXPECT_EQ(r.to_s, 2047.0 / kFs);
  EXPECT_NEAR(r.sample_rate_hz, kFs, 1e-9);
  EXPECT_EQ(r.pairs.at(0).spectrum.record_length, kSamples - 512);
}

TEST(RunAnalysis, TransmissionErrorStatisticsCoverOnlyTheWindow) {
  // TE = c + a·sin(2π·256 Hz·t) from 0.25 s on: 8 samples a period, two on the crests, whole
  // periods: mean c, extremes c ± a, RMS a/√2 (to rounding of 1e-16 of a); before it a ramp's
  // 1 mrad, which must not count.
  constexpr double kC = 20e-6, kA = 100e-6;
  RunSignals s = synthetic_run();
  s.from_s = 0.25;
  std::vector<double> te(kSamples);
  for (std::size_t n = 0; n < kSamples; ++n) te[n] = n < 512 ? 1e-3 : kC + kA * std::sin(kTwoPi * 256.0 * s.time_s[n]);
  s.te = transmission_error_series(s.time_s, te, 5.0);
  const RunAnalysis r = analyze_signals(s, paper_like_train());
  ASSERT_TRUE(r.te);
  EXPECT_NEAR(r.te->rad.mean, kC, 1e-15);
  EXPECT_NEAR(r.te->rad.min, kC - kA, 1e-15);
  EXPECT_NEAR(r.te->rad.max, kC + kA, 1e-15);
  EXPECT_NEAR(r.te->rad.peak_to_peak, 2 * kA, 1e-15);
  EXPECT_NEAR(r.te->rad.rms, kA / std::sqrt(2.0), 1e-15);
}

TEST(RunAnalysis, AGearPairHasNoFaultFamilyAndNoSynchronousAverage) {
  TrainDescription pair;
  pair.frequencies = gear_pair_frequencies({24, 36, 12 * kTwoPi, 3});  // f_m = 24·12 = 288 Hz
  const RunAnalysis r = analyze_signals(synthetic_run(), pair);
  EXPECT_TRUE(r.pairs.at(0).planet_fault_family.empty());
  EXPECT_FALSE(r.synchronous);
  EXPECT_FALSE(r.tooth_loads);
  ASSERT_TRUE(r.pairs.at(0).mesh.harmonics.at(0).peak);
  EXPECT_NEAR(r.pairs.at(0).mesh.harmonics[0].peak->frequency_hz, kMesh, 1e-9);
}

// A window in which the planet turns less than once on its carrier gets no synchronous average
// (and a note why), not a failed analysis: the spectra of a slow run still count.
TEST(RunAnalysis, APlanetTurningLessThanOnceHasNoSynchronousAverageAndSaysWhy) {
  RunSignals s = synthetic_run();
  for (double& a : s.angles[0].angle_rad) a *= 0.1 / (kFault * s.time_s.back());  // 0.1 turn in the record
  const RunAnalysis r = analyze_signals(s, paper_like_train());
  ASSERT_TRUE(r.synchronous);
  EXPECT_TRUE(r.synchronous->empty());
  EXPECT_NE(r.synchronous_note.find("less than one whole turn of planet_0"), std::string::npos) << r.synchronous_note;
  EXPECT_FALSE(r.pairs.at(0).mesh.harmonics.empty());
  const RunAnalysis full = analyze_signals(synthetic_run(), paper_like_train());
  ASSERT_TRUE(full.synchronous);
  EXPECT_EQ(full.synchronous->size(), 1u);
  EXPECT_TRUE(full.synchronous_note.empty());
}

TEST(RunAnalysis, TooFewSamplesInTheWindowAreRefused) {
  RunSignals s = synthetic_run();
  s.from_s = 2000.0 / kFs;  // 48 samples left
  try {
    analyze_signals(s, paper_like_train());
    FAIL() << "accepted 48 samples";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("only 48 output samples"), std::string::npos) << e.what();
  }
}

TEST(RunAnalysis, ARunWithoutGearPairsIsRefused) {
  RunSignals s = synthetic_run();
  s.pair_forces.clear();
  EXPECT_THROW(analyze_signals(s, paper_like_train()), InputError);
}

TEST(RunAnalysis, AMissingPlanetAngleIsNamed) {
  RunSignals s = synthetic_run();
  s.angles.clear();
  try {
    analyze_signals(s, paper_like_train());
    FAIL() << "analysed a planet without its angle";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("'planet_0'"), std::string::npos) << e.what();
  }
}

TEST(RunAnalysis, AForceOfTheWrongLengthIsNamedByItsPair) {
  RunSignals s = synthetic_run();
  s.pair_forces[1].force_N.pop_back();
  try {
    analyze_signals(s, paper_like_train());
    FAIL() << "accepted a short force record";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("planet_0–ring"), std::string::npos) << e.what();
  }
}

}  // namespace test_run_analysis
}  // namespace gearsim

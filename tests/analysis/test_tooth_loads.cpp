// Per-tooth loads of a planet, two ways: exactly from a tooth-contact log (each tooth carries the
// impulse logged on it; over whole revolutions each meshes equally long), and from the
// angle-synchronous average of the sun–planet force (the window where a tooth faces the sun).
// A 36-tooth planet whose tooth 7 (log) or 5 (average) carries half: found, by the right number.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "analysis/run_analysis.hpp"
#include "analysis/synchronous_teeth.hpp"
#include "analysis/tooth_loads.hpp"
#include "core/errors.hpp"
#include "tests/analysis/synthetic_signals.hpp"

namespace gearsim {
namespace test_tooth_loads {

using test::kTwoPi;

constexpr int kTeeth = 36;
constexpr double kForce = 120.0;  // N, while a tooth is in mesh
constexpr double kDt = 1.0 / 1024.0;  // s, the step: binary, so step times are exact
constexpr int kStepsPerTooth = 10;  // steps each planet tooth stays in mesh per revolution
constexpr int kStepsPerRev = kTeeth * kStepsPerTooth;

// Steps 0 … steps − 1, one contact each: planet tooth (step/10) mod 36 on side b of {sun,
// planet_0}, carrying kForce·dt, except tooth `weak` which carries half.
ToothContactLog planet_log(int steps, int weak) {
  ToothContactLog log;
  log.pairs = {{"sun", "planet_0"}};
  for (int c = 0; c < steps; ++c) {
    const int tooth = (c / kStepsPerTooth) % kTeeth;
    log.time_s.push_back(c * kDt);
    log.pair.push_back(0);
    log.tooth_a.push_back(c % 24);
    log.tooth_b.push_back(tooth);
    log.normal_impulse_N_s.push_back((tooth == weak ? 0.5 : 1.0) * kForce * kDt);
  }
  return log;
}

TEST(ToothLoads, EachToothCarriesItsShareOfTheMeshOverWholeRevolutions) {
  // Over 10 revolutions each tooth is in mesh 1/36 of the time: mean kForce/36; tooth 7, half
  // that. Sums of 100 equal binary-exact impulses: exact to rounding (1e-12 relative).
  const double to_s = 10 * kStepsPerRev * kDt;
  const ToothLoads t = tooth_loads(planet_log(12 * kStepsPerRev, 7), 0, false, kTeeth, 0.0, to_s, 10);
  EXPECT_EQ(t.pair, (PairId{"sun", "planet_0"}));
  EXPECT_EQ(t.gear, "planet_0");
  ASSERT_EQ(t.mean_force_N.size(), static_cast<std::size_t>(kTeeth));
  for (int k = 0; k < kTeeth; ++k) EXPECT_NEAR(t.mean_force_N[k], (k == 7 ? 0.5 : 1.0) * kForce / kTeeth, 1e-12 * kForce) << "tooth " << k;
  EXPECT_EQ(t.flagged, std::vector<int>{7});
  EXPECT_LT(t.z_score[7], -5.0);
}

TEST(ToothLoads, ALoggedToothOutsideTheGearIsRefusedNamingThePair) {
  try {
    tooth_loads(planet_log(kStepsPerRev, -1), 0, false, 30, 0.0, kStepsPerRev * kDt, 1);
    FAIL() << "tooth 35 of a 30-tooth gear accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("sun–planet_0"), std::string::npos) << e.what();
  }
}

TEST(WholeRevolutions, EndWhereTheAngleCompletesThem) {
  // −10 rev/s sampled at 1 kHz to 1.05 s; from 0.1005 s (between samples) 9.495 turns remain:
  // 9 whole ones end 0.9 s later. The angle is linear, so interpolation is exact to rounding.
  std::vector<double> t, angle;
  for (int n = 0; n <= 1050; ++n) t.push_back(n / 1000.0), angle.push_back(-kTwoPi * 10 * t.back());
  const WholeRevolutions w = whole_revolutions(t, angle, 0.1005);
  EXPECT_EQ(w.turns, 9);
  EXPECT_NEAR(w.to_s, 1.0005, 1e-12);
  EXPECT_EQ(whole_revolutions(t, angle, 1.0).turns, 0);  // 0.5 turn left
}

TEST(SynchronousTeeth, TheToothFacingTheSunWhenTheForceDropsIsFlagged) {
  // A planet turning −2 rev/s relative to the carrier, sampled 1024 times a revolution for
  // 3 revolutions. Tooth k faces the sun at angle sun_direction − k·pitch; while tooth 5 does, the
  // force is half. No grid angle lies within 2e-5 rad of a window edge, so every tooth's mean is
  // exact: 60 N for tooth 5, 120 N for the others.
  const PlanetGear planet{"planet_0", kTeeth, 0.3};
  const double pitch = kTwoPi / kTeeth;
  std::vector<double> force, angle;
  for (int n = 0; n < 3 * 1024 + 1; ++n) {
    const double theta = -kTwoPi * n / 1024.0;
    const double from_tooth5 = std::remainder(theta - (planet.sun_direction_rad - 5 * pitch), kTwoPi);
    angle.push_back(theta);
    force.push_back(std::abs(from_tooth5) < pitch / 2 ? kForce / 2 : kForce);
  }
  const SynchronousTeeth s = synchronous_teeth({"sun", "planet_0"}, planet, force, angle);
  EXPECT_EQ(s.revolutions, 3);
  for (int k = 0; k < kTeeth; ++k) EXPECT_NEAR(s.mean_force_N[k], k == 5 ? kForce / 2 : kForce, 1e-9 * kForce) << "tooth " << k;
  EXPECT_EQ(s.flagged_teeth, std::vector<int>{5});
}

TEST(RunAnalysisToothLoads, ThePlanetIsCountedInEachOfItsMeshesAndNothingElse) {
  // Pairs {sun, planet_0} and {planet_0, ring}: planet_0 is side b of one and side a of the other;
  // the sun and the ring are not counted gears.
  const int steps = 12 * kStepsPerRev;
  RunSignals s;
  ToothContactLog log = planet_log(steps, 7);
  log.pairs.push_back({"planet_0", "ring"});
  for (int c = 0; c < steps; ++c) {
    log.time_s.push_back(c * kDt);
    log.pair.push_back(1);
    log.tooth_a.push_back((c / kStepsPerTooth) % kTeeth);
    log.tooth_b.push_back(c % 96);
    log.normal_impulse_N_s.push_back(kForce * kDt);
  }
  s.tooth_contacts = log;
  std::vector<double> angle;
  for (int c = 0; c < steps; ++c) s.time_s.push_back(c * kDt), angle.push_back(-kTwoPi * c / kStepsPerRev);
  s.angles = {{"planet_0", angle}};
  s.pair_forces = {{{"sun", "planet_0"}, std::vector<double>(steps, kForce), {}},
                   {{"planet_0", "ring"}, std::vector<double>(steps, kForce), {}}};
  s.from_s = 0.5;
  TrainDescription train;
  train.frequencies = gear_pair_frequencies({24, 36, 10.0, 3});
  train.counted_gears = {{"planet_0", kTeeth}};
  const RunAnalysis r = analyze_signals(s, train);
  ASSERT_TRUE(r.tooth_loads);
  ASSERT_EQ(r.tooth_loads->size(), 2u);
  EXPECT_EQ(r.tooth_loads->at(0).pair, (PairId{"sun", "planet_0"}));
  EXPECT_EQ(r.tooth_loads->at(1).pair, (PairId{"planet_0", "ring"}));
  for (const ToothLoads& t : *r.tooth_loads) {
    EXPECT_EQ(t.gear, "planet_0");
    EXPECT_EQ(t.revolutions, 10);  // 10.6 turns from 0.5 s on: 10 whole ones
  }
  EXPECT_EQ(r.tooth_loads->at(0).flagged, std::vector<int>{7});
  EXPECT_TRUE(r.tooth_loads->at(1).flagged.empty());
}

}  // namespace test_tooth_loads
}  // namespace gearsim

// simulate() (sim/simulate.hpp) as a library call, without the CLI: observers see every step and
// every output sample at its time, a requested stop ends the run at that step with a last sample
// there, the same scenario gives the same observations twice, and the steady window's means are
// the gear train's: the spur pair (20 → 31 teeth, meshes from assets/) turns at 20/31 of its
// pinion's speed.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <vector>

#include "input/scenario_file.hpp"
#include "sim/simulate.hpp"

namespace gearsim::sim {
namespace test_simulate {

namespace fs = std::filesystem;

physics::Scenario spur_pair(const std::string& duration_s) {
  const fs::path file = fs::path(GEARSIM_SOURCE_DIR) / "assets/scenarios/spur_pair.yaml";
  return input::load_scenario(file, {"duration_s=" + duration_s, "output.per_step_log=false"});
}

// Records what it was shown.
struct Recorder : Observer {
  void on_start(const physics::World& w) override { starts += 1, start_time_s = w.time_s(); }
  void on_step(const physics::World&) override { ++steps; }
  void on_sample(const physics::World& w) override {
    times_s.push_back(w.time_s());
    double f = 0;
    for (const physics::ContactSample& c : w.contacts()) f += c.normal_force_N;
    forces_N.push_back(f);
  }
  void on_stop(const physics::World& w) override { stops += 1, stop_time_s = w.time_s(); }
  int starts = 0, stops = 0;
  long steps = 0;
  double start_time_s = -1, stop_time_s = -1;
  std::vector<double> times_s, forces_N;
};

TEST(Simulate, ObserversSeeEveryStepAndEverySampleAtItsTime) {
  const physics::Scenario s = spur_pair("0.05");
  Recorder rec;
  const RunSummary r = simulate(s, {&rec});
  EXPECT_EQ(r.status, RunStatus::Completed);
  EXPECT_EQ(rec.starts, 1);
  EXPECT_EQ(rec.stops, 1);
  EXPECT_EQ(rec.start_time_s, 0.0);
  EXPECT_EQ(rec.steps, 2500);  // 0.05 s / 2e-5 s
  EXPECT_EQ(r.steps, 2500);
  ASSERT_EQ(rec.times_s.size(), 100u);  // 0.05 s at 2000 Hz
  for (std::size_t k = 0; k < rec.times_s.size(); ++k)
    EXPECT_NEAR(rec.times_s[k], static_cast<double>(k + 1) / 2000.0, 1e-12) << "sample " << k;
  EXPECT_NEAR(rec.stop_time_s, 0.05, 1e-12);
  EXPECT_NEAR(r.sim_seconds, 0.05, 1e-12);
}

TEST(Simulate, ARequestedStopEndsTheRunAtThatStepWithALastSampleThere) {
  const physics::Scenario s = spur_pair("0.05");
  Recorder rec;
  SimOptions o;
  long polls = 0;
  o.stop_requested = [&] { return ++polls == 333 ? 15 : 0; };
  const RunSummary r = simulate(s, {&rec}, o);
  EXPECT_EQ(r.status, RunStatus::Interrupted);
  EXPECT_EQ(r.stop_signal, 15);
  EXPECT_EQ(r.steps, 333);
  EXPECT_EQ(rec.steps, 333);
  ASSERT_FALSE(rec.times_s.empty());
  EXPECT_NEAR(rec.times_s.back(), 333 * 2e-5, 1e-12);  // not a sample time (every 25 steps): added
  EXPECT_EQ(rec.times_s.size(), 13u + 1u);  // 13 regular samples up to step 325, then the stop
  EXPECT_NEAR(rec.stop_time_s, 333 * 2e-5, 1e-12);
}

TEST(Simulate, TheSameScenarioGivesTheSameObservations) {
  const physics::Scenario s = spur_pair("0.03");
  Recorder a, b;
  simulate(s, {&a});
  simulate(s, {&b});
  ASSERT_EQ(a.forces_N.size(), b.forces_N.size());
  for (std::size_t k = 0; k < a.forces_N.size(); ++k) EXPECT_EQ(a.forces_N[k], b.forces_N[k]) << "sample " << k;
}

TEST(Simulate, SteadyMeansFollowTheGearRatio) {
  const physics::Scenario s = spur_pair("0.15");
  const RunSummary r = simulate(s, {});
  ASSERT_EQ(r.bodies.size(), 2u);
  ASSERT_GT(r.steady_steps, 0);
  EXPECT_NEAR(r.steady_from_s, physics::ramps_end_s(s), 1e-15);
  const double pinion = r.bodies[0].mean_absolute_speed_rad_s, wheel = r.bodies[1].mean_absolute_speed_rad_s;
  EXPECT_EQ(r.bodies[1].parent, "ground");
  EXPECT_EQ(r.bodies[1].mean_speed_relative_rad_s, wheel);  // on the ground: the same
  EXPECT_NEAR(pinion, 50.0, 0.05);  // the motor's target
  EXPECT_NEAR(std::abs(wheel / pinion), 20.0 / 31.0, 2e-4);  // rigid teeth: the tooth ratio
  ASSERT_EQ(r.pairs.size(), 1u);
  EXPECT_GT(r.pairs[0].mean_ccw_flank_force_N + r.pairs[0].mean_cw_flank_force_N, 0.0);
  EXPECT_TRUE(r.warnings.empty());
}

TEST(Simulate, TheMeanSpeedsAreTheRatesTheBodiesTurnAt) {
  // The healthy paper set (sun 24, ring 96: 5:1) with the default integrator, whose θ changes from
  // step to step: the positions advance with a mean of each step's start and end velocities, so a
  // mean of the end velocities was off the carrier's turn by 1.5e-5 (ratio 5.0000738 at 2e-5 s).
  // A steady planetary turns its carrier at the sun's speed / 5 up to the change of the
  // transmission error between the window's ends, less than 1e-4 rad (its per-step peak-to-peak
  // is 7.0e-5 rad), against the sun's turn over the window (104.7 rad/s · 0.15 s = 15.7 rad).
  const physics::Scenario s = input::load_scenario(fs::path(GEARSIM_SOURCE_DIR) / "assets/scenarios/paper_dynamics_healthy.yaml",
                                                   {"duration_s=0.2", "output.per_step_log=false"});
  ASSERT_EQ(s.solver.integrator, physics::SolverDef::Integrator::trapezoid_closed);
  const RunSummary r = simulate(s, {});
  ASSERT_TRUE(r.ratio.has_value());
  const double sun_turn_rad = 104.7 * (0.2 - r.steady_from_s);
  EXPECT_NEAR(*r.ratio, 5.0, 5.0 * 1e-4 / sun_turn_rad);
  // A planet turns on its carrier: relative to it at −(z_ring/z_planet)·ω_c (it rolls inside the
  // fixed ring), absolutely at (1 − z_ring/z_planet)·ω_c, ring 96, planets 36.
  double carrier = 0;
  for (const BodyResult& b : r.bodies)
    if (b.name == "carrier") carrier = b.mean_absolute_speed_rad_s;
  EXPECT_NEAR(carrier, 104.7 / 5, 104.7 / 5 * 1e-4);
  int planets = 0;
  for (const BodyResult& b : r.bodies) {
    if (b.name.rfind("planet_", 0) != 0) continue;
    ++planets;
    EXPECT_EQ(b.parent, "carrier");
    EXPECT_NEAR(b.mean_speed_relative_rad_s, -96.0 / 36 * carrier, 1e-4 * carrier) << b.name;
    EXPECT_NEAR(b.mean_absolute_speed_rad_s, (1 - 96.0 / 36) * carrier, 1e-4 * carrier) << b.name;
    EXPECT_NEAR(b.mean_absolute_speed_rad_s - b.mean_speed_relative_rad_s, carrier, 1e-12 * carrier) << b.name;
  }
  EXPECT_EQ(planets, 3);
}

}  // namespace test_simulate
}  // namespace gearsim::sim

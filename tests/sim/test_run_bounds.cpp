// RunBounds on the paper's planetary set: a sound run stays inside every bound (and dissipates
// energy), while a time step far too large for the contact stiffness, a load beyond the motor's
// torque limit, or gears overlapping at the start are caught at once.
#include <gtest/gtest.h>

#include <cstdio>

#include <cmath>

#include "input/scenario_file.hpp"
#include "core/errors.hpp"
#include "sim/run_bounds.hpp"
#include "physics/world.hpp"

namespace gearsim::sim {
namespace test_run_bounds {

physics::Scenario paper(std::vector<std::string> sets) {
  sets.push_back("motors[0].ramp_time_s=0.002");
  return input::load_scenario(std::string(GEARSIM_SOURCE_DIR) + "/assets/scenarios/paper_dynamics_healthy.yaml", sets);
}

// Steps until a bound is crossed or `steps` have run.
std::optional<Divergence> run(const physics::Scenario& s, long steps, double* created_J = nullptr) {
  physics::World w(s);
  RunBounds bounds(s, w);
  for (long i = 0; i < steps; ++i) {
    w.step();
    if (auto d = bounds.check(w)) return d;
  }
  if (created_J) *created_J = bounds.created_energy_J();
  return std::nullopt;
}

TEST(RunBounds, ASoundRunStaysInsideAndDissipates) {
  double created = 0;
  const auto d = run(paper({}), 300, &created);  // 6 ms, past the 2 ms ramp
  EXPECT_FALSE(d) << d->message;
  // Contact damping only takes energy out: what the bodies gained is less than the external work.
  EXPECT_LT(created, 0.0);
}

// dt 1 ms against k = 1.4e8 N/m on a ~0.1 kg reduced mass (period ≈ 0.2 ms). The rigid-body
// engine's contact springs go unstable and the teeth pass through each other within a few steps
// (step 3). The multibody engine's implicit springs stay stable, but once the motor's 2 ms ramp
// is done the sun turns 0.1 rad (0.4 of a pitch) per step: teeth jump through each other between
// two steps (step 15). Either way the run stops before its 50 steps as diverged.
void expect_caught_with_a_millisecond_step(const std::string& engine) {
  const auto d = run(paper({"solver.time_step_s=1e-3", "output.sample_rate_hz=500", "sensors=null", "solver.engine=" + engine}), 50);
  ASSERT_TRUE(d) << engine;
  std::printf("  %s: %s at step %ld\n", engine.c_str(), d->what.c_str(), d->step);
  EXPECT_LT(d->step, 50);
  EXPECT_TRUE(d->what == "tooth penetration" || d->what == "dropped contacts" || d->what == "energy") << d->what;
}

TEST(RunBounds, ATimeStepFarTooLargeForTheContactStiffnessIsCaught) {
  expect_caught_with_a_millisecond_step("rigid_bodies");
  expect_caught_with_a_millisecond_step("multibody");
}

TEST(RunBounds, ALoadBeyondTheMotorsTorqueLimitIsCaught) {
  // The carrier load −300 N·m needs 60 N·m at the sun (1.8 kN per mesh, ~13 µm deep: the teeth
  // hold); the motor gives at most 50 N·m, so the sun falls behind its target once it is reached.
  const auto d = run(paper({"loads[0].constant_torque_N_m=-300", "loads[0].ramp_time_s=0.002"}), 1000);
  ASSERT_TRUE(d);
  EXPECT_EQ(d->what, "motor speed");
  EXPECT_EQ(d->where, "sun");
  EXPECT_GT(d->time_s, 0.002);  // not during the ramp
}

TEST(RunBounds, AnAbsurdLoadIsCaughtAtTheFirstStep) {
  // The largest load torque the input takes (1e8 N·m) on the paper's carrier: it would turn the
  // train past the speed bound within the first step.
  const auto d = run(paper({"loads[0].constant_torque_N_m=-1e8"}), 10);
  ASSERT_TRUE(d);
  EXPECT_EQ(d->step, 1);
  EXPECT_EQ(d->what, "speed");
}

TEST(World, GearsOverlappingAtTheStartAreRefusedNamingThePair) {
  // The planets 0.1 mm closer to the sun: the teeth overlap by ~0.1 mm · sin 20° ≈ 34 µm.
  physics::Scenario s = paper({});
  for (physics::JointDef& j : s.joints)
    if (j.name.rfind("planet_", 0) == 0) j.pivot_m *= (30e-3 - 0.1e-3) / 30e-3;
  for (physics::BodyDef& b : s.bodies)
    if (b.name.rfind("planet_", 0) == 0) b.pose.position_m *= (30e-3 - 0.1e-3) / 30e-3;
  try {
    physics::World w(s);
    FAIL() << "overlapping gears were accepted";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("overlap"), std::string::npos) << m;
    EXPECT_NE(m.find("'sun'"), std::string::npos) << m;
    EXPECT_NE(m.find("um deep"), std::string::npos) << m;
  }
  // Thrown after every body was added to Bullet's world: the world is torn down without touching
  // freed bodies (an ASan build, -DGEARSIM_SANITIZE=ON, reports it otherwise), and a second
  // world builds as usual.
  EXPECT_NO_THROW(physics::World{paper({})});
}

TEST(LoadTorque, RampsLinearlyLikeAMotor) {
  physics::LoadDef l;
  l.constant_torque_N_m = -20;
  l.viscous_N_m_s_per_rad = 0.5;
  l.ramp_time_s = 0.1;
  EXPECT_DOUBLE_EQ(physics::load_torque_N_m(l, 0.0, 0.0), 0.0);
  EXPECT_DOUBLE_EQ(physics::load_torque_N_m(l, 0.05, 0.0), -10.0);
  EXPECT_DOUBLE_EQ(physics::load_torque_N_m(l, 0.2, 2.0), -21.0);  // full constant part, viscous −c·ω
  physics::Scenario s;
  s.motors.push_back({"sun", 10, 0.05, 1});
  s.loads.push_back(l);
  EXPECT_DOUBLE_EQ(physics::ramps_end_s(s), 0.1);
}

}  // namespace test_run_bounds
}  // namespace gearsim::sim

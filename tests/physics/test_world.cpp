// The Bullet world on the paper's planetary set: kinematics (Willis ratio), torque balance
// through the logged tooth contacts, joints that hold, determinism.
#include <gtest/gtest.h>

#include <cmath>

#include "physics/world.hpp"
#include "tests/support/paper_scenario.hpp"

namespace gearsim::physics {
namespace {

// Runs `seconds` and averages over the last half: sun and carrier speed, motor torque, and the
// torque the sun receives from its tooth contacts (Σ force × base radius).
struct Averages {
  double sun_speed = 0, carrier_speed = 0, motor_torque = 0, contact_torque = 0;
  double max_pin_drift_m = 0;
};

Averages run(const Scenario& s, double seconds) {
  World w(s);
  const long n = std::lround(seconds / s.solver.time_step_s);
  Averages a;
  long counted = 0;
  for (long i = 0; i < n; ++i) {
    w.step();
    for (int k = 1; k <= 3; ++k)
      a.max_pin_drift_m = std::max(a.max_pin_drift_m, std::abs(w.bodies()[k].position_m.head<2>().norm() - 30e-3));
    if (i < n / 2) continue;
    ++counted;
    a.sun_speed += w.bodies()[0].speed_rad_s;
    a.carrier_speed += w.bodies()[5].speed_rad_s;
    a.motor_torque += w.motor_torque_N_m("sun");
    for (const ContactSample& c : w.contacts())
      if (c.pair < 3) a.contact_torque += c.normal_force_N * 11.2763e-3;  // sun base radius
  }
  a.sun_speed /= counted;
  a.carrier_speed /= counted;
  a.motor_torque /= counted;
  a.contact_torque /= counted;
  return a;
}

TEST(World, CarrierTurnsAtTheWillisRatioOfTheSun) {
  Scenario s = test::paper_planetary(50.0, 20.0, 0.01, /*floating_sun=*/false);
  s.motors[0].ramp_time_s = 0.002;
  const Averages a = run(s, 0.01);
  // i = 1 + 96/24 = 5. Over 5 ms the mesh passes ~0.6 tooth per planet: the tooth-pair
  // alternation modulates the speed ratio by ~1 %, so the mean is within 0.5 %.
  EXPECT_NEAR(a.sun_speed / a.carrier_speed, 5.0, 0.025);
}

TEST(World, MotorTorqueIsCarriedByTheLoggedToothContacts) {
  Scenario s = test::paper_planetary(50.0, 20.0, 0.01, false);
  s.motors[0].ramp_time_s = 0.002;
  const Averages a = run(s, 0.01);
  // Steady speed: the motor's torque equals the contacts' torque on the sun, and both equal the
  // carrier load over the ratio, 20/5 = 4 N·m (less the small torque that accelerates nothing).
  // 5 %: inertial torque of speed ripple and the friction-free contact damping.
  EXPECT_NEAR(a.contact_torque, a.motor_torque, 0.05 * std::abs(a.motor_torque));
  EXPECT_NEAR(a.motor_torque, 4.0, 0.2);
}

TEST(World, PlanetPinsHoldTheirRadius) {
  Scenario s = test::paper_planetary(50.0, 20.0, 0.004, false);
  const Averages a = run(s, 0.004);
  // Rigid hinges: the planet centres stay on the 30 mm circle to the solver's accuracy.
  EXPECT_LT(a.max_pin_drift_m, 1e-6);
}

TEST(World, SameScenarioGivesTheSameStatesBitForBit) {
  Scenario s = test::paper_planetary(50.0, 20.0, 0.002, true);
  World a(s), b(s);
  for (int i = 0; i < 100; ++i) {
    a.step();
    b.step();
  }
  for (std::size_t k = 0; k < a.bodies().size(); ++k) {
    EXPECT_EQ(a.bodies()[k].angle_rad, b.bodies()[k].angle_rad) << a.bodies()[k].name;
    EXPECT_EQ(a.bodies()[k].speed_rad_s, b.bodies()[k].speed_rad_s) << a.bodies()[k].name;
  }
}

}  // namespace
}  // namespace gearsim::physics

// The Bullet world on the paper's planetary set: kinematics (Willis ratio), torque balance
// through the logged tooth contacts, joints that hold, determinism.
#include <gtest/gtest.h>

#include <cmath>

#include "input/scenario_file.hpp"
#include "physics/world.hpp"

namespace gearsim::physics {
namespace test_world {

// The paper's healthy scenario (assets/scenarios), shortened and sped down for a unit test: sun
// at 50 rad/s reached in 2 ms, friction off so that normal forces alone carry the torque.
Scenario paper(double seconds) {
  return input::load_scenario(
      std::string(GEARSIM_SOURCE_DIR) + "/assets/scenarios/paper_dynamics_healthy.yaml",
      {"duration_s=" + std::to_string(seconds), "motors[0].target_speed_rad_s=50", "motors[0].ramp_time_s=0.002", "contact.friction=0"});
}

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
  const double c = static_cast<double>(counted);
  a.sun_speed /= c;
  a.carrier_speed /= c;
  a.motor_torque /= c;
  a.contact_torque /= c;
  return a;
}

TEST(World, CarrierTurnsAtTheWillisRatioOfTheSun) {
  const Averages a = run(paper(0.01), 0.01);
  // i = 1 + 96/24 = 5. Over 5 ms the mesh passes ~0.6 tooth per planet: the tooth-pair
  // alternation modulates the speed ratio by ~1 %, so the mean is within 0.5 %.
  EXPECT_NEAR(a.sun_speed / a.carrier_speed, 5.0, 0.025);
}

TEST(World, MotorTorqueIsCarriedByTheLoggedToothContacts) {
  const Averages a = run(paper(0.01), 0.01);
  // Steady speed: the motor's torque equals the contacts' torque on the sun, and both equal the
  // carrier load over the ratio, 20/5 = 4 N·m (less the small torque that accelerates nothing).
  // 5 %: inertial torque of speed ripple and the friction-free contact damping.
  EXPECT_NEAR(a.contact_torque, a.motor_torque, 0.05 * std::abs(a.motor_torque));
  EXPECT_NEAR(a.motor_torque, 4.0, 0.2);
}

TEST(World, PlanetPinsHoldTheirRadius) {
  const Averages a = run(paper(0.004), 0.004);
  // Rigid hinges: the planet centres stay on the 30 mm circle to the solver's accuracy.
  EXPECT_LT(a.max_pin_drift_m, 1e-6);
}

TEST(World, SameScenarioGivesTheSameStatesBitForBit) {
  const Scenario s = paper(0.002);
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

TEST(World, SpurPairFromStlFilesTurnsAtItsToothRatio) {
  // An external pair imported from STL meshes (assets/scenarios/spur_pair.yaml): z 20 drives
  // z 31 at 50 rad/s (ramp shortened to 2 ms). Over 2–12 ms (1.6 mesh periods) the mean speed
  // ratio is 31/20 to within the transmission-error ripple, 0.5 %.
  const Scenario s =
      input::load_scenario(std::string(GEARSIM_SOURCE_DIR) + "/assets/scenarios/spur_pair.yaml", {"motors[0].ramp_time_s=0.002"});
  World w(s);
  double pinion = 0, wheel = 0;
  for (int i = 1; i <= 600; ++i) {
    w.step();
    if (i <= 100) continue;
    pinion += w.bodies()[0].speed_rad_s;
    wheel += w.bodies()[1].speed_rad_s;
  }
  ASSERT_EQ(w.bodies()[0].name, "pinion");
  // The wheel turns the other way.
  EXPECT_NEAR(-pinion / wheel, 31.0 / 20.0, 0.005 * 31.0 / 20.0);
}

}  // namespace test_world
}  // namespace gearsim::physics

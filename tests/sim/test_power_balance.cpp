// Energy bookkeeping of a run: what the sun's motor puts in leaves through the carrier load or is
// dissipated by tooth friction, contact damping and bearing damping (issue 3: within 2 %).
#include <gtest/gtest.h>

#include <cmath>

#include "input/scenario_file.hpp"
#include "sim/power_balance.hpp"

namespace gearsim::sim {
namespace test_power_balance {

// The paper's healthy scenario, sun at 50 rad/s reached in 2 ms, averaged over 2–10 ms.
PowerBalance balance(double friction) {
  const physics::Scenario s = input::load_scenario(
      std::string(GEARSIM_SOURCE_DIR) + "/assets/scenarios/paper_dynamics_healthy.yaml",
      {"motors[0].target_speed_rad_s=50", "motors[0].ramp_time_s=0.002", "contact.friction=" + std::to_string(friction)});
  physics::World w(s);
  PowerBalance b;
  for (int i = 0; i < 500; ++i) {
    w.step();
    if (w.time_s() >= 0.002) b.add(w.power(), w.time_s());
  }
  return b;
}

TEST(PowerBalance, MotorInputEqualsLoadOutputPlusDissipation) {
  const PowerBalance b = balance(0.05);
  // Carrier at 50/5 rad/s against 20 N·m: 200 W out (ripple of the speed averages out to 0.5 %).
  EXPECT_NEAR(-b.load_W(), 200.0, 1.0);
  // The acceptance: input = output + dissipation (+ kinetic energy change) within 2 %.
  EXPECT_NEAR(b.imbalance_fraction(), 0.0, 0.02);
  // Contacts and bearings dissipate, they do not feed power in.
  EXPECT_LT(b.contact_W(), 0.0);
  EXPECT_LE(b.joint_W(), 1e-3 * b.motor_W());
}

TEST(PowerBalance, FlankFrictionIsWhatTheContactsDissipate) {
  const PowerBalance dry = balance(0.05), frictionless = balance(0.0);
  // Without friction only contact damping dissipates, on sub-µm ripple: next to nothing.
  EXPECT_LT(std::abs(frictionless.contact_W()), 1e-3 * frictionless.motor_W());
  // With μ = 0.05: P = μ·F·Σ|v_slide|. Relative to the carrier the sun turns at 40 rad/s and the
  // planets at 26.7, the ring at 10: sliding speed s·66.7 rad/s on the sun meshes and s·16.7 on
  // the ring meshes (s: distance from the pitch point, mean |s| ≈ 1.2 mm over the ±2.4 mm path),
  // 0.08 and 0.02 m/s; F ≈ 118 N per mesh: 0.05·118·3·(0.08 + 0.02) ≈ 1.8 W. The ±0.6 W band
  // covers the load sharing between one and two tooth pairs that weights |s|.
  EXPECT_NEAR(-dry.contact_W(), 1.8, 0.6);
  // And the motor supplies exactly that extra power.
  EXPECT_NEAR(dry.motor_W() - frictionless.motor_W(), -dry.contact_W() + frictionless.contact_W(),
              0.02 * (dry.motor_W() - frictionless.motor_W()));
}

}  // namespace test_power_balance
}  // namespace gearsim::sim

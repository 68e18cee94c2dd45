// Tooth friction in the multibody engine (verify.friction_model, physics/slip_friction.hpp,
// docs/solver.md "Friction at the pitch point"). Gear flanks slide by their kinematics: the
// sliding speed is (ω_a + ω_b)·(distance of the contact from the pitch point) for an external pair,
// so friction is μ·λ_n against the slip everywhere but at the pitch point, where it reverses.
//  - sliding (the default): friction is μ·F_n on every contact and step except where the contact's
//    slip changes sign, which gets the two directions' shares (|F_f| < μ·F_n): at the operating
//    pitch point, within two steps' travel of the contact, and in at most two steps per
//    engagement (a reversal predicted at a step's end falls partly into the next step) — in every
//    engagement;
//  - stick_slip: a box ±μ·λ_n, which takes the direction of the slip at the step's end for the
//    whole step (its reversal is early by up to a step) and sticks only where one step's impulse
//    can stop the slip (a few engagements); both never exceed μ·F_n.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <string>
#include <tuple>

#include "input/scenario_file.hpp"
#include "physics/world.hpp"
#include "sim/observer.hpp"
#include "sim/simulate.hpp"

namespace gearsim {
namespace test_sliding_friction {

namespace fs = std::filesystem;
const fs::path kScenarios = fs::path(GEARSIM_SOURCE_DIR) / "assets/scenarios";

// Per sun–planet contact and step after the motor's ramp: whether its friction is below μ·F_n
// (a shared or sticking step) and, for those, how far the contact lies from the sun's operating
// pitch circle against the radial travel of the contact point in one step.
struct FrictionSteps : sim::Observer {
  FrictionSteps(double mu_, double from) : mu(mu_), from_s(from) {}
  double mu, from_s;
  long contact_steps = 0, below = 0, above = 0;
  double worst_pitch_offset = 0;  // |r − r_w| / (radial travel per step), over the steps below μ·F_n
  std::map<std::tuple<int, int, int>, int> below_per_engagement;  // (pair, tooth_a, tooth_b): steps below
  int worst_engagement = 0;
  double dt = 0;
  void on_step(const physics::World& w) override {
    if (w.time_s() < from_s) return;
    Eigen::Vector3d sun = Eigen::Vector3d::Zero();
    double sun_speed = 0, carrier_speed = 0;
    for (const physics::BodyState& b : w.bodies()) {
      if (b.name == "sun") sun = b.position_m, sun_speed = b.speed_rad_s;
      if (b.name == "carrier") carrier_speed = b.speed_rad_s;
    }
    // The paper set: m 1 mm, 24/36 teeth at the standard centre distance 30 mm; operating pitch
    // radius of the sun 12 mm, base radius 12·cos 20° mm; the contact runs along the line of
    // action at r_b·(ω_sun − ω_carrier), its radius changing by sin α_w of that near the pitch point.
    const double r_w = 0.012, r_b = 0.012 * std::cos(20 * M_PI / 180),
                 travel = r_b * std::abs(sun_speed - carrier_speed) * dt * std::sin(20 * M_PI / 180);
    for (const physics::ContactSample& c : w.contacts()) {
      if (w.gear_pairs()[static_cast<std::size_t>(c.pair)].body_a != "sun" || !(c.normal_force_N > 0)) continue;
      ++contact_steps;
      EXPECT_LE(c.friction_force_N, mu * c.normal_force_N * (1 + 1e-9));
      if (c.friction_force_N > mu * c.normal_force_N * (1 + 1e-9)) ++above;
      if (!(c.friction_force_N < mu * c.normal_force_N * (1 - 1e-6))) continue;
      ++below;
      const double r = (c.geometry.point_m - sun.head<2>()).norm();
      worst_pitch_offset = std::max(worst_pitch_offset, std::abs(r - r_w) / travel);
      int& n = below_per_engagement[{c.pair, c.geometry.tooth_a, c.geometry.tooth_b}];
      worst_engagement = std::max(worst_engagement, ++n);
    }
  }
};

FrictionSteps run(const std::string& model, const std::string& dt) {
  const physics::Scenario s =
      input::load_scenario(kScenarios / "paper_dynamics_healthy.yaml",
                           {"duration_s=0.12", "output.per_step_log=false", "solver.time_step_s=" + dt, "verify.friction_model=" + model});
  FrictionSteps obs(s.contact.friction, 0.06);
  obs.dt = s.solver.time_step_s;
  const sim::RunSummary r = sim::simulate(s, {&obs});
  EXPECT_EQ(r.status, sim::RunStatus::Completed) << model;
  std::printf(
      "  %-10s dt %s: %ld sun–planet contact steps, %ld below μ·F_n in %zu engagements (at most %d in one), "
      "worst |r − r_w| %.2f steps' radial travel\n",
      model.c_str(), dt.c_str(), obs.contact_steps, obs.below, obs.below_per_engagement.size(), obs.worst_engagement,
      obs.worst_pitch_offset);
  return obs;
}

TEST(SlidingFriction, FrictionIsMuTimesTheNormalForceButInTheStepThatCrossesThePitchPoint) {
  for (const std::string dt : {"2e-5", "1e-5"}) {
    const FrictionSteps sl = run("sliding", dt), st = run("stick_slip", dt);
    ASSERT_GT(sl.contact_steps, 1000);
    EXPECT_EQ(sl.above, 0);
    EXPECT_EQ(st.above, 0);
    // 0.06 s at ω_sun − ω_carrier = 83.8 rad/s: 0.8 sun turns relative to the carrier, 19 teeth of
    // the sun through each of three meshes — every engagement crosses the pitch point once.
    EXPECT_GE(sl.below_per_engagement.size(), 3u * 18u);
    EXPECT_LE(sl.worst_engagement, 2);
    EXPECT_LE(sl.worst_pitch_offset, 2.0);
    EXPECT_LT(st.below_per_engagement.size(), sl.below_per_engagement.size() / 2);
  }
}

}  // namespace test_sliding_friction
}  // namespace gearsim

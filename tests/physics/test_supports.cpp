// Compliant supports in the Bullet world: a ring held by a torsional spring turns until the
// spring carries the torque the set hands it, T_ring = −(T_sun + T_carrier), Δθ = −T_ring/k_t;
// and the constant mesh stiffness holds the loaded set where a linear spring would.
#include <gtest/gtest.h>

#include <filesystem>

#include "input/scenario_file.hpp"
#include "physics/world.hpp"
#include "sim/observer.hpp"
#include "sim/simulate.hpp"

namespace gearsim {
namespace test_supports {

struct RingAngle : sim::Observer {
  double start = 0, sum = 0;
  long n = 0;
  void on_start(const physics::World& w) override { start = angle(w); }
  void on_step(const physics::World& w) override {
    if (w.time_s() < 0.03) return;  // after the 10 ms load ramps and their ringing
    sum += angle(w) - start;
    ++n;
  }
  static double angle(const physics::World& w) {
    for (const physics::BodyState& b : w.bodies())
      if (b.name == "ring") return b.angle_rad;
    return 0;
  }
};

TEST(Supports, ARingOnATorsionalSpringTurnsByTheReactionTorqueOverItsStiffness) {
  const physics::Scenario s = input::load_scenario(std::filesystem::path(GEARSIM_SOURCE_DIR) / "assets/scenarios/lin_parker_1999.yaml",
                                                   {"duration_s=0.06", "solver.time_step_s=1e-5", "output.sample_rate_hz=1000"});
  RingAngle obs;
  const sim::RunSummary r = sim::simulate(s, {&obs});
  ASSERT_EQ(r.status, sim::RunStatus::Completed);
  double k_t = 0;
  for (const physics::JointDef& j : s.joints)
    if (j.body == "ring") k_t = j.bearing->torsional_stiffness_N_m_per_rad;
  const double held = -(s.loads[0].constant_torque_N_m + s.loads[1].constant_torque_N_m);  // +36.15 N·m on the ring's spring
  const double expected = -held / k_t;  // −1.847 µrad
  EXPECT_NEAR(obs.sum / static_cast<double>(obs.n), expected, 0.02 * std::abs(expected));
}

}  // namespace test_supports
}  // namespace gearsim

#include <fstream>
#include <sstream>

#include "input/csv_table.hpp"
#include "sim/csv_logs.hpp"
#include "tests/support/asset_scenario.hpp"

namespace gearsim {
namespace test_supports {

// A planet on its carrier bearing deflects tangentially by the carrier's load share over the
// bearing stiffness: T_c/(N·a·k_p) = 46.154/(3 · 0.098223 · 1e8) = 1.566 µm (state.csv
// planet_<i>_dt_m), and barely radially.
TEST(Supports, APlanetBearingDeflectsByItsShareOfTheCarrierTorque) {
  const std::filesystem::path dir = test::fresh_test_dir();
  const physics::Scenario s = input::load_scenario(std::filesystem::path(GEARSIM_SOURCE_DIR) / "assets/scenarios/lin_parker_1999.yaml",
                                                   {"duration_s=0.06", "solver.time_step_s=1e-5", "output.sample_rate_hz=1000"});
  sim::CsvLogs logs(dir, s);
  ASSERT_EQ(sim::simulate(s, {&logs}).status, sim::RunStatus::Completed);
  const input::CsvTable state = input::read_csv(dir / "state.csv");
  double a = 0;
  for (const physics::BodyDef& b : s.bodies)
    if (b.name == "planet_0") a = b.pose.position_m.head<2>().norm();
  const double expected = -s.loads[1].constant_torque_N_m / (3 * a * 1e8);
  for (const char* planet : {"planet_0", "planet_1", "planet_2"}) {
    const std::vector<double>& t = state.column("time_s");
    const std::vector<double>& dt = state.column(std::string(planet) + "_dt_m");
    const std::vector<double>& dr = state.column(std::string(planet) + "_dr_m");
    double mean_t = 0, mean_r = 0;
    int n = 0;
    for (std::size_t i = 0; i < t.size(); ++i)
      if (t[i] >= 0.03) mean_t += dt[i], mean_r += dr[i], ++n;
    EXPECT_NEAR(std::abs(mean_t / n), expected, 0.02 * expected) << planet;
    EXPECT_LT(std::abs(mean_r / n), 0.05 * expected) << planet;
  }
}

}  // namespace test_supports
}  // namespace gearsim

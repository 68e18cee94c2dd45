// Contact onset located within the step (verify.locate_contact_onset, physics/onset_split.hpp,
// docs/solver.md "Contact onset"). A tooth pair found overlapping at a step's start has
// penetrated by δ₀ with no force since it touched: its spring holds ½·k·δ₀² that no work put in
// (the faulty paper set's re-contact after the thinned tooth closes at ≈ 0.06 m/s: δ₀ up to
// 1.2 µm at 2e-5 s). With the option the step is split where a near pair touches, so the pair
// starts at 1 % of the step's approach: the elastic energy new contacts bring in collapses, the
// run's other figures stay (mean mesh forces).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <set>
#include <string>
#include <tuple>

#include "input/scenario_file.hpp"
#include "physics/world.hpp"
#include "sim/observer.hpp"
#include "sim/simulate.hpp"

namespace gearsim {
namespace test_contact_onset {

namespace fs = std::filesystem;
const fs::path kScenarios = fs::path(GEARSIM_SOURCE_DIR) / "assets/scenarios";

// Σ ½·k·δ₀² over the contacts in the step they first appear (δ₀ their depth as searched then),
// and the mean sun–planet 0 force.
struct NewContacts : sim::Observer {
  std::set<std::tuple<int, int, int, int>> before;
  double energy_J = 0, deepest_m = 0, force_sum = 0;
  long count = 0, steps = 0;
  void on_step(const physics::World& w) override {
    std::set<std::tuple<int, int, int, int>> now;
    for (const physics::ContactSample& c : w.contacts()) {
      const std::tuple<int, int, int, int> key{c.pair, c.geometry.tooth_a, c.geometry.tooth_b, static_cast<int>(c.geometry.flank_a)};
      now.insert(key);
      if (c.pair == 0) force_sum += c.normal_force_N;
      if (before.count(key) || w.time_s() < 0.06) continue;
      ++count;
      energy_J += 0.5 * c.stiffness_N_per_m * c.geometry.depth_m * c.geometry.depth_m;
      deepest_m = std::max(deepest_m, c.geometry.depth_m);
    }
    before.swap(now);
    ++steps;
  }
};

NewContacts run(bool locate, long& splits) {
  const physics::Scenario s = input::load_scenario(
      kScenarios / "paper_dynamics.yaml",
      {"duration_s=0.15", "output.per_step_log=false", std::string("verify.locate_contact_onset=") + (locate ? "true" : "false")});
  NewContacts obs;
  const sim::RunSummary r = sim::simulate(s, {&obs});
  EXPECT_EQ(r.status, sim::RunStatus::Completed);
  splits = r.profile.onset_splits;
  std::printf(
      "  locate_contact_onset %-5s: %ld new contacts after 0.06 s, Σ ½kδ₀² %.3e J, deepest δ₀ %.3e m, %ld splits, "
      "mean sun–planet 0 force %.4f N\n",
      locate ? "true" : "false", obs.count, obs.energy_J, obs.deepest_m, splits, obs.force_sum / static_cast<double>(obs.steps));
  return obs;
}

TEST(ContactOnset, NewContactsStartWithTheirSpringNearlyAtRest) {
  long split_on = 0, split_off = 0;
  const NewContacts on = run(true, split_on), off = run(false, split_off);
  EXPECT_EQ(split_off, 0);
  EXPECT_GT(split_on, 0);
  // 0.09 s of the faulty set: every tooth engagement of six meshes (≈ 170) and the fault's
  // re-contact at 0.137 s.
  ASSERT_GT(off.count, 150);
  EXPECT_NEAR(static_cast<double>(on.count), static_cast<double>(off.count), 0.05 * static_cast<double>(off.count));
  // Located onsets start at 1 % of a step's approach; only pairs that were not near in the step
  // before (closing faster than the search's window per step) still start late.
  EXPECT_LT(on.energy_J, 0.05 * off.energy_J);
  EXPECT_LT(on.deepest_m, off.deepest_m);
  EXPECT_NEAR(on.force_sum / static_cast<double>(on.steps), off.force_sum / static_cast<double>(off.steps),
              1e-3 * off.force_sum / static_cast<double>(off.steps));
}

}  // namespace test_contact_onset
}  // namespace gearsim

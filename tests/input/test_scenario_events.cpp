// A scenario's impulses against the run's duration (input/scenario_events.hpp): each pulse lies
// within [0, duration_s], when the scenario is read and again when --duration shortens the run.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "core/errors.hpp"
#include "input/scenario_events.hpp"
#include "input/scenario_file.hpp"
#include "tests/support/asset_scenario.hpp"

namespace gearsim::input {
namespace test_scenario_events {

// A wheel on a hinge, struck at 0.05 s for 1 ms in a 0.1 s run.
physics::Scenario struck_wheel() {
  const std::filesystem::path p = test::fresh_test_dir() / "struck.yaml";
  std::ofstream(p) << "name: t\nduration_s: 0.1\n"
                      "bodies:\n  - {name: wheel, mass_kg: 1.0, principal_inertia_kg_m2: [0.01, 0.01, 0.02]}\n"
                      "joints:\n  - {name: hinge, body: wheel}\n"
                      "impulses:\n  - {body: wheel, at_s: 0.05, duration_s: 0.001, torque_N_m: [0, 0, 1]}\n";
  return load_scenario(p);
}

TEST(ScenarioEvents, APulseWithinTheRunPasses) {
  EXPECT_EQ(event_outside_run(0.05, 0.001, 0.1), "");
  EXPECT_EQ(event_outside_run(0.0, 0.1, 0.1), "");  // the whole run
  EXPECT_NO_THROW(check_events_within_duration(struck_wheel(), "--duration 0.1"));
}

TEST(ScenarioEvents, APulseBeforeTheStartOrPastTheEndIsRefused) {
  EXPECT_EQ(event_outside_run(-0.01, 0.001, 0.1),
            "the pulse from -0.01 s to -0.009 s starts before the run's start at 0 s: expected a pulse within [0, 0.1] s "
            "(the run would skip its end)");
  EXPECT_EQ(event_outside_run(9999, 0.001, 0.1),
            "the pulse from 9999 s to 9999.001 s ends after the run's end at 0.1 s: expected a pulse within [0, 0.1] s "
            "(the run would skip it)");
}

TEST(ScenarioEvents, ADurationShortenedAfterLoadingIsCheckedNamingTheImpulseAndTheOption) {
  physics::Scenario s = struck_wheel();
  s.duration_s = 0.01;  // as --duration 0.01 sets it
  try {
    check_events_within_duration(s, "--duration 0.01");
    ADD_FAILURE() << "a pulse at 0.05 s in a 0.01 s run was accepted";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("struck.yaml: impulses[0].at_s: the pulse from 0.05 s to 0.051 s ends after the run's end at 0.01 s"),
              std::string::npos)
        << m;
    EXPECT_NE(m.find("(duration set by --duration 0.01)"), std::string::npos) << m;
  }
}

}  // namespace test_scenario_events
}  // namespace gearsim::input

// Every number that sizes a run is checked against its bound (input/input_limits.hpp) before
// anything is allocated from it: one check per key, the message naming file:line:key, the bound
// and the value. The CLI's --duration the same (NaN, 1e300, ≤ 0 refused); a bad command line
// exits with code 2 as `gearsim --help` says, not CLI11's own 105–109.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <utility>

#include "input/scenario_file.hpp"
#include "core/errors.hpp"
#include "tests/support/asset_scenario.hpp"
#include "tests/support/cli_run.hpp"

namespace gearsim::app {
namespace test_input_limits {

namespace fs = std::filesystem;
const std::string kSource = GEARSIM_SOURCE_DIR;

// A wheel on a hinge, driven and loaded (7 lines); tests append one section or edit one value.
const std::string kWheel =
    "name: t\n"
    "duration_s: 0.1\n"
    "bodies:\n"
    "  - {name: wheel, mass_kg: 1.0, principal_inertia_kg_m2: [0.01, 0.01, 0.02]}\n"
    "joints:\n"
    "  - {name: hinge, body: wheel}\n"
    "motors:\n"
    "  - {joint: hinge, target_speed_rad_s: 1, max_torque_N_m: 1}\n";

fs::path write_scenario(const std::string& text) {
  const fs::path p = test::fresh_test_dir() / "bad.yaml";
  std::ofstream(p) << text;
  return p;
}

std::string error_for(const std::string& text) {
  try {
    input::load_scenario(write_scenario(text));
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

std::string with(const std::string& from, const std::string& to) {
  std::string t = kWheel;
  return t.replace(t.find(from), from.size(), to);
}

#define EXPECT_REFUSED(text, where, message)                                       \
  do {                                                                             \
    const std::string e_ = error_for(text);                                        \
    EXPECT_NE(e_.find(std::string("bad.yaml:") + where), std::string::npos) << e_; \
    EXPECT_NE(e_.find(message), std::string::npos) << e_;                          \
  } while (0)

TEST(InputLimits, TheWheelLoads) { EXPECT_EQ(error_for(kWheel), ""); }

TEST(InputLimits, Duration) {
  EXPECT_REFUSED(with("0.1", "1e300"), "2:", "duration_s: expected a duration in (0, 10000] s, got 1e+300");
  EXPECT_REFUSED(with("0.1", ".nan"), "2:", "duration_s: expected a finite number");
  EXPECT_REFUSED(with("0.1", "-.inf"), "2:", "duration_s: expected a finite number");
}

TEST(InputLimits, TimeStepAndIterations) {
  EXPECT_REFUSED(kWheel + "solver: {time_step_s: 1e-9}\n", "9:", "solver.time_step_s: expected a time step in [1e-07, 0.01] s, got 1e-09");
  EXPECT_REFUSED(kWheel + "solver: {time_step_s: 0.05}\n", "9:", "solver.time_step_s: expected a time step in [1e-07, 0.01] s, got 0.05");
  EXPECT_REFUSED(kWheel + "solver: {engine: rigid_bodies, iterations: 0}\n",
                 "9:", "solver.iterations: expected a number of solver iterations in [1, 100000], got 0");
  EXPECT_REFUSED(kWheel + "solver: {engine: rigid_bodies, iterations: 2000000}\n",
                 "9:", "solver.iterations: expected a number of solver iterations in [1, 100000]");
  EXPECT_EQ(error_for(kWheel + "solver: {engine: rigid_bodies, iterations: 400}\n"), "");
  // The default engine has no iteration count: the key would be ignored, so it is refused.
  EXPECT_REFUSED(kWheel + "solver: {iterations: 50}\n", "9:", "solver.iterations: only engine rigid_bodies iterates");
}

TEST(InputLimits, EngineAndTheta) {
  EXPECT_EQ(error_for(kWheel + "solver: {engine: rigid_bodies}\n"), "");
  EXPECT_EQ(error_for(kWheel + "solver: {engine: multibody, theta: 0.5}\n"), "");
  EXPECT_REFUSED(kWheel + "solver: {engine: featherstone}\n", "9:", "solver.engine");
  EXPECT_REFUSED(kWheel + "solver: {theta: 0.4}\n", "9:", "solver.theta: expected a θ-method weight in [0.5, 1], got 0.4");
  EXPECT_REFUSED(kWheel + "solver: {theta: 1.5}\n", "9:", "solver.theta: expected a θ-method weight in [0.5, 1]");
  EXPECT_REFUSED(kWheel + "solver: {engine: rigid_bodies, theta: 0.6}\n", "9:", "solver.theta: only engine multibody has the θ-method");
  EXPECT_EQ(error_for(kWheel + "solver: {integrator: bdf2}\n"), "");
  EXPECT_REFUSED(kWheel + "solver: {integrator: rk4}\n", "9:", "solver.integrator");
  EXPECT_REFUSED(kWheel + "solver: {integrator: bdf2, theta: 0.6}\n", "9:", "solver.theta: integrator bdf2 has no θ");
  EXPECT_EQ(error_for(kWheel + "solver: {integrator: trapezoid_closed}\n"), "");
  EXPECT_REFUSED(kWheel + "solver: {integrator: trapezoid_closed, theta: 0.5}\n",
                 "9:", "solver.theta: integrator trapezoid_closed has no θ");
  EXPECT_REFUSED(kWheel + "solver: {engine: rigid_bodies, integrator: bdf2}\n", "9:", "solver.integrator: only engine multibody");
}

TEST(InputLimits, SampleRateGivesAtLeastOneRowAndAtMostOnePerStep) {
  EXPECT_REFUSED(kWheel + "output: {sample_rate_hz: 1e-300}\n", "9:", "output.sample_rate_hz: expected at least one output row");
  EXPECT_REFUSED(kWheel + "output: {sample_rate_hz: 1e6}\n", "9:", "output.sample_rate_hz: sample rate 1e+06 Hz is above the step rate");
}

TEST(InputLimits, RampTimes) {
  EXPECT_REFUSED(with("max_torque_N_m: 1}", "max_torque_N_m: 1, ramp_time_s: 1e5}"),
                 "8:", "motors[0].ramp_time_s: expected a ramp time in [0, 10000] s, got 100000");
  EXPECT_REFUSED(kWheel + "loads:\n  - {joint: hinge, ramp_time_s: -1}\n",
                 "10:", "loads[0].ramp_time_s: expected a ramp time in [0, 10000] s, got -1");
}

TEST(InputLimits, RenderSlowMotionAndTimes) {
  EXPECT_REFUSED(kWheel + "render: {slowmo: 1e4}\n", "9:", "render.slowmo: expected a slow-motion factor in (0, 1000], got 10000");
  EXPECT_REFUSED(kWheel + "render: {from_s: .inf}\n", "9:", "render.from_s: expected a finite number");
  EXPECT_REFUSED(kWheel + "render: {to_s: 1e9}\n", "9:", "render.to_s: expected a time in [0, 10000] s, got 1e+09");
}

TEST(InputLimits, ChordalDeviation) {
  EXPECT_REFUSED(kWheel + "contact: {chordal_deviation_m: 1e5}\n",
                 "9:", "contact.chordal_deviation_m: expected a chordal deviation in [1e-09, 0.0001] m, got 100000");
}

TEST(InputLimits, PlanetsAreCountedBeforeAnyAllocation) {
  const std::string e = error_for("duration_s: 0.1\nplanetary:\n  spec: " + kSource +
                                  "/assets/specs/paper_gearset.yaml\n"
                                  "  planets: 2000000000\n  carrier: {mass_kg: 0.3, inertia_z_kg_m2: 2.0e-4}\n");
  EXPECT_NE(e.find("bad.yaml:4:"), std::string::npos) << e;
  EXPECT_NE(e.find("planetary.planets: expected a number of planets in [1, 64], got 2e+09"), std::string::npos) << e;
}

TEST(InputLimits, TeethOfAMeshAndOfAGear) {
  const std::string mesh = kSource + "/tests/data/mcad/mcad_m1_z12_a20_f5_b005.stl";
  EXPECT_REFUSED(
      with("mass_kg: 1.0, principal_inertia_kg_m2: [0.01, 0.01, 0.02]", "mass_kg: 1.0, mesh: {file: " + mesh + ", unit: mm, teeth: 7850}"),
      "4:", "bodies[0].mesh.teeth: expected a number of teeth in [3, 1000], got 7850");
  EXPECT_REFUSED(with("mass_kg: 1.0, principal_inertia_kg_m2: [0.01, 0.01, 0.02]",
                      "density_kg_m3: 7850, gear: {kind: external, teeth: 2000, module_m: 1e-3, face_width_m: 0.01}"),
                 "4:", "bodies[0].gear.teeth: expected a number of teeth in [3, 1000], got 2000");
}

TEST(InputLimits, TheRunDurationOptionIsCheckedLikeTheKey) {
  const fs::path scenario = write_scenario(kWheel), out = scenario.parent_path() / "out";
  for (const std::string bad : {"nan", "1e300", "0", "-1", "inf", "fast"}) {
    const test::CliRun r = test::gearsim("run " + scenario.string() + " --out " + out.string() + " --duration=" + bad);
    EXPECT_EQ(r.exit_code, 2) << bad << ": " << r.output;
    EXPECT_NE(r.output.find("--duration"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(bad == "fast" ? "expected a number" : "expected a duration in (0, 10000] s"), std::string::npos) << r.output;
  }
  const test::CliRun r = test::gearsim("run " + scenario.string() + " --out " + out.string() + " --duration 1e-4");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("--duration 0.000100: shorter than one output interval"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(out / "summary.json"));
}

TEST(InputLimits, InspectsNumericOptionsAreCheckedLikeKeys) {
  const std::string mesh = kSource + "/assets/gears/spur_pair/pinion.stl";
  const std::pair<std::string, std::string> cases[] = {
      {"--density=nan", "expected a density in [1, 100000] kg/m³, got nan"},  // CLI::PositiveNumber lets NaN through
      {"--tooth0-deg=inf", "expected an angle in [-360, 360] °, got inf"},  // an angle like any other
      {"--teeth=5000", "expected a number of teeth in [3, 1000], got 5000"},
      {"--prism-tolerance=inf", "expected a prism tolerance in (0, 1000] µm, got inf"},
      {"--hausdorff-spacing=1e-300", "expected a sample spacing in [0.01, 100] mm, got 1e-300"},
  };
  for (const auto& [option, message] : cases) {
    const test::CliRun r = test::gearsim("inspect " + mesh + " " + option);
    EXPECT_EQ(r.exit_code, 2) << option << ": " << r.output;
    EXPECT_NE(r.output.find(option.substr(0, option.find('='))), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(message), std::string::npos) << r.output;
  }
}

TEST(InputLimits, TheModesAndGearsOptionsAreCheckedLikeKeys) {
  const std::string scenario = kSource + "/assets/scenarios/lin_parker_1999.yaml";
  test::CliRun r = test::gearsim("modes " + scenario + " --max-speed=nan");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("expected a drive speed in (0, 100000] rad/s, got nan"), std::string::npos) << r.output;
  r = test::gearsim("gears " + kSource + "/assets/specs/spur_pair_gearset.yaml --hausdorff-spacing=inf");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("expected a sample spacing in [0.01, 100] mm, got inf"), std::string::npos) << r.output;
}

TEST(InputLimits, AGearSpecsModuleOf1e300ExitsWithTwoNotThree) {
  const fs::path spec = test::fresh_test_dir() / "spec.yaml";
  std::ofstream(spec) << "name: t\ndensity_kg_m3: 7850\ngears:\n"
                         "  pinion: {kind: external, teeth: 20, module_m: 1.0e300, face_width_m: 0.01}\n";
  const test::CliRun r = test::gearsim("gears " + spec.string());
  EXPECT_EQ(r.exit_code, 2) << r.output;  // not an internal error (3) in the tessellation
  EXPECT_NE(r.output.find("spec.yaml:4:"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("gears.pinion.module_m: expected a module in [1e-05, 0.1] m, got 1e+300"), std::string::npos) << r.output;
}

TEST(InputLimits, AScenarioNameThatIsNotUtf8ExitsWithTwoAndWritesNoRecord) {
  const fs::path scenario = write_scenario(with("name: t", "name: \"gear\xe9\"")), out = scenario.parent_path() / "out";
  const test::CliRun r = test::gearsim("run " + scenario.string() + " --out " + out.string());
  EXPECT_EQ(r.exit_code, 2) << r.output;  // not exit 1 and a 0-byte scenario.json
  EXPECT_NE(r.output.find("bad.yaml:1:7: name: expected UTF-8 text, got 'gear\\xE9'"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(out / "scenario.json"));
}

TEST(InputLimits, ABadCommandLineExitsWithTwo) {
  for (const char* args : {"run", "nosuchcommand", "run --out", "tolerance --module x"})
    EXPECT_EQ(test::gearsim(args).exit_code, 2) << args;
  EXPECT_EQ(test::gearsim("run --help").exit_code, 0);
}

TEST(InputLimits, AnImpulseADurationCutsOffIsRefusedNamingTheDuration) {
  // The impulse lies within the file's 0.1 s; --duration 0.04 would end the run before it.
  const std::filesystem::path p = test::fresh_test_dir() / "struck.yaml";
  std::ofstream(p) << "name: t\nduration_s: 0.1\n"
                      "bodies:\n  - {name: wheel, mass_kg: 1.0, principal_inertia_kg_m2: [0.01, 0.01, 0.02]}\n"
                      "joints:\n  - {name: hinge, body: wheel}\n"
                      "impulses:\n  - {body: wheel, at_s: 0.05, duration_s: 0.001, torque_N_m: [0, 0, 1]}\n";
  const test::CliRun r = test::gearsim("run " + p.string() + " --out " + (p.parent_path() / "out").string() + " --duration 0.04");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("impulses[0]"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("--duration 0.04"), std::string::npos) << r.output;
}

}  // namespace test_input_limits
}  // namespace gearsim::app

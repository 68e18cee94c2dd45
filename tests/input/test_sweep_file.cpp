// Sweep files are untrusted input read strictly: a good file gives its parameters, values in
// their exact round-trip text, collect lists and a content hash; every bad one is refused naming
// file:line:col and the key, and the case count is bounded before anything is expanded.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/errors.hpp"
#include "input/sweep_file.hpp"
#include "tests/support/asset_scenario.hpp"

namespace gearsim::input {
namespace test_sweep_file {

namespace fs = std::filesystem;

const std::string kScenario = std::string(GEARSIM_SOURCE_DIR) + "/assets/scenarios/spur_pair.yaml";

fs::path write(const fs::path& dir, const std::string& text) {
  const fs::path p = dir / "sweep.yaml";
  std::ofstream(p) << text;
  return p;
}

// The InputError message of loading `text` ("" when it loads).
std::string refusal(const std::string& text) {
  const fs::path p = write(test::fresh_test_dir(), text);
  try {
    load_sweep_file(p);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

const std::string kHead = "name: t\nscenario: " + kScenario + "\n";

TEST(SweepFile, GridAxesAndCollectAreRead) {
  const fs::path p = write(test::fresh_test_dir(), kHead +
                                                       "set: [\"duration_s=0.2\"]\n"
                                                       "grid:\n"
                                                       "  motors[0].target_speed_rad_s: {from: 10, to: 100, steps: 4}\n"
                                                       "  loads[0].constant_torque_N_m: [-1, 0.1, 2e-5]\n"
                                                       "collect:\n"
                                                       "  summary: [bodies.wheel.mean_absolute_speed_rad_s]\n"
                                                       "  metrics: [dynamic_factor_band_limited, rms_dynamic_te_rad]\n");
  const SweepFile f = load_sweep_file(p);
  EXPECT_TRUE(f.grid);
  EXPECT_EQ(f.case_count, 12u);  // 4 × 3
  ASSERT_EQ(f.parameters.size(), 2u);
  EXPECT_EQ(f.parameters[0].key, "motors[0].target_speed_rad_s");
  // Evenly spaced with both ends exact; numbers in their shortest round-trip text.
  EXPECT_EQ(f.parameters[0].values, (std::vector<std::string>{"10", "40", "70", "100"}));
  EXPECT_EQ(f.parameters[1].values, (std::vector<std::string>{"-1", "0.1", "2e-05"}));
  EXPECT_EQ(f.set, std::vector<std::string>{"duration_s=0.2"});
  EXPECT_EQ(f.collect.metrics, (std::vector<std::string>{"dynamic_factor_band_limited", "rms_dynamic_te_rad"}));
  EXPECT_EQ(f.scenario, fs::path(kScenario).lexically_normal());
  EXPECT_EQ(f.content_hash.size(), 16u);
  EXPECT_NE(f.parameters[0].where.find("sweep.yaml:5:3"), std::string::npos) << f.parameters[0].where;
}

TEST(SweepFile, NumbersRoundTripExactly) {
  for (const double v : {0.1, 1.0 / 3.0, 2e-5, 123456789.123456789, -7.0})
    EXPECT_EQ(std::stod(override_number(v)), v) << override_number(v);
}

TEST(SweepFile, ScenarioPathIsRelativeToTheSweepFile) {
  const fs::path dir = test::fresh_test_dir();
  fs::create_directories(dir / "sweeps");
  std::ofstream(dir / "base.yaml") << "name: x\n";
  std::ofstream(dir / "sweeps/s.yaml") << "name: t\nscenario: ../base.yaml\ngrid: {duration_s: [1]}\n";
  EXPECT_EQ(load_sweep_file(dir / "sweeps/s.yaml").scenario, (dir / "base.yaml").lexically_normal());
}

TEST(SweepFile, UnknownKeyNamesLineAndKey) {
  const std::string m = refusal(kHead + "grid: {duration_s: [1]}\ncolect: {}\n");
  EXPECT_NE(m.find("sweep.yaml:4:1: colect: unknown key"), std::string::npos) << m;
}

TEST(SweepFile, UnknownRangeKeyNamesItsPath) {
  const std::string m = refusal(kHead + "grid:\n  duration_s: {from: 1, to: 2, step: 3}\n");
  EXPECT_NE(m.find("sweep.yaml:4:"), std::string::npos) << m;
  EXPECT_NE(m.find("grid.duration_s.steps: missing"), std::string::npos) << m;
}

TEST(SweepFile, UnknownMetricRefused) {
  const std::string m = refusal(kHead + "grid: {duration_s: [1]}\ncollect: {metrics: [peak_joy]}\n");
  EXPECT_NE(m.find("sweep.yaml:4:"), std::string::npos) << m;
  EXPECT_NE(m.find("collect.metrics: unknown metric 'peak_joy'"), std::string::npos) << m;
  // The dynamic factor has two figures: a sweep names the one it wants.
  const std::string d = refusal(kHead + "grid: {duration_s: [1]}\ncollect: {metrics: [dynamic_factor]}\n");
  EXPECT_NE(d.find("dynamic_factor_band_limited, dynamic_factor_per_step"), std::string::npos) << d;
  EXPECT_NE(d.find("band-limited and per step: name one"), std::string::npos) << d;
}

TEST(SweepFile, TooManyCasesRefusedBeforeExpansion) {
  // 1000 × 1000 = 10⁶ cases > 10⁵: refused at the second axis, naming it.
  const std::string m = refusal(kHead + "grid:\n  a: {from: 0, to: 1, steps: 1000}\n  b: {from: 0, to: 1, steps: 1000}\n");
  EXPECT_NE(m.find("sweep.yaml:5:6: grid.b: the grid has more than 100000 cases"), std::string::npos) << m;
}

TEST(SweepFile, StepsOutOfLimitRefused) {
  const std::string m = refusal(kHead + "grid:\n  a: {from: 0, to: 1, steps: 1000000000}\n");
  EXPECT_NE(m.find("grid.a.steps: expected a number of grid steps"), std::string::npos) << m;
}

TEST(SweepFile, OptionLikeKeyRefused) {
  // A key that would read as an option of `gearsim run` never reaches its argument list.
  const std::string m = refusal(kHead + "grid:\n  --out: [/etc]\n");
  EXPECT_NE(m.find("sweep.yaml:4:10: grid.--out: expected a key path"), std::string::npos) << m;
}

TEST(SweepFile, MissingScenarioNamesKey) {
  const std::string m = refusal("name: t\nscenario: nowhere.yaml\ngrid: {duration_s: [1]}\n");
  EXPECT_NE(m.find("sweep.yaml:2:11: scenario: no scenario file at"), std::string::npos) << m;
}

TEST(SweepFile, GridAndCasesTogetherRefused) {
  const std::string m = refusal(kHead + "grid: {duration_s: [1]}\ncases: [{duration_s: 1}]\n");
  EXPECT_NE(m.find("expected either grid:"), std::string::npos) << m;
}

TEST(SweepFile, NonFiniteValueRefused) {
  const std::string m = refusal(kHead + "grid: {duration_s: [1, .nan]}\n");
  EXPECT_NE(m.find("grid.duration_s: expected a finite number"), std::string::npos) << m;
}

TEST(SweepFile, CaseListColumnsInFirstAppearanceOrder) {
  const fs::path p = write(test::fresh_test_dir(), kHead + "cases:\n  - {a: 1}\n  - {b: x, a: 2}\n");
  const SweepFile f = load_sweep_file(p);
  EXPECT_FALSE(f.grid);
  EXPECT_EQ(f.case_count, 2u);
  ASSERT_EQ(f.parameters.size(), 2u);
  EXPECT_EQ(f.parameters[0].key, "a");
  EXPECT_EQ(f.parameters[1].key, "b");
  EXPECT_NE(f.cases[1].where.find("sweep.yaml:5:"), std::string::npos) << f.cases[1].where;
  EXPECT_NE(f.cases[1].where.find("cases[1]"), std::string::npos) << f.cases[1].where;
}

TEST(SweepFile, ContentHashFollowsTheBytes) {
  const fs::path dir = test::fresh_test_dir();
  const fs::path p = write(dir, kHead + "grid: {duration_s: [1]}\n");
  const std::string h1 = load_sweep_file(p).content_hash;
  std::ofstream(p) << kHead + "grid: {duration_s: [2]}\n";
  EXPECT_NE(load_sweep_file(p).content_hash, h1);
}

TEST(SweepFile, ShippedExampleReads) {
  // assets/sweeps/spur_speed_sweep.yaml: 4 speeds × 2 loads, its scenario beside it in assets/.
  const SweepFile f = load_sweep_file(std::string(GEARSIM_SOURCE_DIR) + "/assets/sweeps/spur_speed_sweep.yaml");
  EXPECT_EQ(f.case_count, 8u);
  EXPECT_EQ(f.parameters[0].values, (std::vector<std::string>{"20", "40", "60", "80"}));
  EXPECT_EQ(f.scenario, fs::path(kScenario).lexically_normal());
}

}  // namespace test_sweep_file
}  // namespace gearsim::input

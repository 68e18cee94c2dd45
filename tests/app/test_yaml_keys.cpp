// YAML files are read strictly: a key given twice in one mapping (yaml-cpp keeps the first one
// silently) and a key that is not text (`[a]: 1`, which yaml-cpp cannot convert) are refused
// naming file:line and the key path; so are oversized files and alias bombs, before the parser
// or the reader spends memory on them. Through the CLI, such a file exits with code 2.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "input/gearset_file.hpp"
#include "input/scenario_file.hpp"
#include "core/errors.hpp"
#include "tests/support/asset_scenario.hpp"
#include "tests/support/cli_run.hpp"

namespace gearsim::app {
namespace test_yaml_keys {

namespace fs = std::filesystem;

const std::string kWheel =
    "name: t\n"
    "duration_s: 0.1\n"
    "bodies:\n"
    "  - {name: wheel, mass_kg: 1.0, principal_inertia_kg_m2: [0.01, 0.01, 0.02]}\n"
    "joints:\n"
    "  - {name: hinge, body: wheel}\n";

fs::path write_file(const std::string& name, const std::string& text) {
  const fs::path p = test::fresh_test_dir() / name;
  std::ofstream(p) << text;
  return p;
}

std::string scenario_error(const std::string& text) {
  try {
    input::load_scenario(write_file("bad.yaml", text));
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(YamlKeys, TheSmallScenarioLoads) { EXPECT_EQ(scenario_error(kWheel), ""); }

TEST(YamlKeys, AKeyGivenTwiceIsRefusedWithBothLines) {
  const std::string e = scenario_error(kWheel + "duration_s: 5\n");
  EXPECT_NE(e.find("bad.yaml:7:1: duration_s: the key appears twice in one mapping (first at line 2)"), std::string::npos) << e;
}

TEST(YamlKeys, AKeyGivenTwiceInsideAListItemIsRefused) {
  const std::string e = scenario_error(kWheel + "motors:\n  - {joint: hinge, target_speed_rad_s: 1, target_speed_rad_s: 2}\n");
  EXPECT_NE(e.find("bad.yaml:8:"), std::string::npos) << e;
  EXPECT_NE(e.find("motors[0].target_speed_rad_s: the key appears twice"), std::string::npos) << e;
}

TEST(YamlKeys, AListAsAKeyIsRefusedNotABadConversion) {
  const std::string e = scenario_error(kWheel + "[a]: 1\n");
  EXPECT_NE(e.find("bad.yaml:7:1: expected a text key, got a list"), std::string::npos) << e;
  EXPECT_EQ(e.find("bad conversion"), std::string::npos) << e;
  const std::string nested = scenario_error(kWheel + "solver: {{x: 1}: 2}\n");
  EXPECT_NE(nested.find("bad.yaml:7:"), std::string::npos) << nested;
  EXPECT_NE(nested.find("solver: expected a text key, got a mapping"), std::string::npos) << nested;
}

TEST(YamlKeys, AMappingWhereANumberBelongsNamesTheKey) {
  const std::string e = scenario_error(kWheel + "solver: {time_step_s: {a: 1}}\n");
  EXPECT_NE(e.find("bad.yaml:7:"), std::string::npos) << e;
  EXPECT_NE(e.find("solver.time_step_s: expected a number"), std::string::npos) << e;
}

TEST(YamlKeys, AGearSpecWithAGearTwiceIsRefused) {
  const fs::path p = write_file("spec.yaml",
                                "name: s\ndensity_kg_m3: 7850\ndefaults: {module_m: 1.0e-3, face_width_m: 0.01}\n"
                                "gears:\n  sun: {kind: external, teeth: 20}\n  sun: {kind: external, teeth: 30}\n");
  try {
    input::load_gearset(p);
    FAIL() << "a second gear 'sun' was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("spec.yaml:6:3: gears.sun: the key appears twice in one mapping (first at line 5)"),
              std::string::npos)
        << e.what();
  }
}

TEST(YamlKeys, AnAliasBombIsRefusedBeforeItIsWalked) {
  // Nine levels of nine aliases: 9^9 ≈ 3.9e8 values from 300 bytes.
  std::string text = kWheel + "x0: &x0 [1, 1, 1, 1, 1, 1, 1, 1, 1]\n";
  for (int k = 1; k <= 9; ++k) {
    const std::string p = "*x" + std::to_string(k - 1);
    text += "x" + std::to_string(k) + ": &x" + std::to_string(k) + " [" + p;
    for (int i = 1; i < 9; ++i) text += ", " + p;
    text += "]\n";
  }
  const std::string e = scenario_error(text);
  EXPECT_NE(e.find("more than 1000000 values"), std::string::npos) << e;
}

TEST(YamlKeys, AnAliasInsideItsOwnAnchorIsRefusedNotACrash) {
  // yaml-cpp builds `&r [1, *r]` as a list holding itself: every walk of it is endless.
  const std::string e = scenario_error(kWheel + "x: &r [1, *r]\n");
  EXPECT_NE(e.find("bad.yaml:"), std::string::npos) << e;
  EXPECT_NE(e.find("nested deeper than 64 levels"), std::string::npos) << e;
}

TEST(YamlKeys, ARecursiveSetValueIsRefusedNamingTheSet) {
  try {
    input::load_scenario(write_file("ok.yaml", kWheel), {"x=&r [1, *r]"});
    FAIL() << "a recursive --set value was accepted";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("--set 'x=&r [1, *r]'"), std::string::npos) << m;
    EXPECT_NE(m.find("nested deeper than 64 levels"), std::string::npos) << m;
  }
}

TEST(YamlKeys, AnAliasBombInASetValueIsCountedBeforeItIsCopied) {
  // The same nine levels of nine aliases as a file's bomb, as one flow mapping on the command line.
  std::string value = "{x0: &x0 [1, 1, 1, 1, 1, 1, 1, 1, 1]";
  for (int k = 1; k <= 9; ++k) {
    const std::string p = "*x" + std::to_string(k - 1);
    value += ", x" + std::to_string(k) + ": &x" + std::to_string(k) + " [" + p;
    for (int i = 1; i < 9; ++i) value += ", " + p;
    value += "]";
  }
  value += "}";
  try {
    input::load_scenario(write_file("ok.yaml", kWheel), {"x=" + value});
    FAIL() << "an alias bomb in --set was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("more than 1000000 values"), std::string::npos) << e.what();
  }
}

TEST(YamlKeys, AKeyGivenTwiceInASetMappingIsRefusedAsInAFile) {
  try {
    input::load_scenario(write_file("ok.yaml", kWheel), {"solver={time_step_s: 1e-4, time_step_s: 1e-5}"});
    FAIL() << "a --set mapping with a key twice was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("time_step_s: the key appears twice in one mapping"), std::string::npos) << e.what();
  }
}

TEST(YamlKeys, TheCliRefusesARecursiveFileWithTwoInEveryCommandThatReadsOne) {
  const fs::path p = write_file("r.yaml", "duration_s: 0.1\nx: &r [1, *r]\n");
  const fs::path out = p.parent_path() / "out";
  for (const std::string& cmd : {"run " + p.string() + " --out " + out.string(), "gears " + p.string()}) {
    const test::CliRun r = test::gearsim(cmd);
    EXPECT_EQ(r.exit_code, 2) << cmd << "\n" << r.output;
    EXPECT_NE(r.output.find("nested deeper than 64 levels"), std::string::npos) << cmd << "\n" << r.output;
  }
}

TEST(YamlKeys, AnOversizedFileIsRefusedBeforeParsing) {
  const std::string e = scenario_error(kWheel + "# " + std::string(5 << 20, 'x') + "\n");
  EXPECT_NE(e.find("bad.yaml: "), std::string::npos) << e;
  EXPECT_NE(e.find("bytes: larger than the 4194304 bytes"), std::string::npos) << e;
}

TEST(YamlKeys, TheCliExitsWithTwoAndTheMessage) {
  const fs::path p = write_file("bad.yaml", kWheel + "[a]: 1\n");
  const test::CliRun r = test::gearsim("run " + p.string() + " --out " + (p.parent_path() / "out").string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find(p.string() + ":7:1: expected a text key"), std::string::npos) << r.output;
}

}  // namespace test_yaml_keys
}  // namespace gearsim::app

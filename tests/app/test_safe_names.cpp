// Names that become file names or log columns follow one rule (input/safe_name.hpp): a gear named
// like a path is refused before `gearsim gears --out DIR` writes anything, so nothing lands
// outside DIR; body names with separators or "__" and multi-line scenario names are refused
// naming file, line and key.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "input/safe_name.hpp"
#include "input/scenario_file.hpp"
#include "core/errors.hpp"
#include "tests/support/asset_scenario.hpp"
#include "tests/support/cli_run.hpp"

namespace gearsim::app {
namespace test_safe_names {

namespace fs = std::filesystem;
using test::fresh_test_dir;

// Every file below `dir` (recursively) whose name ends with `ext`.
int files_with_extension(const fs::path& dir, const std::string& ext) {
  int n = 0;
  for (const auto& e : fs::recursive_directory_iterator(dir)) n += e.path().extension() == ext;
  return n;
}

TEST(SafeNames, AGearNamedLikeAPathIsRefusedAndNothingIsWritten) {
  const fs::path dir = fresh_test_dir(), out = dir / "a" / "b" / "out";
  for (const std::string& name : {std::string("../../x"), (dir / "abs" / "x").string(), std::string("a/b"), std::string(".hidden"),
                                  std::string("-rf"), std::string("")}) {
    const fs::path spec = dir / "spec.yaml";
    std::ofstream(spec) << "name: s\ndensity_kg_m3: 7850\ndefaults: {module_m: 1.0e-3, face_width_m: 0.01}\n"
                           "gears:\n  ok: {kind: external, teeth: 20}\n  \""
                        << name << "\": {kind: external, teeth: 21}\n";
    const test::CliRun r = test::gearsim("gears " + spec.string() + " --out " + out.string());
    EXPECT_EQ(r.exit_code, 2) << name << ": " << r.output;
    EXPECT_NE(r.output.find(spec.string() + ":6:"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("gears." + name + ": expected a name of 1 to 64 characters"), std::string::npos) << r.output;
  }
  EXPECT_EQ(files_with_extension(dir, ".stl"), 0);
  EXPECT_EQ(files_with_extension(dir, ".obj"), 0);
  EXPECT_FALSE(fs::exists(out)) << "refused before anything was written";
}

TEST(SafeNames, TheRuleAcceptsOrdinaryNamesOnly) {
  for (const char* ok : {"sun", "planet_0", "ring_relieved", "Gear-2.v1", "a"})
    EXPECT_TRUE(input::is_safe_name(ok, input::NameUse::Body)) << ok;
  for (const char* bad : {"", ".", "..", "../x", "a/b", "a\\b", "-x", ".x", "a b", "a,b", "a'b", "a\nb", "é"})
    EXPECT_FALSE(input::is_safe_name(bad, input::NameUse::File)) << bad;
  EXPECT_TRUE(input::is_safe_name("sun__planet", input::NameUse::File));
  EXPECT_FALSE(input::is_safe_name("sun__planet", input::NameUse::Body));
  EXPECT_TRUE(input::is_safe_name(std::string(64, 'x'), input::NameUse::File));
  EXPECT_FALSE(input::is_safe_name(std::string(65, 'x'), input::NameUse::File));
}

// The error load_scenario gives for `text` saved as bad.yaml ("" if none).
std::string scenario_error(const std::string& text) {
  const fs::path p = fresh_test_dir() / "bad.yaml";
  std::ofstream(p) << text;
  try {
    input::load_scenario(p);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

std::string wheel_scenario(const std::string& name_line, const std::string& body_name) {
  return name_line + "duration_s: 0.1\nbodies:\n  - {name: \"" + body_name +
         "\", mass_kg: 1.0, principal_inertia_kg_m2: [0.01, 0.01, 0.02]}\n"
         "joints:\n  - {name: hinge, body: \"" +
         body_name +
         "\"}\n"
         "motors:\n  - {joint: hinge, target_speed_rad_s: 1, max_torque_N_m: 1}\n";
}

TEST(SafeNames, BodyNamesWithSeparatorsOrTheTwoUnderscoresAreRefused) {
  for (const std::string& bad : {std::string("../w"), std::string("a/b"), std::string("x__y"), std::string("w,1")}) {
    const std::string e = scenario_error(wheel_scenario("name: t\n", bad));
    EXPECT_NE(e.find("bad.yaml:4:"), std::string::npos) << e;
    EXPECT_NE(e.find("bodies[0].name: expected a name of 1 to 64 characters"), std::string::npos) << e;
  }
  EXPECT_EQ(scenario_error(wheel_scenario("name: t\n", "wheel")), "");
}

TEST(SafeNames, APairMemberNamedLikeAPathIsRefused) {
  const std::string spec = std::string(GEARSIM_SOURCE_DIR) + "/assets/specs/spur_pair_gearset.yaml";
  const std::string e = scenario_error("name: t\nduration_s: 0.1\npair:\n  driver: {name: ../p, gear_from: {spec: " + spec +
                                       ", gear: pinion}}\n  driven: {gear_from: {spec: " + spec + ", gear: wheel}}\n");
  EXPECT_NE(e.find("pair.driver.name: expected a name"), std::string::npos) << e;
}

TEST(SafeNames, AScenarioNameIsOneLineOfText) {
  const std::string e = scenario_error(wheel_scenario("name: \"two\\nlines\"\n", "wheel"));
  EXPECT_NE(e.find("bad.yaml:1:"), std::string::npos) << e;
  EXPECT_NE(e.find("name: expected a one-line text"), std::string::npos) << e;
  EXPECT_EQ(scenario_error(wheel_scenario("name: \"x' ; it's free text, #1\"\n", "wheel")), "");
}

}  // namespace test_safe_names
}  // namespace gearsim::app

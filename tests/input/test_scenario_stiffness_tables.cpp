// contact.stiffness_tables in scenario files: gear names resolve to every meshing body pair they
// match (the planetary macro's "planet" is planet_0..2), and every bad table is refused with a
// message naming the scenario file and line, the key, and the CSV file (and its line).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "input/scenario_file.hpp"
#include "core/errors.hpp"
#include "tests/support/expect_has.hpp"

namespace gearsim::input {
namespace test_scenario_stiffness_tables {

namespace fs = std::filesystem;

fs::path test_dir() {
  const fs::path d =
      fs::temp_directory_path() / "gearsim_stiffness_tables" / ::testing::UnitTest::GetInstance()->current_test_info()->name();
  fs::create_directories(d);
  return d;
}

void write(const fs::path& p, const std::string& text) { std::ofstream(p) << text; }

// The paper's planetary set (rigid sun, no motors: parsing only) with the given table entries
// under contact.stiffness_tables (line 5 on), saved as bad.yaml beside the CSV files.
fs::path scenario(const std::string& entries) {
  const fs::path p = test_dir() / "bad.yaml";
  write(p,
        "name: t\n"
        "duration_s: 0.01\n"
        "contact:\n"
        "  stiffness_tables:\n" +
            entries +
            "planetary:\n"
            "  spec: " +
            std::string(GEARSIM_SOURCE_DIR) +
            "/assets/specs/paper_gearset.yaml\n"
            "  ring: ring_relieved\n"
            "  carrier: {mass_kg: 0.3, inertia_z_kg_m2: 2.0e-4}\n");
  return p;
}

// The sun's active flank meshing a planet: 11.39 mm (start of active profile) to 13 mm (tip).
const std::string kSunTable = "radius_a_m,stiffness_N_per_m_per_m\n0.0110,1.2e10\n0.0120,1.4e10\n0.0131,1.3e10\n";

std::string error_for(const fs::path& p) {
  try {
    load_scenario(p);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(ScenarioStiffnessTables, PlanetNamesEveryPlanetOfTheMacro) {
  const fs::path p = scenario("    - {gears: [sun, planet], file: sun.csv}\n");
  write(test_dir() / "sun.csv", kSunTable);
  const physics::Scenario s = load_scenario(p);
  ASSERT_EQ(s.contact.stiffness_tables.size(), 3u);
  for (int k = 0; k < 3; ++k) {
    const physics::PairStiffnessDef& t = s.contact.stiffness_tables[static_cast<std::size_t>(k)];
    EXPECT_EQ(t.body_a, "sun");
    EXPECT_EQ(t.body_b, "planet_" + std::to_string(k));
    EXPECT_EQ(t.table.radius_m.size(), 3u);
    EXPECT_DOUBLE_EQ(t.table.stiffness_N_per_m_per_m[1], 1.4e10);
  }
}

TEST(ScenarioStiffnessTables, BodyNameSelectsOnePair) {
  const fs::path p = scenario("    - {gears: [sun, planet_1], file: sun.csv}\n");
  write(test_dir() / "sun.csv", kSunTable);
  const physics::Scenario s = load_scenario(p);
  ASSERT_EQ(s.contact.stiffness_tables.size(), 1u);
  EXPECT_EQ(s.contact.stiffness_tables[0].body_b, "planet_1");
}

TEST(ScenarioStiffnessTables, MissingFile) {
  EXPECT_HAS(error_for(scenario("    - {gears: [sun, planet], file: nowhere.csv}\n")), "bad.yaml:5:", "contact.stiffness_tables[0].file",
             "stiffness table not found", "nowhere.csv");
}

TEST(ScenarioStiffnessTables, UnsortedRadiiNameTheCsvLine) {
  write(test_dir() / "sun.csv", "radius_a_m,stiffness_N_per_m_per_m\n0.0110,1.2e10\n0.0125,1.4e10\n0.0120,1.4e10\n0.0131,1e10\n");
  EXPECT_HAS(error_for(scenario("    - {gears: [sun, planet], file: sun.csv}\n")),
             "bad.yaml:5:", "sun.csv:4:", "radii must increase strictly");
}

TEST(ScenarioStiffnessTables, NonPositiveStiffness) {
  write(test_dir() / "sun.csv", "radius_a_m,stiffness_N_per_m_per_m\n0.0110,1.2e10\n0.0131,0\n");
  EXPECT_HAS(error_for(scenario("    - {gears: [sun, planet], file: sun.csv}\n")), "sun.csv:3:", "not positive");
}

TEST(ScenarioStiffnessTables, UnreadableNumberNamesTheCsvLine) {
  write(test_dir() / "sun.csv", "radius_a_m,stiffness_N_per_m_per_m\n0.0110,1.2e10\n0.0131,stiff\n");
  EXPECT_HAS(error_for(scenario("    - {gears: [sun, planet], file: sun.csv}\n")), "sun.csv:3:", "is not a number");
}

TEST(ScenarioStiffnessTables, WrongColumns) {
  write(test_dir() / "sun.csv", "radius_m,stiffness\n0.0110,1.2e10\n0.0131,1e10\n");
  EXPECT_HAS(error_for(scenario("    - {gears: [sun, planet], file: sun.csv}\n")), "no column 'radius_a_m'");
}

TEST(ScenarioStiffnessTables, RangeNotCoveringTheActiveFlank) {
  // Starts at 11.5 mm: above the sun's start of active profile, 11.39 mm.
  write(test_dir() / "sun.csv", "radius_a_m,stiffness_N_per_m_per_m\n0.0115,1.2e10\n0.0131,1.3e10\n");
  EXPECT_HAS(error_for(scenario("    - {gears: [sun, planet], file: sun.csv}\n")), "bad.yaml:5:", "sun.csv covers radii 11.5–13.1 mm",
             "active flank meshing 'planet_0' spans 11.39", "–13 mm");
}

TEST(ScenarioStiffnessTables, TableOnTheRingCoversItsActiveFlank) {
  // The relieved ring (tip 47.2 mm) meshing a planet: active from its tip out to ≈ 48.2 mm.
  write(test_dir() / "ring.csv", "radius_a_m,stiffness_N_per_m_per_m\n0.0470,1.2e10\n0.0480,1.3e10\n");
  EXPECT_HAS(error_for(scenario("    - {gears: [ring, planet], file: ring.csv}\n")), "active flank meshing 'planet_0' spans 47.2–48.");
  write(test_dir() / "ring.csv", "radius_a_m,stiffness_N_per_m_per_m\n0.0470,1.2e10\n0.0490,1.3e10\n");
  EXPECT_EQ(load_scenario(test_dir() / "bad.yaml").contact.stiffness_tables.size(), 3u);
}

TEST(ScenarioStiffnessTables, UnknownKey) {
  write(test_dir() / "sun.csv", kSunTable);
  EXPECT_HAS(error_for(scenario("    - {gears: [sun, planet], file: sun.csv, smoothing: 3}\n")),
             "bad.yaml:5:", "contact.stiffness_tables[0].smoothing: unknown key");
}

TEST(ScenarioStiffnessTables, BodyStiffnessIsReadAndMustBePositive) {
  write(test_dir() / "sun.csv", kSunTable);
  const physics::Scenario s = load_scenario(scenario("    - {gears: [sun, planet], file: sun.csv, body_stiffness_N_per_m: 1.35e8}\n"));
  ASSERT_FALSE(s.contact.stiffness_tables.empty());
  EXPECT_DOUBLE_EQ(s.contact.stiffness_tables[0].body_stiffness_N_per_m, 1.35e8);
  EXPECT_HAS(error_for(scenario("    - {gears: [sun, planet], file: sun.csv, body_stiffness_N_per_m: 0}\n")),
             "bad.yaml:5:", "contact.stiffness_tables[0].body_stiffness_N_per_m",
             "expected a stiffness in (0, 1e+13] N/m, got 0 (omit the key for rigid gear bodies)");
}

TEST(ScenarioStiffnessTables, GearsThatDoNotMesh) {
  write(test_dir() / "sun.csv", kSunTable);
  EXPECT_HAS(error_for(scenario("    - {gears: [sun, ring], file: sun.csv}\n")), "bad.yaml:5:", "'sun' and 'ring' do not mesh");
}

TEST(ScenarioStiffnessTables, UnknownGearName) {
  write(test_dir() / "sun.csv", kSunTable);
  EXPECT_HAS(error_for(scenario("    - {gears: [sun, moon], file: sun.csv}\n")), "no gear body named 'moon'");
}

TEST(ScenarioStiffnessTables, TwoTablesForOnePair) {
  write(test_dir() / "sun.csv", kSunTable);
  EXPECT_HAS(error_for(scenario("    - {gears: [sun, planet], file: sun.csv}\n"
                                "    - {gears: [planet_2, sun], file: sun.csv}\n")),
             "bad.yaml:6:", "already have a stiffness table");
}

TEST(ScenarioStiffnessTables, PaperTeLoadedIsTheRigidSunLoadedFaultyRun) {
  const physics::Scenario s = load_scenario(fs::path(GEARSIM_SOURCE_DIR) / "assets/scenarios/paper_te_loaded.yaml");
  EXPECT_FALSE(s.joints.front().bearing.has_value());  // the sun's hinge: rigid, not floating
  EXPECT_EQ(s.joints.front().body, "sun");
  ASSERT_EQ(s.loads.size(), 1u);
  EXPECT_DOUBLE_EQ(s.loads[0].constant_torque_N_m, -20.0);
  EXPECT_EQ(s.bodies[1].name, "planet_0");
  EXPECT_EQ(s.bodies[1].gear->name, "planet_faulty");
  EXPECT_TRUE(s.contact.stiffness_tables.empty());  // the constant ISO stiffness
}

}  // namespace test_scenario_stiffness_tables
}  // namespace gearsim::input

// `stages:` and `shafts:`: a train of two spur stages joined by a shaft is read with its members
// named by stage and its transmission chained; each way of writing a train wrongly is refused
// with one message naming the file, the entry and what was expected.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/errors.hpp"
#include "input/gear_train.hpp"
#include "input/scenario_file.hpp"

namespace gearsim::input {
namespace test_scenario_stages {

namespace fs = std::filesystem;

// Stage a: 20 → 40 about the origin; stage b: 20 → 40 with its pinion on a's wheel axis
// (x = 30 mm), 20 mm further along z. `shafts`, `drives` and `extra` are appended as given.
std::string train(const std::string& shafts, const std::string& drives = "", const std::string& extra = "") {
  const std::string g = "{kind: external, teeth: ", rest = ", module_m: 0.001, face_width_m: 0.01, bore_diameter_m: 0.005}";
  return "name: t\nduration_s: 0.01\n"
         "stages:\n"
         "  - name: a\n"
         "    pair: {driver: {name: pinion, density_kg_m3: 7850, gear: " +
         g + "20" + rest + "}, driven: {name: wheel, density_kg_m3: 7850, gear: " + g + "40" + rest +
         "}}\n"
         "  - name: b\n"
         "    pair: {origin_m: [0.03, 0, 0.02], driver: {name: pinion, density_kg_m3: 7850, gear: " +
         g + "20" + rest + "}, driven: {name: wheel, density_kg_m3: 7850, gear: " + g + "40" + rest + "}}\n" + shafts + drives + extra;
}

const std::string kShaft = "shafts:\n  - {from: a_wheel, to: b_pinion, torsional_stiffness_N_m_per_rad: 1.0e4}\n";

std::string error_for(const std::string& text) {
  const fs::path dir =
      fs::temp_directory_path() / "gearsim_scenario_stages" / ::testing::UnitTest::GetInstance()->current_test_info()->name();
  fs::create_directories(dir);
  std::ofstream(dir / "train.yaml") << text;
  try {
    load_scenario(dir / "train.yaml");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

physics::Scenario loaded(const std::string& text) {
  const fs::path dir =
      fs::temp_directory_path() / "gearsim_scenario_stages" / ::testing::UnitTest::GetInstance()->current_test_info()->name();
  fs::create_directories(dir);
  std::ofstream(dir / "train.yaml") << text;
  return load_scenario(dir / "train.yaml");
}

#define EXPECT_SAYS(error, ...)                                                               \
  do {                                                                                        \
    const std::string e_ = (error);                                                           \
    EXPECT_NE(e_.find("train.yaml:"), std::string::npos) << e_;                               \
    for (const char* part : {__VA_ARGS__}) EXPECT_NE(e_.find(part), std::string::npos) << e_; \
  } while (0)

TEST(ScenarioStages, MembersAreNamedByStageAndTheTransmissionChainsThroughTheShaft) {
  const physics::Scenario s = loaded(train(kShaft));
  std::vector<std::string> names;
  for (const physics::BodyDef& b : s.bodies) names.push_back(b.name);
  EXPECT_EQ(names, (std::vector<std::string>{"a_pinion", "a_wheel", "b_pinion", "b_wheel"}));
  EXPECT_DOUBLE_EQ(s.bodies[2].pose.position_m.z(), 0.02);  // stage b's plane
  ASSERT_TRUE(s.transmission);
  EXPECT_EQ(s.transmission->input_joint, "a_pinion");
  EXPECT_EQ(s.transmission->output_joint, "b_wheel");
  EXPECT_DOUBLE_EQ(s.transmission->ratio, 4.0);  // (−40/20)·(−40/20)
  // Without the shaft the stages are not one train: no transmission is proposed.
  EXPECT_FALSE(loaded(train("")).transmission);
}

// The analysis sees the train as its two stages, named as written, in order from the motor: each
// with its input and output, its ratio and its own mesh frequency from the rigid kinematics.
TEST(ScenarioStages, TheAnalysisNamesEachStageWithItsSpeedsAndMeshFrequency) {
  const physics::Scenario s = loaded(train(kShaft, "motors:\n  - {joint: a_pinion, target_speed_rad_s: 10, max_torque_N_m: 5}\n"));
  // Listed in the other order: the stages are ordered from the motor, not by the list.
  const GearTrain t = gear_train_of(s, {{"b_wheel", "b_pinion"}, {"a_pinion", "a_wheel"}});
  ASSERT_EQ(t.stages.size(), 2u);
  EXPECT_EQ(t.stages[0].name, "a");
  EXPECT_EQ(t.stages[1].name, "b");
  EXPECT_EQ(t.stages[1].driver, "b_pinion");  // the gear the shaft drives
  EXPECT_NEAR(t.stages[0].output_speed_rad_s, -5.0, 1e-12);
  EXPECT_NEAR(t.stages[1].input_speed_rad_s, -5.0, 1e-12);  // turns with a_wheel on its shaft
  EXPECT_NEAR(t.stages[1].output_speed_rad_s, 2.5, 1e-12);
  EXPECT_NEAR(t.stages[0].ratio * t.stages[1].ratio, s.transmission->ratio, 1e-12);
  const double two_pi = 2 * 3.14159265358979323846;
  EXPECT_NEAR(t.frequencies.at("a.mesh").value_hz, 20 * 10 / two_pi, 1e-12);
  EXPECT_NEAR(t.frequencies.at("b.mesh").value_hz, 20 * 5 / two_pi, 1e-12);
  EXPECT_EQ(t.frequencies.at("b.driven_shaft").name, "stage b: driven rotation");
  // b_pinion's absolute angle is its angle on the shaft plus a_wheel's.
  EXPECT_EQ(t.angle_chain.at("b_pinion"), (std::vector<std::string>{"b_pinion", "a_wheel"}));
}

TEST(ScenarioStages, AShaftJoiningTwoMembersOfOneStageIsRefused) {
  EXPECT_SAYS(error_for(train("shafts:\n  - {from: a_pinion, to: a_wheel, torsional_stiffness_N_m_per_rad: 1.0e4}\n")), "shafts[0].to",
              "are members of one stage ('a')");
}

TEST(ScenarioStages, AShaftBetweenMembersOffOneAxisLineIsRefused) {
  EXPECT_SAYS(error_for(train("shafts:\n  - {from: a_pinion, to: b_pinion, torsional_stiffness_N_m_per_rad: 1.0e4}\n")), "shafts[0].to",
              "turns 30.000000 mm off the axis of 'a_pinion'");
}

TEST(ScenarioStages, AMotorOnAShaftsDownstreamMemberIsRefused) {
  // Two motors on one shaft line: the second drives the member that turns on the shaft.
  const std::string drives =
      "motors:\n  - {joint: a_wheel, target_speed_rad_s: 10, max_torque_N_m: 5}\n  - {joint: b_pinion, target_speed_rad_s: 10, "
      "max_torque_N_m: 5}\n";
  EXPECT_SAYS(error_for(train(kShaft, drives)), "motors[1].joint", "joint 'b_pinion' is a shaft's downstream end");
}

TEST(ScenarioStages, AShaftNeedsItsStiffnessOnce) {
  EXPECT_SAYS(error_for(train("shafts:\n  - {from: a_wheel, to: b_pinion}\n")), "shafts[0]",
              "torsional_stiffness_N_m_per_rad, or length_m");
  EXPECT_SAYS(error_for(train("shafts:\n  - {from: a_wheel, to: b_pinion, torsional_stiffness_N_m_per_rad: 1.0e4, length_m: 0.1}\n")),
              "shafts[0].torsional_stiffness_N_m_per_rad", "not both");
}

TEST(ScenarioStages, ATopLevelMacroBesideStagesAndShaftsWithoutStagesAreRefused) {
  const std::string pair = "pair: {driver: {gear_from: {spec: x.yaml, gear: a}}, driven: {gear_from: {spec: x.yaml, gear: b}}}\n";
  EXPECT_SAYS(error_for(train(kShaft, "", pair)), "pair", "give it as one of `stages`");
  EXPECT_SAYS(error_for("name: t\nduration_s: 0.01\n" + kShaft), "shafts", "shafts join the members of `stages`");
}

TEST(ScenarioStages, APlanetarySetHoldsOneMemberStillNamedOnce) {
  const std::string set = "name: t\nduration_s: 0.01\nplanetary:\n  spec: " + std::string(GEARSIM_SOURCE_DIR) +
                          "/assets/specs/paper_gearset.yaml\n  sun: sun\n  planet: planet\n  ring: ring_relieved\n  planets: 3\n"
                          "  carrier: {mass_kg: 0.3, inertia_z_kg_m2: 2.0e-4}\n";
  const physics::Scenario star = loaded(set + "  fixed: carrier\n");
  for (const physics::BodyDef& b : star.bodies) EXPECT_EQ(b.fixed, b.name == "carrier") << b.name;
  EXPECT_EQ(star.transmission->input_joint + ">" + star.transmission->output_joint, "sun>ring");
  EXPECT_SAYS(error_for(set + "  fixed: carrier\n  ring_fixed: true\n"), "planetary.ring_fixed", "not also ring_fixed");
  EXPECT_SAYS(error_for(set + "  fixed: planet\n"), "planetary.fixed");
  EXPECT_SAYS(error_for(set + "  fixed: sun\n  floating_sun: {radial_stiffness_N_per_m: 1.0e7}\n"), "planetary.floating_sun",
              "a fixed sun is welded");
}

TEST(ScenarioStages, TwoStagesOfOneName) {
  std::string t = train("");
  t.replace(t.find("name: b"), 7, "name: a");
  EXPECT_SAYS(error_for(t), "stages[1].name", "a second stage named 'a'");
}

}  // namespace test_scenario_stages
}  // namespace gearsim::input

// Compliant supports, constant mesh stiffnesses and given inertias in scenario files: the Lin &
// Parker scenario expands into bearings on every member, a ring held by its torsional spring and
// six constant meshes; the scenario record keeps them; bad values are refused with their key.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "core/errors.hpp"
#include "input/scenario_file.hpp"
#include "input/gear_train.hpp"
#include "input/scenario_record.hpp"

namespace gearsim::input {
namespace test_scenario_supports {

const std::filesystem::path kLinParker = std::filesystem::path(GEARSIM_SOURCE_DIR) / "assets/scenarios/lin_parker_1999.yaml";

const physics::JointDef& joint(const physics::Scenario& s, const std::string& name) {
  for (const physics::JointDef& j : s.joints)
    if (j.name == name) return j;
  throw std::runtime_error("no joint " + name);
}

std::string refusal(const std::vector<std::string>& sets) {
  try {
    load_scenario(kLinParker, sets);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(ScenarioSupports, LinParkerPutsEveryMemberOnABearingAndHoldsTheRingTorsionally) {
  const physics::Scenario s = load_scenario(kLinParker);
  for (const char* name : {"sun", "carrier", "planet_0", "planet_1", "planet_2", "ring"}) {
    const physics::JointDef& j = joint(s, name);
    ASSERT_TRUE(j.bearing) << name;
    EXPECT_EQ(j.bearing->radial_stiffness_N_per_m, 1e8) << name;
    EXPECT_EQ(j.bearing->torsional_stiffness_N_m_per_rad, std::string(name) == "ring" ? 1.957631e7 : 0.0) << name;
  }
  EXPECT_EQ(joint(s, "planet_1").parent, "carrier");
  for (const physics::BodyDef& b : s.bodies) {
    if (b.name == "ring") {
      EXPECT_FALSE(b.fixed) << "held by its springs, not welded";
    }
  }
  ASSERT_EQ(s.contact.mesh_stiffnesses.size(), 6u);
  for (const physics::PairMeshStiffnessDef& m : s.contact.mesh_stiffnesses) EXPECT_EQ(m.stiffness_N_per_m, 5e8);
  ASSERT_TRUE(s.transmission);  // the ring is held: sun in, carrier out
  EXPECT_NEAR(s.transmission->ratio, 1 + 94.0 / 26, 1e-12);
}

TEST(ScenarioSupports, TheRecordKeepsSupportsMeshStiffnessesAndInertias) {
  const physics::Scenario s = load_scenario(kLinParker);
  const physics::Scenario back = scenario_from_json(nlohmann::json::parse(scenario_json(s).dump()), "scenario.json");
  EXPECT_EQ(joint(back, "ring").bearing->torsional_stiffness_N_m_per_rad, 1.957631e7);
  ASSERT_EQ(back.contact.mesh_stiffnesses.size(), 6u);
  EXPECT_EQ(back.contact.mesh_stiffnesses[3].body_a, s.contact.mesh_stiffnesses[3].body_a);
  EXPECT_EQ(back.bodies[0].principal_inertia_kg_m2->z(), 5.840991e-4);
}

TEST(ScenarioSupports, AWeldlessFixedRingNeedsATorsionalSpring) {
  const std::string m = refusal({"planetary.supports.ring.torsional_stiffness_N_m_per_rad=0"});
  EXPECT_NE(m.find("torsional_stiffness_N_m_per_rad"), std::string::npos) << m;
  EXPECT_NE(m.find("held against rotation"), std::string::npos) << m;
}

TEST(ScenarioSupports, UnknownSupportKeysAndNegativeValuesAreRefusedByKey) {
  std::string m = refusal({"planetary.supports.sun.spin_stiffness=1"});
  EXPECT_NE(m.find("spin_stiffness"), std::string::npos) << m;
  m = refusal({"planetary.supports.planets.torsional_damping_N_m_s_per_rad=-1"});
  EXPECT_NE(m.find("torsional_damping_N_m_s_per_rad"), std::string::npos) << m;
  m = refusal({"planetary.floating_sun.radial_stiffness_N_per_m=1e7"});
  EXPECT_NE(m.find("given twice"), std::string::npos) << m;
}

TEST(ScenarioSupports, AMeshStiffnessNamesMeshingGearsOnce) {
  std::string m = refusal({"contact.mesh_stiffnesses[0].gears[1]=moon"});
  EXPECT_NE(m.find("no gear body named 'moon'"), std::string::npos) << m;
  m = refusal({"contact.mesh_stiffnesses[1].gears[0]=sun"});  // sun–ring: no mesh
  EXPECT_NE(m.find("do not mesh"), std::string::npos) << m;
  m = refusal({"contact.mesh_stiffnesses[1].gears[0]=sun", "contact.mesh_stiffnesses[1].gears[1]=planet"});  // sun–planet again
  EXPECT_NE(m.find("already have a mesh stiffness"), std::string::npos) << m;
  m = refusal({"contact.mesh_stiffnesses[0].stiffness_N_per_m=-5"});
  EXPECT_NE(m.find("stiffness_N_per_m"), std::string::npos) << m;
}

}  // namespace test_scenario_supports
}  // namespace gearsim::input

namespace gearsim::input {
namespace test_scenario_supports {

// A ring held by its torsional support stands still: the train's mesh frequency is the welded
// ring's, z_r·ω_c/2π = 96·104.7/5/2π = 319.94 Hz for the paper set on bearings.
TEST(ScenarioSupports, ARingHeldTorsionallyCountsAsTheFixedMember) {
  const physics::Scenario s = load_scenario(std::filesystem::path(GEARSIM_SOURCE_DIR) / "assets/scenarios/paper_dynamics_bearings.yaml");
  std::vector<Mesh> meshes;
  for (const physics::BodyDef& b : s.bodies)
    if (b.name.rfind("planet", 0) == 0) meshes.push_back({"sun", b.name}), meshes.push_back({b.name, "ring"});
  const GearTrain t = gear_train_of(s, meshes);
  EXPECT_EQ(t.stages.front().fixed, "ring");
  EXPECT_NEAR(t.frequencies.mesh_hz, 96 * 104.7 / 5 / (2 * 3.14159265358979323846), 1e-9);
}

}  // namespace test_scenario_supports
}  // namespace gearsim::input

// `sensors:` in scenario files: the paper scenarios' housing accelerometer is read as written and
// kept in the run record; bad entries are refused naming the key.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <numbers>

#include "core/errors.hpp"
#include "input/scenario_file.hpp"
#include "input/scenario_record.hpp"

namespace gearsim::input {
namespace test_scenario_sensors {

const std::filesystem::path kPaper = std::filesystem::path(GEARSIM_SOURCE_DIR) / "assets/scenarios/paper_dynamics.yaml";

std::string refusal(const std::vector<std::string>& sets) {
  try {
    load_scenario(kPaper, sets);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(ScenarioSensors, ThePaperHousingSensorIsReadAndRecorded) {
  const physics::Scenario s = load_scenario(kPaper);
  ASSERT_EQ(s.sensors.size(), 1u);
  const physics::SensorDef& d = s.sensors[0];
  EXPECT_EQ(d.name, "housing_top");
  EXPECT_EQ(d.body, "ring");
  EXPECT_NEAR(d.angle_rad, std::numbers::pi / 2, 1e-15);
  EXPECT_NEAR(d.window_width_rad, 2 * std::numbers::pi / 3, 1e-15);
  EXPECT_EQ(d.resonance_hz, 4000);
  EXPECT_EQ(d.sample_rate_hz, 25000);
  const physics::Scenario back = scenario_from_json(nlohmann::json::parse(scenario_json(s).dump()), "scenario.json");
  ASSERT_EQ(back.sensors.size(), 1u);
  EXPECT_EQ(back.sensors[0].effective_mass_kg, 1.0);
  EXPECT_EQ(back.sensors[0].other_meshes_weight, 0.1);
}

TEST(ScenarioSensors, BadSensorsAreRefusedByKey) {
  std::string m = refusal({"sensors[0].body=housing"});
  EXPECT_NE(m.find("sensors[0].body"), std::string::npos) << m;
  m = refusal({"sensors[0].window_width_deg=0"});
  EXPECT_NE(m.find("window_width_deg"), std::string::npos) << m;
  m = refusal({"sensors[0].resonance_hz=30000"});  // the 2e-5 s step's Nyquist is 25 kHz
  EXPECT_NE(m.find("Nyquist"), std::string::npos) << m;
  m = refusal({"sensors[0].sample_rate_hz=20000"});  // 2.5 steps
  EXPECT_NE(m.find("not a whole number"), std::string::npos) << m;
  m = refusal({"sensors[0].effective_mass_kg=-1"});
  EXPECT_NE(m.find("effective_mass_kg"), std::string::npos) << m;
  m = refusal({"sensors[0].gain=3"});
  EXPECT_NE(m.find("gain"), std::string::npos) << m;
}

}  // namespace test_scenario_sensors
}  // namespace gearsim::input

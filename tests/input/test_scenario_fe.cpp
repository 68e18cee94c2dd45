// The scenario's fe: section (gearsim fe-te): the input torque follows from the output load and
// the train's ratio, defaults come from fe/constants.hpp, and every bad value is refused
// with a message naming the file, line and key.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "input/scenario_file.hpp"
#include "core/errors.hpp"
#include "tests/support/expect_has.hpp"
#include "fe/constants.hpp"

namespace gearsim::input {
namespace test_scenario_fe {

namespace fs = std::filesystem;
const std::string kPaper = std::string(GEARSIM_SOURCE_DIR) + "/assets/scenarios/paper_te_loaded.yaml";

std::string error_for(const std::string& file, const std::vector<std::string>& sets) {
  try {
    load_scenario(file, sets);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(ScenarioFe, PaperTorqueIsTheCarrierLoadOverTheRatio) {
  const physics::Scenario s = load_scenario(kPaper);
  ASSERT_TRUE(s.fe && s.planetary);
  // −20 N·m on the carrier, i = 1 + 96/24 = 5: the sun carries 4 N·m.
  EXPECT_NEAR(s.fe->sun_torque_N_m, 4.0, 1e-12);
  EXPECT_EQ(s.planetary->spec.planets, 3);
  ASSERT_EQ(s.planetary->planet_gears.size(), 3u);
  // Planet 0 is the faulty gear: one flank offset of −43 µm.
  ASSERT_EQ(s.planetary->planet_gears[0].errors.flank_offsets.size(), 1u);
  EXPECT_DOUBLE_EQ(s.planetary->planet_gears[0].errors.flank_offsets[0].normal_offset_m, -43e-6);
  EXPECT_TRUE(s.planetary->planet_gears[1].errors.flank_offsets.empty());
  EXPECT_DOUBLE_EQ(s.fe->thinning_per_flank_m, 20e-6);
  EXPECT_EQ(s.fe->element_type, "CPS4R");
}

TEST(ScenarioFe, DefaultsAndAGivenTorque) {
  const physics::Scenario s = load_scenario(kPaper, {"fe={thinning_per_flank_m: 1.0e-5, sun_torque_N_m: 2.5}"});
  ASSERT_TRUE(s.fe);
  EXPECT_DOUBLE_EQ(s.fe->sun_torque_N_m, 2.5);
  EXPECT_DOUBLE_EQ(s.fe->flank_size_m, fe::kDefaultFeTeFlankSize_m);
  EXPECT_DOUBLE_EQ(s.fe->max_sagitta_m, fe::kDefaultMaxSagitta_m);
  EXPECT_DOUBLE_EQ(s.fe->friction, fe::kDefaultFlankFriction);
  EXPECT_EQ(s.fe->positions_per_mesh, fe::kDefaultPositionsPerMesh);
  EXPECT_EQ(s.fe->jobs, fe::kDefaultFeJobs);
}

TEST(ScenarioFe, BadValuesNameTheKey) {
  EXPECT_HAS(error_for(kPaper, {"fe.flank_size_m=0"}), "paper_te_loaded.yaml", "fe.flank_size_m",
             "expected an element size in [1e-05, 0.1] m, got 0");
  // Each length of the FE model is bounded (1e-300 m elements would never finish meshing).
  EXPECT_HAS(error_for(kPaper, {"fe.flank_size_m=1e-300"}), "fe.flank_size_m", "expected an element size in [1e-05, 0.1] m, got 1e-300");
  EXPECT_HAS(error_for(kPaper, {"fe.transition_m=1e300"}), "fe.transition_m", "expected a size transition in [0, 1] m, got 1e+300");
  EXPECT_HAS(error_for(kPaper, {"fe.max_sagitta_m=1e300"}), "fe.max_sagitta_m", "expected a sagitta in [0, 0.001] m, got 1e+300");
  EXPECT_HAS(error_for(kPaper, {"fe.thinning_per_flank_m=1e300"}), "fe.thinning_per_flank_m",
             "expected a thinning per flank in [0, 0.001] m, got 1e+300");
  EXPECT_HAS(error_for(kPaper, {"fe.core_size_m=1e-4"}), "fe.core_size_m", "at least flank_size_m");
  EXPECT_HAS(error_for(kPaper, {"fe.friction=-0.1"}), "fe.friction");
  EXPECT_HAS(error_for(kPaper, {"fe.element_type=C3D8"}), "fe.element_type");
  EXPECT_HAS(error_for(kPaper, {"fe.positions_per_mesh=0"}), "fe.positions_per_mesh");
  EXPECT_HAS(error_for(kPaper, {"fe.jobs=0"}), "fe.jobs");
  EXPECT_HAS(error_for(kPaper, {"fe.mesh_periods=-1"}), "fe.mesh_periods");
  EXPECT_HAS(error_for(kPaper, {"fe.sun_torque_N_m=-4"}), "fe.sun_torque_N_m", "positive");
  EXPECT_HAS(error_for(kPaper, {"fe.smoothing=2"}), "fe.smoothing", "unknown key");
}

TEST(ScenarioFe, GearsWithoutBacklashAreRefused) {
  // Without a backlash allowance every FE tooth wedges in its mate's space (both flanks load).
  EXPECT_HAS(error_for(kPaper, {"fe.thinning_per_flank_m=0"}), "fe.thinning_per_flank_m", "backlash");
}

TEST(ScenarioFe, NoOutputLoadToReflect) { EXPECT_HAS(error_for(kPaper, {"loads=[]"}), "fe.sun_torque_N_m", "no resisting constant load"); }

TEST(ScenarioFe, OnlyPlanetaryTrains) {
  const std::string pair = std::string(GEARSIM_SOURCE_DIR) + "/assets/scenarios/spur_pair.yaml";
  EXPECT_HAS(error_for(pair, {"fe={thinning_per_flank_m: 2.0e-5}"}), "planetary");
}

}  // namespace test_scenario_fe
}  // namespace gearsim::input

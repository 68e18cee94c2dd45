// A spur pair from meshes nobody here made (OpenSCAD MCAD, tests/data/mcad: z 12 drives z 24,
// module 1 mm, 20°, 5 facets per involute, 0.05 mm backlash each) runs physically at its
// standard centre distance, and the usual mistakes with such meshes are refused before the first
// step with a message naming what is wrong.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "app/scenario_file.hpp"
#include "geometry/errors.hpp"
#include "physics/run_bounds.hpp"
#include "physics/world.hpp"

namespace gearsim::physics {
namespace {

namespace fs = std::filesystem;

// r_b of the z 24 wheel, m; the load torque gives 100 N along the line of action.
const double kRbWheel = 0.5 * 24e-3 * std::cos(20 * M_PI / 180);
const double kForce_N = 100;

Scenario mcad_pair(const std::string& pinion_extra, const std::string& wheel_extra, double centre_distance_m,
                   const std::string& unit = "mm") {
  const fs::path dir = fs::temp_directory_path() / "gearsim_cad_gears";
  fs::create_directories(dir);
  const std::string data = std::string(GEARSIM_SOURCE_DIR) + "/tests/data/mcad/";
  std::ofstream(dir / "pair.yaml") << "name: mcad_pair\nduration_s: 0.03\n"
                                      "solver: {time_step_s: 1.0e-5, iterations: 50}\n"
                                      "output: {sample_rate_hz: 2000, per_step_log: false}\n"
                                      "pair:\n"
                                      "  driver: {name: pinion, mesh: {file: " << data << "mcad_m1_z12_a20_f5_b005.stl, unit: " << unit
                                   << ", teeth: 12" << pinion_extra << "}, density_kg_m3: 7850}\n"
                                      "  driven: {name: wheel, mesh: {file: " << data << "mcad_m1_z24_a20_f5_b005.stl, unit: " << unit
                                   << ", teeth: 24" << wheel_extra << "}, density_kg_m3: 7850}\n"
                                      "  centre_distance_m: " << centre_distance_m << "\n"
                                      "motors: [{joint: pinion, target_speed_rad_s: 20, ramp_time_s: 0.01, max_torque_N_m: 5}]\n"
                                      "loads: [{joint: wheel, constant_torque_N_m: " << kForce_N * kRbWheel << ", ramp_time_s: 0.01}]\n";
  return app::load_scenario(dir / "pair.yaml", {});
}

// The InputError a World built from s throws ("" when it builds).
std::string refusal(const Scenario& s) {
  try {
    World w(s);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(CadGears, McadPairCarriesItsLoadAlongTheLineOfAction) {
  const Scenario s = mcad_pair("", "", 18e-3);
  World w(s);
  RunBounds bounds(s, w);
  double force = 0, depth = 0;
  long n = 0;
  for (int i = 0; i < 3000; ++i) {
    w.step();
    ASSERT_FALSE(bounds.check(w)) << bounds.check(w)->message;
    if (w.time_s() < 0.015) continue;  // the ramps end at 10 ms
    for (const ContactSample& c : w.contacts()) force += c.normal_force_N, depth = std::max(depth, c.geometry.depth_m);
    ++n;
  }
  // With backlash only the drive flanks touch: their force times r_b carries the load torque. 3 %:
  // the acceptance figure (measured: 100.0 N over 15 ms, 5 mesh periods).
  EXPECT_NEAR(force / static_cast<double>(n), kForce_N, 0.03 * kForce_N);
  // Deepest contact within the static deflection F/k of one tooth pair (k = 1.4e10 N/m/m × 6 mm)
  // + 2 µm (the bound for a sound run).
  EXPECT_LT(depth, kForce_N / (1.4e10 * 6e-3) + 2e-6);
}

TEST(CadGears, AHalfPitchToothLayoutErrorIsRefused) {
  // tooth0 15° on the 12-tooth pinion: the macro then puts a pinion tooth into a wheel tooth.
  const std::string m = refusal(mcad_pair(", tooth0_deg: 15", "", 18e-3));
  EXPECT_NE(m.find("overlap"), std::string::npos) << m;
  EXPECT_NE(m.find("'pinion'"), std::string::npos) << m;
}

TEST(CadGears, ACentreDistanceTooSmallIsRefusedWithTheDepth) {
  // 0.2 mm short of the standard 18 mm: the backlash (0.1 mm along the pitch circles, ≈ 0.07 mm
  // radially) is used up and the teeth overlap by tens of µm.
  const std::string m = refusal(mcad_pair("", "", 17.8e-3));
  EXPECT_NE(m.find("overlap"), std::string::npos) << m;
  EXPECT_NE(m.find("um deep"), std::string::npos) << m;
}

TEST(CadGears, AMillimetreFileReadAsMetresIsRefused) {
  // Gears 12 m across 18 mm apart.
  EXPECT_NE(refusal(mcad_pair("", "", 18e-3, "m")), "");
}

TEST(CadGears, AWrongToothCountIsRefused) {
  // 13 teeth on a 12-tooth mesh: sectors hold no whole flank, or the teeth land on teeth.
  Scenario s = mcad_pair("", "", 18e-3);
  s.bodies[0].mesh->teeth->teeth = 13;
  EXPECT_NE(refusal(s), "");
}

}  // namespace
}  // namespace gearsim::physics

// `gearsim run` and `gearsim report` on gear trains of several stages: the shipped three-stage
// wind-turbine gearbox, the shipped two-stage planetary reducer, and a two-stage reducer written
// body by body (no macros). Each run is analysed (exit 0): every stage named, its mesh harmonics
// found within one frequency bin of the rigid kinematics' mesh frequency, its transmission error
// given; and the report shows the gearbox that was run, without the paper's rows.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "input/scenario_file.hpp"
#include "tests/support/asset_scenario.hpp"
#include "tests/support/cli_run.hpp"

namespace test_train_analysis {

namespace fs = std::filesystem;
using json = nlohmann::json;
constexpr double kTwoPi = 2 * std::numbers::pi;

std::string read_text(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Runs `scenario` into `dir` (exit 0 expected: the train is analysed) and returns dir.
fs::path run(const fs::path& scenario, const fs::path& dir) {
  const gearsim::test::CliRun r = gearsim::test::gearsim("run " + scenario.string() + " --out " + dir.string());
  EXPECT_EQ(r.exit_code, 0) << r.output;
  return dir;
}

// Every pair of stage `stage` has its first two mesh harmonics within one bin of k·f_m.
void expect_harmonics_at(const json& a, const std::string& stage, double mesh_hz) {
  int pairs = 0;
  for (const auto& [name, p] : a["pairs"].items()) {
    if (p["stage"] != stage) continue;
    ++pairs;
    for (int k = 1; k <= 2; ++k) {
      const json& h = p["mesh_harmonics"][static_cast<std::size_t>(k - 1)];
      ASSERT_TRUE(h.contains("peak_hz")) << name << " harmonic " << k;
      EXPECT_NEAR(h["peak_hz"].get<double>(), k * mesh_hz, p["bin_width_hz"].get<double>()) << name << " harmonic " << k;
    }
  }
  EXPECT_GT(pairs, 0) << "no pair of stage " << stage;
}

const json* stage_named(const json& a, const std::string& name) {
  for (const auto& st : a["gear_train"]["stages"])
    if (st["name"] == name) return &st;
  return nullptr;
}

// The report of a train shows its stages and gears and none of the paper's rows.
void expect_report_of_the_train(const fs::path& dir, const std::vector<std::string>& stages) {
  const gearsim::test::CliRun r = gearsim::test::gearsim("report " + dir.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::string html = read_text(dir / "report.html");
  EXPECT_NE(html.find("<h2>The gearbox</h2>"), std::string::npos);
  EXPECT_NE(html.find("dynamic factor, band-limited"), std::string::npos);
  for (const std::string& st : stages) EXPECT_NE(html.find("<td>" + st + "</td>"), std::string::npos) << st;
  for (const char* paper : {"The paper and this run", "paper Fig.", "planet z = 36", "f<sub>m</sub>/36", "paper's"})
    EXPECT_EQ(html.find(paper), std::string::npos) << paper;
}

TEST(TrainAnalysis, TheWindTurbineGearboxIsAnalysedStageByStage) {
  const fs::path file = fs::path(GEARSIM_SOURCE_DIR) / "assets/scenarios/wind_turbine_3stage.yaml";
  const double carrier_hz = gearsim::input::load_scenario(file).motors.front().target_speed_rad_s / kTwoPi;
  const fs::path dir = run(file, gearsim::test::fresh_test_dir() / "run");
  const json a = json::parse(read_text(dir / "analysis.json"));
  // Its stage-1 teeth deflect ~64 µm under 197 kN (steel, 220 mm face): no penetration warning
  // for what its load does.
  const json summary = json::parse(read_text(dir / "summary.json"));
  EXPECT_TRUE(summary["warnings"].empty()) << summary["warnings"].dump();
  EXPECT_GT(summary["max_penetration_um"].get<double>(), 10.0);
  ASSERT_EQ(a["gear_train"]["kind"], "train");
  ASSERT_EQ(a["gear_train"]["stages"].size(), 3u);
  // Theory: ring fixed, carrier in, sun out (1 + 99/21); then 82 → 23 and 88 → 22.
  const double sun_hz = carrier_hz * (1 + 99.0 / 21), s2_pinion_hz = sun_hz * 82 / 23;
  const double mesh_hz[3] = {99 * carrier_hz, 82 * sun_hz, 88 * s2_pinion_hz};
  const char* names[3] = {"s1", "s2", "s3"};
  double ratio = 1;
  for (int k = 0; k < 3; ++k) {
    const json* st = stage_named(a, names[k]);
    ASSERT_TRUE(st) << names[k];
    EXPECT_NEAR((*st)["mesh_hz"].get<double>(), mesh_hz[k], 1e-9 * mesh_hz[k]) << names[k];
    EXPECT_TRUE((*st)["transmission_error"]["peak_to_peak_rad"].get<double>() > 0) << names[k];
    // Without the assembly phase (the stage's gears start turned by up to a pitch, 0.07–0.27
    // rad): what is left is the loaded deflection, under 1 mrad (64 µm on a 98.7 mm base radius).
    EXPECT_LT(std::abs((*st)["transmission_error"]["mean_rad"].get<double>()), 1e-3) << names[k];
    expect_harmonics_at(a, names[k], mesh_hz[k]);
    ratio *= (*st)["ratio"].get<double>();
  }
  EXPECT_EQ(a["gear_train"]["stages"][0]["input"], "s1_carrier");
  EXPECT_EQ(a["gear_train"]["stages"][0]["members"]["fixed"], "s1_ring");
  EXPECT_NEAR(ratio, 21.0 / 120 * 23 / 82 * 22 / 88, 1e-12);
  EXPECT_NEAR(a["gear_train"]["ratio"].get<double>(), ratio, 1e-15);
  // summary.json: each stage's ratio measured from its members' mean speeds, beside the nominal.
  ASSERT_EQ(summary["stages"].size(), 3u);
  for (const auto& st : summary["stages"])
    EXPECT_NEAR(st["ratio"].get<double>() / st["ratio_nominal"].get<double>(), 1.0, 1e-3) << st.dump();
  // Each stage's frequencies under its own name.
  bool s3_mesh = false;
  for (const auto& f : a["gear_train"]["characteristic_frequencies"])
    if (f["key"] == "s3.mesh") s3_mesh = std::abs(f["value_hz"].get<double>() - mesh_hz[2]) < 1e-9 * mesh_hz[2];
  EXPECT_TRUE(s3_mesh);
  expect_report_of_the_train(dir, {"s1", "s2", "s3"});
  std::printf("mesh frequencies %.4f / %.4f / %.4f Hz, ratio 1:%.4f\n", mesh_hz[0], mesh_hz[1], mesh_hz[2], 1 / ratio);
}

TEST(TrainAnalysis, TheTwoStagePlanetaryIsAnalysedStageByStage) {
  const fs::path file = fs::path(GEARSIM_SOURCE_DIR) / "assets/scenarios/two_stage_planetary.yaml";
  const double sun_hz = gearsim::input::load_scenario(file).motors.front().target_speed_rad_s / kTwoPi;
  const fs::path dir = run(file, gearsim::test::fresh_test_dir() / "run");
  const json a = json::parse(read_text(dir / "analysis.json"));
  ASSERT_EQ(a["gear_train"]["stages"].size(), 2u);
  // Each stage: ring fixed, sun in, carrier out: f_m = z_r·f_c = z_r·f_s/(1 + z_r/z_s).
  const double stage1_mesh_hz = 96 * sun_hz / 5, stage2_mesh_hz = stage1_mesh_hz / 5;
  expect_harmonics_at(a, "s1", stage1_mesh_hz);
  expect_harmonics_at(a, "s2", stage2_mesh_hz);
  EXPECT_NEAR(a["gear_train"]["ratio"].get<double>(), 25.0, 1e-12);
  expect_report_of_the_train(dir, {"s1", "s2"});
}

// A housing sensor on stage 2's ring of the two-stage planetary is analysed against stage 2's
// planets (2.5 s: two passes of each before the window's end); sensors on both rings are refused
// with one message naming both stages (the run completes, its analysis refused: exit 9).
TEST(TrainAnalysis, AHousingSensorIsAnalysedAgainstThePlanetaryStageItSitsOn) {
  const fs::path file = fs::path(GEARSIM_SOURCE_DIR) / "assets/scenarios/two_stage_planetary.yaml";
  const auto sensor = [](const std::string& name, const std::string& ring) {
    return "{name: " + name + ", body: " + ring +
           ", angle_deg: 90, window_width_deg: 120, other_meshes_weight: 0.1, resonance_hz: 4000, damping_ratio: 0.05, "
           "effective_mass_kg: 1.0, sample_rate_hz: 25000}";
  };
  const fs::path dir = gearsim::test::fresh_test_dir();
  const gearsim::test::CliRun one = gearsim::test::gearsim("run " + file.string() + " --out " + (dir / "one").string() +
                                                           " --duration 2.5 --set 'sensors=[" + sensor("top", "s2_ring") + "]'");
  ASSERT_EQ(one.exit_code, 0) << one.output;
  const json a = json::parse(read_text(dir / "one" / "analysis.json"));
  ASSERT_EQ(a["sensors"].size(), 1u);
  std::vector<std::string> planets;
  for (const auto& p : a["sensors"][0]["planets"]) planets.push_back(p["planet"].get<std::string>());
  EXPECT_EQ(planets, (std::vector<std::string>{"s2_planet_0", "s2_planet_1", "s2_planet_2"}));
  const gearsim::test::CliRun two =
      gearsim::test::gearsim("run " + file.string() + " --out " + (dir / "two").string() + " --set 'sensors=[" + sensor("top", "s2_ring") +
                             ", " + sensor("low", "s1_ring") + "]'");
  EXPECT_EQ(two.exit_code, 9) << two.output;
  EXPECT_NE(two.output.find("sensors on two planetary stages ('s2', 's1')"), std::string::npos) << two.output;
}

// The two-stage reducer written body by body: the planetary set (sun 21, three planets
// 39, ring 99 with h_a* 0.8, fixed) whose carrier turns, through a torsional coupling on its own
// axis, a 23 → 82 spur pair 40 mm along the axis. The planets' and ring's tooth angles are the
// planetary macro's (the assembly condition), copied into the file as numbers.
TEST(TrainAnalysis, AReducerWrittenBodyByBodyIsFoundAsItsTwoStagesAndAnalysed) {
  const fs::path dir = gearsim::test::fresh_test_dir();
  // The macro's placement of the planetary set, read back for its angles.
  const auto gear = [](const std::string& kind, int z, const std::string& extra) {
    return "{kind: " + kind + ", teeth: " + std::to_string(z) + ", module_m: 0.001, face_width_m: 0.01, " + extra + "}";
  };
  std::ofstream(dir / "set.yaml") << "name: set\nduration_s: 0.01\nplanetary:\n  sun: {density_kg_m3: 7850, gear: "
                                  << gear("external", 21, "bore_diameter_m: 0.004")
                                  << "}\n  planet: {density_kg_m3: 7850, gear: " << gear("external", 39, "bore_diameter_m: 0.004")
                                  << "}\n  ring: {density_kg_m3: 7850, gear: "
                                  << gear("internal", 99, "addendum_coeff: 0.8, rim_diameter_m: 0.11")
                                  << "}\n  planets: 3\n  carrier: {mass_kg: 0.2, inertia_z_kg_m2: 2.0e-4}\n";
  const gearsim::physics::Scenario set = gearsim::input::load_scenario(dir / "set.yaml");
  std::ostringstream bodies;
  bodies.precision(17);
  for (const gearsim::physics::BodyDef& b : set.bodies) {
    const Eigen::Vector3d& p = b.pose.position_m;
    const double angle = 2 * std::atan2(b.pose.orientation.z(), b.pose.orientation.w());
    bodies << "  - {name: " << b.name;
    if (b.gear)
      bodies << ", density_kg_m3: 7850, gear: "
             << gear(b.gear->kind == gearsim::GearKind::Internal ? "internal" : "external", b.gear->teeth,
                     std::string(b.gear->kind == gearsim::GearKind::Internal ? "addendum_coeff: 0.8, rim_diameter_m: 0.11"
                                                                             : "bore_diameter_m: 0.004") +
                         ", tooth0_angle_rad: " + std::to_string(b.gear->tooth0_angle_rad));
    else
      bodies << ", mass_kg: 0.2, principal_inertia_kg_m2: [1.0e-4, 1.0e-4, 2.0e-4]";
    bodies << ", position_m: [" << p.x() << ", " << p.y() << ", " << p.z() << "], angle_rad: " << angle << (b.fixed ? ", fixed: true" : "")
           << "}\n";
  }
  std::ostringstream joints;
  for (const gearsim::physics::JointDef& j : set.joints)
    joints << "  - {name: " << j.name << ", body: " << j.body << ", parent: " << j.parent << "}\n";
  std::ofstream(dir / "reducer.yaml")
      << "name: reducer\nduration_s: 0.5\nsolver: {time_step_s: 1.0e-5}\noutput: {sample_rate_hz: 2000, per_step_log: false}\n"
      << "bodies:\n"
      << bodies.str() << "  - {name: pinion, density_kg_m3: 7850, gear: " << gear("external", 23, "bore_diameter_m: 0.004")
      << ", position_m: [0, 0, 0.04]}\n"
      << "  - {name: wheel, density_kg_m3: 7850, gear: " << gear("external", 82, "bore_diameter_m: 0.01")
      << ", position_m: [0.0525, 0, 0.04], angle_rad: " << std::numbers::pi / 82 << "}\n"
      << "joints:\n"
      << joints.str()
      << "  - {name: pinion, body: pinion, parent: carrier,\n"
         "     bearing: {radial_stiffness_N_per_m: 1.0e9, torsional_stiffness_N_m_per_rad: 2.0e3, torsional_damping_N_m_s_per_rad: 0.05}}\n"
         "  - {name: wheel, body: wheel}\n"
         "motors: [{joint: sun, target_speed_rad_s: 50, ramp_time_s: 0.02, max_torque_N_m: 20}]\n"
         "loads: [{joint: wheel, constant_torque_N_m: 7.7066, ramp_time_s: 0.02}]\n";
  const fs::path out = run(dir / "reducer.yaml", dir / "run");
  const json a = json::parse(read_text(out / "analysis.json"));
  ASSERT_EQ(a["gear_train"]["stages"].size(), 2u) << read_text(dir / "reducer.yaml");
  // No shared prefix: the stages are numbered from the motor.
  const json &s1 = a["gear_train"]["stages"][0], &s2 = a["gear_train"]["stages"][1];
  EXPECT_EQ(s1["name"], "stage_1");
  EXPECT_EQ(s1["kind"], "planetary");
  EXPECT_EQ(s1["output"], "carrier");
  EXPECT_EQ(s2["kind"], "external pair");
  EXPECT_EQ(s2["members"]["driver"], "pinion");
  const double carrier_rad_s = 50.0 * 21 / 120;
  EXPECT_NEAR(s2["input_speed_rad_s"].get<double>(), carrier_rad_s, 1e-12);
  expect_harmonics_at(a, "stage_1", 99 * carrier_rad_s / kTwoPi);
  expect_harmonics_at(a, "stage_2", 23 * carrier_rad_s / kTwoPi);
  // Physical: each mesh carries the torque of its stage. The load 7.7066 N·m on the wheel's base
  // radius (82 mm·cos 20°/2), and on the planets a third of the carrier's torque (that load's
  // 23/82) over their base radius from the sun.
  const double rb = [](int z) { return 0.5e-3 * z * std::cos(20 * std::numbers::pi / 180); }(82);
  for (const auto& [name, p] : a["pairs"].items()) {
    if (p["stage"] == "stage_2") {
      EXPECT_NEAR(p["mean_force_N"].get<double>(), 7.7066 / rb, 0.01 * 7.7066 / rb) << name;
    }
    if (name.rfind("sun__", 0) == 0) {
      const double carrier_torque = 7.7066 * 23 / 82, sun_torque = carrier_torque * 21 / 120;
      const double force = sun_torque / 3 / (0.5e-3 * 21 * std::cos(20 * std::numbers::pi / 180));
      EXPECT_NEAR(p["mean_force_N"].get<double>(), force, 0.02 * force) << name;
    }
  }
  expect_report_of_the_train(out, {"stage_1", "stage_2"});
}

}  // namespace test_train_analysis

// Gears mesh in planes: a two-stage reducer whose stages lie side by side along one shaft line
// (stage 2's pinion on stage 1's wheel, 15 mm further along the axis) has exactly its two meshes,
// whatever the distance between gears of different stages; gears of two stages whose faces
// overlap along the axis are refused when one lies inside the other. A train written as
// `stages:` joined by a `shafts:` entry turns at the product of its stages' ratios and each mesh
// carries the torque its stage passes on.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/errors.hpp"
#include "input/scenario_file.hpp"
#include "physics/world.hpp"
#include "sim/run_bounds.hpp"
#include "sim/simulate.hpp"
#include "tests/support/asset_scenario.hpp"

namespace gearsim::physics {
namespace test_gear_planes {

namespace fs = std::filesystem;

// Stage 1: pinion_1 z 20 drives wheel_1 z 40 in the plane z = 0; stage 2: pinion_2 z 20 on
// wheel_1's shaft line at z = `stage2_z_m`, turning on wheel_1 through a stiff torsional
// coupling, drives wheel_2 z 40. Module 1 mm, 20°, faces 10 mm, zero-backlash distance 30 mm.
// wheel_2 carries `load_N_m`.
fs::path two_stage_file(double stage2_z_m, double load_N_m) {
  const fs::path file = test::fresh_test_dir() / "two_stage.yaml";
  auto gear = [](int z) {
    return "{kind: external, teeth: " + std::to_string(z) + ", module_m: 0.001, face_width_m: 0.01, bore_diameter_m: 0.005}";
  };
  const std::string z2 = std::to_string(stage2_z_m);
  std::ofstream(file) << "name: two_stage\nduration_s: 0.06\n"
                         "solver: {time_step_s: 1.0e-5}\n"
                         "output: {sample_rate_hz: 2000, per_step_log: false}\n"
                         "bodies:\n"
                         "  - {name: pinion_1, density_kg_m3: 7850, gear: "
                      << gear(20)
                      << "}\n"
                         "  - {name: wheel_1, density_kg_m3: 7850, gear: "
                      << gear(40)
                      << ", position_m: [0.03, 0, 0], angle_deg: 4.5}\n"
                         "  - {name: pinion_2, density_kg_m3: 7850, gear: "
                      << gear(20) << ", position_m: [0.03, 0, " << z2
                      << "]}\n"
                         "  - {name: wheel_2, density_kg_m3: 7850, gear: "
                      << gear(40) << ", position_m: [0.06, 0, " << z2
                      << "], angle_deg: 4.5}\n"
                         "joints:\n"
                         "  - {name: pinion_1, body: pinion_1}\n"
                         "  - {name: wheel_1, body: wheel_1}\n"
                         "  - {name: pinion_2, body: pinion_2, parent: wheel_1,\n"
                         "     bearing: {radial_stiffness_N_per_m: 1.0e9, torsional_stiffness_N_m_per_rad: 1.0e5,\n"
                         "               torsional_damping_N_m_s_per_rad: 1.0}}\n"
                         "  - {name: wheel_2, body: wheel_2}\n"
                         "motors: [{joint: pinion_1, target_speed_rad_s: 20, ramp_time_s: 0.02, max_torque_N_m: 50}]\n"
                         "loads: [{joint: wheel_2, constant_torque_N_m: "
                      << load_N_m << ", ramp_time_s: 0.02}]\n";
  return file;
}

TEST(GearPlanes, GearsOfStagesSideBySideMeshOnlyInTheirOwnPlane) {
  // wheel_1 and pinion_2 share an axis 15 mm apart along it; wheel_1 and wheel_2 are 33.5 mm
  // apart in space with tips reaching 42 mm: neither is a mesh. (Taken by their distance in
  // space, both were, and refused: "root circles overlap: one body lies inside the other".)
  const double rb40 = 0.5 * 40e-3 * std::cos(20 * M_PI / 180), force_N = 100;
  const Scenario s = input::load_scenario(two_stage_file(0.015, -force_N * rb40), {});
  World w(s);
  ASSERT_EQ(w.gear_pairs().size(), 2u);
  EXPECT_EQ(w.gear_pairs()[0].body_a + "–" + w.gear_pairs()[0].body_b, "pinion_1–wheel_1");
  EXPECT_EQ(w.gear_pairs()[1].body_a + "–" + w.gear_pairs()[1].body_b, "pinion_2–wheel_2");
  for (const GearPairInfo& p : w.gear_pairs()) EXPECT_DOUBLE_EQ(p.face_width_m, 0.01);
  // Running: wheel_2 turns at a quarter of pinion_1's speed (the product of the stages' 2 and
  // 2), and each mesh carries its torque over its base radius: stage 2 F = 100 N, stage 1
  // 50 N (wheel_1's torque is pinion_2's, on half the base radius).
  sim::RunBounds bounds(s, w);
  double speed_in = 0, speed_out = 0, force[2] = {0, 0};
  long n = 0;
  while (w.time_s() < 0.06 - 1e-9) {
    w.step();
    ASSERT_FALSE(bounds.check(w)) << bounds.check(w)->message;
    if (w.time_s() < 0.03) continue;
    for (const BodyState& b : w.bodies()) {
      if (b.name == "pinion_1") speed_in += b.speed_rad_s;
      if (b.name == "wheel_2") speed_out += b.speed_rad_s;
    }
    for (const ContactSample& c : w.contacts()) force[c.pair] += c.normal_force_N;
    ++n;
  }
  EXPECT_NEAR(speed_out / speed_in, 0.25, 1e-3);
  EXPECT_NEAR(force[1] / static_cast<double>(n), force_N, 0.01 * force_N);
  EXPECT_NEAR(force[0] / static_cast<double>(n), 0.5 * force_N, 0.01 * 0.5 * force_N);
  std::printf("ratio %.6f, stage 1 %.3f N, stage 2 %.3f N\n", speed_in / speed_out, force[0] / static_cast<double>(n),
              force[1] / static_cast<double>(n));
}

TEST(GearPlanes, GearsOfTwoStagesWhoseFacesOverlapAlongTheAxisAreRefusedWhenInsideEachOther) {
  // Stage 2 only 5 mm further along: pinion_2's face overlaps wheel_1's by 5 mm on one axis.
  const Scenario s = input::load_scenario(two_stage_file(0.005, -1.0), {});
  try {
    World w(s);
    ADD_FAILURE() << "gears inside each other were built";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(
                  "gears 'wheel_1' and 'pinion_2' share a plane (their faces overlap by 5 mm along the axis) and are 0 mm apart"),
              std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("one body lies inside the other"), std::string::npos) << e.what();
  }
}

// The two-stage reducer of issue 47 as stages: a planetary stage (sun 21, three planets 39, ring
// 99 with the shortened addendum h_a* = 0.8 that clears the planets' fillets; ring fixed, carrier
// out) whose carrier drives, through an elastic shaft, a 23 → 82 spur pair 40 mm further along
// the axis. Module 1 mm, 20°, faces 10 mm.
fs::path two_stage_train_file(const std::string& shaft, double stage2_z_m = 0.04) {
  const fs::path file = test::fresh_test_dir() / "train.yaml";
  auto gear = [](const std::string& kind, int z, const std::string& extra) {
    return "{density_kg_m3: 7850, gear: {kind: " + kind + ", teeth: " + std::to_string(z) + ", module_m: 0.001, face_width_m: 0.01, " +
           extra + "}}";
  };
  std::ofstream(file) << "name: two_stage_train\nduration_s: 0.08\n"
                         "solver: {time_step_s: 1.0e-5}\n"
                         "output: {sample_rate_hz: 2000, per_step_log: false}\n"
                         "stages:\n"
                         "  - name: s1\n"
                         "    planetary:\n"
                         "      sun: "
                      << gear("external", 21, "bore_diameter_m: 0.004")
                      << "\n      planet: " << gear("external", 39, "bore_diameter_m: 0.004")
                      << "\n      ring: " << gear("internal", 99, "addendum_coeff: 0.8, rim_diameter_m: 0.11")
                      << "\n      planets: 3\n"
                         "      carrier: {mass_kg: 0.2, inertia_z_kg_m2: 2.0e-4}\n"
                         "  - name: s2\n"
                         "    pair:\n"
                         "      origin_m: [0, 0, "
                      << stage2_z_m
                      << "]\n"
                         "      driver: {name: pinion, "
                      << gear("external", 23, "bore_diameter_m: 0.004").substr(1) << "\n      driven: {name: wheel, "
                      << gear("external", 82, "bore_diameter_m: 0.01").substr(1) << "\nshafts:\n  - " << shaft
                      << "\nmotors: [{joint: s1_sun, target_speed_rad_s: 50, ramp_time_s: 0.02, max_torque_N_m: 20}]\n"
                         "loads: [{joint: s2_wheel, constant_torque_N_m: 7.7066, ramp_time_s: 0.02}]\n";
  return file;
}

TEST(GearTrain, TwoStagesOnAShaftTurnAtTheProductOfTheirRatiosAndCarryTheirTorques) {
  const Scenario s = input::load_scenario(
      two_stage_train_file("{name: low_speed, from: s1_carrier, to: s2_pinion, torsional_stiffness_N_m_per_rad: 5.0e3, "
                           "torsional_damping_N_m_s_per_rad: 0.05}"),
      {});
  // Members named by stage; the pinion turns on the carrier through the shaft.
  ASSERT_TRUE(s.transmission);
  EXPECT_EQ(s.transmission->input_joint, "s1_sun");
  EXPECT_EQ(s.transmission->output_joint, "s2_wheel");
  const double ratio = (1 + 99.0 / 21) * (-82.0 / 23);  // Willis, then the pair: −20.3727
  EXPECT_NEAR(s.transmission->ratio, ratio, 1e-12);
  for (const JointDef& j : s.joints)
    if (j.body == "s2_pinion") {
      EXPECT_EQ(j.parent, "s1_carrier");
      ASSERT_TRUE(j.bearing);
      EXPECT_TRUE(j.bearing->radially_rigid);
      EXPECT_EQ(j.bearing->torsional_stiffness_N_m_per_rad, 5.0e3);
    }
  const sim::RunSummary r = sim::simulate(s, {});
  ASSERT_EQ(r.status, sim::RunStatus::Completed);
  ASSERT_TRUE(r.ratio);
  EXPECT_NEAR(*r.ratio, ratio, 1e-4 * std::abs(ratio));
  // Stage 2: F = T/r_b,wheel; stage 1: the carrier's torque F·r_b,pinion over the Willis ratio
  // and the three planets, on the sun's base radius (and the same on each planet–ring mesh).
  const double cos20 = std::cos(20 * M_PI / 180);
  const double f2 = 7.7066 / (41e-3 * cos20), f1 = f2 * 11.5e-3 * cos20 / ((1 + 99.0 / 21) * 3 * 10.5e-3 * cos20);
  ASSERT_EQ(r.pairs.size(), 7u);
  for (const sim::PairResult& p : r.pairs) {
    const double drive = p.mean_ccw_flank_force_N + p.mean_cw_flank_force_N;
    const double expected = p.info.body_a == "s2_pinion" ? f2 : f1;
    EXPECT_NEAR(drive, expected, 0.01 * expected) << p.info.body_a << "–" << p.info.body_b;
    EXPECT_LT(std::min(p.mean_ccw_flank_force_N, p.mean_cw_flank_force_N), 0.01 * expected);  // one flank side loaded
  }
  // The pinion turns with the carrier (its speed relative to it: the shaft's twist rate, ~0).
  for (const sim::BodyResult& b : r.bodies)
    if (b.name == "s2_pinion") {
      EXPECT_EQ(b.parent, "s1_carrier");
      EXPECT_NEAR(b.mean_absolute_speed_rad_s, 50 / (1 + 99.0 / 21), 1e-4 * 50);
      EXPECT_NEAR(b.mean_speed_relative_rad_s, 0.0, 1e-4);
    }
  std::printf("ratio %.6f (nominal %.6f); stage 2 %.3f N (T/r_b %.3f), stage 1 %.3f N per mesh (%.3f)\n", *r.ratio, ratio,
              r.pairs.back().mean_ccw_flank_force_N + r.pairs.back().mean_cw_flank_force_N, f2,
              r.pairs.front().mean_ccw_flank_force_N + r.pairs.front().mean_cw_flank_force_N, f1);
}

// A stage plane that puts stage 2's pinion inside stage 1's sun: its origin 5 mm along the axis
// (faces 10 mm wide, so they overlap by 5 mm) on the same axis line. Refused naming both gears.
TEST(GearTrain, AStagePlaneThatPutsTwoGearsInsideEachOtherIsRefused) {
  const Scenario s =
      input::load_scenario(two_stage_train_file("{from: s1_carrier, to: s2_pinion, torsional_stiffness_N_m_per_rad: 5.0e3}", 0.005), {});
  try {
    World w(s);
    ADD_FAILURE() << "stage 2's pinion was built inside stage 1's sun";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("share a plane (their faces overlap by 5 mm along the axis)"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("s2_pinion"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("one body lies inside the other"), std::string::npos) << e.what();
  }
}

TEST(GearTrain, AShaftSizedByLengthAndDiameterTakesSteelsShearModulus) {
  // k = G·π·d⁴/(32·L): 20 mm over 100 mm of steel (G = 79.3 GPa) is 12 456 N·m/rad.
  const Scenario s = input::load_scenario(two_stage_train_file("{from: s1_carrier, to: s2_pinion, length_m: 0.1, diameter_m: 0.02}"),
                                          {"duration_s=0.001"});
  for (const JointDef& j : s.joints) {
    if (j.body == "s2_pinion") {
      EXPECT_NEAR(j.bearing->torsional_stiffness_N_m_per_rad, 79.3e9 * M_PI * std::pow(0.02, 4) / 3.2, 1e-6);
    }
  }
}

TEST(GearTrain, McadMeshesAsOneStageOfATwoStageTrain) {
  // Stage 1: OpenSCAD MCAD's z 12 drives its z 24 (tests/data/mcad: module 1 mm, 20°, 0.05 mm
  // backlash each, 5 facets per involute) at their standard 18 mm (their zero-backlash distance,
  // where the macro would place them, is 69.7 µm closer: off stage 2's axis); stage 2, 20 mm
  // along the axis: a generated z 20 → z 40 on the MCAD wheel's shaft. 100 N on stage 2's mesh
  // is the wheel's 0.9397 N·m on stage 1, 83.3 N on its mesh.
  const std::string mcad = std::string(GEARSIM_SOURCE_DIR) + "/tests/data/mcad/";
  const fs::path file = test::fresh_test_dir() / "mcad_train.yaml";
  const double cos20 = std::cos(20 * M_PI / 180);
  const double load = 100 * 0.5 * 40e-3 * cos20;
  auto gear = [](int z) {
    return "{kind: external, teeth: " + std::to_string(z) + ", module_m: 0.001, face_width_m: 0.005, bore_diameter_m: 0.004}";
  };
  std::ofstream(file)
      << "name: mcad_train\nduration_s: 0.15\n"
         "solver: {time_step_s: 1.0e-5}\n"
         "output: {sample_rate_hz: 2000, per_step_log: false}\n"
         "stages:\n"
         "  - name: a\n"
         "    pair:\n"
         "      driver: {name: pinion, density_kg_m3: 7850, mesh: {file: "
      << mcad
      << "mcad_m1_z12_a20_f5_b005.stl, unit: mm}}\n"
         "      driven: {name: wheel, density_kg_m3: 7850, mesh: {file: "
      << mcad
      << "mcad_m1_z24_a20_f5_b005.stl, unit: mm}}\n"
         "      centre_distance_m: 0.018\n"
         "  - name: b\n"
         "    pair:\n"
         "      origin_m: [0.018, 0, 0.02]\n"
         "      driver: {name: pinion, density_kg_m3: 7850, gear: "
      << gear(20) << "}\n      driven: {name: wheel, density_kg_m3: 7850, gear: " << gear(40)
      << "}\n"
         "shafts: [{from: a_wheel, to: b_pinion, torsional_stiffness_N_m_per_rad: 2.0e3, torsional_damping_N_m_s_per_rad: 0.01}]\n"
         "motors: [{joint: a_pinion, target_speed_rad_s: 20, ramp_time_s: 0.05, max_torque_N_m: 5}]\n"
         "loads: [{joint: b_wheel, constant_torque_N_m: "
      << -load << ", ramp_time_s: 0.05}]\n";
  const Scenario s = input::load_scenario(file, {});
  ASSERT_TRUE(s.transmission);
  EXPECT_DOUBLE_EQ(s.transmission->ratio, 4.0);
  const sim::RunSummary r = sim::simulate(s, {});
  ASSERT_EQ(r.status, sim::RunStatus::Completed);
  EXPECT_NEAR(*r.ratio, 4.0, 4e-4);
  ASSERT_EQ(r.pairs.size(), 2u);
  const double f_b = 100, f_a = 100 * 0.5 * 20e-3 * cos20 / (0.5 * 24e-3 * cos20);
  for (const sim::PairResult& p : r.pairs) {
    const double expected = p.info.body_a == "a_pinion" ? f_a : f_b;
    const double drive = std::max(p.mean_ccw_flank_force_N, p.mean_cw_flank_force_N);
    EXPECT_NEAR(drive, expected, 0.01 * expected) << p.info.body_a << "–" << p.info.body_b;
    EXPECT_LT(std::min(p.mean_ccw_flank_force_N, p.mean_cw_flank_force_N), 0.01 * expected);
    std::printf("%s–%s: %.3f N (T/r_b %.3f N)\n", p.info.body_a.c_str(), p.info.body_b.c_str(), drive, expected);
  }
}

// Each mesh's mean normal force over the steady window (drive and back flanks of a summed).
double mesh_force(const sim::PairResult& p) { return p.mean_ccw_flank_force_N + p.mean_cw_flank_force_N; }

// The paper's set (sun 24, planets 36, ring 96 relieved) with `fixed:` carrier or sun, driven at
// `driver` and loaded at `loaded` with `load_N_m`, frictionless, 0.2 s.
sim::RunSummary planetary_with_fixed(const std::string& fixed, const std::string& driver, double speed, const std::string& loaded,
                                     double load_N_m, Scenario& s) {
  const fs::path file = test::fresh_test_dir() / (fixed + ".yaml");
  std::ofstream(file) << "name: fixed_" << fixed
                      << "\nduration_s: 0.2\nsolver: {time_step_s: 2.0e-5}\noutput: {sample_rate_hz: 2000, per_step_log: false}\n"
                         "contact: {friction: 0}\n"
                         "planetary:\n  spec: "
                      << GEARSIM_SOURCE_DIR
                      << "/assets/specs/paper_gearset.yaml\n  sun: sun\n  planet: planet\n  ring: ring_relieved\n  planets: 3\n"
                         "  carrier: {mass_kg: 0.3, inertia_z_kg_m2: 2.0e-4}\n  fixed: "
                      << fixed << "\nmotors: [{joint: " << driver << ", target_speed_rad_s: " << speed
                      << ", ramp_time_s: 0.05, max_torque_N_m: 50}]\nloads: [{joint: " << loaded << ", constant_torque_N_m: " << load_N_m
                      << ", ramp_time_s: 0.05}]\n";
  s = input::load_scenario(file, {});
  return sim::simulate(s, {});
}

TEST(GearTrain, AStarStageTurnsItsRingAgainstItsSunAndAFixedSunStageItsCarrierWithItsRing) {
  // Carrier fixed: θ_sun/θ_ring = −z_r/z_s = −4; 16 N·m on the ring is 4 N·m on the sun, F =
  // 4 N·m/(3·r_b,sun) on every mesh.
  Scenario star;
  const sim::RunSummary r = planetary_with_fixed("carrier", "sun", 104.7, "ring", 16, star);
  ASSERT_EQ(r.status, sim::RunStatus::Completed);
  EXPECT_EQ(star.transmission->input_joint + ">" + star.transmission->output_joint, "sun>ring");
  EXPECT_DOUBLE_EQ(star.transmission->ratio, -4.0);
  EXPECT_NEAR(*r.ratio, -4.0, 4e-4);
  const double cos20 = std::cos(20 * M_PI / 180), f = 4 / (3 * 12e-3 * cos20);
  for (const sim::PairResult& p : r.pairs) EXPECT_NEAR(mesh_force(p), f, 0.01 * f) << p.info.body_a << "–" << p.info.body_b;
  // Sun fixed: θ_ring/θ_carrier = 1 + z_s/z_r = 1.25; 10 N·m on the carrier is 8 N·m on the
  // ring, F = 8 N·m/(3·r_b,ring).
  Scenario sun_fixed;
  const sim::RunSummary q = planetary_with_fixed("sun", "ring", 20, "carrier", -10, sun_fixed);
  ASSERT_EQ(q.status, sim::RunStatus::Completed);
  EXPECT_EQ(sun_fixed.transmission->input_joint + ">" + sun_fixed.transmission->output_joint, "ring>carrier");
  EXPECT_DOUBLE_EQ(sun_fixed.transmission->ratio, 1.25);
  EXPECT_NEAR(*q.ratio, 1.25, 1.25e-4);
  const double g = 8 / (3 * 48e-3 * cos20);
  for (const sim::PairResult& p : q.pairs) EXPECT_NEAR(mesh_force(p), g, 0.01 * g) << p.info.body_a << "–" << p.info.body_b;
  std::printf("star: ratio %.6f, %.3f N per mesh (%.3f); sun fixed: ratio %.6f, %.3f N (%.3f)\n", *r.ratio, mesh_force(r.pairs[0]), f,
              *q.ratio, mesh_force(q.pairs[0]), g);
}

TEST(GearTrain, TheShippedWindTurbineGearboxTurnsAtItsRatioAndEveryMeshCarriesItsTorque) {
  // assets/scenarios/wind_turbine_3stage.yaml (NREL GRC gear data, spur): the carrier at 22 rpm,
  // 3995 N·m on the high-speed pinion. Each mesh carries the torque of the stage's output over
  // its base radius: stage 3 T/r_b,pinion; stage 2 the pinion's torque ·88/22 (the stage-3
  // wheel's) over the stage-2 pinion's r_b; stage 1 the sun's torque (the stage-2 wheel's) over
  // three sun–planet meshes, and the same on each planet–ring mesh. Without flank friction: with
  // the scenario's μ = 0.05 the friction forces' moments shift the normal forces (measured: +0.5 %
  // in stage 3 to +3.2 % on the planet–ring meshes).
  const Scenario s =
      input::load_scenario(fs::path(GEARSIM_SOURCE_DIR) / "assets/scenarios/wind_turbine_3stage.yaml", {"contact.friction=0"});
  const sim::RunSummary r = sim::simulate(s, {});
  ASSERT_EQ(r.status, sim::RunStatus::Completed);
  // The ratio of the turns over the steady window (0.8 s after the 0.2 s ramps): the twist of
  // the shafts and meshes still swings after the ramps, and its change between the window's
  // ends is a share of the high-speed pinion's 150 rad turn (over a 0.2 s window: 2.5e-4).
  const double product = (1 + 99.0 / 21) * (82.0 / 23) * (88.0 / 22);
  ASSERT_TRUE(r.ratio);
  EXPECT_NEAR(1 / *r.ratio, product, 1e-4 * product);
  std::printf("overall ratio 1 : %.5f (product of the stages' %.5f)\n", 1 / *r.ratio, product);
  EXPECT_NEAR(s.transmission->ratio, 1 / product, 1e-9);
  const double cos20 = std::cos(20 * M_PI / 180), t_out = 3995;
  const double f3 = t_out / (0.5 * 22 * 5e-3 * cos20);
  const double t_w3 = t_out * 88 / 22;
  const double f2 = t_w3 / (0.5 * 23 * 8.25e-3 * cos20);
  const double t_sun = t_w3 * 82 / 23;
  const double f1 = t_sun / (3 * 0.5 * 21 * 10e-3 * cos20);
  ASSERT_EQ(r.pairs.size(), 8u);
  for (const sim::PairResult& p : r.pairs) {
    const std::string stage = p.info.body_a.substr(0, 2);
    const double expected = stage == "s3" ? f3 : stage == "s2" ? f2 : f1;
    EXPECT_NEAR(mesh_force(p), expected, 0.01 * expected) << p.info.body_a << "–" << p.info.body_b;
    std::printf("%s–%s: %.1f N (T/r_b %.1f N)\n", p.info.body_a.c_str(), p.info.body_b.c_str(), mesh_force(p), expected);
  }
}

TEST(GearTrain, TheShippedTwoStagePlanetaryTurnsAtTwentyFiveToOne) {
  // assets/scenarios/two_stage_planetary.yaml: the paper's set twice, stage 1's carrier driving
  // stage 2's sun through an 8 mm shaft; 50 N·m on stage 2's carrier: 10 N·m into its sun over
  // three meshes, 2 N·m into stage 1's. Without flank friction, as above (with μ = 0.05: stage 1's
  // sun–planet meshes +1.3 %).
  const Scenario s = input::load_scenario(fs::path(GEARSIM_SOURCE_DIR) / "assets/scenarios/two_stage_planetary.yaml",
                                          {"duration_s=0.25", "contact.friction=0"});
  ASSERT_TRUE(s.transmission);
  EXPECT_DOUBLE_EQ(s.transmission->ratio, 25.0);
  const sim::RunSummary r = sim::simulate(s, {});
  ASSERT_EQ(r.status, sim::RunStatus::Completed);
  EXPECT_NEAR(*r.ratio, 25.0, 25.0 * 1e-4);
  const double rb_sun = 0.5 * 24e-3 * std::cos(20 * M_PI / 180);
  for (const sim::PairResult& p : r.pairs) {
    const double expected = (p.info.body_a.substr(0, 2) == "s2" ? 10.0 : 2.0) / (3 * rb_sun);
    EXPECT_NEAR(mesh_force(p), expected, 0.01 * expected) << p.info.body_a << "–" << p.info.body_b;
    std::printf("%s–%s: %.3f N (T/r_b %.3f N)\n", p.info.body_a.c_str(), p.info.body_b.c_str(), mesh_force(p), expected);
  }
}

// A helical pair is read, but the planar contact cannot carry its load along the face: the world
// refuses it (naming the gear and its helix) rather than running it as a spur pair.
TEST(GearPlanes, AHelicalGearIsNotRunAsASpurGear) {
  const fs::path file = test::fresh_test_dir() / "helical.yaml";
  const std::string g = ", normal_module_m: 0.002, helix_angle_deg: 15, face_width_m: 0.02, bore_diameter_m: 0.008}";
  std::ofstream(file) << "name: helical\nduration_s: 0.01\npair:\n"
                         "  driver: {name: pinion, density_kg_m3: 7850, gear: {kind: external, teeth: 20, hand: right"
                      << g << "}\n  driven: {name: wheel, density_kg_m3: 7850, gear: {kind: external, teeth: 40, hand: left" << g
                      << "}\nmotors: [{joint: pinion, target_speed_rad_s: 10, max_torque_N_m: 5}]\n";
  const Scenario s = input::load_scenario(file, {});
  try {
    World w(s);
    ADD_FAILURE() << "a helical pair was built as a spur pair";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("a helical gear (β = 15.000000°)"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("pinion"), std::string::npos) << e.what();
  }
}

}  // namespace test_gear_planes
}  // namespace gearsim::physics

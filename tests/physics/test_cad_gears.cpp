// A spur pair from meshes nobody here made (OpenSCAD MCAD, tests/data/mcad: z 12 drives z 24,
// module 1 mm, 20°, 5 facets per involute, 0.05 mm backlash each) runs physically at its
// standard centre distance, and the usual mistakes with such meshes are refused before the first
// step with a message naming what is wrong.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "input/scenario_file.hpp"
#include "core/errors.hpp"
#include "geometry/involute_pair.hpp"
#include "sim/run_bounds.hpp"
#include "physics/world.hpp"
#include "tests/support/asset_scenario.hpp"
#include "tests/support/mcad_planetary.hpp"

namespace gearsim::physics {
namespace test_cad_gears {

namespace fs = std::filesystem;

// r_b of the z 24 wheel, m; the load torque gives 100 N along the line of action.
const double kRbWheel = 0.5 * 24e-3 * std::cos(20 * M_PI / 180);
const double kForce_N = 100;

// The pair file: `pinion`/`wheel`: extra keys of each mesh (teeth, tooth0_deg); centre distance
// ≤ 0: none given (the macro derives it from the recognised gears).
// `driver_file`, `driven_file` in tests/data/mcad/ and the driven gear's load torque (N·m, about
// +z) default to the external pair z 12 → z 24.
fs::path mcad_pair_file(const std::string& pinion, const std::string& wheel, double centre_distance_m, const std::string& unit = "mm",
                        const std::string& driver_file = "mcad_m1_z12_a20_f5_b005.stl",
                        const std::string& driven_file = "mcad_m1_z24_a20_f5_b005.stl", double load_N_m = kForce_N * kRbWheel) {
  const fs::path dir = test::fresh_test_dir();  // ctest runs this file's cases in parallel
  const std::string data = std::string(GEARSIM_SOURCE_DIR) + "/tests/data/mcad/";
  std::ofstream f(dir / "pair.yaml");
  f << "name: mcad_pair\nduration_s: 0.03\n"
       "solver: {time_step_s: 1.0e-5}\n"
       "output: {sample_rate_hz: 2000, per_step_log: false}\n"
       "pair:\n"
       "  driver: {name: pinion, mesh: {file: "
    << data << driver_file << ", unit: " << unit << pinion
    << "}, density_kg_m3: 7850}\n"
       "  driven: {name: wheel, mesh: {file: "
    << data << driven_file << ", unit: " << unit << wheel << "}, density_kg_m3: 7850}\n";
  if (centre_distance_m > 0) f << "  centre_distance_m: " << centre_distance_m << "\n";
  f << "motors: [{joint: pinion, target_speed_rad_s: 20, ramp_time_s: 0.01, max_torque_N_m: 5}]\n"
       "loads: [{joint: wheel, constant_torque_N_m: "
    << load_N_m << ", ramp_time_s: 0.01}]\n";
  return dir / "pair.yaml";
}

Scenario mcad_pair(const std::string& pinion, const std::string& wheel, double centre_distance_m, const std::string& unit = "mm") {
  return input::load_scenario(mcad_pair_file(pinion, wheel, centre_distance_m, unit), {});
}

// The InputError reading the scenario or building its World throws ("" when both succeed).
std::string refusal(const std::string& pinion, const std::string& wheel, double centre_distance_m, const std::string& unit = "mm") {
  try {
    World w(mcad_pair(pinion, wheel, centre_distance_m, unit));
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(CadGears, McadPairCarriesItsLoadAlongTheLineOfAction) {
  const Scenario s = mcad_pair(", teeth: 12", ", teeth: 24", 18e-3);
  World w(s);
  sim::RunBounds bounds(s, w);
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

// A ring cut from MCAD's gear shape (z 48, relieved tip 0.8 m, 0.05 mm backlash) driven by the
// MCAD z 24 pinion through the pair macro: the ring sits at the origin, the pinion 12 mm off on
// +x, both turn the same way (ratio +2), and the drive flanks carry the load torque.
TEST(CadGears, McadRingFromThePairMacroTurnsWithItsPinionAndCarriesTheLoad) {
  const double rb_ring = 0.5 * 48e-3 * std::cos(20 * M_PI / 180);
  // The ring turns +z with the pinion; its load resists: −F·r_b.
  const Scenario s = input::load_scenario(
      mcad_pair_file("", "", 12e-3, "mm", "mcad_m1_z24_a20_f5_b005.stl", "mcadring_m1_z48_a20_f5_b005.stl", -kForce_N * rb_ring), {});
  ASSERT_TRUE(s.transmission);
  EXPECT_DOUBLE_EQ(s.transmission->ratio, 2.0);
  EXPECT_NEAR(s.bodies[1].pose.position_m.norm(), 0.0, 1e-15);  // the ring
  EXPECT_NEAR((s.bodies[0].pose.position_m - Eigen::Vector3d(12e-3, 0, 0)).norm(), 0.0, 1e-15);
  World w(s);
  sim::RunBounds bounds(s, w);
  double drive = 0, back = 0, depth = 0;
  long n = 0;
  for (int i = 0; i < 3000; ++i) {
    w.step();
    ASSERT_FALSE(bounds.check(w)) << bounds.check(w)->message;
    if (w.time_s() < 0.015) continue;  // the ramps end at 10 ms
    for (const ContactSample& c : w.contacts()) {
      (c.geometry.flank_a == Flank::Ccw ? drive : back) += c.normal_force_N;
      depth = std::max(depth, c.geometry.depth_m);
    }
    ++n;
  }
  // 0.05 mm of backlash: one flank side carries it all, F·r_b = T within the 3 %
  // (measured 0.15 s from the CLI: 99.89 N).
  EXPECT_NEAR(drive / static_cast<double>(n), kForce_N, 0.03 * kForce_N);
  EXPECT_EQ(back, 0.0);
  EXPECT_LT(depth, kForce_N / (1.4e10 * 6e-3) + 2e-6);
}

// FreeCAD 0.20's z 12 pinion in its z 24 ring (tests/data/freecad), at the standard 6 mm: the
// ring's tip corners meet the pinion's flanks low, near its base circle, where the ring's tip
// land turns 70–80° into its flank within a vertex spacing. Measured along the land's normal
// (a lever of 3.7 mm about the pinion against r_b 5.6 mm), those contacts took the corner's
// sliding for approach and the drive flanks read 108.3 N against T/r_b = 100 N; measured along
// the pinion flank's normal (tooth_contact: a corner in a smooth flank), 99.8 N.
TEST(CadGears, TheTipCornersOfAFreecadRingCarryWhatTheirSpringsGive) {
  const std::string data = std::string(GEARSIM_SOURCE_DIR) + "/tests/data/freecad/";
  const double rb_ring = 0.5 * 24e-3 * std::cos(20 * M_PI / 180);
  const fs::path dir = test::fresh_test_dir();
  std::ofstream(dir / "pair.yaml") << "name: freecad_internal_pair\nduration_s: 0.15\n"
                                      "solver: {time_step_s: 5.0e-6}\n"
                                      "output: {sample_rate_hz: 2000, per_step_log: false}\n"
                                      "contact: {stiffness_N_per_m_per_m: 1.4e10, damping_ratio: 0.05, friction: 0.05}\n"
                                      "pair:\n"
                                      "  driver: {name: pinion, density_kg_m3: 7850, mesh: {file: "
                                   << data
                                   << "fc_m1_z12_a20_face4_l0p02a15.stl, unit: mm, teeth: 12, tooth0_deg: 0}}\n"
                                      "  driven: {name: ring, density_kg_m3: 7850, mesh: {file: "
                                   << data
                                   << "fcring_m1_z24_a20_face4_l0p02a15.stl, unit: mm, teeth: 24, tooth0_deg: 0}}\n"
                                      "  centre_distance_m: 0.006\n"
                                      "motors: [{joint: pinion, target_speed_rad_s: 20, ramp_time_s: 0.05, max_torque_N_m: 1.69245}]\n"
                                      "loads: [{joint: ring, constant_torque_N_m: "
                                   << -kForce_N * rb_ring << "}]\n";
  const Scenario s = input::load_scenario(dir / "pair.yaml", {});
  World w(s);
  sim::RunBounds bounds(s, w);
  double drive = 0, back = 0;
  long n = 0;
  while (w.time_s() < 0.15 - 1e-9) {
    w.step();
    ASSERT_FALSE(bounds.check(w)) << bounds.check(w)->message;
    if (w.time_s() < 0.05) continue;  // the motor's ramp
    for (const ContactSample& c : w.contacts()) {
      (c.geometry.flank_a == Flank::Ccw ? drive : back) += c.normal_force_N;
    }
    ++n;
  }
  EXPECT_NEAR(drive / static_cast<double>(n), kForce_N, 0.01 * kForce_N);
  EXPECT_LT(back / static_cast<double>(n), 0.01 * kForce_N);
  std::printf("drive flanks %.3f N, back flanks %.4f N\n", drive / static_cast<double>(n), back / static_cast<double>(n));
}

// FreeCAD's default export (`Mesh.export`, tests/data/freecad) of a z 12 pinion in a z 24 ring,
// m 1 mm, 20°, no backlash, given without teeth or centre distance: their flank fits put zero
// backlash 0.38 µm from the standard 6 mm, within what the fits can tell (±1.16 µm), so the pair
// is placed at the standard distance and says so; there it carries its load on the drive flanks
// alone. (Placed at the fits' own distance, such a pair was pressed together: both flanks loaded.)
TEST(CadGears, AFreecadDefaultExportPairIsPlacedWhereItsFitsCanTellAndLoadsOnlyItsDriveFlanks) {
  const std::string data = std::string(GEARSIM_SOURCE_DIR) + "/tests/data/freecad/";
  const double rb_ring = 0.5 * 24e-3 * std::cos(20 * M_PI / 180);
  const fs::path dir = test::fresh_test_dir();
  std::ofstream(dir / "pair.yaml") << "name: freecad_default_export_pair\nduration_s: 0.15\n"
                                      "solver: {time_step_s: 5.0e-6}\n"
                                      "output: {sample_rate_hz: 2000, per_step_log: false}\n"
                                      "contact: {stiffness_N_per_m_per_m: 1.4e10, damping_ratio: 0.05, friction: 0.05}\n"
                                      "pair:\n"
                                      "  driver: {name: pinion, density_kg_m3: 7850, mesh: {file: "
                                   << data
                                   << "fc_m1_z12_a20_export.stl, unit: mm}}\n"
                                      "  driven: {name: ring, density_kg_m3: 7850, mesh: {file: "
                                   << data
                                   << "fcring_m1_z24_a20_export.stl, unit: mm}}\n"
                                      "motors: [{joint: pinion, target_speed_rad_s: 20, ramp_time_s: 0.05, max_torque_N_m: 1.69245}]\n"
                                      "loads: [{joint: ring, constant_torque_N_m: "
                                   << -kForce_N * rb_ring << "}]\n";
  const Scenario s = input::load_scenario(dir / "pair.yaml", {});
  ASSERT_EQ(s.pair_tables.size(), 1u);
  EXPECT_EQ(s.pair_tables.front().figures.centre_distance_m, 6e-3);
  EXPECT_NE(s.pair_tables.front().placement_note.find("pair 'pinion'–'ring': placed at the standard distance 6 mm"), std::string::npos)
      << s.pair_tables.front().placement_note;
  World w(s);
  sim::RunBounds bounds(s, w);
  double drive = 0, back = 0;
  long n = 0;
  while (w.time_s() < 0.15 - 1e-9) {
    w.step();
    ASSERT_FALSE(bounds.check(w)) << bounds.check(w)->message;
    if (w.time_s() < 0.05) continue;  // the motor's ramp
    for (const ContactSample& c : w.contacts()) (c.geometry.flank_a == Flank::Ccw ? drive : back) += c.normal_force_N;
    ++n;
  }
  EXPECT_NEAR(drive / static_cast<double>(n), kForce_N, 0.01 * kForce_N);
  EXPECT_LT(back / static_cast<double>(n), 0.01 * kForce_N);
  std::printf("%s; drive flanks %.3f N, back flanks %.4f N\n", s.pair_tables.front().placement_note.c_str(), drive / static_cast<double>(n),
              back / static_cast<double>(n));
}

// A planetary set whose sun's flanks are not recognised involutes (FreeCAD's z 12 at 0.02 mm /
// 15°: one chord per flank piece, rms 151 µm) with MCAD's planets z 18 and ring z 48: its centre
// distance cannot be derived and must be given; given, the set is built and the start checks
// judge its meshes, as the pair macro's.
TEST(CadGears, APlanetarySetWithoutRecognisedInvolutesRunsAtItsGivenCentreDistance) {
  const std::string fc = std::string(GEARSIM_SOURCE_DIR) + "/tests/data/freecad/";
  const std::string mcad = std::string(GEARSIM_SOURCE_DIR) + "/tests/data/mcad/";
  auto file = [&](const std::string& extra) {
    const fs::path dir = test::fresh_test_dir();
    std::ofstream(dir / "set.yaml") << "name: mixed_set\nduration_s: 0.01\nsolver: {time_step_s: 1.0e-5}\n"
                                       "planetary:\n"
                                       "  sun: {density_kg_m3: 7850, mesh: {file: "
                                    << fc
                                    << "fc_m1_z12_a20_face4_l0p02a15.stl, unit: mm}}\n"
                                       "  planet: {density_kg_m3: 7850, mesh: {file: "
                                    << mcad
                                    << "mcad_m1_z18_a20_f5_b005.stl, unit: mm}}\n"
                                       "  ring: {density_kg_m3: 7850, mesh: {file: "
                                    << mcad
                                    << "mcadring_m1_z48_a20_f5_b005.stl, unit: mm}}\n"
                                       "  planets: 3\n  carrier: {mass_kg: 0.1, inertia_z_kg_m2: 5.0e-5}\n"
                                    << extra;
    return dir / "set.yaml";
  };
  try {
    input::load_scenario(file(""), {});
    ADD_FAILURE() << "a set without the sun's involutes placed itself";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("planetary.sun: "), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("the centre distance cannot be derived: give centre_distance_m"), std::string::npos) << e.what();
  }
  const Scenario s = input::load_scenario(file("  centre_distance_m: 0.015\n"), {});
  EXPECT_TRUE(s.pair_tables.empty());
  ASSERT_TRUE(s.transmission);
  EXPECT_DOUBLE_EQ(s.transmission->ratio, 5.0);
  for (const BodyDef& b : s.bodies) {
    if (b.name != "planet_1") continue;
    EXPECT_NEAR((b.pose.position_m - 15e-3 * Eigen::Vector3d(std::cos(2 * M_PI / 3), std::sin(2 * M_PI / 3), 0)).norm(), 0.0, 1e-12);
  }
  World w(s);  // the start checks pass: the meshes do not overlap
}

// A planetary set of MCAD meshes (sun z 12, three planets z 18, ring z 48 cut from MCAD's gear
// shape; 0.05 mm backlash each) built by the planetary macro from its members' shapes: the
// planets sit 15 mm out at 0°, 120°, 240°, the ratio is Willis' 1 + 48/12, and the sun–planet
// meshes carry the sun's torque T_c/5 between them (F·r_b,sun summed over the planets).
TEST(CadGears, McadPlanetarySetFromMeshesCarriesTheSunTorqueOverItsPlanets) {
  const double carrier_load_N_m = 1.0;
  const fs::path file = test::mcad_planetary_file(test::fresh_test_dir(), carrier_load_N_m);
  const Scenario s = input::load_scenario(file, {});
  ASSERT_TRUE(s.transmission);
  EXPECT_NEAR(s.transmission->ratio, 5.0, 1e-12);
  // Without centre_distance_m: midway between the two meshes' zero-backlash distances (MCAD's
  // 0.05 mm of backlash each way about m·(z_s + z_p)/2 = 15 mm).
  ASSERT_EQ(s.pair_tables.size(), 2u);
  const double a = s.pair_tables[0].figures.centre_distance_m;
  EXPECT_NEAR(a, 15e-3, 0.1e-3);
  for (int k = 0; k < 3; ++k) {
    const std::string name = "planet_" + std::to_string(k);
    for (const BodyDef& b : s.bodies)
      if (b.name == name) {
        const double angle = 2 * M_PI * k / 3;
        EXPECT_NEAR((b.pose.position_m - a * Eigen::Vector3d(std::cos(angle), std::sin(angle), 0)).norm(), 0.0, 1e-12) << name;
      }
  }
  World w(s);
  sim::RunBounds bounds(s, w);
  std::vector<double> net(3, 0.0);
  long n = 0;
  for (int i = 0; i < 3000; ++i) {
    w.step();
    ASSERT_FALSE(bounds.check(w)) << bounds.check(w)->message;
    if (w.time_s() < 0.015) continue;  // the ramps end at 10 ms
    for (const ContactSample& c : w.contacts()) {
      const GearPairInfo& p = w.gear_pairs()[static_cast<std::size_t>(c.pair)];
      if (p.body_a != "sun") continue;
      net[static_cast<std::size_t>(p.body_b.back() - '0')] += (c.geometry.flank_a == Flank::Ccw ? 1 : -1) * c.normal_force_N;
    }
    ++n;
  }
  const double rb_sun = 0.5 * 12e-3 * std::cos(20 * M_PI / 180), expected = carrier_load_N_m / 5 / rb_sun;  // 35.5 N
  double total = 0;
  for (double f : net) total += f / static_cast<double>(n);
  // 3 %, the figure (measured over 0.1 s from the CLI: 0.05 % off, each planet within 1.3 %
  // of a third: a rigid carrier shares by the meshes' phases only).
  EXPECT_NEAR(total, expected, 0.03 * expected);
  for (double f : net) EXPECT_NEAR(f / static_cast<double>(n), expected / 3, 0.1 * expected / 3);
}

TEST(CadGears, ContactsOfMeshFlanksAreTheDeeperOfTheContinuedAndTheSearched) {
  // verify.continued_search on CAD meshes: the deeper of the continued maximum and the
  // stateless search's. The MCAD planetary set with it on (the default) and off runs the same
  // until a step where a continued maximum is the deeper: there, from the same poses, every
  // contact is at least as deep as without, one deeper (the runs part after that). Contact onsets
  // are not located here: the near pairs' gaps, which place a split, come from the continued or
  // the searched maximum too, and would part the runs before the contacts differ.
  const fs::path file = test::mcad_planetary_file(test::fresh_test_dir(), 1.0);
  World on(input::load_scenario(file, {"verify.locate_contact_onset=false"})),
      off(input::load_scenario(file, {"verify.continued_search=false", "verify.locate_contact_onset=false"}));
  int parted = -1;
  for (int i = 0; i < 3000 && parted < 0; ++i) {
    on.step();
    off.step();
    ASSERT_EQ(on.contacts().size(), off.contacts().size()) << "step " << i;
    for (std::size_t c = 0; c < on.contacts().size(); ++c) {
      const contact::ToothContact &u = on.contacts()[c].geometry, &v = off.contacts()[c].geometry;
      ASSERT_EQ(u.tooth_a, v.tooth_a);
      ASSERT_EQ(u.tooth_b, v.tooth_b);
      ASSERT_GE(u.depth_m, v.depth_m) << "step " << i;
      if (u.depth_m > v.depth_m) parted = i;
    }
  }
  EXPECT_GE(parted, 0) << "no step where a continued maximum was the deeper";
}

TEST(CadGears, TheTrapezoidClosedIntegratorKeepsTheRattlingMcadSetWithinItsEnergyBound) {
  // solver.integrator trapezoid_closed (θ = ½ but in steps where a tooth contact starts): the
  // MCAD planetary set, whose teeth separate and strike through their backlash, runs 0.03 s
  // inside its physical bounds, with contact onsets located (the default) or not. A fixed θ = ½
  // with onsets found a step late gains 2.3 mJ beyond the motors' work (each new contact's
  // ½·k·δ₀²) and is stopped (docs/solver.md); with onsets located it stays inside too: a contact
  // that starts at 1 % of a step's approach brings next to no such energy.
  const fs::path file = test::mcad_planetary_file(test::fresh_test_dir(), 1.0);
  auto stays_inside = [&](const std::vector<std::string>& set) {
    const Scenario s = input::load_scenario(file, set);
    World w(s);
    sim::RunBounds bounds(s, w);
    for (int i = 0; i < 3000; ++i) {
      w.step();
      if (const auto out = bounds.check(w)) {
        std::printf("  %s ...: stopped at step %d: %s\n", set[0].c_str(), i, out->message.c_str());
        return false;
      }
    }
    return true;
  };
  EXPECT_TRUE(stays_inside({"solver.integrator=trapezoid_closed"}));
  EXPECT_TRUE(stays_inside({"solver.integrator=trapezoid_closed", "verify.locate_contact_onset=false"}));
  EXPECT_TRUE(stays_inside({"solver.theta=0.5"}));
  EXPECT_FALSE(stays_inside({"solver.theta=0.5", "verify.locate_contact_onset=false"}))
      << "a fixed θ = ½ with late onsets should leave the bounds here (what the per-step choice avoids)";
}

TEST(CadGears, AHalfPitchToothLayoutErrorIsRefusedWithTheToothTheMeshShows) {
  // tooth0 15° on the 12-tooth pinion (pitch 30°): the layout's sector boundaries through the teeth.
  const std::string m = refusal(", teeth: 12, tooth0_deg: 15", "", 18e-3);
  EXPECT_NE(m.find("driver.mesh.tooth0_deg"), std::string::npos) << m;
  EXPECT_NE(m.find("50 % of a pitch"), std::string::npos) << m;
  EXPECT_NE(m.find("tooth 0 at"), std::string::npos) << m;
}

TEST(CadGears, ARoundedToothZeroNamesTheToothAndTakesTheMeshAngle) {
  // 0.3° off MCAD's tooth 0 (1 % of the pitch): within kTooth0Tolerance (2 %), so it names tooth
  // 0; the angle used is the mesh's (0.3° would phase the pair 31 µm off at the pinion's pitch
  // circle, more than the 25 µm of backlash on each side).
  EXPECT_EQ(refusal(", teeth: 12, tooth0_deg: 0.3", "", 18e-3), "");
  EXPECT_EQ(refusal(", teeth: 12, tooth0_deg: 30.3", "", 18e-3), "");
  const Scenario s = mcad_pair(", teeth: 12, tooth0_deg: 30.3", "", 18e-3);
  ASSERT_TRUE(s.bodies[0].mesh && s.bodies[0].mesh->teeth && s.bodies[0].mesh->recognised);
  EXPECT_FALSE(s.bodies[0].mesh->teeth_recognised);
  // Tooth 0 is the tooth centred at 30° in the file (MCAD's teeth are centred on multiples of 30°).
  EXPECT_NEAR(s.bodies[0].mesh->teeth->tooth0_angle_rad, s.bodies[0].mesh->recognised->tooth0_angle_rad + M_PI / 6, 1e-12);
}

TEST(CadGears, ACentreDistanceTooSmallIsRefusedWithTheOverlap) {
  // 0.2 mm short of the standard 18 mm: the backlash (0.05 mm along the pitch circles) is used up.
  const std::string m = refusal("", "", 17.8e-3);
  EXPECT_NE(m.find("centre_distance_m"), std::string::npos) << m;
  EXPECT_NE(m.find("overlap by"), std::string::npos) << m;
  EXPECT_NE(m.find("zero backlash at"), std::string::npos) << m;
}

TEST(CadGears, AMillimetreFileReadAsMetresIsRefusedNamingTheUnit) {
  // Gears 12 m across: no standard module that large, so the module is the tooth depth / 2.25
  // (MCAD's depth is 2.2906 modules: 7 − 4.7094 mm at z 12), about 1.018 m.
  const std::string m = refusal("", "", 18e-3, "m");
  EXPECT_NE(m.find("driver.mesh.unit"), std::string::npos) << m;
  EXPECT_NE(m.find("module is about 1018"), std::string::npos) << m;
  EXPECT_NE(m.find("read as mm it would be about 1.018"), std::string::npos) << m;
}

TEST(CadGears, AWrongToothCountIsRefusedWithTheCountTheMeshShows) {
  const std::string m = refusal(", teeth: 13", "", 18e-3);
  EXPECT_NE(m.find("driver.mesh.teeth"), std::string::npos) << m;
  EXPECT_NE(m.find("13 teeth given, the mesh shows 12"), std::string::npos) << m;
}

TEST(CadGears, MeshesWithoutTeethOrCentreDistanceSetThemselvesUp) {
  const Scenario s = mcad_pair("", "", 0.0);
  ASSERT_EQ(s.bodies.size(), 2u);
  for (const BodyDef& b : s.bodies) {
    ASSERT_TRUE(b.mesh && b.mesh->teeth && b.mesh->recognised);
    EXPECT_TRUE(b.mesh->teeth_recognised);
    // MCAD's tooth 0 lies on +x.
    EXPECT_NEAR(std::remainder(b.mesh->teeth->tooth0_angle_rad, 2 * M_PI / b.mesh->teeth->teeth), 0.0, 1e-5);
    EXPECT_DOUBLE_EQ(b.mesh->recognised->module_m, 1e-3);
    EXPECT_NEAR(b.mesh->recognised->pressure_angle_rad, 20 * M_PI / 180, 1e-12);
  }
  EXPECT_EQ(s.bodies[0].mesh->teeth->teeth, 12);
  EXPECT_EQ(s.bodies[1].mesh->teeth->teeth, 24);
  ASSERT_EQ(s.pair_tables.size(), 1u);
  const InvolutePair& p = s.pair_tables[0].figures;
  // MCAD's backlash (involute_gears.scad: half_thick_angle = (360/z − backlash_angle)/4, the
  // backlash as an arc on the pitch circle) thins each tooth by half of it, 0.025 mm: 0.05 mm of
  // circular backlash for the pair at 18 mm, 0.05·cos 20° along the line of action. The
  // zero-backlash distance closes it: Δa = j_n / (2 sin α_w) to first order, 0.069 mm.
  const InvolutePair at18 =
      involute_pair(involute_teeth(*s.bodies[0].mesh->recognised), involute_teeth(*s.bodies[1].mesh->recognised), 18e-3, "test");
  EXPECT_NEAR(at18.normal_backlash_m, 0.05e-3 * std::cos(20 * M_PI / 180), 1e-6);
  EXPECT_NEAR(p.zero_backlash_centre_distance_m, 18e-3 - at18.normal_backlash_m / (2 * std::sin(20 * M_PI / 180)), 2e-6);
  // Placed not tighter than the flank fits can tell (place_pair): their tolerance (MCAD's vertices
  // lie on the involutes: ~0.01 µm per flank; base radii within 0.5 µm of m·z·cos α/2) left as
  // backlash: 2 sin α_w times the distance moved out.
  EXPECT_GT(p.zero_backlash_tolerance_m, 0.0);
  EXPECT_LT(p.zero_backlash_tolerance_m, 1.5e-6);
  EXPECT_NEAR(p.centre_distance_m - p.zero_backlash_centre_distance_m, p.zero_backlash_tolerance_m, 1e-15);
  EXPECT_NEAR(p.normal_backlash_m, 2 * std::sin(p.operating_pressure_angle_rad) * p.zero_backlash_tolerance_m, 1e-10);
  EXPECT_NE(s.pair_tables[0].placement_note.find("outside the flank fits' zero-backlash distance"), std::string::npos)
      << s.pair_tables[0].placement_note;
  // Transverse contact ratio at 18 mm from the nominal tip and base circles: 1.511.
  const double rb1 = 6e-3 * std::cos(20 * M_PI / 180), rb2 = 2 * rb1, pb = M_PI * 1e-3 * std::cos(20 * M_PI / 180);
  const double eps = (std::sqrt(49e-6 - rb1 * rb1) + std::sqrt(169e-6 - rb2 * rb2) - 18e-3 * std::sin(20 * M_PI / 180)) / pb;
  EXPECT_NEAR(at18.contact_ratio, eps, 0.01);
}

}  // namespace test_cad_gears
}  // namespace gearsim::physics

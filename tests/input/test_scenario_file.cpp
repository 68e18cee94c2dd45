// Scenario files: the shipped scenarios expand into the bodies and joints physics needs, placed
// so that every mesh engages; --set overrides edit the file before validation; every bad input
// is refused with the file and the key.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

#include "input/gear_train.hpp"
#include "input/scenario_file.hpp"
#include "input/scenario_record.hpp"
#include "core/errors.hpp"
#include "geometry/constants.hpp"
#include "tests/support/asset_scenario.hpp"

namespace gearsim::input {
namespace test_scenario_file {

namespace fs = std::filesystem;
using gearsim::constants::kPi;
const fs::path kSource(GEARSIM_SOURCE_DIR);
const fs::path kScenarios = kSource / "assets/scenarios";

const physics::Scenario& paper() {
  static const physics::Scenario s = load_scenario(kScenarios / "paper_dynamics.yaml");
  return s;
}

const physics::BodyDef& body(const physics::Scenario& s, const std::string& name) {
  for (const physics::BodyDef& b : s.bodies)
    if (b.name == name) return b;
  throw std::runtime_error("no body " + name);
}
const physics::JointDef& joint(const physics::Scenario& s, const std::string& name) {
  for (const physics::JointDef& j : s.joints)
    if (j.name == name) return j;
  throw std::runtime_error("no joint " + name);
}

// Rotation of a body about +z (its poses here are rotations about z only).
double angle_z(const physics::BodyDef& b) {
  const Eigen::Vector3d x = b.pose.orientation * Eigen::Vector3d::UnitX();
  return std::atan2(x.y(), x.x());
}
double frac(double v) { return v - std::floor(v); }
// Position, in teeth, of polar angle `at` on body b (0 = a tooth centre, ½ = a gap centre).
double tooth_fraction(const physics::BodyDef& b, double at) {
  return frac((at - b.gear->tooth0_angle_rad - angle_z(b)) * b.gear->teeth / (2 * kPi));
}
// Distance of a fraction from ½ (a tooth centred in the mating gap), in teeth.
double off_half(double f) { return std::abs(frac(f) - 0.5); }

TEST(ScenarioFile, PaperScenarioExpandsToSunThreePlanetsRingAndCarrier) {
  std::vector<std::string> names;
  for (const physics::BodyDef& b : paper().bodies) names.push_back(b.name);
  EXPECT_EQ(names, (std::vector<std::string>{"sun", "planet_0", "planet_1", "planet_2", "ring", "carrier"}));
}

TEST(ScenarioFile, PaperPlanetCentresSit30mmFromTheAxisAt0_120_240Degrees) {
  // Centre distance m·(z_s + z_p)/2 = 1 mm · 60/2 = 30 mm; 1e-12 m allows the cos/sin rounding.
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector3d c = body(paper(), "planet_" + std::to_string(k)).pose.position_m;
    const double beta = 2 * kPi * k / 3;
    EXPECT_NEAR(c.x(), 0.030 * std::cos(beta), 1e-12) << k;
    EXPECT_NEAR(c.y(), 0.030 * std::sin(beta), 1e-12) << k;
    EXPECT_EQ(c.z(), 0.0);
    EXPECT_EQ(joint(paper(), "planet_" + std::to_string(k)).parent, "carrier");
    EXPECT_EQ(joint(paper(), "planet_" + std::to_string(k)).pivot_m, c);
  }
}

TEST(ScenarioFile, PaperPlanetZeroCarriesThe43MicrometreFlankErrorAndTheOthersNone) {
  const GearSpec& g0 = *body(paper(), "planet_0").gear;
  ASSERT_EQ(g0.errors.flank_offsets.size(), 1u);
  EXPECT_EQ(g0.errors.flank_offsets[0].tooth, 0);
  EXPECT_EQ(g0.errors.flank_offsets[0].flank, Flank::Ccw);
  EXPECT_DOUBLE_EQ(g0.errors.flank_offsets[0].normal_offset_m, -43e-6);
  EXPECT_TRUE(body(paper(), "planet_1").gear->errors.flank_offsets.empty());
  EXPECT_TRUE(body(paper(), "planet_2").gear->errors.flank_offsets.empty());
}

TEST(ScenarioFile, PaperRingIsFixedAndCarrierIsShapelessWithTheStatedMass) {
  EXPECT_TRUE(body(paper(), "ring").fixed);
  const physics::BodyDef& c = body(paper(), "carrier");
  EXPECT_FALSE(c.gear || c.mesh);
  EXPECT_DOUBLE_EQ(*c.mass_kg, 0.3);
  EXPECT_DOUBLE_EQ(c.principal_inertia_kg_m2->z(), 2e-4);
  EXPECT_DOUBLE_EQ(*body(paper(), "sun").density_kg_m3, 7580);  // from the gear-set spec
}

TEST(ScenarioFile, PaperTransmissionIsWillisRatioFiveFromSunToCarrier) {
  ASSERT_TRUE(paper().transmission);
  EXPECT_EQ(paper().transmission->input_joint, "sun");
  EXPECT_EQ(paper().transmission->output_joint, "carrier");
  EXPECT_DOUBLE_EQ(paper().transmission->ratio, 1.0 + 96.0 / 24.0);
}

TEST(ScenarioFile, PaperSunFloatsInARadialBearing) {
  const physics::JointDef& sun = joint(paper(), "sun");
  ASSERT_TRUE(sun.bearing);
  EXPECT_DOUBLE_EQ(sun.bearing->radial_stiffness_N_per_m, 1e7);
  EXPECT_DOUBLE_EQ(sun.bearing->radial_damping_N_s_per_m, 50);
  EXPECT_FALSE(joint(paper(), "carrier").bearing);
}

TEST(ScenarioFile, PaperRunSettingsAreThoseStated) {
  EXPECT_DOUBLE_EQ(paper().duration_s, 1.0);
  EXPECT_DOUBLE_EQ(paper().solver.time_step_s, 2e-5);
  EXPECT_DOUBLE_EQ(paper().output.sample_rate_hz, 2000);
  ASSERT_EQ(paper().motors.size(), 1u);
  EXPECT_DOUBLE_EQ(paper().motors[0].target_speed_rad_s, 104.7);
  ASSERT_EQ(paper().loads.size(), 1u);
  EXPECT_EQ(paper().loads[0].joint, "carrier");
  EXPECT_DOUBLE_EQ(paper().loads[0].constant_torque_N_m, -20);
}

TEST(ScenarioFile, EveryPaperPlanetToothSitsCentredInASunGapAndARingGap) {
  // External mesh on the line of centres: f_sun + f_planet ≡ ½; internal: f_ring − f_planet ≡ ½.
  // 1e-9 teeth: the placement is exact up to rounding of angles of order 2π.
  const physics::BodyDef &sun = body(paper(), "sun"), &ring = body(paper(), "ring");
  for (int k = 0; k < 3; ++k) {
    const physics::BodyDef& p = body(paper(), "planet_" + std::to_string(k));
    const double beta = 2 * kPi * k / 3;
    EXPECT_NEAR(off_half(tooth_fraction(sun, beta) + tooth_fraction(p, beta + kPi)), 0.0, 1e-9) << k;
    EXPECT_NEAR(off_half(tooth_fraction(ring, beta) - tooth_fraction(p, beta)), 0.0, 1e-9) << k;
  }
}

TEST(ScenarioFile, HealthyTwinDiffersOnlyByPlanetZerosErrors) {
  nlohmann::ordered_json faulty = scenario_json(paper());
  const physics::Scenario twin = load_scenario(kScenarios / "paper_dynamics_healthy.yaml");
  EXPECT_TRUE(body(twin, "planet_0").gear->errors.flank_offsets.empty());
  nlohmann::ordered_json healthy = scenario_json(twin);
  for (auto* j : {&faulty, &healthy}) {
    j->erase("name");
    j->erase("source");
  }
  // planet_0 (bodies[1]) is gear 'planet_faulty' in one and 'planet' in the other.
  auto& g_faulty = faulty["bodies"][1]["gear"];
  const auto& g_healthy = healthy["bodies"][1]["gear"];
  EXPECT_NE(g_faulty["errors"], g_healthy["errors"]);
  g_faulty["errors"] = g_healthy["errors"];
  g_faulty["name"] = g_healthy["name"];
  // The planetary macro's record of the planet gears: the same difference.
  auto& p_faulty = faulty["planetary"]["planet_gears"][0];
  EXPECT_NE(p_faulty["errors"], healthy["planetary"]["planet_gears"][0]["errors"]);
  p_faulty = healthy["planetary"]["planet_gears"][0];
  EXPECT_EQ(faulty, healthy);
}

TEST(ScenarioFile, PaperTeRunIsSlowUnloadedAndRigidlyHinged) {
  const physics::Scenario s = load_scenario(kScenarios / "paper_te_rigid.yaml");
  EXPECT_DOUBLE_EQ(s.motors.at(0).target_speed_rad_s, 3.14);
  EXPECT_DOUBLE_EQ(s.output.sample_rate_hz, 5000);
  EXPECT_TRUE(s.loads.empty());
  EXPECT_FALSE(joint(s, "sun").bearing);
  EXPECT_EQ(body(s, "planet_0").gear->errors.flank_offsets.size(), 1u);
}

TEST(ScenarioFile, SpurPairResolvesItsMeshFilesAndCentreDistance) {
  const physics::Scenario s = load_scenario(kScenarios / "spur_pair.yaml");
  const physics::BodyDef &pinion = body(s, "pinion"), &wheel = body(s, "wheel");
  EXPECT_EQ(pinion.mesh->path, (kSource / "assets/gears/spur_pair/pinion.stl").lexically_normal());
  EXPECT_EQ(wheel.mesh->path, (kSource / "assets/gears/spur_pair/wheel.stl").lexically_normal());
  EXPECT_TRUE(fs::is_regular_file(wheel.mesh->path));
  EXPECT_EQ(pinion.mesh->unit, LengthUnit::Millimetre);
  EXPECT_EQ(pinion.mesh->teeth->teeth, 20);
  EXPECT_EQ(wheel.mesh->teeth->teeth, 31);
  EXPECT_DOUBLE_EQ((wheel.pose.position_m - pinion.pose.position_m).norm(), 0.051);  // m·(z1+z2)/2
  EXPECT_EQ(joint(s, "wheel").pivot_m, wheel.pose.position_m);
}

TEST(ScenarioFile, SpurPairTurnsOppositeWaysSoItsRatioIsNegative) {
  const physics::Scenario s = load_scenario(kScenarios / "spur_pair.yaml");
  ASSERT_TRUE(s.transmission);
  EXPECT_EQ(s.transmission->input_joint, "pinion");
  EXPECT_DOUBLE_EQ(s.transmission->ratio, -31.0 / 20.0);
  // The wheel's gap at the pitch point (its −x side) holds the pinion's tooth 0 (on +x).
  const physics::BodyDef& w = body(s, "wheel");
  const double f = frac((kPi - w.mesh->teeth->tooth0_angle_rad - angle_z(w)) * 31 / (2 * kPi));
  EXPECT_NEAR(off_half(f), 0.0, 1e-9);
}

// An internal pair through the pair macro: the paper's planet driving its relieved ring (the
// standard-addendum ring cuts the planet's fillet by 5.8 µm: `gearsim gears` finds it too).
physics::Scenario planet_ring_pair(const std::string& driver, const std::string& driven) {
  const fs::path dir = test::fresh_test_dir();
  const std::string spec = (kSource / "assets/specs/paper_gearset.yaml").string();
  auto member = [&](const std::string& gear) { return "{name: " + gear + ", gear_from: {spec: " + spec + ", gear: " + gear + "}}"; };
  std::ofstream(dir / "ring_pair.yaml") << "name: ring_pair\nduration_s: 0.01\npair:\n  driver: " << member(driver)
                                        << "\n  driven: " << member(driven) << "\nmotors: [{joint: " << driver
                                        << ", target_speed_rad_s: 20, max_torque_N_m: 10}]\n";
  return load_scenario(dir / "ring_pair.yaml");
}

TEST(ScenarioFile, InternalPairPutsTheRingAtTheOriginAndTurnsBothTheSameWay) {
  for (const auto& [driver, driven] : {std::pair{"planet", "ring_relieved"}, std::pair{"ring_relieved", "planet"}}) {
    const physics::Scenario s = planet_ring_pair(driver, driven);
    const physics::BodyDef &planet = body(s, "planet"), &ring = body(s, "ring_relieved");
    EXPECT_DOUBLE_EQ(ring.pose.position_m.norm(), 0.0);
    // m·(z_ring − z_planet)/2, both unshifted: 30 mm on +x.
    EXPECT_NEAR((planet.pose.position_m - Eigen::Vector3d(0.030, 0, 0)).norm(), 0.0, 1e-15);
    ASSERT_TRUE(s.transmission);
    EXPECT_DOUBLE_EQ(s.transmission->ratio, std::string(driver) == "planet" ? 96.0 / 36 : 36.0 / 96) << driver;
    // At the pitch point (+x of both centres) a planet tooth sits in a ring gap:
    // f_ring − f_planet ≡ ½.
    EXPECT_NEAR(off_half(tooth_fraction(ring, 0.0) - tooth_fraction(planet, 0.0)), 0.0, 1e-9) << driver;
  }
}

// The analysis sees a ring meshing one pinion about the ground as a gear pair (not a planetary
// set without planets): mesh frequency z_driver·ω/2π.
TEST(ScenarioFile, AnInternalPairIsAnalysedAsAGearPair) {
  const GearTrain train = gear_train_of(planet_ring_pair("planet", "ring_relieved"), {{"planet", "ring_relieved"}});
  ASSERT_EQ(train.stages.size(), 1u);
  const TrainStage& t = train.stages.front();
  EXPECT_FALSE(t.planetary);
  EXPECT_TRUE(t.internal_pair);
  EXPECT_EQ(t.driver, "planet");
  EXPECT_EQ(t.driven, "ring_relieved");
  EXPECT_NEAR(train.frequencies.mesh_hz, 36 * 20 / (2 * kPi), 1e-9);
  // A ring turning the same way as its pinion, at z_p/z_r of its speed.
  EXPECT_NEAR(t.ratio, 96.0 / 36, 1e-12);
  std::vector<Mesh> meshes;
  for (const char* p : {"planet_0", "planet_1", "planet_2"}) meshes.push_back({"sun", p}), meshes.push_back({p, "ring"});
  const GearTrain set = gear_train_of(paper(), meshes);
  ASSERT_EQ(set.stages.size(), 1u);
  EXPECT_TRUE(set.stages.front().planetary);
  EXPECT_EQ(set.stages.front().fixed, "ring");
  EXPECT_NEAR(set.stages.front().ratio, 5.0, 1e-12);  // sun in, carrier out: 1 + z_r/z_s
}

// The planetary macro with members given as shapes (here gear_from: the paper's gears): the
// same bodies, placements and ratio as with their names; a name beside shapes, or an external
// gear as the ring, is refused.
std::string planetary_from_shapes(const std::string& sun, const std::string& ring) {
  const std::string spec = (kSource / "assets/specs/paper_gearset.yaml").string();
  auto member = [&](const std::string& gear) { return "{gear_from: {spec: " + spec + ", gear: " + gear + "}}"; };
  return "name: shapes\nduration_s: 0.01\nplanetary:\n  sun: " + sun + "\n  planet: " + member("planet") +
         "\n  ring: " + (ring.empty() ? member("ring_relieved") : ring) +
         "\n  planets: 3\n"
         "  carrier: {mass_kg: 0.3, inertia_z_kg_m2: 2.0e-4}\n";
}

physics::Scenario load_text(const std::string& text) {
  const fs::path file = test::fresh_test_dir() / "s.yaml";
  std::ofstream(file) << text;
  return load_scenario(file);
}

TEST(ScenarioFile, PlanetaryFromShapesPlacesItsMembersAsFromNames) {
  const std::string spec = (kSource / "assets/specs/paper_gearset.yaml").string();
  const physics::Scenario s = load_text(planetary_from_shapes("{gear_from: {spec: " + spec + ", gear: sun}}", ""));
  const physics::Scenario& named = paper();  // the paper scenario: sun, planet, ring_relieved by name
  for (const char* name : {"sun", "planet_0", "planet_1", "planet_2", "ring"}) {
    EXPECT_NEAR((body(s, name).pose.position_m - body(named, name).pose.position_m).norm(), 0.0, 1e-12) << name;
    EXPECT_NEAR(std::remainder(angle_z(body(s, name)) - angle_z(body(named, name)), 2 * kPi), 0.0, 1e-12) << name;
  }
  ASSERT_TRUE(s.transmission);
  EXPECT_DOUBLE_EQ(s.transmission->ratio, 5.0);
}

TEST(ScenarioFile, PlanetaryMembersAreAllNamesOrAllShapesAndTheRingIsInternal) {
  const std::string spec = (kSource / "assets/specs/paper_gearset.yaml").string();
  auto refusal = [&](const std::string& text) {
    try {
      load_text(text);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  std::string m = refusal(planetary_from_shapes("sun", ""));
  EXPECT_NE(m.find("all as gear names of `spec`, or all as shapes"), std::string::npos) << m;
  m = refusal(planetary_from_shapes("{gear_from: {spec: " + spec + ", gear: sun}}", "{gear_from: {spec: " + spec + ", gear: sun}}"));
  EXPECT_NE(m.find("the ring must be an internal gear"), std::string::npos) << m;
}

TEST(ScenarioFile, TwoInternalGearsAreNoPair) {
  try {
    planet_ring_pair("ring", "ring_relieved");
    FAIL() << "two rings accepted as a pair";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("two internal gears cannot mesh"), std::string::npos) << e.what();
  }
}

// --- Overrides ---------------------------------------------------------------------------------

// Overrides are tested on the spur pair: its load is fast (the planetary macro runs the mesh
// interference analysis, ~0.5 s).
const fs::path kSpur = kScenarios / "spur_pair.yaml";

TEST(ScenarioOverrides, SetReplacesTopLevelAndNestedValues) {
  const physics::Scenario s = load_scenario(kSpur, {"duration_s=0.1", "solver.time_step_s=1e-5"});
  EXPECT_DOUBLE_EQ(s.duration_s, 0.1);
  EXPECT_DOUBLE_EQ(s.solver.time_step_s, 1e-5);
}

TEST(ScenarioOverrides, SetReachesListItemsAndNestedMappings) {
  const physics::Scenario s = load_scenario(kSpur, {"motors[0].target_speed_rad_s=10", "pair.driven.density_kg_m3=7000"});
  EXPECT_DOUBLE_EQ(s.motors[0].target_speed_rad_s, 10);
  EXPECT_DOUBLE_EQ(*body(s, "wheel").density_kg_m3, 7000);
}

TEST(ScenarioOverrides, SetOfAKnownOptionalKeyCreatesIt) {
  // Neither key is in the file: transmission.ratio overrides the pair's −1.55 alone; origin_m
  // moves the whole pair.
  const physics::Scenario s = load_scenario(kSpur, {"transmission.ratio=-1.5", "pair.origin_m=[0, 0, 0.1]"});
  EXPECT_DOUBLE_EQ(s.transmission->ratio, -1.5);
  EXPECT_EQ(s.transmission->input_joint, "pinion");
  EXPECT_DOUBLE_EQ(body(s, "pinion").pose.position_m.z(), 0.1);
}

std::string override_error(const std::vector<std::string>& overrides) {
  try {
    load_scenario(kScenarios / "paper_te_rigid.yaml", overrides);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(ScenarioOverrides, SetOfAnUnknownKeyPathIsAnErrorNamingIt) {
  const std::string e = override_error({"solver.step_size_s=1e-5"});
  EXPECT_NE(e.find("paper_te_rigid.yaml"), std::string::npos) << e;
  EXPECT_NE(e.find("solver.step_size_s: unknown key"), std::string::npos) << e;
  EXPECT_NE(e.find("--set 'solver.step_size_s=1e-5'"), std::string::npos) << e;
}

TEST(ScenarioOverrides, SetReachesNumericMappingKeysOfTheMacros) {
  // faulty_planets.N names planet N's gear; the check fails before the (slow) mesh analysis.
  const std::string e = override_error({"planetary.faulty_planets.5=planet"});
  EXPECT_NE(e.find("planetary.faulty_planets.5: expected a planet index 0..2"), std::string::npos) << e;
  EXPECT_NE(e.find("--set 'planetary.faulty_planets.5=planet'"), std::string::npos) << e;
}

TEST(ScenarioOverrides, SetOfAWrongValueNamesTheOverride) {
  const std::string e = override_error({"duration_s=long"});
  EXPECT_NE(e.find("duration_s: expected a number"), std::string::npos) << e;
  EXPECT_NE(e.find("--set 'duration_s=long'"), std::string::npos) << e;
}

TEST(ScenarioOverrides, AKeySetTwiceNamesTheOverrideWhoseValueStands) {
  // The later --set replaces the earlier: a wrong value there is the later one's.
  const std::string e = override_error({"duration_s=0.1", "duration_s=long"});
  EXPECT_NE(e.find("duration_s: expected a number, got 'long'"), std::string::npos) << e;
  EXPECT_NE(e.find("--set 'duration_s=long'"), std::string::npos) << e;
  EXPECT_EQ(e.find("--set 'duration_s=0.1'"), std::string::npos) << e;
}

TEST(ScenarioOverrides, MalformedOverrideIsAnErrorQuotingIt) {
  EXPECT_NE(override_error({"duration_s"}).find("--set 'duration_s': expected key.path=value"), std::string::npos);
  EXPECT_NE(override_error({"motors[x].joint=sun"}).find("--set 'motors[x].joint=sun'"), std::string::npos);
  EXPECT_NE(override_error({"motors[4].joint=sun"}).find("has 1 items, no item 4"), std::string::npos);
  EXPECT_NE(override_error({"duration_s.x=1"}).find("'duration_s' does not hold a mapping"), std::string::npos);
}

}  // namespace test_scenario_file
}  // namespace gearsim::input

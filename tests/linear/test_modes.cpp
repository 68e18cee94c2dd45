// The linearised model and its modes: Lin & Parker's structural results on their example system
// (rotational modes with planets alike, translational modes of multiplicity two, planet modes of
// multiplicity N − 3, one rigid-body mode), the analytic frequency of a torsional spur pair, the
// paper gearbox's symmetry, mass normalisation and energy shares, and the Campbell rates.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <numbers>

#include "input/scenario_file.hpp"
#include "linear/campbell.hpp"
#include "linear/lumped_model.hpp"
#include "linear/modes.hpp"
#include "physics/world.hpp"
#include "tests/support/asset_scenario.hpp"
#include "tests/support/mcad_planetary.hpp"

namespace gearsim {
namespace test_modes {

using linear::ModeType;

struct Solved {
  physics::Scenario scenario;
  std::unique_ptr<physics::World> world;
  linear::LumpedModel model;
  linear::ModalAnalysis modes;
};

Solved solve(const std::filesystem::path& file, const std::vector<std::string>& sets = {}) {
  Solved s;
  s.scenario = input::load_scenario(file, sets);
  s.world = std::make_unique<physics::World>(s.scenario);
  s.model = linear::build_lumped_model(*s.world, s.scenario, {});
  s.modes = linear::solve_modes(s.model);
  return s;
}

std::filesystem::path asset(const std::string& name) { return std::filesystem::path(GEARSIM_SOURCE_DIR) / "assets/scenarios" / name; }

// Counts of modes (not groups) by type and multiplicity.
std::map<std::pair<ModeType, int>, int> census(const linear::ModalAnalysis& a) {
  std::map<std::pair<ModeType, int>, int> c;
  for (const linear::ModeGroup& g : a.groups) c[{g.type, g.multiplicity}] += g.multiplicity;
  return c;
}

// Lin & Parker 1999: with N ≥ 3 equally spaced planets and three planar coordinates per member,
// 3(N + 3) modes: 6 rotational (one of them the rigid-body mode here, sun and carrier free),
// 6 translational pairs (12), and 3 planet modes each of multiplicity N − 3.
void expect_lin_parker_structure(int planets) {
  const Solved s = solve(asset("lin_parker_1999.yaml"), {"planetary.planets=" + std::to_string(planets)});
  const linear::ModalAnalysis& a = s.modes;
  ASSERT_EQ(static_cast<int>(a.modes.size()), 3 * (planets + 3));
  const auto c = census(a);
  EXPECT_EQ((c.count({ModeType::Rigid, 1}) ? c.at({ModeType::Rigid, 1}) : 0), 1);
  EXPECT_EQ(c.at({ModeType::Rotational, 1}), 5);
  EXPECT_EQ(c.at({ModeType::Translational, 2}), 12);
  if (planets > 3) {
    EXPECT_EQ(c.at({ModeType::Planet, planets - 3}), 3 * (planets - 3));
  }
  EXPECT_EQ(static_cast<int>(c.size()), planets > 3 ? 4 : 3) << "no mode of any other type or multiplicity";
  for (const linear::ModeGroup& g : a.groups) {
    if (g.type == ModeType::Rotational) {
      EXPECT_TRUE(a.modes[g.modes.front()].planets_alike) << g.frequency_hz << " Hz";
    }
  }
}

TEST(LinParker, ThreePlanetsHaveRotationalAndDoubleTranslationalModesOnly) { expect_lin_parker_structure(3); }
TEST(LinParker, FourPlanetsAddPlanetModesOfMultiplicityOne) { expect_lin_parker_structure(4); }
TEST(LinParker, FivePlanetsHavePlanetModesOfMultiplicityTwo) {
  // The five-planet variant's own gears (planets of five cannot have the three-planet gears' size).
  const Solved s = solve(asset("lin_parker_1999_5planets.yaml"));
  const auto c = census(s.modes);
  EXPECT_EQ(c.at({ModeType::Planet, 2}), 6);
  EXPECT_EQ(c.at({ModeType::Translational, 2}), 12);
  EXPECT_EQ(c.at({ModeType::Rotational, 1}), 5);
  EXPECT_EQ(c.at({ModeType::Rigid, 1}), 1);
}

// The member radii do not enter Lin & Parker's model beyond u = r·θ: the five-planet file's
// other gears, with inertias scaled by their radii, give the three-planet frequencies at N = 3.
TEST(LinParker, FrequenciesDependOnTheirParametersNotOnTheGearSizes) {
  const Solved a = solve(asset("lin_parker_1999.yaml"));
  const Solved b = solve(asset("lin_parker_1999_5planets.yaml"), {"planetary.planets=3"});
  ASSERT_EQ(a.modes.modes.size(), b.modes.modes.size());
  for (std::size_t i = 0; i < a.modes.modes.size(); ++i)
    EXPECT_NEAR(a.modes.modes[i].frequency_hz, b.modes.modes[i].frequency_hz, 1e-4 * (1 + a.modes.modes[i].frequency_hz)) << i;
}

TEST(LinParker, ShapesAreMassNormalisedAndEnergySharesSumToOne) {
  const Solved s = solve(asset("lin_parker_1999.yaml"));
  const linear::LumpedModel& m = s.model;
  for (std::size_t i = 0; i < s.modes.modes.size(); ++i) {
    const linear::Mode& md = s.modes.modes[i];
    EXPECT_NEAR(md.shape.dot(m.mass * md.shape), 1.0, 1e-9);
    if (md.frequency_hz > 0) {
      const double omega = 2 * std::numbers::pi * md.frequency_hz;
      EXPECT_NEAR(md.shape.dot(m.stiffness * md.shape), omega * omega, 1e-6 * omega * omega);
      double sum = 0;
      for (double e : md.energy_share) sum += e;
      EXPECT_NEAR(sum, 1.0, 1e-9);
    }
    for (std::size_t j = 0; j < i; ++j) EXPECT_NEAR(md.shape.dot(m.mass * s.modes.modes[j].shape), 0.0, 1e-8);
  }
}

TEST(LinParker, MeshesCarryTheirConstantStiffnessOnTheLoadedFlanks) {
  const Solved s = solve(asset("lin_parker_1999.yaml"));
  ASSERT_EQ(s.model.meshes.size(), 6u);
  for (const linear::MeshInfo& mi : s.model.meshes) {
    EXPECT_NEAR(mi.mean_N_per_m, 5e8, 1e-6 * 5e8);
    EXPECT_NEAR(mi.min_N_per_m, 5e8, 1e-6 * 5e8);
    // The sun drives counter-clockwise: planets are turned clockwise, the ring held clockwise.
    EXPECT_EQ(mi.driven_sense, -1);
  }
  // Ring held, sun in: the mesh frequency is z_r·ω_carrier/2π = 94/(2π·(1 + 94/26)) per rad/s of the sun.
  const linear::Campbell c = linear::campbell(s.model, s.world->structure(), s.modes, 3, 1e9);
  ASSERT_TRUE(c.why_not.empty()) << c.why_not;
  for (const linear::MeshRate& r : c.rates) EXPECT_NEAR(r.hz_per_rad_s, 94.0 / (2 * std::numbers::pi * (1 + 94.0 / 26)), 1e-12);
  for (const linear::Crossing& x : c.crossings)
    EXPECT_NEAR(x.drive_speed_rad_s * x.harmonic * c.rates.front().hz_per_rad_s, x.natural_frequency_hz, 1e-9 * x.natural_frequency_hz);
}

// A spur pair on rigid hinges, the pinion held by its velocity motor: one free coordinate, the
// wheel's turn, on the mesh spring at the wheel's base radius: f = √(k r_b² / I)/2π.
TEST(SpurPair, TorsionalFrequencyIsTheMeshSpringOnTheWheelsInertia) {
  const std::filesystem::path dir = test::fresh_test_dir();
  const auto file = test::asset_scenario_copy(
      "spur_pair.yaml", dir,
      {{"  chordal_deviation_m: 5.0e-7      # m, the default: flank tables resolve depths to ~2 nm",
        "  chordal_deviation_m: 5.0e-7\n  mesh_stiffnesses: [{gears: [pinion, wheel], stiffness_N_per_m: 3.0e8}]"}});
  const Solved s = solve(file);
  ASSERT_EQ(s.modes.free_coordinates, 1);
  ASSERT_EQ(s.modes.modes.size(), 1u);
  double inertia = 0;
  for (const linear::BodyInfo& b : s.model.bodies)
    if (b.name == "wheel") inertia = b.inertia_z_kg_m2;
  // The wheel's base radius: gearsim's spur_pair wheel, z 31, m 2 mm, 20°.
  const double rb = 0.5 * 31 * 2.0e-3 * std::cos(20 * std::numbers::pi / 180);
  const double expected = std::sqrt(3e8 * rb * rb / inertia) / (2 * std::numbers::pi);
  const linear::Mode& elastic = s.modes.modes.back();
  EXPECT_NEAR(elastic.frequency_hz, expected, 2e-4 * expected);
  EXPECT_EQ(elastic.type, ModeType::Rotational);
}

// The paper gearbox (floating sun, rigid carrier pins, welded ring, motor-held sun): its
// healthy set is symmetric, so its elastic modes are rotational singles and translational pairs.
TEST(PaperGearbox, HealthySetHasOnlyRotationalSinglesAndTranslationalPairs) {
  const Solved s = solve(asset("paper_dynamics_healthy.yaml"));
  EXPECT_EQ(s.modes.free_coordinates, 6);  // sun x, y; carrier turn; three planet turns
  for (const linear::ModeGroup& g : s.modes.groups) {
    if (g.type == ModeType::Rotational)
      EXPECT_EQ(g.multiplicity, 1) << g.frequency_hz;
    else
      EXPECT_TRUE(g.type == ModeType::Translational && g.multiplicity == 2) << linear::to_string(g.type) << " " << g.frequency_hz;
  }
  // The flawed planet lowers its own sun mesh's mean stiffness and splits the pairs.
  const Solved f = solve(asset("paper_dynamics.yaml"));
  EXPECT_LT(f.model.meshes[0].mean_N_per_m, s.model.meshes[0].mean_N_per_m);
  for (const linear::ModeGroup& g : f.modes.groups) EXPECT_EQ(g.multiplicity, 1);
}

}  // namespace test_modes
}  // namespace gearsim

namespace gearsim {
namespace test_modes {

// Gears nobody here made (OpenSCAD MCAD meshes, tests/data/mcad): a 12/18/48 planetary set on a
// floating sun and planet bearings. Its modes are rotational singles and translational near-pairs
// — split by the meshes' own asymmetry (centres of mass microns off their axes, facets), by less
// than 0.1 %, and reported split rather than merged.
TEST(CadPlanetary, McadSetHasRotationalModesAndTranslationalNearPairs) {
  const std::filesystem::path file = test::mcad_planetary_file(
      test::fresh_test_dir(), 1.0, "{sun: {radial_stiffness_N_per_m: 1.0e7}, planets: {radial_stiffness_N_per_m: 5.0e7}}");
  const Solved s = solve(file);
  int rotational = 0, translational = 0;
  for (std::size_t i = 0; i < s.modes.modes.size(); ++i) {
    const linear::Mode& m = s.modes.modes[i];
    EXPECT_TRUE(m.type == ModeType::Rotational || m.type == ModeType::Translational) << m.frequency_hz;
    if (m.type == ModeType::Rotational) ++rotational;
    if (m.type != ModeType::Translational) continue;
    ++translational;
    // Its partner: the nearest other translational mode, within 0.1 %.
    double nearest = 1e300;
    for (std::size_t j = 0; j < s.modes.modes.size(); ++j)
      if (j != i && s.modes.modes[j].type == ModeType::Translational)
        nearest = std::min(nearest, std::abs(s.modes.modes[j].frequency_hz - m.frequency_hz));
    EXPECT_LT(nearest, 1e-3 * m.frequency_hz) << m.frequency_hz;
  }
  EXPECT_EQ(rotational, 4);  // carrier turn + three planet turns, the sun held by its motor
  EXPECT_EQ(translational, 8);  // sun x, y and the planets' x, y: four pairs
}

// A train of two planetary stages joined by a shaft (assets/scenarios/two_stage_planetary.yaml:
// stage 1's carrier drives stage 2's sun through 8 mm of steel, 1063 N·m/rad): the drive's
// flanks reach stage 2 through the shaft (a carrier has no mesh of its own to take a sense from),
// and the train's lowest mode is the shaft's: nearly all its strain energy is in the shaft, so a
// shaft four times softer halves its frequency.
TEST(Modes, AShaftCarriesTheDriveToTheNextStageAndItsSpringSetsTheLowestMode) {
  auto lowest = [](const Solved& s, double& shaft_share) {
    const linear::Mode& m = s.modes.modes.at(s.modes.modes.front().frequency_hz > 0 ? 0 : 1);
    shaft_share = 0;
    for (std::size_t e = 0; e < s.model.elements.size(); ++e)
      if (s.model.elements[e].name == "shaft s1_carrier–s2_sun") shaft_share = m.energy_share[e];
    return m.frequency_hz;
  };
  double share = 0, soft_share = 0;
  const Solved s = solve(asset("two_stage_planetary.yaml"));
  const double f = lowest(s, share);
  const double f_soft = lowest(solve(asset("two_stage_planetary.yaml"), {"shafts[0].length_m=0.12"}), soft_share);
  EXPECT_GT(share, 0.95);
  EXPECT_GT(soft_share, 0.95);
  EXPECT_NEAR(f_soft / f, 0.5, 0.5 * (1 - share));
  std::printf("lowest mode %.2f Hz (shaft %.1f %% of its strain energy), 4x softer shaft %.2f Hz\n", f, 100 * share, f_soft);
}

// The wind-turbine gearbox is driven at its carrier (the rotor): the carrier pushes its planets
// on their pins, each planet pushing sun and ring on in the carrier's sense, and the drive reaches
// stages 2 and 3 through the shafts. Every stage has its own mesh rate per rad/s of the carrier
// (z·|ω_gear − ω_carrier| by the train's kinematics: 99/2π, 82·(1 + 99/21)/2π, and that times
// 88/23), so the Campbell diagram crosses each mode with each stage's lines.
TEST(Modes, ACarrierDrivenThreeStageTrainHasEveryStagesMeshRate) {
  const Solved s = solve(asset("wind_turbine_3stage.yaml"));
  EXPECT_EQ(s.model.bodies[static_cast<std::size_t>(s.model.driver)].name, "s1_carrier");
  const linear::Campbell c = linear::campbell(s.model, s.world->structure(), s.modes, 1, 1e3);
  ASSERT_TRUE(c.why_not.empty()) << c.why_not;
  const double two_pi = 2 * std::numbers::pi, sun = 1 + 99.0 / 21;
  const std::map<std::string, double> expected{{"s1_sun–s1_planet_0", 99 / two_pi},
                                               {"s1_planet_0–s1_ring", 99 / two_pi},
                                               {"s2_wheel–s2_pinion", 82 * sun / two_pi},
                                               {"s3_wheel–s3_pinion", 88 * sun * 82 / 23 / two_pi}};
  int found = 0;
  for (const linear::MeshRate& r : c.rates) {
    const linear::MeshInfo& mi = s.model.meshes[static_cast<std::size_t>(r.mesh)];
    const auto e =
        expected.find(s.model.bodies[static_cast<std::size_t>(mi.a)].name + "–" + s.model.bodies[static_cast<std::size_t>(mi.b)].name);
    if (e == expected.end()) continue;
    EXPECT_NEAR(r.hz_per_rad_s, e->second, 1e-9 * e->second) << e->first;
    ++found;
  }
  EXPECT_EQ(found, 4);
  // The sun and ring meshes of a planet carry load on the flanks the carrier's sense pushes:
  // the sun and the ring are each the driven gear of their mesh, driven counter-clockwise.
  for (const linear::MeshInfo& mi : s.model.meshes) {
    const std::string driven = s.model.bodies[static_cast<std::size_t>(mi.driven)].name;
    if (driven == "s1_sun" || driven == "s1_ring") {
      EXPECT_EQ(mi.driven_sense, 1) << driven;
    }
  }
  // The two lowest elastic modes are the shafts' (most of their strain energy in one shaft).
  ASSERT_GE(s.modes.modes.size(), 3u);
  for (int k = 0; k < 2; ++k) {
    double shafts = 0;
    for (std::size_t e = 0; e < s.model.elements.size(); ++e)
      if (s.model.elements[e].name.rfind("shaft ", 0) == 0) shafts += s.modes.modes[static_cast<std::size_t>(k)].energy_share[e];
    EXPECT_GT(shafts, 0.8) << "mode " << k;
  }
  std::printf("wind turbine: lowest natural frequencies %.2f, %.2f, %.2f Hz\n", s.modes.modes[0].frequency_hz,
              s.modes.modes[1].frequency_hz, s.modes.modes[2].frequency_hz);
}

}  // namespace test_modes
}  // namespace gearsim

// Tooth contact stiffness from a table (contact/stiffness_table.hpp) in the Bullet world: a
// statically loaded gear pair in the Bullet world whose deflection follows the table: the same
// as the constant for a constant table, 1/k for a stiffer one, the table's value at the
// contact's radius for one that varies. The pair: the paper's sun (24) holding still, its
// planet (36) pressed by a 4 N·m torque, turned to where one tooth pair alone is in contact.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "input/scenario_file.hpp"
#include "core/errors.hpp"
#include "contact/stiffness_table.hpp"
#include "physics/world.hpp"
#include "tests/support/asset_scenario.hpp"

namespace gearsim::physics {
namespace test_stiffness_table_world {

namespace fs = std::filesystem;

constexpr double kFace_m = 10e-3;  // paper gears' face width
constexpr double kTorque_N_m = 4.0;  // on the planet
constexpr double kBaseSun_m = 11.2763e-3;  // r_b = 12 mm · cos 20°
constexpr double kBasePlanet_m = 16.9145e-3;  // r_b = 18 mm · cos 20°

// Where the pair macro places the sun (a tooth centred on the line of centres), two tooth pairs
// touch, at rolls of 1.89 and 4.84 mm along the line of action. Turning the sun by −0.0709 rad
// (and the planet by +2/3 of that) rolls them 0.80 mm back: one pair alone, at a roll of 4.04 mm,
// in the single-pair zone 3.52–4.56 mm (ε = 1.65): r_sun = √(r_b² + 4.04²) = 11.98 mm.
constexpr double kTurnSun_rad = -0.0709;
constexpr double kContactRadiusSun_m = 11.978e-3;

// The held pair: sun motor at zero speed, planet loaded, both on rigid hinges; damping 0.2 of
// critical so the ~16 kHz tooth mode settles within the run.
Scenario held_pair() {
  const fs::path dir = test::fresh_test_dir();  // ctest runs this file's cases in parallel
  const fs::path file = dir / "held_pair.yaml";
  const std::string spec = std::string(GEARSIM_SOURCE_DIR) + "/assets/specs/paper_gearset.yaml";
  std::ofstream(file) << "name: held_pair\n"
                         "duration_s: 0.02\n"
                         "contact: {stiffness_N_per_m_per_m: 1.4e10, damping_ratio: 0.2, friction: 0}\n"
                         "pair:\n"
                         "  driver: {name: sun, gear_from: {spec: "
                      << spec
                      << ", gear: sun}}\n"
                         "  driven: {name: planet, gear_from: {spec: "
                      << spec
                      << ", gear: planet}}\n"
                         "motors: [{joint: sun, target_speed_rad_s: 0, max_torque_N_m: 50}]\n"
                         "loads: [{joint: planet, constant_torque_N_m: "
                      << kTorque_N_m << "}]\n";
  Scenario s = input::load_scenario(file);
  auto turn = [](Pose& p, double angle_rad) {
    p.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(angle_rad, Eigen::Vector3d::UnitZ())) * p.orientation;
  };
  turn(s.bodies[0].pose, kTurnSun_rad);
  turn(s.bodies[1].pose, -kTurnSun_rad * 24.0 / 36.0);
  return s;
}

PairStiffnessDef table(const std::string& on, const std::string& other, std::vector<double> r, std::vector<double> k) {
  return {on, other, {"test table", std::move(r), std::move(k)}};
}

// The pair after 0.02 s (1000 steps): transmission error (from the unloaded start) and its
// loaded contact.
struct Held {
  double te_rad = 0;
  ContactSample contact;
  int contacts = 0;
  long misses = 0;
  Eigen::Vector2d sun_centre_m, planet_centre_m;
};

Held settle(const Scenario& s) {
  World w(s);
  const double ratio = s.transmission->ratio;  // −36/24
  auto te = [&] { return w.bodies()[0].angle_rad - ratio * w.bodies()[1].angle_rad; };
  const double te0 = te();
  for (int i = 0; i < 1000; ++i) w.step();
  Held h;
  h.te_rad = te() - te0;
  h.contacts = 0;
  for (const ContactSample& c : w.contacts())
    if (c.normal_force_N > 0) h.contact = c, ++h.contacts;
  h.misses = w.stiffness_table_misses();
  h.sun_centre_m = w.bodies()[0].position_m.head<2>();
  h.planet_centre_m = w.bodies()[1].position_m.head<2>();
  return h;
}

// Radius of the contact on one gear: the point on that gear's surface, half the depth from the
// overlap's mid-point (the sun is the world's gear a, pushed along +normal_on_b).
double radius_on(const Held& h, bool sun) {
  const contact::ToothContact& c = h.contact.geometry;
  const Eigen::Vector2d on = c.point_m + (sun ? -0.5 : 0.5) * c.depth_m * c.normal_on_b;
  return (on - (sun ? h.sun_centre_m : h.planet_centre_m)).norm();
}

TEST(StiffnessTableWorld, HeldPairDeflectsByLoadOverStiffness) {
  const Held h = settle(held_pair());
  ASSERT_EQ(h.contacts, 1);
  // Closed form: F = T/r_b,planet along the line of action, δ = F/k, te = δ/r_b,sun.
  const double k = 1.4e10 * kFace_m;
  const double te = kTorque_N_m / (kBasePlanet_m * k * kBaseSun_m);
  // 1 %: the contact sits a few µm off the ideal line of action (lever arms), and the held
  // sun's motor is a velocity constraint (its angle may creep by the solver's residual).
  EXPECT_NEAR(std::abs(h.te_rad), te, 0.01 * te);
  EXPECT_NEAR(h.contact.normal_force_N, kTorque_N_m / kBasePlanet_m, 0.01 * kTorque_N_m / kBasePlanet_m);
}

TEST(StiffnessTableWorld, ConstantTableReproducesTheConstantStiffness) {
  const Held plain = settle(held_pair());
  Scenario s = held_pair();
  s.contact.stiffness_tables.push_back(table("sun", "planet", {0.011, 0.0125, 0.0135}, {1.4e10, 1.4e10, 1.4e10}));
  const Held tabled = settle(s);
  // Same stiffness and damping by the same arithmetic: equal to rounding (1e-9 relative).
  EXPECT_NEAR(tabled.te_rad, plain.te_rad, 1e-9 * std::abs(plain.te_rad));
  EXPECT_NEAR(tabled.contact.normal_force_N, plain.contact.normal_force_N, 1e-9 * plain.contact.normal_force_N);
  EXPECT_DOUBLE_EQ(tabled.contact.stiffness_N_per_m, 1.4e10 * kFace_m);
  EXPECT_EQ(tabled.misses, 0);
}

TEST(StiffnessTableWorld, StaticTeScalesAsOneOverStiffness) {
  const Held plain = settle(held_pair());
  Scenario s = held_pair();
  s.contact.stiffness_tables.push_back(table("sun", "planet", {0.011, 0.0135}, {2.8e10, 2.8e10}));
  const Held stiff = settle(s);
  // Same load, twice the stiffness: half the deflection. 0.5 %: the contact point moves with
  // the deflection (µm), which changes the lever arms to second order.
  EXPECT_NEAR(plain.te_rad / stiff.te_rad, 2.0, 0.01);
  EXPECT_NEAR(stiff.contact.normal_force_N, plain.contact.normal_force_N, 0.005 * plain.contact.normal_force_N);
}

// Gear bodies in series with the pairs (body_stiffness_N_per_m): one pair of stiffness k with a
// body of stiffness k deflects twice as far, δ = F (1/k + 1/k_body), under the same force.
TEST(StiffnessTableWorld, BodyInSeriesAddsItsCompliance) {
  const Held plain = settle(held_pair());
  Scenario s = held_pair();
  PairStiffnessDef t = table("sun", "planet", {0.011, 0.0135}, {1.4e10, 1.4e10});
  t.body_stiffness_N_per_m = 1.4e10 * kFace_m;
  s.contact.stiffness_tables.push_back(t);
  const Held soft = settle(s);
  ASSERT_EQ(soft.contacts, 1);
  EXPECT_NEAR(soft.te_rad / plain.te_rad, 2.0, 0.01);
  EXPECT_NEAR(soft.contact.normal_force_N, plain.contact.normal_force_N, 0.005 * plain.contact.normal_force_N);
}

// Two pairs share one body: the mesh compliance is 1/(2k) + 1/k_body, so with k_body = 2k the
// static TE is twice that of the two pairs alone (not 1/(2k) + 2/k_body as a body per pair would
// give). The macro's own pose, where two pairs touch.
TEST(StiffnessTableWorld, TwoPairsShareOneBody) {
  auto two_pairs = [] {
    Scenario s = held_pair();
    auto turn = [](Pose& p, double angle_rad) {
      p.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(angle_rad, Eigen::Vector3d::UnitZ())) * p.orientation;
    };
    turn(s.bodies[0].pose, -kTurnSun_rad);
    turn(s.bodies[1].pose, kTurnSun_rad * 24.0 / 36.0);
    return s;
  };
  const Held plain = settle(two_pairs());
  Scenario s = two_pairs();
  PairStiffnessDef t = table("sun", "planet", {0.011, 0.0135}, {1.4e10, 1.4e10});
  t.body_stiffness_N_per_m = 2 * 1.4e10 * kFace_m;
  s.contact.stiffness_tables.push_back(t);
  const Held soft = settle(s);
  ASSERT_EQ(plain.contacts, 2);
  ASSERT_EQ(soft.contacts, 2);
  // 2 %: the two pairs' lever arms differ (rolls 1.89 and 4.84 mm), so their shares do too.
  EXPECT_NEAR(soft.te_rad / plain.te_rad, 2.0, 0.02);
}

TEST(StiffnessTableWorld, VaryingTableGivesItsValueAtTheContactRadius) {
  Scenario s = held_pair();
  // 1e10 at 11 mm rising to 2e10 at 13 mm: 1.489e10 at the contact's 11.978 mm.
  s.contact.stiffness_tables.push_back(table("sun", "planet", {0.011, 0.013}, {1.0e10, 2.0e10}));
  const Held h = settle(s);
  ASSERT_EQ(h.contacts, 1);
  const double r = radius_on(h, true);
  // Where the rigid mesh puts it; the 1.7 µm deflection moves it by less than 10 µm.
  EXPECT_NEAR(r, kContactRadiusSun_m, 10e-6);
  const double k = (1.0e10 + (r - 0.011) / 0.002 * 1.0e10) * kFace_m;
  EXPECT_NEAR(h.contact.stiffness_N_per_m, k, 1e-9 * k);
  EXPECT_NEAR(h.contact.stiffness_N_per_m, 1.489e10 * kFace_m, 0.001 * 1.489e10 * kFace_m);
  // And the contact deflects by F/k at that stiffness (1 %, as HeldPairDeflectsByLoadOverStiffness).
  EXPECT_NEAR(h.contact.geometry.depth_m, h.contact.normal_force_N / k, 0.01 * h.contact.normal_force_N / k);
}

TEST(StiffnessTableWorld, TableOnTheSecondGearTakesItsRadiusThere) {
  Scenario s = held_pair();
  // On the planet (the world's gear b): 1e10 at 17 mm to 2e10 at 19 mm. The contact's roll on
  // the planet is the line of action's 10.26 mm less the sun's 4.04: r = √(16.91² + 6.22²) mm.
  s.contact.stiffness_tables.push_back(table("planet", "sun", {0.017, 0.019}, {1.0e10, 2.0e10}));
  const Held h = settle(s);
  const double r = radius_on(h, false);
  EXPECT_NEAR(r, 18.02e-3, 10e-6);
  const double k = (1.0e10 + (r - 0.017) / 0.002 * 1.0e10) * kFace_m;
  EXPECT_NEAR(h.contact.stiffness_N_per_m, k, 1e-9 * k);
}

TEST(StiffnessTableWorld, ContactsOutsideTheTableAreCounted) {
  Scenario s = held_pair();
  // Covers only the sun's tip region: the contact at 11.98 mm lies below it, every step.
  s.contact.stiffness_tables.push_back(table("sun", "planet", {0.0125, 0.013}, {2.0e10, 3.0e10}));
  const Held h = settle(s);
  // Every step's loaded contact at least (the first step also touches the unloaded back flank).
  EXPECT_GE(h.misses, 1000);
  EXPECT_LE(h.misses, 1002);
  EXPECT_DOUBLE_EQ(h.contact.stiffness_N_per_m, 2.0e10 * kFace_m);  // the end row, counted
}

TEST(StiffnessTableWorld, TableForGearsThatDoNotMeshIsRefused) {
  Scenario s = held_pair();
  s.contact.stiffness_tables.push_back(table("sun", "nothing", {0.011, 0.013}, {1.0e10, 2.0e10}));
  EXPECT_THROW(World w(s), InputError);
}

}  // namespace test_stiffness_table_world
}  // namespace gearsim::physics

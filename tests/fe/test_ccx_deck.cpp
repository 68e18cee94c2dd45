// Deck generator against closed-form mechanics, solved by ccx: torsion of a plane-stress annulus
// through the rigid hub coupling (rotation and stress output), and a lever pressed on a block through a contact pair (the
// contact's moment about the axis equals the applied torque).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <functional>
#include <fstream>
#include <numbers>

#include "core/errors.hpp"
#include "fe/ccx_dat.hpp"
#include "fe/deck.hpp"
#include "fe/process.hpp"

using namespace gearsim;
using namespace gearsim::fe;
namespace fs = std::filesystem;

namespace test_ccx_deck {

fs::path fresh_dir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("gearsim_fe_deck_" + name);
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

// Structured grid of nu × nv quads over a map (u, v) ∈ [0,1]² → plane; counter-clockwise when the
// map preserves orientation. Boundary edges are collected for the v = 1 side.
FeMesh grid(int nu, int nv, const std::function<Eigen::Vector2d(double, double)>& map) {
  FeMesh m;
  for (int j = 0; j <= nv; ++j)
    for (int i = 0; i <= nu; ++i) m.nodes_m.push_back(map(double(i) / nu, double(j) / nv));
  auto id = [&](int i, int j) { return j * (nu + 1) + i; };
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      m.quads.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
      if (j == nv - 1) m.boundary_edges.push_back({static_cast<int>(m.quads.size()) - 1, 2});
    }
  return m;
}

// A ring r_i…r_o of nu × nv quads (nu around, counter-clockwise), its inner edge the hub; the
// outer edge held when hold_outer.
FeBody annulus(const std::string& name, double ri, double ro, int nu, int nv, bool hold_outer) {
  FeBody b;
  b.name = name;
  b.support = FeSupport::Driving;
  b.mesh = grid(nu, nv, [&](double u, double v) {
    const double r = ri + (ro - ri) * v, a = -2 * std::numbers::pi * u;  // clockwise in u: ccw quads
    return Eigen::Vector2d(r * std::cos(a), r * std::sin(a));
  });
  // The u = 1 column repeats u = 0: merge it by pointing at the first column's nodes.
  for (auto& q : b.mesh.quads)
    for (int& n : q)
      if (n % (nu + 1) == nu) n -= nu;
  for (int i = 0; i < nu; ++i) {
    b.mesh.hub_nodes.push_back(i);
    if (hold_outer) b.mesh.fixed_nodes.push_back(nv * (nu + 1) + i);
  }
  return b;
}

Deck solve(const DeckDef& def, const fs::path& dir) {
  const Deck deck = write_deck(def);
  std::ofstream(dir / "job.inp") << deck.text;
  run_ccx({"ccx", dir, "job"});
  return deck;
}

// Value of a node's dof at the end of step k (total time k).
double at_step(const std::vector<DatBlock>& blocks, const std::string& q, const std::string& set, int node, int dof, int k) {
  for (const DatBlock& b : blocks)
    if (b.quantity == q && b.set == set && std::abs(b.time - k) < 1e-9) return b.rows.at(node)[dof];
  ADD_FAILURE() << "no " << q << " at time " << k;
  return NAN;
}

// Annulus r_i = 5 mm, r_o = 15 mm, t = 10 mm, outer edge held, hub turned by T = 10 N·m:
// θ = T/(4π G t)·(1/r_i² − 1/r_o²) = 3.502e-5 rad (plane stress, G = E/2(1+ν)). Tolerance 1 %:
// 48 × 16 bilinear elements resolve the 1/r² shear within a few tenths of a percent.
TEST(CcxDeck, AnnulusTorsionMatchesClosedForm) {
  const double ri = 5e-3, ro = 15e-3, t = 10e-3, T = 10.0;
  const int nu = 48, nv = 16;
  const FeBody hub = annulus("HUB", ri, ro, nu, nv, true);
  DeckDef def;
  def.bodies = {hub};
  def.thickness_m = t;
  def.torque_N_m = T;
  def.load_fractions = {1.0};
  def.element_type = "CPS4";
  const fs::path dir = fresh_dir("torsion");
  const Deck deck = solve(def, dir);
  const auto blocks = read_dat(dir / "job.dat");
  const double G = def.young_modulus_Pa / (2 * (1 + def.poisson_ratio));
  const double expected = T / (4 * std::numbers::pi * G * t) * (1 / (ri * ri) - 1 / (ro * ro));
  const double theta = at_step(blocks, "displacements", "NROT", deck.layout[0].rotation_node, 0, 2);
  EXPECT_NEAR(theta / expected, 1.0, 0.01) << "θ = " << theta << " rad, closed form " << expected;
}

// The same annulus with a stress set on its middle ring of elements (r 9.69…10.31 mm): pure
// shear τ = T/(2π r² t) at the element centres, so the principal stresses are ±τ (plane stress,
// σ_r = σ_θ = 0). 2 %: τ varies as 1/r² by ±6 % across the ring; its centre value is the mean
// within 0.5 %, plus the bilinear elements' error.
TEST(CcxDeck, StressSetReadsTheShearOfATwistedAnnulus) {
  const double ri = 5e-3, ro = 15e-3, t = 10e-3, T = 10.0;
  const int nu = 48, nv = 16;
  const FeBody hub = annulus("HUB", ri, ro, nu, nv, true);
  FeElementSet ring{"MID", 0, {}};
  const int row = nv / 2;  // elements between r = ri + 8/16 (ro − ri) and ri + 9/16 (ro − ri)
  for (int i = 0; i < nu; ++i) ring.elements.push_back(row * nu + i);
  DeckDef def;
  def.bodies = {hub};
  def.thickness_m = t;
  def.torque_N_m = T;
  def.load_fractions = {1.0};
  def.element_type = "CPS4";
  def.stress_sets = {ring};
  const fs::path dir = fresh_dir("stress");
  solve(def, dir);
  const auto blocks = read_dat(dir / "job.dat");
  const DatBlock& b = last_block(blocks, "stresses", "MID");
  ASSERT_EQ(b.row_list.size(), static_cast<size_t>(nu) * 8);  // CPS4 → C3D8: 8 points each
  const double r = ri + (ro - ri) * (row + 0.5) / nv;
  const double tau = T / (2 * std::numbers::pi * r * r * t) * 1e-6;  // MPa (deck units)
  // Means over the ring's integration points (they sit ±0.29 of an element off its centre, where
  // the bilinear field adds a σ_r, σ_θ of either sign).
  double s1_mean = 0, s2_mean = 0;
  for (const auto& [id, v] : b.row_list) {
    ASSERT_GE(v.size(), 5u);
    const double c = 0.5 * (v[1] + v[2]), rad = std::hypot(0.5 * (v[1] - v[2]), v[4]);
    s1_mean += (c + rad) / static_cast<double>(b.row_list.size());
    s2_mean += (c - rad) / static_cast<double>(b.row_list.size());
  }
  EXPECT_NEAR(s1_mean / tau, 1.0, 0.02) << "σ1 " << s1_mean << " MPa, τ " << tau << " MPa";
  EXPECT_NEAR(s2_mean / tau, -1.0, 0.02) << "σ2 " << s2_mean << " MPa, τ " << tau << " MPa";
}

// A lever (x 8…12 mm, y −1…1 mm) on the axis through its hub edge x = 8 mm, pressed by T = 1 N·m
// against a block above it (y 1…3 mm) clamped at its top: the contact force on the block has a
// moment about the axis equal to T (equilibrium; 0.5 % covers the solver's residual tolerance),
// pushes the lever down, and its centre of pressure T/|F_y| lies on the 8…12 mm contact.
TEST(CcxDeck, ContactCarriesTheTorque) {
  FeBody lever, block;
  lever.name = "LEVER";
  lever.support = FeSupport::Driving;
  lever.mesh = grid(8, 4, [](double u, double v) { return Eigen::Vector2d(8e-3 + 4e-3 * u, -1e-3 + 2e-3 * v); });
  for (int j = 0; j <= 4; ++j) lever.mesh.hub_nodes.push_back(j * 9);
  block.name = "BLOCK";
  block.support = FeSupport::Fixed;
  // Block upside down in its own frame so its free (bottom) edge is the grid's v = 1 side.
  block.mesh = grid(8, 4, [](double u, double v) { return Eigen::Vector2d(12e-3 - 4e-3 * u, 3e-3 - 2e-3 * v); });
  for (int i = 0; i <= 8; ++i) block.mesh.fixed_nodes.push_back(i);
  DeckDef def;
  def.bodies = {lever, block};
  def.contacts = {{"C1", 0, 1, lever.mesh.boundary_edges, block.mesh.boundary_edges}};
  def.torque_N_m = 1.0;
  def.closing_rotation_rad = 1e-6;
  def.load_fractions = {0.5, 1.0};
  const fs::path dir = fresh_dir("contact");
  const Deck deck = solve(def, dir);
  const auto totals = read_contact_totals(dir / "job.dat");
  ASSERT_FALSE(totals.empty());
  const ContactTotals& last = totals.back();
  EXPECT_NEAR(last.time, 3.0, 1e-9);
  // Slave = lever: the block pushes it down (−y), with moment −T about +z (deck units N·mm).
  EXPECT_NEAR(last.moment[2], -1000.0, 5.0);
  EXPECT_LT(last.force[1], 0.0);
  const double arm_mm = 1000.0 / -last.force[1];
  EXPECT_GT(arm_mm, 8.0);
  EXPECT_LT(arm_mm, 12.0);
  const auto blocks = read_dat(dir / "job.dat");
  const double theta = at_step(blocks, "displacements", "NROT", deck.layout[0].rotation_node, 0, 3);
  EXPECT_GT(theta, 0.0);
}

// A free annulus (nothing holds it but its hub) turned by a torque has no equilibrium: with CPS4
// the solve returns a rotation of order 1e8 rad (a singular system). With CPS4R ccx (plane-stress
// quads expanded to hourglass-controlled C3D8R bricks) resists the rigid turn: here 0.4 N·m turns
// it 0.027 rad (15 N·m/rad). This is why gearsim's planetary FE takes the torque through the teeth
// from the contact moments and not the applied one (docs/fe-results.md, "Hub leak").
TEST(CcxDeck, ReducedIntegrationResistsARigidTurnOfTheHub) {
  double theta[2] = {0, 0};
  const char* types[2] = {"CPS4R", "CPS4"};
  for (int k = 0; k < 2; ++k) {
    const FeBody ring = annulus("FREE", 5e-3, 10e-3, 48, 6, false);
    DeckDef def;
    def.bodies = {ring};
    def.torque_N_m = 0.4;
    def.load_fractions = {1.0};
    def.element_type = types[k];
    const fs::path dir = fresh_dir(std::string("free_") + types[k]);
    const Deck deck = solve(def, dir);
    theta[k] = at_step(read_dat(dir / "job.dat"), "displacements", "NROT", deck.layout[0].rotation_node, 0, 2);
  }
  const double k_cps4r = 0.4 / theta[0];  // N·m/rad
  EXPECT_GT(k_cps4r, 1.0) << "θ " << theta[0];
  EXPECT_LT(k_cps4r, 100.0) << "θ " << theta[0];
  EXPECT_GT(std::abs(theta[1]), 1e4 * std::abs(theta[0])) << "CPS4 θ " << theta[1];
}

// A driving body held by nothing but its rotational spring turns θ = T / k (the hub equations make
// the whole plate rigid): the spring element sits on the rotation node with the stiffness given,
// in N·m/rad. Tolerance 1e-6: a linear solve, 7 printed digits.
TEST(CcxDeck, DrivingSpringAloneHoldsTheTorque) {
  FeBody plate;
  plate.name = "PLATE";
  plate.support = FeSupport::Driving;
  plate.mesh = grid(2, 2, [](double u, double v) { return Eigen::Vector2d(5e-3 + 2e-3 * u, -1e-3 + 2e-3 * v); });
  for (int i = 0; i < 9; ++i) plate.mesh.hub_nodes.push_back(i);
  DeckDef def;
  def.bodies = {plate};
  def.torque_N_m = 2.0;
  def.load_fractions = {1.0};
  def.driving_spring_N_m_per_rad = 400.0;
  const fs::path dir = fresh_dir("spring");
  const Deck deck = solve(def, dir);
  const double theta = at_step(read_dat(dir / "job.dat"), "displacements", "NROT", deck.layout[0].rotation_node, 0, 2);
  EXPECT_NEAR(theta / (2.0 / 400.0), 1.0, 1e-6);
}

TEST(CcxDeck, RejectsBadDefinitions) {
  DeckDef def;
  EXPECT_THROW(write_deck(def), InputError);  // no driving body
  FeBody b;
  b.name = "bad name";
  b.support = FeSupport::Driving;
  b.mesh = grid(1, 1, [](double u, double v) { return Eigen::Vector2d(u, v); });
  b.mesh.hub_nodes = {0};
  def.bodies = {b};
  EXPECT_THROW(write_deck(def), InputError);  // name with a space
  def.bodies[0].name = "OK";
  def.load_fractions = {1.0, 0.5};
  EXPECT_THROW(write_deck(def), InputError);  // load stages not increasing
}

}  // namespace test_ccx_deck

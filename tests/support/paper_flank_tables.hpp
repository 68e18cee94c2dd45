// Test helper: the flank tables of a scenario's gears as the simulation builds them, with their
// start poses and turn ratios (the paper's faulty set built once), and the check that a move
// within FlankTable::face()'s margin keeps a point facing its flank (tests/contact).
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "contact/flank_table.hpp"
#include "contact/tooth_contact.hpp"
#include "input/scenario_file.hpp"
#include "physics/world_bodies.hpp"

namespace gearsim::test {

// A gear of a scenario: its flank table and start pose, and how far it turns in the carrier's
// frame per unit turn of the sun (1 for the sun, −Zs/Z for the others).
struct Gear {
  std::string name;
  std::shared_ptr<const contact::FlankTable> table;
  contact::PlanarPose pose;
  double ratio = 0;
};

inline double angle_of(const Eigen::Quaterniond& q) {
  const Eigen::Vector3d x = q * Eigen::Vector3d::UnitX();
  return std::atan2(x.y(), x.x());
}

inline std::vector<Gear> gears_of(const physics::Scenario& s, const std::string& driver, int driver_teeth) {
  std::vector<Gear> gears;
  for (const physics::BodyDef& d : s.bodies) {
    if (!d.gear && !d.mesh) continue;
    const physics::BuiltBody b = physics::build_body(d, s.contact);
    if (!b.flanks) continue;
    const double ratio = d.name == driver ? 1.0 : -static_cast<double>(driver_teeth) / b.flanks->teeth();
    gears.push_back({d.name, b.flanks, {d.pose.position_m.head<2>(), angle_of(d.pose.orientation)}, ratio});
  }
  return gears;
}

// The paper's faulty set (paper_dynamics.yaml), built once.
inline const std::vector<Gear>& paper_gears() {
  static const std::vector<Gear> gears =
      gears_of(input::load_scenario(std::string(GEARSIM_SOURCE_DIR) + "/assets/scenarios/paper_dynamics.yaml"), "sun", 24);
  return gears;
}

inline const Gear& named(const std::vector<Gear>& gears, const std::string& name) {
  for (const Gear& g : gears)
    if (g.name == name) return g;
  throw std::runtime_error("no gear " + name);
}

// The facing margin (contact::FlankTable::face()) a continued contact's flank check rests on: for points
// anywhere in the teeth moved by up to 300 µm, a move within the margin's reach (twice the
// offsets' slope bound times the move, below the margin) leaves the point facing the same flank;
// and face() chooses what probe_depth() chooses. `moves` random moves per table.
inline void expect_facing_margin_holds(const contact::FlankTable& t, const std::string& name, int moves) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(0, 1);
  long within = 0, kept = 0, moved_away = 0;
  for (int i = 0; i < moves; ++i) {
    const double r = t.r_min_m() + unit(rng) * (t.r_max_m() - t.r_min_m()), at = 2 * M_PI * unit(rng);
    const Eigen::Vector2d q0 = r * Eigen::Vector2d(std::cos(at), std::sin(at));
    const contact::FlankTable::Probe p0 = t.probe_depth(q0);
    if (!p0.has_flank) continue;
    const contact::FlankTable::Facing f0 = t.face(q0, p0.tooth);
    const contact::FlankTable::Probe p0h = t.probe_depth(q0, p0.tooth);
    ASSERT_TRUE(f0.has_flank) << name;
    EXPECT_TRUE(f0.tooth == p0h.tooth && f0.flank == p0h.flank) << name << ": face() and probe_depth() differ at " << q0.transpose();
    const double dir = 2 * M_PI * unit(rng), delta = 300e-6 * unit(rng) * unit(rng);
    const Eigen::Vector2d q1 = q0 + delta * Eigen::Vector2d(std::cos(dir), std::sin(dir));
    const double lo = std::min(q0.norm(), q1.norm()) - delta, hi = std::max(q0.norm(), q1.norm()) + delta;
    if (!(lo > t.r_min_m() && hi < t.r_max_m())) continue;
    const double side = t.first_order_rise(lo, hi).side;
    const contact::FlankTable::Probe p1 = t.probe_depth(q1, f0.tooth);
    const bool same = p1.has_flank && p1.tooth == f0.tooth && p1.flank == f0.flank;
    if (side < contact::FlankTable::kInfinity && 2 * side * delta < f0.margin_m) {
      ++within;
      kept += same;
    } else {
      moved_away += !same;
    }
  }
  EXPECT_GT(within, moves / 4) << name;
  EXPECT_EQ(kept, within) << name << ": moves within the margin's reach that changed the facing flank";
  EXPECT_GT(moved_away, 0) << name << ": the sample should hold moves that change the flank";
}

}  // namespace gearsim::test

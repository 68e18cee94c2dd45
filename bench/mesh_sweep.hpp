// The kinematic sweep bench_contact_sweep and bench_mesh_table share: every gear body of a
// planetary scenario with its flank table, the pairs that mesh, and the poses of one relative
// planet turn in sun steps of the run's motion per time step, pressed by −0.5…+2 µm and with the
// sun shifted by 0 / ±1 µm (the floating sun). Header-only, for the benchmarks.
#pragma once

#include <Eigen/Geometry>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "contact/tooth_contact.hpp"
#include "input/scenario_file.hpp"
#include "physics/world_bodies.hpp"

namespace gearsim::bench {

// One contact of a sweep as the dumps store it (binary, host order).
struct Record {
  std::int64_t call;
  std::int32_t tooth_a, tooth_b, flank_a, pad;
  double point_x, point_y, normal_x, normal_y, depth;
};

inline double angle_of(const Eigen::Quaterniond& q) {
  const Eigen::Vector3d x = q * Eigen::Vector3d::UnitX();
  return std::atan2(x.y(), x.x());
}

struct SweepGear {
  std::string name;
  std::shared_ptr<const contact::FlankTable> table;
  contact::PlanarPose pose;
  double ratio = 0;  // spin in the carrier frame per unit sun spin
};

struct MeshSweep {
  std::string name;  // the scenario's
  std::vector<SweepGear> gears;
  std::vector<std::pair<int, int>> pairs;  // (external gear, its mate)
  double step_rad = 0;  // sun relative to the carrier, per step
  long steps = 0;  // one relative planet turn
  static constexpr double presses_m[5] = {-0.5e-6, 0.0, 0.5e-6, 1e-6, 2e-6};
  static constexpr double shifts_m[3] = {0.0, 1e-6, -1e-6};

  // The sweep of a scenario's gears; false (with a message) without a gear body named 'sun'.
  bool load(const std::string& file) {
    const physics::Scenario s = input::load_scenario(file);
    // Every body with flank tables: generated gears and recognised CAD meshes alike.
    int sun_teeth = 0;
    for (const physics::BodyDef& d : s.bodies) {
      const physics::BuiltBody b = physics::build_body(d, s.contact);
      if (!b.flanks) continue;
      if (d.name == "sun") sun_teeth = b.flanks->teeth();
      gears.push_back({d.name, b.flanks, {d.pose.position_m.head<2>(), angle_of(d.pose.orientation)}, 0});
    }
    if (sun_teeth == 0) {
      std::fprintf(stderr, "%s: no gear body named 'sun'\n", file.c_str());
      return false;
    }
    // Carrier-frame kinematics: the sun turns by φ, a planet by −φ·Zs/Zp, the ring by −φ·Zs/Zr.
    for (SweepGear& g : gears) g.ratio = g.name == "sun" ? 1.0 : -static_cast<double>(sun_teeth) / g.table->teeth();
    // Pairs that mesh: the sun with each planet, each planet with the ring (the external gear first).
    for (std::size_t i = 0; i < gears.size(); ++i)
      for (std::size_t j = 0; j < gears.size(); ++j) {
        if (i == j || gears[i].table->internal()) continue;
        const double d = (gears[i].pose.centre_m - gears[j].pose.centre_m).norm();
        const bool meshes = gears[j].table->internal() ? d + gears[i].table->r_max_m() > gears[j].table->r_min_m()
                                                       : i < j && d < gears[i].table->r_max_m() + gears[j].table->r_max_m();
        if (meshes) pairs.emplace_back(static_cast<int>(i), static_cast<int>(j));
      }
    // One relative planet turn in sun steps of ω·dt (104.7 rad/s in the paper's run).
    step_rad = 104.7 * s.solver.time_step_s * 0.8;
    int planet_teeth = 0;
    for (const SweepGear& g : gears)
      if (g.name != "sun" && !g.table->internal()) planet_teeth = g.table->teeth();
    steps = std::lround(2 * 3.141592653589793 * planet_teeth / sun_teeth / step_rad);
    name = s.name;
    return true;
  }

  // The poses of pair (ga, gb) at step i, pressed (a turned forward by press over its tip radius)
  // and with the sun shifted.
  void poses(const SweepGear& ga, const SweepGear& gb, long i, double press_m, double shift_m, contact::PlanarPose* pa,
             contact::PlanarPose* pb) const {
    const double phi = static_cast<double>(i) * step_rad;
    *pa = ga.pose, *pb = gb.pose;
    pa->angle_rad += phi * ga.ratio + press_m / ga.table->r_max_m();
    pb->angle_rad += phi * gb.ratio;
    if (ga.name == "sun") pa->centre_m.x() += shift_m, pa->centre_m.y() += 0.5 * shift_m;
    if (gb.name == "sun") pb->centre_m.x() += shift_m, pb->centre_m.y() += 0.5 * shift_m;
  }
};

inline Record record_of(long call, const contact::ToothContact& c) {
  return {call,
          c.tooth_a,
          c.tooth_b,
          c.flank_a == Flank::Ccw ? 0 : 1,
          0,
          c.point_m.x(),
          c.point_m.y(),
          c.normal_on_b.x(),
          c.normal_on_b.y(),
          c.depth_m};
}

}  // namespace gearsim::bench

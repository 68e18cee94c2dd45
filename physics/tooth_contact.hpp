// Tooth contact between two spur gears with parallel axes: one contact per touching tooth pair,
// found by probing each gear's flanks against the other's FlankTable. Pure geometry: no Bullet,
// no forces. Depths resolve to the flank tables' accuracy (the outline's chordal deviation),
// which is what an elastic contact of sub-µm deflections needs.
// Not a general collision detector: both gears must be star-shaped spur gears in one plane.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "physics/flank_table.hpp"

namespace gearsim::physics {

// A gear's placement in the common plane: centre and rotation about +z.
struct PlanarPose {
  Eigen::Vector2d centre_m = Eigen::Vector2d::Zero();
  double angle_rad = 0;
};

struct ToothContact {
  int tooth_a = -1, tooth_b = -1;
  Flank flank_a = Flank::Ccw;           // which flank of a's tooth is touched
  Eigen::Vector2d point_m;              // mid-point of the overlap, plane coordinates
  Eigen::Vector2d normal_on_b;          // unit, from b toward a (pushes a away from b)
  double depth_m = 0;                   // penetration, > 0
};

// All tooth-pair contacts between gear a and gear b, at most one per (tooth_a, tooth_b).
std::vector<ToothContact> find_tooth_contacts(const FlankTable& a, const PlanarPose& pa,
                                              const FlankTable& b, const PlanarPose& pb);
// The same into `out` (cleared first), which keeps its storage from call to call.
void find_tooth_contacts(const FlankTable& a, const PlanarPose& pa, const FlankTable& b,
                         const PlanarPose& pb, std::vector<ToothContact>& out);

}  // namespace gearsim::physics

// Tooth contact between two spur gears with parallel axes: one contact per touching tooth pair,
// found by probing each gear's flanks against the other's FlankTable. Pure geometry: no Bullet,
// no forces. Depths resolve to the flank tables' accuracy (the outline's chordal deviation),
// which is what an elastic contact of sub-µm deflections needs. A contact's normal is the common
// normal of the two flanks, or where one of them has a corner (a tip corner, or an outline corner
// the flank table keeps, such as where a ring's tip land meets its flank) the normal of the
// smooth flank the corner is in: the direction its depth grows along as the corner slides.
// Not a general collision detector: both gears must be star-shaped spur gears in one plane.
#pragma once

#include <Eigen/Core>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "contact/flank_table.hpp"

namespace gearsim::contact {

// A gear's placement in the common plane: centre and rotation about +z.
struct PlanarPose {
  Eigen::Vector2d centre_m = Eigen::Vector2d::Zero();
  double angle_rad = 0;
  // std::cos and std::sin of the angle, where the caller has them (a gear meshing in several
  // pairs turns its angle into them once per step, not once per pair: with_rotation()), and the
  // angle they are of: used only while angle_rad is still that angle, bit for bit, so a pose
  // turned afterwards is never taken at a stale rotation. NaN by default: the search takes them
  // itself.
  double cos_angle = std::numeric_limits<double>::quiet_NaN(), sin_angle = std::numeric_limits<double>::quiet_NaN();
  double rotation_of_rad = std::numeric_limits<double>::quiet_NaN();
  bool has_rotation() const { return std::bit_cast<std::uint64_t>(rotation_of_rad) == std::bit_cast<std::uint64_t>(angle_rad); }
};

inline PlanarPose with_rotation(PlanarPose p) {
  p.cos_angle = std::cos(p.angle_rad);
  p.sin_angle = std::sin(p.angle_rad);
  p.rotation_of_rad = p.angle_rad;
  return p;
}

struct ToothContact {
  int tooth_a = -1, tooth_b = -1;
  Flank flank_a = Flank::Ccw;  // which flank of a's tooth is touched
  Eigen::Vector2d point_m;  // mid-point of the overlap, plane coordinates
  Eigen::Vector2d normal_on_b;  // unit, from b toward a (pushes a away from b)
  double depth_m = 0;  // penetration, > 0 (a near pair's gap: ≤ 0)
};

// All tooth-pair contacts between gear a and gear b, at most one per (tooth_a, tooth_b).
std::vector<ToothContact> find_tooth_contacts(const FlankTable& a, const PlanarPose& pa, const FlankTable& b, const PlanarPose& pb);
// The same into `out` (cleared first), which keeps its storage from call to call. With `near`,
// also the tooth pairs whose refinement measured a gap (depth ≤ 0, ToothContact::depth_m then
// the gap's negative, within a few µm of touching: the refinement window of flank_search_impl.hpp)
// and that do not touch, into `near` (cleared first) in the same order: where contacts may start.
void find_tooth_contacts(const FlankTable& a, const PlanarPose& pa, const FlankTable& b, const PlanarPose& pb,
                         std::vector<ToothContact>& out, std::vector<ToothContact>* near = nullptr);

}  // namespace gearsim::contact

namespace gearsim::contact {

// The deepest tooth overlap of two gears turned through one mesh period (one pitch of a) about
// their fixed centres at the ideal ratio of their tooth counts (opposite senses for two
// external gears, the same sense for an external gear in a ring), from their poses pa and pb:
// interference of tip and fillet, or flanks fuller than conjugate, shows here before a run.
struct MeshCycleOverlap {
  ToothContact deepest;  // depth_m 0 when the teeth never overlap
  double turn_a_rad = 0;  // a's turn from pa at which it is deepest
  double radius_a_m = 0;  // of the contact point on a, and on b
  double radius_b_m = 0;
};
MeshCycleOverlap mesh_cycle_overlap(const FlankTable& a, const PlanarPose& pa, const FlankTable& b, const PlanarPose& pb, int steps);

}  // namespace gearsim::contact

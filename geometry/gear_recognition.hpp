// Gear recognition: which spur gear a planar outline is, from its shape alone. The toothed loop
// and the tooth count come from the loop's z-fold periodicity about its own centroid; the axis
// is the common centre of the tip and root circles (unmoved by a damaged flank); tooth 0 from
// the teeth's centre lines; the flanks are fitted with
// involutes (base radius, base thickness, active radii), and module and pressure angle follow
// from the base pitch and the tooth depth. Works for external and internal gears, from any CAD
// tool, at any size, with 5 to 1024 teeth. Not a gear generator (gear_profile.hpp) and not a validator of meshes
// (mesh_validate.hpp): the outline must be a valid one already.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "core/result.hpp"
#include "geometry/outline.hpp"

namespace gearsim {

// One side of every tooth fitted with one involute: in the tooth's frame (centre line on +x) the
// flank's half-angle is y(r) = base_half_angle − inv(acos(r_b / r)) for an external gear and
// base_half_angle + inv(...) for an internal one (its teeth widen toward the root).
struct InvoluteFit {
  bool involute = false;  // the points fit within kInvoluteFitTolerance (outliers aside)
  double base_radius_m = 0;  // m
  double base_half_angle_rad = 0;  // the flank's angle to the tooth centre line at the base circle
  double rms_m = 0;  // normal distance of the kept points from the fitted involute, m
  double active_from_m = 0;  // radial range of the flank points on the involute, m
  double active_to_m = 0;
  int points = 0;  // points kept in the fit
  std::vector<int> outlier_teeth;  // teeth with points off the involute (flank errors, damage)
  double largest_outlier_m = 0;  // their largest normal distance, m
};

struct RecognisedGear {
  int teeth = 0;
  double tooth0_angle_rad = 0;  // centre line of tooth 0 (the tooth nearest +x), in [−π/z, π/z)
  bool internal = false;  // teeth on a hole of the outline (a ring)
  int loop = -1;  // −1: the outer loop; else the index of the hole
  Eigen::Vector2d axis_m = Eigen::Vector2d::Zero();  // the axis in the outline's coordinates, m
  double tip_radius_m = 0;  // about the axis: the teeth's tips (smallest radius if internal)
  double root_radius_m = 0;  // and roots, m
  double symmetry_residual_m = 0;  // rms of r(θ) − r(θ + 2π/z) about the axis, m
  InvoluteFit ccw, cw;  // the counter-clockwise and clockwise flank of every tooth

  // From the fits, when both flanks are involutes of one base circle (`involute`). Sides fitting
  // involutes of different base circles (by more than 0.1 %) are an asymmetric tooth: no single
  // base circle, module or pressure angle; ccw and cw hold each side's.
  bool asymmetric = false;
  bool involute = false;
  double base_radius_m = 0;  // mean of the two flanks', m
  double base_pitch_m = 0;  // 2π r_b / z, m
  // Module and pressure angle: m·cos α equals the base pitch / π exactly; which (m, α) is an
  // assumption. `standard` when a module of ISO 54 / DIN 780 (or a diametral pitch) with a common
  // pressure angle matches the base pitch within kStandardMatch and the tooth depth within 25 %
  // (of several, the one with depth nearest 2.25 m and the smallest profile shift);
  // otherwise m is the depth / 2.25 (the ISO 53 rack) and α follows. Without involute flanks
  // only module_m is set, to that depth / 2.25.
  bool standard = false;
  double module_m = 0;
  double pressure_angle_rad = 0;
  double reference_radius_m = 0;  // m·z/2
  double reference_thickness_m = 0;  // arc tooth thickness at the reference radius, m
  // (reference_thickness − π·m/2) / (2·m·tan α), external gears: the profile shift coefficient
  // with the backlash allowance folded in (thinned teeth read as a negative shift).
  double profile_shift = 0;
};

// Recognises the gear in an outline (m; any origin), or refuses saying why no gear was
// recognised. Never throws on a valid outline.
Result<RecognisedGear> recognise_gear(const Outline2& outline);

// The outline moved so that `axis` lies on the origin.
Outline2 recentred(const Outline2& outline, const Eigen::Vector2d& axis_m);

}  // namespace gearsim

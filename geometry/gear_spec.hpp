// GearSpec: the description of one spur gear (external or internal) and its manufacturing
// errors, in SI units. Plain data with defaults; validate_gear_spec() rejects impossible values.
// Not the geometry itself: gear_profile.hpp turns a spec into an outline.
//
// Conventions (used by every module):
//  - The gear axis is +z, the gear's rotation centre is the origin of its body frame.
//  - Tooth k's centre line lies at polar angle tooth0_angle_rad + k·2π/z (counter-clockwise
//    seen from +z). For an internal gear the tooth points inward, still centred on that line.
//  - A tooth's two flanks are named by the side of the centre line they lie on, seen from +z:
//    Flank::Ccw (counter-clockwise side, larger polar angle) and Flank::Cw.
//  - A positive flank deviation adds material (ISO 21771 sign: "plus material").
#pragma once

#include <numbers>
#include <string>
#include <vector>

#include "geometry/constants.hpp"

namespace gearsim {

enum class GearKind { External, Internal };
enum class Flank { Ccw, Cw };

// One flank of one tooth moved along its normal by a constant amount (the paper's single flank
// error). For an involute this equals rotating that flank about the axis by offset / r_b.
struct FlankOffset {
  int tooth = 0;
  Flank flank = Flank::Ccw;
  double normal_offset_m = 0.0;  // + adds material, − removes it
};

// Tooth k displaced along the reference circle (both flanks rotated by error / r), m.
struct PitchError {
  int tooth = 0;
  double error_m = 0.0;  // + counter-clockwise
};

// Profile slope deviation f_Hα on one flank of one tooth (or all teeth when tooth < 0): a normal
// offset growing linearly with roll length from 0 at the start of the involute (form circle) to
// slope_m at the tip circle.
struct ProfileSlopeError {
  int tooth = -1;
  Flank flank = Flank::Ccw;
  double slope_m = 0.0;  // + adds material toward the tip
};

// Geometric eccentricity of the toothing relative to the rotation axis: the toothed outline is
// shifted by eccentricity_m toward polar angle phase_rad. Radial runout F_r = 2·eccentricity.
struct Eccentricity {
  double eccentricity_m = 0.0;
  double phase_rad = 0.0;
};

struct GearErrors {
  std::vector<FlankOffset> flank_offsets;
  std::vector<PitchError> pitch_errors;
  std::vector<ProfileSlopeError> profile_slopes;
  Eccentricity eccentricity;
};

struct GearSpec {
  std::string name;
  GearKind kind = GearKind::External;
  int teeth = 0;
  double module_m = 0.0;
  double pressure_angle_rad = constants::kDefaultPressureAngle_rad;
  double face_width_m = 0.0;
  double profile_shift = 0.0;  // x, in modules; for internal gears + moves the profile outward
  double addendum_coeff = constants::kAddendumCoeff;  // h_a*, in modules
  double dedendum_coeff = constants::kDedendumCoeff;  // h_f*, in modules
  double root_fillet_coeff = constants::kRootFilletCoeff;  // cutter tip radius ρ*, in modules
  double thinning_per_flank_m = 0.0;  // backlash allowance: each flank moved inward along its normal
  // External gears: bore diameter (0 = solid). Internal gears: outer rim diameter (required).
  double bore_diameter_m = 0.0;
  double rim_diameter_m = 0.0;
  double tooth0_angle_rad = 0.0;
  double chordal_deviation_m = constants::kDefaultChordalDeviation_m;
  GearErrors errors;
  // A helical gear: the helix angle on the reference circle, + right hand, − left hand (ISO
  // 21771), 0 for a spur gear. The values above then describe the transverse section (module_m =
  // m_n/cos β, pressure_angle_rad = α_t, the coefficients in transverse modules): the section the
  // outline, flank tables and mesh checks are made of. helical.hpp converts from the normal values
  // a spec gives.
  double helix_angle_rad = 0.0;
};

// Throws InputError naming the gear (spec.name) and the field when a value is impossible.
void validate_gear_spec(const GearSpec& spec);

}  // namespace gearsim

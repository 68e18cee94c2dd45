// The meshing of two spur gears: centre distance, working pressure angle, contact ratio, where
// contact starts on each flank, and a kinematic tip/fillet interference check. Gear `a` is an
// external gear; `b` is external or internal. Not dynamics: this is the ideal rigid geometry.
#pragma once

#include <string>
#include <vector>

#include "geometry/gear_spec.hpp"

namespace gearsim {

struct MeshGeometry {
  bool internal = false;  // b is an internal gear
  double ratio = 0;  // z_b / z_a
  double centre_distance_m = 0;  // operating centre distance
  double working_pressure_angle_rad = 0;
  double base_pitch_m = 0;
  // Length of the path of contact limited by the tip circles, and the contact ratio it gives.
  double contact_length_m = 0;
  double contact_ratio = 0;
  // Roll lengths (from each gear's base tangent point) where the mating tip starts contact,
  // against where each gear's involute begins (its form circle). Active < form: the mating tip
  // reaches below the involute, into the root fillet region.
  double active_start_roll_a_m = 0, form_roll_a_m = 0;
  double active_start_roll_b_m = 0, form_roll_b_m = 0;
  // Contact ratio once contact below the form circles is cut off (what the teeth really give).
  double effective_contact_ratio = 0;
  // Helical pairs: the overlap ratio ε_β = b·sin|β|/(π·m_n) (0 for spur); the total contact ratio
  // ε_γ is contact_ratio + overlap_ratio. contact_ratio is the transverse one, ε_α.
  double overlap_ratio = 0;
  // Deepest penetration of the mating tip corners into the other gear's outline along the
  // kinematic meshing path (error-free geometry, zero backlash): > 0 is a real collision.
  double tip_interference_a_m = 0;  // b's tips into a
  double tip_interference_b_m = 0;  // a's tips into b
  std::vector<std::string> problems;  // human-readable findings, empty when the mesh is clean
};

// Zero-backlash centre distance of the pair from the profile shifts (inv α_w formula).
double zero_backlash_centre_distance(const GearSpec& a, const GearSpec& b);

// Analyses the mesh at the given centre distance (pass zero_backlash_centre_distance() for the
// design value). Throws InputError when the pair cannot mesh (different modules or pressure
// angles, an internal gear as `a`, a centre distance the base circles cannot bridge).
MeshGeometry analyse_mesh(const GearSpec& a, const GearSpec& b, double centre_distance_m);

}  // namespace gearsim

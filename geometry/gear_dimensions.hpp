// GearDimensions: the derived sizes of one spur gear (the numbers of a gear table), computed from
// first principles of the involute and the generating rack. Radii in m, angles in rad.
// Not the outline: gear_profile.hpp draws it; these numbers are what it must agree with.
#pragma once

#include "geometry/gear_spec.hpp"

namespace gearsim {

struct GearDimensions {
  double reference_radius_m = 0;  // r = m·z/2
  double base_radius_m = 0;  // r_b = r·cos α
  double tip_radius_m = 0;  // external: r + m(h_a* + x); internal: r − m(h_a* − x)
  double root_radius_m = 0;  // external: r − m(h_f* − x); internal: r + m(h_f* + x)
  // Where the involute meets the root fillet (the generated form circle, d_Ff/2).
  double form_radius_m = 0;
  double pitch_m = 0;  // p = π·m
  double base_pitch_m = 0;  // p_b = π·m·cos α
  // Arc tooth thickness and space width on the reference circle, thinning included.
  double tooth_thickness_m = 0;
  double space_width_m = 0;
  double tip_thickness_m = 0;  // arc thickness on the tip circle (external) / tip of internal tooth
  // Span measurement over k teeth (external gears; 0 for internal), thinning included.
  int span_teeth = 0;
  double span_m = 0;
};

// Throws InputError (naming the gear) for geometry that cannot be made: undercut, pointed teeth,
// an internal tip circle inside the base circle, a bore through the root.
GearDimensions gear_dimensions(const GearSpec& spec);

// Rack-generation constants of an external gear (see gear_profile.cpp): the roll length at the
// form circle, m. Negative means undercut.
double rack_form_roll_length(const GearSpec& spec);

}  // namespace gearsim

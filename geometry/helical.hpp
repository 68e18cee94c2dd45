// Helical gears: the transverse section a helical gear's normal values give (ISO 21771), the
// helix on the base cylinder, and the overlap ratio of a helical pair. A helical gear is its
// transverse section twisted along the axis: the section at axial position ζ (from the face's
// middle) turned by ζ·tan β/r about the axis, r the reference radius.
#pragma once

#include "geometry/gear_spec.hpp"

namespace gearsim {

// What a helical gear is given by: its normal module and normal pressure angle, the helix angle
// on the reference circle (signed: + right hand) and the coefficients in normal modules.
struct NormalValues {
  double module_m = 0;  // m_n
  double pressure_angle_rad = 0;  // α_n
  double helix_angle_rad = 0;  // β, signed
  double addendum_coeff = 0, dedendum_coeff = 0, root_fillet_coeff = 0;  // h_a*, h_f*, ρ* in m_n
  double profile_shift = 0;  // x_n
};

// Sets spec's transverse values from the normal ones: m_t = m_n/cos β, tan α_t = tan α_n/cos β,
// the coefficients times cos β (each length kept: h_a*·m_n = h_a,t*·m_t), x_t = x_n·cos β (the
// same shift x_n·m_n) and spec.helix_angle_rad = β. The root fillet's radius is taken in the
// transverse section (ρ*·m_n there): the fillet of a hobbed helical gear's section is an ellipse's
// arc, which the contact never reaches. Lengths along the flank normal (thinning, flank offsets,
// profile slopes) are converted by normal_to_transverse_m.
void set_transverse(GearSpec& spec, const NormalValues& normal);

// The normal module and normal pressure angle of spec (its transverse values for a spur gear).
double normal_module_m(const GearSpec& spec);
double normal_pressure_angle_rad(const GearSpec& spec);

// β_b: tan β_b = tan β·cos α_t, signed as β.
double base_helix_angle_rad(const GearSpec& spec);

// A length along the flank's normal (in the normal plane of the tooth) as the transverse
// section's displacement along its own flank normal: ℓ/cos β_b.
double normal_to_transverse_m(const GearSpec& spec, double normal_length_m);

// The twist of the section per metre along the axis, rad/m: tan β/r (+ turns counter-clockwise
// seen from +z as z grows, for a right-hand gear).
double twist_rad_per_m(const GearSpec& spec);

// The overlap ratio of a pair of helical gears on face width b (the narrower face): ε_β = b·sin|β|/(π·m_n).
double overlap_ratio(const GearSpec& a, const GearSpec& b);

}  // namespace gearsim

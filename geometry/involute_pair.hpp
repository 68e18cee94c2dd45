// The mesh of two involute gears from their measured teeth alone: the centre distance at which
// they mesh without backlash, and at a given distance the operating pressure angle, the normal
// backlash and the contact ratio. For recognised CAD gears (gear_recognition.hpp) as much as for
// generated ones. Not a dynamics model: tooth_contact does the contact; this is the gear table.
#pragma once

#include <string>

#include "geometry/gear_recognition.hpp"
#include "geometry/gear_spec.hpp"

namespace gearsim {

// What the mesh arithmetic needs of one gear's teeth.
struct InvoluteTeeth {
  int teeth = 0;
  bool internal = false;
  double base_radius_m = 0;
  // Half the tooth's angular thickness at the base circle (both flanks' base_half_angle_rad
  // averaged): an external tooth narrows as inv(α_r) grows, an internal one widens.
  double base_half_angle_rad = 0;
  double tip_radius_m = 0;  // where the involute ends at the tip (its active end), m
  // How well the teeth are known: a recognised gear's tooth thickness along the normal is
  // uncertain by the rms of its two flank fits added (0 for a generated gear), m.
  double thickness_tolerance_m = 0;
  // And its base radius to this much: half the two flank fits' difference, or where recognised
  // as standard the fit's distance from m·z·cos α/2 if larger (FreeCAD's Bézier flanks fit base
  // radii 0.8–0.9 µm short on 12–18 teeth at rms 0.01 µm: the rms alone does not bound them), m.
  double base_radius_tolerance_m = 0;
  // The module when recognised as a standard one (ISO 54 / DIN 780 with a common pressure
  // angle; a generated gear's own module), else 0, m.
  double standard_module_m = 0;
};

InvoluteTeeth involute_teeth(const RecognisedGear& g);
InvoluteTeeth involute_teeth(const GearSpec& spec);

struct InvolutePair {
  double centre_distance_m = 0;  // the distance these figures are for
  double zero_backlash_centre_distance_m = 0;
  double operating_pressure_angle_rad = 0;  // at centre_distance_m
  double normal_backlash_m = 0;  // along the line of action; < 0: the teeth overlap
  double contact_ratio = 0;  // transverse, from the active tip radii
  double base_pitch_mismatch_m = 0;  // |p_b1 − p_b2|
  // The zero-backlash distance is known to ± this much: both teeth's thickness tolerances over
  // |dj_n/da| = 2 sin α_w at that distance, plus both base radius tolerances over cos α_w
  // (a = (r_b1 ± r_b2)/cos α_w), m.
  double zero_backlash_tolerance_m = 0;
};

// Base pitches may differ by this much and still mesh (conjugate action needs equal base pitch;
// DIN 3961 class 8 allows single pitch deviations of ~10 µm), m.
inline constexpr double kMaxBasePitchMismatch_m = 5e-6;

// The mesh of a (external) with b (external, or internal with a inside it). centre_distance_m
// ≤ 0: at the zero-backlash distance. Throws InputError naming `who` when the base pitches
// differ by more than kMaxBasePitchMismatch_m, both are internal, or the distance is one at
// which the involutes cannot act (closer than the base circles allow).
InvolutePair involute_pair(const InvoluteTeeth& a, const InvoluteTeeth& b, double centre_distance_m, const std::string& who);

// The distance m·(z_b ± z_a)/2 of two gears of one standard module (− for an internal pair), or
// 0 when either is not recognised as standard or their modules differ.
double standard_centre_distance(const InvoluteTeeth& a, const InvoluteTeeth& b);

// Where a pair is placed when no centre distance is given, and why when it is not the fits'
// zero-backlash distance a_0 itself. With teeth known to a tolerance (zero_backlash_tolerance_m
// = u > 0), a_0 could be anywhere in a_0 ± u: the standard distance when it lies in that band
// (the CAD tool's own distance, exact for unshifted zero-backlash gears), else the loose end of
// the band (a_0 + u external, a_0 − u internal), never tighter than the fits can tell.
struct PairPlacement {
  double centre_distance_m = 0;
  std::string note;  // empty at a_0 (teeth known exactly)
};
PairPlacement place_pair(const InvoluteTeeth& a, const InvoluteTeeth& b, const std::string& who);

// Where a planetary set's planets sit when no centre distance is given: sun–planet backlash grows
// with the distance, planet–ring backlash shrinks, so a distance meshes both from sun–planet's
// zero-backlash distance a_sp to planet–ring's a_pr, each known to ± its tolerance u. With teeth
// known to a tolerance (meshes), the standard distance where it lies in [a_sp − u_sp, a_pr + u_pr]
// (the fits' base radii, 0.8–0.9 µm short on FreeCAD's small gears, move both zero-backlash
// distances by about that); else midway, or where the two conflict by less than u_sp + u_pr, the
// distance equally far into both tolerances. Throws InputError (the pairs' figures, or a conflict
// beyond the tolerances, named) when none meshes both; `note` says why when not midway.
PairPlacement place_planetary(const InvoluteTeeth& sun, const InvoluteTeeth& planet, const InvoluteTeeth& ring);

}  // namespace gearsim

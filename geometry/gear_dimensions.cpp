#include "geometry/gear_dimensions.hpp"

#include <cmath>
#include <numbers>
#include <sstream>

#include "core/errors.hpp"
#include "geometry/involute.hpp"
#include "geometry/constants.hpp"

namespace gearsim {
namespace {

using gearsim::constants::kPi;

std::string gear_name(const GearSpec& s) { return s.name.empty() ? "gear" : "gear '" + s.name + "'"; }

// Internal gear root-fillet circle: tangent to the root circle from inside and to the flank.
// Returns the roll length of the tangency point on the flank's involute.
double internal_form_roll_length(const GearSpec& s, double rb, double rf) {
  const double rho = s.root_fillet_coeff * s.module_m;
  const double centre_roll = roll_length_at(rb, rf - rho);
  return centre_roll + rho;
}

}  // namespace

double rack_form_roll_length(const GearSpec& s) {
  const double m = s.module_m, a = s.pressure_angle_rad;
  const double r = 0.5 * m * s.teeth;
  const double rho = s.root_fillet_coeff * m;
  // Depth below the rolling pitch line of the rack flank's tangency with the cutter tip fillet.
  const double depth = s.dedendum_coeff * m - rho * (1.0 - std::sin(a)) - s.profile_shift * m;
  // A rack-flank point at that depth generates the involute point on the line of action at
  // depth/sin α from the pitch point, i.e. r·sin α − depth/sin α from the base tangent point.
  return r * std::sin(a) - depth / std::sin(a);
}

void validate_gear_spec(const GearSpec& s) {
  const std::string who = gear_name(s);
  auto fail = [&](const std::string& key, const std::string& what) { throw InputError(who + ": " + key + ": " + what); };
  if (s.teeth < 3) fail("teeth", "expected an integer ≥ 3, got " + std::to_string(s.teeth));
  if (!(s.module_m > 0) || !std::isfinite(s.module_m)) fail("module_m", "expected a positive length in m");
  if (!(s.pressure_angle_rad > 0.0 && s.pressure_angle_rad < kPi / 4)) fail("pressure_angle", "expected an angle in (0°, 45°)");
  if (!(s.face_width_m > 0)) fail("face_width_m", "expected a positive length in m");
  if (!(s.addendum_coeff >= 0)) fail("addendum_coeff", "expected ≥ 0");
  if (!(s.dedendum_coeff > s.root_fillet_coeff * (1.0 - std::sin(s.pressure_angle_rad))))
    fail("dedendum_coeff", "must exceed the fillet's height ρ*(1 − sin α)");
  if (!(s.root_fillet_coeff >= 0)) fail("root_fillet_coeff", "expected ≥ 0");
  if (!(s.thinning_per_flank_m >= 0)) fail("thinning_per_flank_m", "expected ≥ 0 (tooth thinning)");
  if (!(s.chordal_deviation_m >= constants::kMinChordalDeviation_m)) fail("chordal_deviation_m", "expected ≥ 1e-9 m");
  if (s.kind == GearKind::Internal && !(s.rim_diameter_m > 0)) fail("rim_diameter_m", "an internal gear needs its outer rim diameter");
  if (s.kind == GearKind::External && s.rim_diameter_m != 0) fail("rim_diameter_m", "only internal gears have a rim; use bore_diameter_m");
  if (s.kind == GearKind::Internal && s.bore_diameter_m != 0) fail("bore_diameter_m", "internal gears have no bore; use rim_diameter_m");
  if (!(s.bore_diameter_m >= 0)) fail("bore_diameter_m", "expected ≥ 0");
  auto check_tooth = [&](int k, const std::string& key) {
    if (k < 0 || k >= s.teeth) fail(key, "tooth index " + std::to_string(k) + " outside 0.." + std::to_string(s.teeth - 1));
  };
  for (const FlankOffset& f : s.errors.flank_offsets) check_tooth(f.tooth, "errors.flank_offsets.tooth");
  for (const PitchError& p : s.errors.pitch_errors) check_tooth(p.tooth, "errors.pitch_errors.tooth");
  for (const ProfileSlopeError& p : s.errors.profile_slopes)
    if (p.tooth >= 0) check_tooth(p.tooth, "errors.profile_slopes.tooth");
  if (!(s.errors.eccentricity.eccentricity_m >= 0)) fail("errors.eccentricity_m", "expected ≥ 0 (use phase for the direction)");
}

GearDimensions gear_dimensions(const GearSpec& s) {
  validate_gear_spec(s);
  const std::string who = gear_name(s);
  const double m = s.module_m, a = s.pressure_angle_rad, x = s.profile_shift;
  const double z = s.teeth;
  GearDimensions d;
  d.reference_radius_m = 0.5 * m * z;
  d.base_radius_m = d.reference_radius_m * std::cos(a);
  d.pitch_m = kPi * m;
  d.base_pitch_m = d.pitch_m * std::cos(a);
  // Thinning t along the normal moves the flank by t/cos α along the reference circle.
  const double thinning_arc = 2.0 * s.thinning_per_flank_m / std::cos(a);
  const bool internal = s.kind == GearKind::Internal;
  const double nominal_tooth = kPi * m / 2 + (internal ? -2.0 : 2.0) * x * m * std::tan(a);
  d.tooth_thickness_m = nominal_tooth - thinning_arc;
  d.space_width_m = d.pitch_m - d.tooth_thickness_m;

  if (!internal) {
    d.tip_radius_m = d.reference_radius_m + m * (s.addendum_coeff + x);
    d.root_radius_m = d.reference_radius_m - m * (s.dedendum_coeff - x);
    const double form_roll = rack_form_roll_length(s);
    if (form_roll < 0) {
      std::ostringstream msg;
      msg << who << ": undercut: the generating rack cuts below the base circle (roll length at the"
          << " form circle " << form_roll * 1e3 << " mm < 0); raise profile_shift or teeth";
      throw InputError(msg.str());
    }
    d.form_radius_m = std::hypot(d.base_radius_m, form_roll);
    if (s.bore_diameter_m / 2 >= d.root_radius_m) throw InputError(who + ": bore_diameter_m: the bore reaches the root circle");
    // Span over k teeth: W = m cos α [π(k − ½) + z inv α] + 2 x m sin α, less the thinning.
    d.span_teeth = std::max(1, static_cast<int>(std::lround(z * a / kPi + 0.5)));
    d.span_m = m * std::cos(a) * (kPi * (d.span_teeth - 0.5) + z * involute(a)) + 2 * x * m * std::sin(a) - 2 * s.thinning_per_flank_m;
  } else {
    d.tip_radius_m = d.reference_radius_m - m * (s.addendum_coeff - x);
    d.root_radius_m = d.reference_radius_m + m * (s.dedendum_coeff + x);
    if (d.tip_radius_m <= d.base_radius_m)
      throw InputError(who +
                       ": internal tip circle lies inside the base circle; the tooth tip"
                       " cannot be an involute (lower addendum_coeff or raise profile_shift)");
    d.form_radius_m = std::hypot(d.base_radius_m, internal_form_roll_length(s, d.base_radius_m, d.root_radius_m));
    if (s.rim_diameter_m / 2 <= d.root_radius_m) throw InputError(who + ": rim_diameter_m: the rim must lie outside the root circle");
  }
  // Tooth thickness on the tip circle from the involute: s_a = d_a (s/d + inv α − inv α_a).
  const double alpha_tip = pressure_angle_at(d.base_radius_m, d.tip_radius_m);
  const double ref_half_angle = 0.5 * d.tooth_thickness_m / d.reference_radius_m;
  double tip_half_angle;
  if (!internal) {
    tip_half_angle = ref_half_angle + involute(a) - involute(alpha_tip);
  } else {
    const double space_half = 0.5 * d.space_width_m / d.reference_radius_m;
    tip_half_angle = kPi / z - (space_half + involute(a) - involute(alpha_tip));
  }
  d.tip_thickness_m = 2.0 * tip_half_angle * d.tip_radius_m;
  if (d.tip_thickness_m <= 0) throw InputError(who + ": pointed teeth: the flanks cross below the tip circle");
  return d;
}

}  // namespace gearsim

#include "geometry/involute_pair.hpp"

#include <cmath>
#include <numbers>
#include <sstream>

#include "core/errors.hpp"
#include "geometry/gear_dimensions.hpp"
#include "geometry/involute.hpp"
#include "geometry/constants.hpp"

namespace gearsim {
namespace {
using gearsim::constants::kPi;
}  // namespace

InvoluteTeeth involute_teeth(const RecognisedGear& g) {
  InvoluteTeeth t;
  t.teeth = g.teeth;
  t.internal = g.internal;
  t.base_radius_m = g.base_radius_m;
  t.base_half_angle_rad = 0.5 * (g.ccw.base_half_angle_rad + g.cw.base_half_angle_rad);
  t.tip_radius_m = g.internal ? std::max(g.ccw.active_from_m, g.cw.active_from_m) : std::min(g.ccw.active_to_m, g.cw.active_to_m);
  t.thickness_tolerance_m = g.ccw.rms_m + g.cw.rms_m;
  t.standard_module_m = g.standard ? g.module_m : 0.0;
  t.base_radius_tolerance_m = 0.5 * std::abs(g.ccw.base_radius_m - g.cw.base_radius_m);
  if (g.standard)
    t.base_radius_tolerance_m =
        std::max(t.base_radius_tolerance_m, std::abs(g.base_radius_m - 0.5 * g.module_m * g.teeth * std::cos(g.pressure_angle_rad)));
  return t;
}

InvoluteTeeth involute_teeth(const GearSpec& spec) {
  const GearDimensions d = gear_dimensions(spec);
  InvoluteTeeth t;
  t.teeth = spec.teeth;
  t.internal = spec.kind == GearKind::Internal;
  t.base_radius_m = d.base_radius_m;
  // Half-angle at the reference circle, carried to the base circle along the involute.
  const double half_at_r = d.tooth_thickness_m / (2 * d.reference_radius_m);
  const double inv_r = involute(spec.pressure_angle_rad);
  t.base_half_angle_rad = t.internal ? half_at_r - inv_r : half_at_r + inv_r;
  t.tip_radius_m = d.tip_radius_m;
  t.standard_module_m = spec.module_m;
  return t;
}

InvolutePair involute_pair(const InvoluteTeeth& a, const InvoluteTeeth& b, double centre_distance_m, const std::string& who) {
  if (a.internal) return involute_pair(b, a, centre_distance_m, who);
  std::ostringstream msg;
  if (b.internal && a.internal) throw InputError(who + ": two internal gears do not mesh");
  InvolutePair p;
  const double pb_a = 2 * kPi * a.base_radius_m / a.teeth, pb_b = 2 * kPi * b.base_radius_m / b.teeth;
  p.base_pitch_mismatch_m = std::abs(pb_a - pb_b);
  if (p.base_pitch_mismatch_m > kMaxBasePitchMismatch_m) {
    msg << who << ": base pitches differ by " << p.base_pitch_mismatch_m * 1e6 << " um (" << pb_a * 1e3 << " and " << pb_b * 1e3
        << " mm; limit " << kMaxBasePitchMismatch_m * 1e6 << " um): these involutes cannot mesh (different module or pressure angle)";
    throw InputError(msg.str());
  }
  const double za = a.teeth, zb = b.teeth, ba = a.base_half_angle_rad, bb = b.base_half_angle_rad;
  const double s = b.internal ? -1.0 : 1.0;  // internal: the ring's base circle is the far one
  // Zero backlash: the teeth fill each other's spaces on the operating pitch circles.
  //  external: z_a(β_a − inv) + z_b(β_b − inv) = π;  internal: z_a(β_a − inv) = π − z_b(β_b + inv).
  const double inv_w = b.internal ? (kPi - za * ba - zb * bb) / (zb - za) : (za * ba + zb * bb - kPi) / (za + zb);
  if (!(inv_w > 0)) {
    msg << who << ": the teeth are too thin to close the backlash at any distance (inv α_w = " << inv_w << ")";
    throw InputError(msg.str());
  }
  const double rb_sum = b.base_radius_m + s * a.base_radius_m;
  p.zero_backlash_centre_distance_m = rb_sum / std::cos(inverse_involute(inv_w));
  p.centre_distance_m = centre_distance_m > 0 ? centre_distance_m : p.zero_backlash_centre_distance_m;
  if (p.centre_distance_m <= rb_sum) {
    msg << who << ": at a centre distance of " << p.centre_distance_m * 1e3 << " mm the base circles (sum " << rb_sum * 1e3
        << " mm) leave no line of action";
    throw InputError(msg.str());
  }
  const double cos_w0 = rb_sum / p.zero_backlash_centre_distance_m;
  p.zero_backlash_tolerance_m = (a.thickness_tolerance_m + b.thickness_tolerance_m) / (2 * std::sqrt(1 - cos_w0 * cos_w0)) +
                                (a.base_radius_tolerance_m + b.base_radius_tolerance_m) / cos_w0;
  const double alpha = std::acos(rb_sum / p.centre_distance_m), inv = involute(alpha);
  p.operating_pressure_angle_rad = alpha;
  // Normal backlash along the line of action: base pitch minus both teeth's base-circle arcs
  // at the operating angle (internal: the ring's space instead of its tooth).
  const double pb = 0.5 * (pb_a + pb_b);
  p.normal_backlash_m = b.internal ? 2 * b.base_radius_m * (kPi / zb - bb - inv) - 2 * a.base_radius_m * (ba - inv)
                                   : pb - 2 * a.base_radius_m * (ba - inv) - 2 * b.base_radius_m * (bb - inv);
  const double ga = std::sqrt(std::max(0.0, a.tip_radius_m * a.tip_radius_m - a.base_radius_m * a.base_radius_m));
  const double gb = std::sqrt(std::max(0.0, b.tip_radius_m * b.tip_radius_m - b.base_radius_m * b.base_radius_m));
  p.contact_ratio = (ga + s * gb - s * p.centre_distance_m * std::sin(alpha)) / pb;
  return p;
}

double standard_centre_distance(const InvoluteTeeth& a, const InvoluteTeeth& b) {
  const double ma = a.standard_module_m, mb = b.standard_module_m;
  if (!(ma > 0) || !(mb > 0) || std::abs(ma - mb) > 1e-9 * ma) return 0.0;
  const double zi = a.internal ? a.teeth : b.internal ? b.teeth : 0, ze = a.internal ? b.teeth : a.teeth;
  return zi > 0 ? 0.5 * ma * (zi - ze) : 0.5 * ma * (a.teeth + b.teeth);
}

PairPlacement place_pair(const InvoluteTeeth& a, const InvoluteTeeth& b, const std::string& who) {
  const InvolutePair p = involute_pair(a, b, 0.0, who);
  const double a0 = p.zero_backlash_centre_distance_m, u = p.zero_backlash_tolerance_m;
  if (!(u > 0)) return {a0, ""};
  std::ostringstream msg;
  msg.precision(7);
  const double standard = standard_centre_distance(a, b);
  if (standard > 0 && std::abs(standard - a0) <= u) {
    msg << who << ": placed at the standard distance " << standard * 1e3 << " mm; the flank fits put zero backlash at " << a0 * 1e3
        << " mm ± " << u * 1e6 << " um";
    return {standard, msg.str()};
  }
  const bool internal = a.internal || b.internal;
  const double placed = internal ? a0 - u : a0 + u;
  msg << who << ": placed at " << placed * 1e3 << " mm, " << u * 1e6 << " um " << (internal ? "inside" : "outside")
      << " the flank fits' zero-backlash distance " << a0 * 1e3
      << " mm (its tolerance from the flank fits: the teeth's thicknesses known to "
      << (a.thickness_tolerance_m + b.thickness_tolerance_m) * 1e6 << " um, their base radii to "
      << (a.base_radius_tolerance_m + b.base_radius_tolerance_m) * 1e6 << " um), so that the teeth do not overlap";
  return {placed, msg.str()};
}

PairPlacement place_planetary(const InvoluteTeeth& sun, const InvoluteTeeth& planet, const InvoluteTeeth& ring) {
  const InvolutePair sp = involute_pair(sun, planet, 0.0, "sun–planet");
  const InvolutePair pr = involute_pair(planet, ring, 0.0, "planet–ring");
  const double a_sp = sp.zero_backlash_centre_distance_m, a_pr = pr.zero_backlash_centre_distance_m;
  const double u_sp = sp.zero_backlash_tolerance_m, u_pr = pr.zero_backlash_tolerance_m;
  std::ostringstream both;
  both.precision(7);
  both << "sun–planet needs at least " << a_sp * 1e3 << " mm (zero backlash), planet–ring at most " << a_pr * 1e3 << " mm";
  if (a_sp - a_pr > u_sp + u_pr + 1e-9) {
    if (u_sp + u_pr > 0) both << ", a conflict of " << (a_sp - a_pr) * 1e6 << " um beyond the flank fits' " << (u_sp + u_pr) * 1e6 << " um";
    throw InputError("no centre distance meshes both: " + both.str());
  }
  const double standard = standard_centre_distance(sun, planet);
  const bool use_standard = u_sp + u_pr > 0 && standard > 0 && std::abs(standard - standard_centre_distance(planet, ring)) <= 1e-12 &&
                            standard >= a_sp - u_sp && standard <= a_pr + u_pr;
  const bool conflict = a_sp > a_pr + 1e-9;
  PairPlacement p;
  p.centre_distance_m = use_standard ? standard : conflict ? a_sp - u_sp * (a_sp - a_pr) / (u_sp + u_pr) : 0.5 * (a_sp + a_pr);
  if (use_standard || conflict) {
    std::ostringstream note;
    note.precision(7);
    note << "planetary: " << both.str() << " (flank fits' tolerances " << u_sp * 1e6 << " and " << u_pr * 1e6 << " um): placed at "
         << (use_standard ? "the standard distance " : "the distance equally far into both, ") << p.centre_distance_m * 1e3 << " mm";
    p.note = note.str();
  }
  return p;
}

}  // namespace gearsim

#include "geometry/gear_profile.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "core/errors.hpp"
#include "geometry/involute.hpp"
#include "geometry/tessellate.hpp"
#include "geometry/constants.hpp"

namespace gearsim {
namespace {

using Eigen::Vector2d;
using gearsim::constants::kPi;

Vector2d rotate(const Vector2d& p, double a) {
  const double c = std::cos(a), s = std::sin(a);
  return {c * p.x() - s * p.y(), s * p.x() + c * p.y()};
}
Vector2d unit(double a) { return {std::cos(a), std::sin(a)}; }

// How one flank of one tooth departs from the nominal: a rigid rotation (flank offset, thinning,
// pitch error) plus a roll-length-proportional normal offset (profile slope).
struct FlankMod {
  double rotation_rad = 0;
  double slope_m = 0;
};

struct ToothMods {
  FlankMod ccw, cw;
};

// Rotation sign that moves a flank out of its tooth: a Ccw flank moves counter-clockwise.
double outward_sign(Flank f) { return f == Flank::Ccw ? 1.0 : -1.0; }

std::vector<ToothMods> collect_mods(const GearSpec& s, const GearDimensions& d) {
  std::vector<ToothMods> mods(s.teeth);
  auto flank_of = [](ToothMods& t, Flank f) -> FlankMod& { return f == Flank::Ccw ? t.ccw : t.cw; };
  for (ToothMods& t : mods) {
    t.ccw.rotation_rad = -s.thinning_per_flank_m / d.base_radius_m;
    t.cw.rotation_rad = +s.thinning_per_flank_m / d.base_radius_m;
  }
  for (const FlankOffset& f : s.errors.flank_offsets)
    flank_of(mods[f.tooth], f.flank).rotation_rad += outward_sign(f.flank) * f.normal_offset_m / d.base_radius_m;
  for (const PitchError& p : s.errors.pitch_errors) {
    mods[p.tooth].ccw.rotation_rad += p.error_m / d.reference_radius_m;
    mods[p.tooth].cw.rotation_rad += p.error_m / d.reference_radius_m;
  }
  for (const ProfileSlopeError& p : s.errors.profile_slopes)
    for (int k = 0; k < s.teeth; ++k)
      if (p.tooth < 0 || p.tooth == k) flank_of(mods[k], p.flank).slope_m += p.slope_m;
  return mods;
}

// Everything needed to evaluate the nominal Cw flank of tooth 0 (centred on polar angle 0);
// the Ccw flank is its mirror image in the x axis.
struct ToothFrame {
  const GearSpec& s;
  const GearDimensions& d;
  bool internal;
  double rb, start;  // Cw flank involute: base-circle start angle, rad
  double roll_form, roll_tip;  // roll lengths at form and tip circle, m
};

ToothFrame make_frame(const GearSpec& s, const GearDimensions& d) {
  const bool internal = s.kind == GearKind::Internal;
  const double a = s.pressure_angle_rad;
  const double nominal_half = (kPi / 2 + (internal ? -2 : 2) * s.profile_shift * std::tan(a)) / s.teeth;
  // External: Cw flank at polar angle −(ψ + inv α − inv α_r). Internal: the flank bounds the space
  // centred at −π/z, whose half angle is η + inv α − inv α_r with η = π/z − ψ.
  const double start = internal ? -kPi / s.teeth + (kPi / s.teeth - nominal_half) + involute(a) : -(nominal_half + involute(a));
  return {s,
          d,
          internal,
          d.base_radius_m,
          start,
          roll_length_at(d.base_radius_m, d.form_radius_m),
          roll_length_at(d.base_radius_m, d.tip_radius_m)};
}

// Nominal Cw-flank involute point at roll length L (external: unwinds counter-clockwise from
// the base circle; internal: clockwise).
Vector2d cw_involute(const ToothFrame& f, double L) {
  const double t = L / f.rb;
  if (!f.internal) {
    const double b = f.start + t;
    return f.rb * unit(b) + L * Vector2d(std::sin(b), -std::cos(b));
  }
  const double b = f.start - t;
  return f.rb * unit(b) + L * Vector2d(-std::sin(b), std::cos(b));
}

double slope_rotation(const ToothFrame& f, const FlankMod& m, Flank flank, double L) {
  if (m.slope_m == 0) return 0;
  const double share = (L - f.roll_form) / (f.roll_tip - f.roll_form);
  return outward_sign(flank) * m.slope_m * share / f.rb;
}

// Flank point of tooth `k` (angle θ_k) at roll length L, errors included.
Vector2d flank_at(const ToothFrame& f, double tooth_angle, const FlankMod& m, Flank flank, double L) {
  Vector2d p = cw_involute(f, L);
  if (flank == Flank::Ccw) p.y() = -p.y();
  return rotate(p, tooth_angle + m.rotation_rad + slope_rotation(f, m, flank, L));
}

// Rack-generated trochoidal fillet of the Cw flank of an external tooth centred on angle 0, as a
// function of the rolling angle φ. The gear is drawn with the tooth on +y while the rack (above,
// reference line at r + x·m) slides by r·φ; the cutter tip circle's envelope point lies on the
// line from its centre through the pitch point I (the normal passes through the instant centre).
struct Trochoid {
  double r, u_centre, v_centre, rho;  // cutter tip-circle centre in rack coordinates, m
  double phi_root, phi_flank;
};

Trochoid make_trochoid(const GearSpec& s, const GearDimensions& d) {
  const double m = s.module_m, a = s.pressure_angle_rad;
  Trochoid t;
  t.r = d.reference_radius_m;
  t.rho = s.root_fillet_coeff * m;
  // Height of the tip-circle centre above the rolling line (negative: below it, in the gap).
  t.v_centre = s.profile_shift * m - s.dedendum_coeff * m + t.rho;
  // Cutter tooth centred at u = π·m/2; its left flank is u = π·m/4 − v·tan α (v from the
  // reference line); the tip circle is tangent to it and to the tip line.
  const double v_ref = t.v_centre - s.profile_shift * m;
  t.u_centre = kPi * m / 4 - v_ref * std::tan(a) + t.rho / std::cos(a);
  if (t.v_centre >= 0) throw InputError("gear '" + s.name + "': profile_shift too large for the rack's fillet geometry");
  t.phi_root = -t.u_centre / t.r;
  t.phi_flank = (t.v_centre / std::tan(a) - t.u_centre) / t.r;
  return t;
}

Vector2d trochoid_point(const Trochoid& t, double phi) {
  const Vector2d c(t.u_centre + t.r * phi, t.r + t.v_centre);
  const Vector2d pitch(0.0, t.r);
  const Vector2d q = c + t.rho * (c - pitch).normalized();
  return rotate(rotate(q, phi), -kPi / 2);
}

// Internal gear: circular fillet of the Cw flank of tooth 0, tangent to the root circle
// (centre at radius r_f − ρ on the flank's offset involute) and to the flank.
struct InternalFillet {
  Vector2d centre, on_flank, on_root;
  double rho;
};

InternalFillet make_internal_fillet(const ToothFrame& f) {
  const double rho = f.s.root_fillet_coeff * f.s.module_m;
  const double centre_roll = roll_length_at(f.rb, f.d.root_radius_m - rho);
  const double b = f.start - (centre_roll + rho) / f.rb;  // base point shared by centre and tangency
  const Vector2d tangent(-std::sin(b), std::cos(b));
  InternalFillet fl;
  fl.rho = rho;
  fl.centre = f.rb * unit(b) + centre_roll * tangent;
  fl.on_flank = fl.centre + rho * tangent;
  fl.on_root = fl.centre.normalized() * f.d.root_radius_m;
  return fl;
}

double angle_of(const Vector2d& p) { return std::atan2(p.y(), p.x()); }

// Shortest signed angle from a0 to a1.
double angle_between(double a0, double a1) { return std::remainder(a1 - a0, 2 * kPi); }

// The toothed loop, counter-clockwise, teeth in order, errors included.
std::vector<Vector2d> toothed_loop(const GearSpec& s, const GearDimensions& d) {
  const ToothFrame f = make_frame(s, d);
  const std::vector<ToothMods> mods = collect_mods(s, d);
  const double tol = s.chordal_deviation_m;
  const double step = 2 * kPi / s.teeth;
  std::vector<Vector2d> loop;

  // Fillet of one flank as a curve from the root end (u = 0) to the flank end (u = 1), nominal Cw.
  Curve2 cw_fillet;
  if (!f.internal) {
    const Trochoid t = make_trochoid(s, d);
    GEARSIM_CHECK((trochoid_point(t, t.phi_flank) - cw_involute(f, f.roll_form)).norm() < 1e-9,
                  "trochoid and involute must meet at the form circle");
    cw_fillet = [t](double u) { return trochoid_point(t, t.phi_root + u * (t.phi_flank - t.phi_root)); };
  } else {
    const InternalFillet fl = make_internal_fillet(f);
    const double a0 = angle_of(fl.on_root - fl.centre);
    const double span = angle_between(a0, angle_of(fl.on_flank - fl.centre));
    cw_fillet = [fl, a0, span](double u) { return Vector2d(fl.centre + fl.rho * unit(a0 + u * span)); };
  }
  auto fillet = [&](double tooth_angle, const FlankMod& m, Flank flank) -> Curve2 {
    const double rot = tooth_angle + m.rotation_rad;
    if (flank == Flank::Cw) return [=](double u) { return rotate(cw_fillet(u), rot); };
    return [=](double u) {  // Ccw: mirrored and run from flank end to root end
      Vector2d p = cw_fillet(1.0 - u);
      p.y() = -p.y();
      return rotate(p, rot);
    };
  };
  const Vector2d origin = Vector2d::Zero();
  const double root_r = d.root_radius_m;
  for (int k = 0; k < s.teeth; ++k) {
    const double theta = s.tooth0_angle_rad + k * step;
    const ToothMods& m = mods[k];
    // Cw half: fillet from the root, then the involute from form to tip circle.
    tessellate_curve(fillet(theta, m.cw, Flank::Cw), 0.0, 1.0, tol, loop);
    tessellate_curve([&](double L) { return flank_at(f, theta, m.cw, Flank::Cw, L); }, f.roll_form, f.roll_tip, tol, loop);
    // Tip arc (top land of an external tooth, inner land of an internal one).
    const double tip0 = angle_of(flank_at(f, theta, m.cw, Flank::Cw, f.roll_tip));
    const double tip1 = angle_of(flank_at(f, theta, m.ccw, Flank::Ccw, f.roll_tip));
    const double tip_span = angle_between(tip0, tip1);
    if (tip_span <= 0) throw InputError("gear '" + s.name + "': tooth " + std::to_string(k) + ": flank errors make the tooth pointed");
    tessellate_arc(origin, d.tip_radius_m, tip0, tip0 + tip_span, tol, loop);
    // Ccw half: involute from tip down to form circle, then the fillet to the root.
    tessellate_curve([&](double L) { return flank_at(f, theta, m.ccw, Flank::Ccw, L); }, f.roll_tip, f.roll_form, tol, loop);
    tessellate_curve(fillet(theta, m.ccw, Flank::Ccw), 0.0, 1.0, tol, loop);
    // Root arc to the next tooth's Cw fillet.
    const int next = (k + 1) % s.teeth;
    const double root0 = angle_of(fillet(theta, m.ccw, Flank::Ccw)(1.0));
    const double root1 = angle_of(fillet(s.tooth0_angle_rad + next * step, mods[next].cw, Flank::Cw)(0.0));
    const double root_span = angle_between(root0, root1);
    if (root_span < 0)
      throw InputError("gear '" + s.name + "': between teeth " + std::to_string(k) + " and " + std::to_string(next) +
                       " the root fillets overlap: flank errors too large");
    tessellate_arc(origin, root_r, root0, root0 + root_span, tol, loop);
  }
  // Geometric eccentricity shifts the toothing, not the rotation axis.
  const Eccentricity& e = s.errors.eccentricity;
  if (e.eccentricity_m != 0)
    for (Vector2d& p : loop) p += e.eccentricity_m * unit(e.phase_rad);
  return loop;
}

Polygon2 circle(double radius_m, double tol, bool clockwise) {
  Polygon2 c;
  tessellate_arc(Vector2d::Zero(), radius_m, 0.0, clockwise ? -2 * kPi : 2 * kPi, tol, c.points);
  return c;
}

}  // namespace

GearOutline make_gear_outline(const GearSpec& s) {
  GearOutline g;
  g.dims = gear_dimensions(s);
  Polygon2 teeth{toothed_loop(s, g.dims)};
  if (s.kind == GearKind::External) {
    g.outline.outer = std::move(teeth);
    if (s.bore_diameter_m > 0) g.outline.holes.push_back(circle(s.bore_diameter_m / 2, s.chordal_deviation_m, true));
  } else {
    g.outline.outer = circle(s.rim_diameter_m / 2, s.chordal_deviation_m, false);
    std::reverse(teeth.points.begin(), teeth.points.end());
    g.outline.holes.push_back(std::move(teeth));
  }
  return g;
}

Vector2d flank_point(const GearSpec& s, const GearDimensions& d, int tooth, Flank flank, double radius_m) {
  const ToothFrame f = make_frame(s, d);
  const ToothMods m = collect_mods(s, d).at(tooth);
  const double theta = s.tooth0_angle_rad + tooth * 2 * kPi / s.teeth;
  Vector2d p = flank_at(f, theta, flank == Flank::Ccw ? m.ccw : m.cw, flank, roll_length_at(d.base_radius_m, radius_m));
  const Eccentricity& e = s.errors.eccentricity;
  return p + e.eccentricity_m * unit(e.phase_rad);
}

Vector2d flank_normal(const GearSpec& s, const GearDimensions& d, int tooth, Flank flank, double radius_m) {
  // Perpendicular to the flank's tangent, from a central difference over ±h along the radius
  // (h = 1e-4 of the radius: truncation error ~h²·curvature, far below 1e-9 in direction).
  const double h = 1e-4 * radius_m;
  const Vector2d t = flank_point(s, d, tooth, flank, radius_m + h) - flank_point(s, d, tooth, flank, radius_m - h);
  Vector2d n(t.y(), -t.x());
  n.normalize();
  // Out of the tooth: a Cw flank faces decreasing polar angle, a Ccw flank increasing.
  const Vector2d p = flank_point(s, d, tooth, flank, radius_m);
  const Vector2d ccw(-p.y(), p.x());
  if (n.dot(ccw) * outward_sign(flank) < 0) n = -n;
  return n;
}

}  // namespace gearsim

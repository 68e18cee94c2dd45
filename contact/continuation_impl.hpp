// Internal to contact/, included by coherent_contact.cpp only (after flank_search_impl.hpp): a
// continued contact solved again from the last call's solution — Newton's method for an
// interior maximum or a corner, the tip-circle crossing solved again — and the checks that it
// is still the stateless search's answer (the facing flank, the probe samples about a crossing).
// docs/tooth-contact.md, "Continuation" and "The crossing continued". Not an interface.
#pragma once

#include "contact/coherent_contact.hpp"
#include "contact/flank_search_impl.hpp"

namespace gearsim::contact {
namespace {

// Added to the facing margin's use, m: the rounding of the offsets (~1e-17 m at gear scale), with
// a wide margin.
constexpr double kFaceRounding_m = 1e-12;

using FaceReference = CoherentToothSearch::FaceReference;

// Does y's point P (y's frame) still face flank (j, g), as FlankTable::face() last found at
// `face.point` with `face.margin_m` to spare? Every candidate flank's offset moves by at most
// L·|P − face.point| (L: first_order_rise().side over the radii the segment between them can
// reach), so the choice stands while twice that stays below the margin. Else P is measured and
// the reference moves to it. False: P faces another flank or none.
[[gnu::always_inline]] inline bool still_faces(const FlankTable& yt, const Vector2d& P, int j, Flank g, FaceReference& face) {
  const double r1 = P.norm();
  if (face.margin_m > 0) {
    const double delta = (P - face.point).norm(), r0 = face.radius_m;
    const double lo = std::min(r0, r1) - delta, hi = std::max(r0, r1) + delta;
    if (lo > yt.r_min_m() && hi < yt.r_max_m()) {
      const double side = yt.first_order_rise(lo, hi).side;
      if (side < FlankTable::kInfinity && 2 * side * delta + kFaceRounding_m < face.margin_m) return true;
    }
  }
  const FlankTable::Facing now = yt.face(P, j);
  if (!now.has_flank || now.tooth != j || now.flank != g) return false;
  face = {P, r1, now.margin_m};
  return true;
}

// Whether the stateless search of x's flank (tooth k, f; the first gear's, probe_flank()) comes
// to a continued tip crossing's maximum at x's radius r_c (`side`: +1 where larger radii of x's
// flank lie beyond y's tip circle): the probe samples about it, measured as it measures them.
// The depth falling away from the crossing inside, its best sample is `in`, the one inside next
// to the crossing, where `out` beyond it has material and measures nothing: it then looks for
// the crossing there (crossing_radius()). It refines only a best sample within the window, and
// gives a flank up where its best after the coarse passes (the first samples, every other one
// where needed) lies more than 4 windows clear. Those passes probe `in` where it is a first
// sample or even (the even ones from 2 on are needed next to a sample two steps away that
// measured nothing: `out`'s neighbour beyond, |P| growing steadily along the flank over two
// spacings); else their best is the even sample inside `in`, which must then lie within 4
// windows.
bool samples_see_crossing(const XY& xy, int k, Flank f, double r_c, int side, int& hint) {
  constexpr int n = FlankTable::kProbeRadii;
  const FlankTable& xt = xy.x.table;
  const double spacing = xy.spacing_m, window = xy.window_m;
  const std::uint32_t material = xt.probe_material(k, f);
  auto has = [&](int i) { return i >= 0 && i < n && ((material >> i) & 1u); };
  auto depth = [&](int i) { return depth_of(xy, xt.probe_point(k, f, i), hint); };
  const int lo = std::clamp(static_cast<int>(floor_small((r_c - xt.probe_radius(0)) / spacing)), 0, n - 2);
  const int in = side > 0 ? lo : lo + 1, out = side > 0 ? lo + 1 : lo;
  if (!has(in) || !has(out) || !(depth(out) <= kNone && depth(in) >= -window)) return false;
  if (((first_samples(material) >> in) & 1u) || in % 2 == 0) return true;
  return has(in - side) && depth(in - side) >= -4 * window;
}

// A maximum where x's flank (tooth k, f) crosses y's tip circle (Hit::kCrossing;
// flank_refine_impl.hpp, Crossing) continued: the crossing solved again by Newton's method from
// r0, the depth checked to still rise toward the circle with nothing measured beyond it
// (tip_crossing_maximum(), as the stateless search checks it), and the probe samples about it
// checked to lead the stateless search there (samples_see_crossing()). No hit where any of that
// fails or the point measured faces another flank of y than (j, g).
Hit continued_crossing(const XY& xy, int k, Flank f, double r0, int j, Flank g, int& hint) {
  double lo, hi;
  xy.x.table.flank_extent(k, f, &lo, &hi);
  double rise = 0;
  const double r_c = circle_crossing(xy, k, f, tip_circle_m(xy.y.table), std::clamp(r0, lo, hi), lo, hi, &rise);
  if (std::isnan(r_c)) return {};
  // Beyond the circle: larger radii of x's flank where |P| grows with them, for an external y.
  const int side = (rise > 0) != xy.y.table.internal() ? 1 : -1;
  const double r = tip_crossing_maximum(xy, k, f, r_c, side, hint);
  if (std::isnan(r) || !samples_see_crossing(xy, k, f, r_c, side, hint)) return {};
  Hit h = probe_at(xy, k, f, r);
  if (!(h.depth > kNone) || h.tooth_y != j || h.flank_y != g) return {};
  h.solved = Hit::kCrossing;
  h.r_x = r_c;
  h.s_y = tip_circle_m(xy.y.table);
  return h;
}

// The deepest point of x's flank (tooth k, f) solved from the last call's solution (`solved`:
// its kind; on y's tooth j, flank g; at radii r_x on x's flank, s_y on y's) on the same flank of
// y: an interior maximum by Newton's method, or the corner
// at the flank's end while the depth still rises toward it; an interior maximum that leaves the
// flank becomes the corner at the end it left by, a corner whose depth no longer rises toward the
// end becomes an interior maximum started next to it. No hit (depth kNone) where the solves fail
// or the point found faces another flank of y than the one solved on (the stateless search's
// foot is on the flank the point faces): the caller searches the flank in full then.
// (r0, s0): where to start, last step's radii (r_x, s_y) or a prediction from them.
// `face`: the facing check's reference (still_faces()), updated.
Hit continued_hit(const XY& xy, int k, Flank f, Hit::Solved solved, int j, Flank g, double r_x, double s_y, double r0, double s0,
                  bool tip_only, FaceReference& face, int& hint) {
  double lo, hi;
  xy.x.table.flank_extent(k, f, &lo, &hi);
  const double spacing = xy.spacing_m, window = xy.window_m;
  Hit h;
  if (solved == Hit::kCrossing) {
    // Kept for the first gear's flanks only (find()): never tip_only.
    h = continued_crossing(xy, k, f, r0, j, g, hint);
    if (h.depth <= kNone || h.depth > window) return {};
    return h;
  }
  if (solved == Hit::kInterior) {
    h = newton_solve(xy, k, f, std::clamp(r0, lo, hi), j, g, s0, lo, hi);
    if (h.depth <= kNone) {
      const bool high = r_x > 0.5 * (lo + hi);
      h = corner_solve(xy, k, f, high ? hi : lo, high, j, g, s_y);
    }
  } else {
    const bool high = solved == Hit::kCornerHigh;
    h = corner_solve(xy, k, f, high ? hi : lo, high, j, g, s0);
    if (h.depth <= kNone) {
      // Start a step inside the end: Newton's first step from the corner itself (where d²D/dr²
      // may not yet be negative) could leave the flank.
      const double step = spacing;
      h = newton_solve(xy, k, f, high ? std::max(lo, hi - 0.5 * step) : std::min(hi, lo + 0.5 * step), j, g, s_y, lo, hi);
    }
  }
  if (h.depth <= kNone) return {};
  if (!h.gentle || h.depth > window) return {};
  // The second gear's flanks are searched at their tips only (probe_tip(): a maximum farther
  // down than its third sample is the first gear's to find): a solution there must stay within
  // 1.5 sample spacings of the tip.
  if (tip_only && !(std::abs(h.r_x - (xy.x.table.internal() ? lo : hi)) <= 1.5 * spacing)) return {};
  if (!still_faces(xy.y.table, xy.y.to_local(h.point), j, g, face)) return {};
  return h;
}

}  // namespace
}  // namespace gearsim::contact

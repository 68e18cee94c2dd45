// Internal to contact/, included by flank_search_impl.hpp only (after FlankSamples and the
// probing): the refinement of a flank's best sample to its deepest point — parabola fits, golden
// section, the crossing of the other gear's tip circle, Newton's method on the smooth flanks
// (flank_newton_impl.hpp) — and the hit it gives. Not an interface.
#pragma once

namespace gearsim::contact {
namespace {

// Radius of the deepest point near r_b, the best of samples spaced `step` apart whose
// neighbours' depths are d_lo and d_hi: successive parabola fits on shrinking brackets.
double parabola_refine(const XY& xy, int k, Flank f, double r, double step, double d_lo, double d0, double d_hi, int& hint) {
  double h = step;
  for (int fit = 0; fit < kParabolaFits; ++fit) {
    const double curvature = d_lo - 2 * d0 + d_hi;
    if (!(curvature < 0)) break;  // not a maximum (flat within rounding): keep the best sample
    r += std::clamp(0.5 * h * (d_lo - d_hi) / curvature, -h, h);
    if (fit + 1 == kParabolaFits) break;
    h *= kParabolaShrink;
    d_lo = depth_at(xy, k, f, r - h, hint), d0 = depth_at(xy, k, f, r, hint), d_hi = depth_at(xy, k, f, r + h, hint);
    if (d_lo <= kNone || d0 <= kNone || d_hi <= kNone) break;
  }
  return r;
}

constexpr double kGolden = 0.6180339887498949;

// Where golden_refine() ends when the depth rises monotonically toward one end of [lo, hi]
// (toward hi with `at_hi`): every comparison then goes the same way, so its brackets follow
// without evaluating the depth. The same arithmetic as golden_refine(), so the same radius.
double golden_end(double lo, double hi, bool at_hi) {
  double c = hi - kGolden * (hi - lo), d = lo + kGolden * (hi - lo);
  for (int it = 0; it < kGoldenIterations; ++it) {
    if (at_hi) {
      lo = c, c = d;
      d = lo + kGolden * (hi - lo);
    } else {
      hi = d, d = c;
      c = hi - kGolden * (hi - lo);
    }
  }
  return at_hi ? d : c;
}

// Radius of the deepest point in [lo, hi] by golden-section search: for a maximum at the end of
// the sampled flank, where the depth is not smooth.
double golden_refine(const XY& xy, int k, Flank f, double lo, double hi, int& hint) {
  double c = hi - kGolden * (hi - lo), d = lo + kGolden * (hi - lo);
  double fc = depth_at(xy, k, f, c, hint), fd = depth_at(xy, k, f, d, hint);
  for (int it = 0; it < kGoldenIterations; ++it) {
    if (fc > fd) {
      hi = d, d = c, fd = fc;
      c = hi - kGolden * (hi - lo), fc = depth_at(xy, k, f, c, hint);
    } else {
      lo = c, c = d, fc = fd;
      d = lo + kGolden * (hi - lo), fd = depth_at(xy, k, f, d, hint);
    }
  }
  return fc > fd ? c : d;
}

// Where x's flank (tooth k, f) crosses y's circle of radius R, inside (lo, hi) on x's flank:
// Newton's method on |P(r)|² = R² from r0. NaN where it leaves that interval or does not
// converge. `rise`: d|P|²/dr at the last point evaluated (its sign: whether |P| grows with r).
double circle_crossing(const XY& xy, int k, Flank f, double R, double r0, double lo, double hi, double* rise = nullptr) {
  FlankTable::FlankJet a;
  double r = r0;
  for (int it = 0; it < 8; ++it) {
    if (!xy.x.table.flank_jet(k, f, r, &a)) break;
    const Vector2d P = xy.in_y(a.point), P1 = xy.rot * a.d1;
    const double slope = 2 * P.dot(P1);
    if (!(slope != 0)) break;
    if (rise) *rise = slope;
    const double dr = -(P.squaredNorm() - R * R) / slope;
    r += dr;
    if (!(r > lo && r < hi)) break;
    if (std::abs(dr) < 1e-13) return r;
  }
  return std::numeric_limits<double>::quiet_NaN();
}

// y's tip circle: beyond it (outside an external y, inside an internal one) y's first-order
// depth measures nothing.
double tip_circle_m(const FlankTable& yt) { return yt.internal() ? yt.r_min_m() : yt.r_max_m(); }

// Where x's flank (tooth k, f) crosses y's tip circle between radii r_in and r_out of x's
// flank, from their middle (circle_crossing()).
double tip_circle_crossing(const XY& xy, int k, Flank f, double r_in, double r_out) {
  const double lo = std::min(r_in, r_out), hi = std::max(r_in, r_out);
  return circle_crossing(xy, k, f, tip_circle_m(xy.y.table), 0.5 * (lo + hi), lo, hi);
}

// A maximum of the depth where x's flank crosses y's tip circle (the depth still rising toward
// it, nothing measured beyond). `r`: the radius on x's flank the hit is measured at (a rising
// check's step inside); `crossing`: where x's flank crosses the circle, of radius `circle_m`. A
// continued search (continuation_impl.hpp) solves the crossing again next step instead of
// searching the flank (Hit::kCrossing). NaN: not such a maximum.
struct Crossing {
  double r = std::numeric_limits<double>::quiet_NaN();
  double crossing = std::numeric_limits<double>::quiet_NaN();
  double circle_m = std::numeric_limits<double>::quiet_NaN();
};

// Whether the first-order depth at x's flank radius r_c (the crossing of y's tip circle) still
// rises toward the circle, measured nothing a step beyond it (`side`: +1 where larger radii of
// x's flank lie beyond the circle, −1 where smaller ones do): the maximum then lies a rising
// check's step inside the circle, returned; NaN where that does not hold.
double tip_crossing_maximum(const XY& xy, int k, Flank f, double r_c, int side, int& hint) {
  const double d_out = depth_at(xy, k, f, r_c + side * kRisingCheck_m, hint);
  const double d_end = depth_at(xy, k, f, r_c - side * kRisingCheck_m, hint);
  const double d_in = depth_at(xy, k, f, r_c - 2 * side * kRisingCheck_m, hint);
  if (d_out <= kNone && d_end > kNone && d_in > kNone && d_end > d_in) return r_c - side * kRisingCheck_m;
  return std::numeric_limits<double>::quiet_NaN();
}

// Best not at an end of its bracket but next to a sample that measured nothing because it lies
// beyond y's tips: where the depth still rises toward the radius at which x's flank crosses y's
// tip circle, a search with one maximum in the bracket ends there, found by Newton's method on
// the circle instead of golden section's 22 depths. NaN where that does not hold.
Crossing crossing_radius(FlankSamples& s) {
  constexpr int n = FlankSamples::n;
  const FlankTable& table = s.xy.x.table;
  const int best_i = s.best_i;
  const double r_b = table.probe_radius(best_i);
  for (int side : {-1, 1}) {
    const int nb = best_i + side;
    if (nb < 0 || nb >= n || s.missing(nb) || s.depth[nb] > kNone) continue;
    const double r_c = tip_circle_crossing(s.xy, s.k, s.f, r_b, table.probe_radius(nb));
    if (std::isnan(r_c)) break;
    const double r = tip_crossing_maximum(s.xy, s.k, s.f, r_c, side, s.hint);
    if (!std::isnan(r)) return {r, r_c, tip_circle_m(s.xy.y.table)};
    break;
  }
  return {};
}

// Whether the best sample lies at an end of its refinement bracket (an end of the flank's samples).
bool best_at_bracket_end(const FlankSamples& s) {
  const FlankTable& table = s.xy.x.table;
  const double r_b = table.probe_radius(s.best_i);
  const double lo = std::max(r_b - s.step, table.probe_radius(0)), hi = std::min(r_b + s.step, table.probe_radius(FlankSamples::n - 1));
  return r_b == hi || r_b == lo;
}

// The radius of the deepest point near the best sample: a parabola through it and its neighbours
// inside the flank, golden section at an end of it. `crossing_tried`: crossing_radius() was
// tried already (refined_hit()) and did not hold. `crossing`: set where the point is the
// crossing of y's tip circle (Crossing).
double refined_radius(FlankSamples& s, bool crossing_tried, Crossing& crossing) {
  constexpr int n = FlankSamples::n;
  const FlankTable& table = s.xy.x.table;
  const int best_i = s.best_i;
  const double r_b = table.probe_radius(best_i), step = s.step;
  const bool interior = best_i > 0 && best_i < n - 1 && s.depth[best_i - 1] > kNone && s.depth[best_i + 1] > kNone;
  if (interior) return parabola_refine(s.xy, s.k, s.f, r_b, step, s.depth[best_i - 1], s.depth[best_i], s.depth[best_i + 1], s.hint);
  const double lo = std::max(r_b - step, table.probe_radius(0)), hi = std::min(r_b + step, table.probe_radius(n - 1));
  // Best at an end of the bracket (a tip corner, or the flank's end): where the depth still
  // rises toward that end at golden section's last point, a search with one maximum in the
  // bracket (what golden section assumes) ends exactly there, found with two evaluations
  // instead of 22.
  if (r_b == hi || r_b == lo) {
    const bool at_hi = r_b == hi;
    const double r_end = golden_end(lo, hi, at_hi);
    const double d_end = depth_at(s.xy, s.k, s.f, r_end, s.hint);
    const double d_in = depth_at(s.xy, s.k, s.f, r_end + (at_hi ? -kRisingCheck_m : kRisingCheck_m), s.hint);
    if (d_end > kNone && d_in > kNone && d_end > d_in) return r_end;
  }
  if (!crossing_tried) {
    const Crossing c = crossing_radius(s);
    if (!std::isnan(c.r)) {
      crossing = c;
      return c.r;
    }
  }
  return golden_refine(s.xy, s.k, s.f, lo, hi, s.hint);
}

}  // namespace
}  // namespace gearsim::contact

#include "contact/flank_newton_impl.hpp"

namespace gearsim::contact {
namespace {

// How much y's flank (tooth j, g) turns about its foot at y-frame point q: 1 − cos of the angle
// between its normals a distance d below and above the foot's radius (within the flank).
double foot_turning(const FlankTable& yt, int j, Flank g, const Vector2d& q, double d) {
  double lo, hi;
  yt.flank_extent(j, g, &lo, &hi);
  const double s = q.norm(), s0 = std::max(lo, s - d), s1 = std::min(hi, s + d);
  FlankTable::FlankJet u, v;
  if (!(s1 > s0) || !yt.flank_jet(j, g, s0, &u) || !yt.flank_jet(j, g, s1, &v)) return 2;
  return 1 - FlankTable::outward_normal(g, u.d1).dot(FlankTable::outward_normal(g, v.d1));
}

// A maximum only the sampled refinement found (x's point at radius r, `probed`) lies where a
// flank turns sharply: a corner of the outline, which the flank tables keep within a vertex
// spacing (FreeCAD's ring tip lands meet the flanks so). Where the corner is y's, x's point found
// by golden section faces it with y's normal at the foot, one side's of the corner, not the
// direction the overlap grows along as the corner slides on x's flank (for a ring's tip corner
// low on a pinion's flank, the tip land's normal has a lever of 2.7–5.8 mm about the pinion,
// r_b 14.5 mm): a contact row on it takes the sliding for approach and pushes 5–20× its spring.
// So the overlap is measured from y's side too — the deepest point of y's flank inside x
// near the foot, by golden section, along x's normal at its foot — and kept where y's flank turns
// by more than 20° about its foot (over half of y's probe spacing either side: a corner) and x's
// less than a tenth as much about its own: a corner in a smooth flank is measured along the
// smooth flank's normal. (The FreeCAD ring's corner turns by 70–80° there, the pinion's flank by
// 5°; the facet corners of MCAD's flanks turn by 5° at most and keep the first measure.)
constexpr double kCornerTurning = 0.0603;  // 1 − cos 20°: y's flank turns by more than 20° about its foot
Hit sharper_side_hit(const XY& xy, int k, Flank f, const Hit& probed) {
  if (!(probed.depth > 0) || probed.tooth_y < 0) return probed;
  const FlankTable& yt = xy.y.table;
  const Vector2d foot_y = xy.y.to_local(probed.point + probed.depth * probed.normal_into_x);
  double lo, hi;
  yt.flank_extent(probed.tooth_y, probed.flank_y, &lo, &hi);
  const XY yx{xy.y, xy.x};
  const double reach = 2 * yx.spacing_m, s = foot_y.norm();
  const double from = std::max(lo, s - reach), to = std::min(hi, s + reach);
  if (!(to > from)) return probed;
  // Golden section twice: the maximum is at a corner, where the depth falls off linearly, so
  // the first bracket's 6.6e-5 of the span (~30 nm of flank) would cost nanometres of depth.
  int hint = k;
  const double r_1 = golden_refine(yx, probed.tooth_y, probed.flank_y, from, to, hint), w = 1e-4 * (to - from);
  const double r_y = golden_refine(yx, probed.tooth_y, probed.flank_y, std::max(from, r_1 - w), std::min(to, r_1 + w), hint);
  Hit c = probe_at(yx, probed.tooth_y, probed.flank_y, r_y);
  if (!(c.depth > 0) || c.tooth_y != k || c.flank_y != f) return probed;
  // At an end of y's flank (its tip corner): that corner solved exactly on x's flank.
  for (const bool high : {true, false}) {
    const double end = high ? hi : lo;
    if (!(std::abs(r_y - end) <= 2 * w)) continue;
    const Hit e =
        corner_solve(yx, probed.tooth_y, probed.flank_y, end, high, k, f, xy.x.to_local(c.point + c.depth * c.normal_into_x).norm());
    if (e.depth > c.depth && e.tooth_y == k && e.flank_y == f) c = e;
  }
  const Vector2d foot_x = xy.x.to_local(c.point + c.depth * c.normal_into_x);
  const double d = 0.25 * reach;
  const double turn_y = foot_turning(yt, probed.tooth_y, probed.flank_y, foot_y, d);
  if (!(turn_y > kCornerTurning && 10 * foot_turning(xy.x.table, k, f, foot_x, d) < turn_y)) return probed;
  // In x's terms: x's surface point is the foot on x, y's outward normal the opposite of x's.
  Hit h = probed;
  h.depth = c.depth;
  h.normal_into_x = -c.normal_into_x;
  h.point = c.point + c.depth * c.normal_into_x;
  return h;
}

// The hit of a sampled refinement that ended at radius c.r: measured exactly there (at the best
// sample where c.r has no material, or measures nothing). Where c.r is a crossing's maximum
// (Crossing) and measured there, marked as one (Hit::kCrossing: r_x the crossing on x's flank,
// s_y the circle's radius).
Hit crossing_hit_at(const FlankSamples& s, const Crossing& c) {
  if (!std::isnan(s.xy.x.table.flank_angle(s.k, s.f, c.r))) {
    Hit h = probe_at(s.xy, s.k, s.f, c.r);
    if (h.depth > kNone) {
      if (!std::isnan(c.circle_m)) {
        h.solved = Hit::kCrossing;
        h.r_x = c.crossing;
        h.s_y = c.circle_m;
      }
      return h;
    }
  }
  return probe_at(s.xy, s.k, s.f, s.xy.x.table.probe_radius(s.best_i));
}

// The hit of a flank whose probing found a best sample within the refinement window: refined,
// then measured exactly.
Hit refined_hit(FlankSamples& s) {
  bool crossing_tried = false;
  const XY& xy = s.xy;
  const int k = s.k;
  const Flank f = s.f;
  const double r_b = xy.x.table.probe_radius(s.best_i);
  // Newton's method on the smooth flanks: an interior maximum from the parabola through the
  // best sample and its neighbours, within their bracket; else a corner of the flank within a
  // sample step (where the depth still rises toward it); else, next to an end, an interior
  // maximum between that end and the sample. The sampled refinement below only where none holds.
  {
    constexpr int n = FlankSamples::n;
    const int i = s.best_i;
    const bool interior = i > 0 && i < n - 1 && s.depth[i - 1] > kNone && s.depth[i + 1] > kNone;
    if (interior) {
      const double lo = s.depth[i - 1], mid = s.depth[i], hi = s.depth[i + 1], curvature = lo - 2 * mid + hi;
      const double r0 = curvature < 0 ? r_b + std::clamp(0.5 * s.step * (lo - hi) / curvature, -s.step, s.step) : r_b;
      const Hit h = newton_hit(xy, k, f, r0, r_b - s.step, r_b + s.step);
      if (h.depth > kNone) return h;
    }
    double end_lo, end_hi;
    xy.x.table.flank_extent(k, f, &end_lo, &end_hi);
    Hit corner;
    for (bool high : {true, false}) {
      const double r_end = high ? end_hi : end_lo;
      if (!(std::abs(r_end - r_b) <= s.step)) continue;
      const Hit c = corner_hit(xy, k, f, r_end, high);
      if (c.depth > corner.depth) corner = c;
    }
    if (corner.depth > kNone) return corner;
    if (!interior) {
      // The depth still rising toward y's tip circle next to the best sample (not at its
      // bracket's end, where refined_radius() looks at the flank's end first): the maximum is
      // where x's flank crosses the circle, and Newton's method from the sample is not tried —
      // it found no other maximum there in any of the 80 737 such refinements of
      // bench_contact_sweep's paper sweep, nor in the paper, bearings, sequential, Lin–Parker and
      // spur-pair runs (docs/tooth-contact.md, "The tip-circle crossing").
      crossing_tried = !best_at_bracket_end(s);
      if (crossing_tried) {
        const Crossing c = crossing_radius(s);
        if (!std::isnan(c.r)) return crossing_hit_at(s, c);
      }
      const bool high = i == n - 1 || s.missing(i + 1);
      const double r_end = high ? end_hi : end_lo;
      if (std::abs(r_end - r_b) <= s.step) {
        const Hit h = newton_hit(xy, k, f, r_b, high ? r_b - s.step : r_end, high ? r_end : r_b + s.step);
        if (h.depth > kNone) return h;
      } else {
        // The neighbour on that side is missing (no material there: the mate's tooth covers it),
        // not the flank's end: a maximum within a step of the best sample is still Newton's.
        const Hit h = newton_hit(xy, k, f, r_b, r_b - s.step, r_b + s.step);
        if (h.depth > kNone) return h;
      }
    }
  }
  Crossing c;
  const double r = refined_radius(s, crossing_tried, c);
  c.r = r;
  const Hit h = crossing_hit_at(s, c);
  return h.solved == Hit::kSampled ? sharper_side_hit(xy, k, f, h) : h;
}

// The deepest point of one flank of x's tooth k inside y: the flank's probe points tested to
// first order, the best refined, and the result measured exactly. A flank whose best sample
// stays more than its refinement window (refine_window_m) clear of y returns no hit. With
// `tip_only`, only a maximum at the tooth's free end (its tip corner) is looked for.
// `hint`: y's tooth the last probe faced (or −1); the next ones along the flank, or on the next
// flank, face it or a neighbour. Updated.
[[maybe_unused]] Hit deepest_on_flank(const XY& xy, int k, Flank f, bool tip_only, int& hint) {
  FlankSamples s(xy, k, f, hint);
  if (!(tip_only ? probe_tip(s) : probe_flank(s))) return {};
  return refined_hit(s);
}

}  // namespace

}  // namespace gearsim::contact

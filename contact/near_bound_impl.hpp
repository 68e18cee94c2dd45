// Internal to contact/, included by coherent_contact.cpp only (after continuation_impl.hpp): the
// bound under which a continued near pair is left unsolved ("parked", CoherentToothSearch::find()).
// docs/tooth-contact.md, "Near pairs: the osculating-circle bound". Not an interface.
#pragma once

#include <cmath>

#include "contact/coherent_contact.hpp"
#include "contact/continuation_impl.hpp"
#include "contact/flank_search_impl.hpp"

namespace gearsim::contact {
namespace {

using NearBound = CoherentToothSearch::NearBound;

// The error of a near pair's solved gap, m: Newton's method stops once its step in radius is
// below kNewtonTaylorSmooth_m (0.1 µm), and the depth at a point δr from the maximum is off by
// ½·|D″|·δr² with |D″| the two flanks' relative curvature (≈ 1/(2 mm) on module-1 involutes):
// ≈ 2.5 pm; four times that.
constexpr double kNearSolve_m = 1e-11;

// A radius of curvature beyond this many times the gear's outer radius is taken as flat: the
// circle's centre is then so far that the distance of the centres loses the gap to rounding.
constexpr double kFlatRadii = 100;

// The slide of each flank's closest point is taken as twice the circles' own: the true closest
// point departs from the circles' by the fraction Δc/(c_x + c_y) of its slide (Δc: how much the
// curvature changes over it; a few per cent on involutes), and the bound is refused where that
// fraction could reach 1 (near_bound()).
constexpr double kSlideFactor = 2;

// |ψ| ≤ kAngleOverSine·|sin ψ| for |ψ| ≤ 0.5 rad (0.5 / sin 0.5 = 1.0429), cos ψ above
// kCosLimit (cos 0.5 = 0.8776): the normal's turn in a gear's frame from its sine.
constexpr double kAngleOverSine = 1.05, kCosLimit = 0.88;

double cross2(const Vector2d& v, const Vector2d& w) { return v.x() * w.y() - v.y() * w.x(); }

// The near pair (x's flank k, f; hit h on y's flank h.tooth_y, h.flank_y with a gap, h.depth < 0)
// as NearBound; invalid where the two circles do not bound the pair: a flank flatter than
// kFlatRadii outer radii, both flanks concave, or the concave one curved more tightly than the
// convex one (the convex disc does not fit its hollow).
[[gnu::noinline]] NearBound near_snapshot(const XY& xy, int k, Flank f, const Hit& h) {
  const Frame &x = xy.x, &y = xy.y;
  NearBound b;
  if (!(h.depth < 0) || h.tooth_y < 0) return b;
  if (h.solved != Hit::kInterior && h.solved != Hit::kCornerHigh && h.solved != Hit::kCornerLow) return b;
  const double gap = -h.depth;
  const Vector2d n = h.normal_into_x;  // from y's foot toward x's point
  const Vector2d p = h.point, q = h.point - gap * n;
  FlankTable::FlankJet jx, jy;
  if (!y.table.flank_jet(h.tooth_y, h.flank_y, h.s_y, &jy) || !x.table.flank_jet(k, f, h.r_x, &jx)) return b;
  b.corner = h.solved != Hit::kInterior;
  b.c_y = FlankTable::convexity(h.flank_y, jy);
  b.c_x = b.corner ? 0 : FlankTable::convexity(f, jx);
  if (!(std::abs(b.c_y) * kFlatRadii * y.table.r_max_m() > 1)) return b;
  if (!b.corner && !(std::abs(b.c_x) * kFlatRadii * x.table.r_max_m() > 1)) return b;
  b.rho_x = b.corner ? 0 : 1 / b.c_x;
  b.rho_y = 1 / b.c_y;
  const double sum = gap + b.rho_x + b.rho_y;
  if (b.rho_x < 0 && b.rho_y < 0) return b;
  b.side = b.rho_x < 0 || b.rho_y < 0 ? -1 : 1;
  if (!(b.side * sum > 0)) return b;  // a concave flank more tightly curved than the convex one's circle
  const Vector2d ox = p + b.rho_x * n, oy = q - b.rho_y * n;
  b.gap_m = gap;
  b.centre_x = x.to_local(ox);
  b.centre_y = y.to_local(oy);
  b.dist0_m = (ox - oy).norm();
  b.n_x = x.to_local_m * n;
  b.n_y = y.to_local_m * n;
  b.point_x = x.to_local(p);
  b.point_y = y.to_local(q);
  b.r_x = h.r_x;
  b.s_y = h.s_y;
  if (b.corner) {
    const Vector2d t = jx.d1.normalized();  // toward larger radii
    b.into_flank_x = h.solved == Hit::kCornerHigh ? Vector2d(-t) : t;
    if (!(b.into_flank_x.dot(b.n_x) > 0)) return NearBound{};  // not (or no longer) a corner's gap
  }
  b.valid = true;
  return b;
}

// A flank's bound after a solve `h`: its snapshot where the solve left a gap, else none (only
// the flag is cleared: the rest is not read without it).
void keep_near_snapshot(NearBound& bound, const XY& xy, int k, Flank f, const Hit& h) {
  if (h.depth < 0)
    bound = near_snapshot(xy, k, f, h);
  else
    bound.valid = false;
}

// The same near pair seen from y (the second pass's flank sharing the first pass's solution).
NearBound swapped(const NearBound& a) {
  NearBound b;
  if (!a.valid || a.corner) return b;
  b = a;
  std::swap(b.centre_x, b.centre_y);
  std::swap(b.rho_x, b.rho_y);
  std::swap(b.c_x, b.c_y);
  std::swap(b.point_x, b.point_y);
  std::swap(b.r_x, b.s_y);
  b.n_x = -a.n_y;
  b.n_y = -a.n_x;
  return b;
}

// Whether a flank's band [r − s, r + s] has a known convexity range, and how far from c its
// convexity strays there (into `dc`).
bool convexity_spread(const FlankTable& t, int tooth, Flank f, double r, double s, double c, double* dc) {
  const FlankTable::ConvexityRange range = t.convexity_range(tooth, f, r - s, r + s);
  if (!(range.lo > -FlankTable::kInfinity && range.hi < FlankTable::kInfinity)) return false;
  *dc = std::max(range.hi - c, c - range.lo);
  return true;
}

// A lower bound on the gap of the near pair `b` (x's flank k, f; y's j, g) at the poses of xy, m
// (−∞: none), and the rate at which the circles close at the given velocities (`closing`, m/s,
// > 0 closing; only where `vx`, `vy` are given).
//  - Circles: x's flank lies within δ_x of its osculating circle at the solved point over an arc
//    of σ_x from it, δ_x = ½·Δc_x·σ_x² (its convexity c within c_x ± Δc_x there: the offset from
//    the circle is the integral twice over of the curvature's difference); y's likewise. The
//    circles' centres move rigidly with their gears, so their distance at the poses now is exact:
//    convex against convex, gap ≥ |o_x − o_y| − ρ_x − ρ_y − δ_x − δ_y; a convex flank in a
//    concave one, |ρ_concave| − ρ_convex − |o_x − o_y| − δ_x − δ_y. As the difference from the
//    solved gap: gap₀ + side·(|o_x − o_y| − |o_x − o_y|₀). A corner (ρ_x = 0) is its own centre:
//    no δ_x, while it stays the flank's closest point (the normal from y to it still points out
//    of the flank's end: into_flank_x·n > 0, less the angle y's circle can be off by, Δc_y·σ_y).
//  - Slides: the circles' closest points lie on the line of their centres; its direction in each
//    gear's frame has turned by ψ since the solve, and each closest point slid by |ρ|·ψ along its
//    circle, kSlideFactor times which bounds the flank's own (refused where Δc_x + Δc_y reaches
//    |c_x + c_y|, the pair's relative curvature, or ψ exceeds 0.5 rad). A radial band of that
//    half-width holds the arc (|dr/ds| ≤ 1).
//  - Tip only (the second gear's flanks, probed at their tips): the solved point must stay within
//    1.5 probe spacings of the tip with its slide, as the continuation keeps it (continued_hit()).
//  - The solved gap's own error, kNearSolve_m.
[[gnu::noinline]] double near_bound(const XY& xy, int k, Flank f, const NearBound& b, int j, Flank g, bool tip_only,
                                    const CoherentToothSearch::PlanarTwist* vx, const CoherentToothSearch::PlanarTwist* vy,
                                    double* closing) {
  constexpr double kNo = -std::numeric_limits<double>::infinity();
  const Frame &x = xy.x, &y = xy.y;
  const Vector2d ox = x.to_world(b.centre_x), oy = y.to_world(b.centre_y), d = ox - oy;
  const double dist = d.norm();
  const Vector2d n = (b.side / dist) * d;  // the circles' normal from y toward x, world
  const Vector2d nx = x.to_local_m * n, ny = y.to_local_m * n;
  const double cos_x = b.n_x.dot(nx), cos_y = b.n_y.dot(ny);
  if (!(cos_x > kCosLimit && cos_y > kCosLimit)) return kNo;
  const double psi_x = kAngleOverSine * std::abs(cross2(b.n_x, nx)), psi_y = kAngleOverSine * std::abs(cross2(b.n_y, ny));
  const double sx = b.corner ? 0 : kSlideFactor * std::abs(b.rho_x) * psi_x, sy = kSlideFactor * std::abs(b.rho_y) * psi_y;
  double dcx = 0, dcy = 0;
  if (!convexity_spread(y.table, j, g, b.s_y, sy, b.c_y, &dcy)) return kNo;
  if (!b.corner && !convexity_spread(x.table, k, f, b.r_x, sx, b.c_x, &dcx)) return kNo;
  if (!(dcx + dcy < std::abs(b.c_x + b.c_y))) return kNo;
  if (b.corner && !(b.into_flank_x.dot(nx) > dcy * sy)) return kNo;
  if (tip_only) {
    double lo, hi;
    x.table.flank_extent(k, f, &lo, &hi);
    if (!(std::abs(b.r_x - (x.table.internal() ? lo : hi)) + sx <= 1.5 * xy.spacing_m)) return kNo;
  }
  if (vx && vy) {
    // d|o_x − o_y|/dt with each centre moving as a point of its gear: v_c + ω ẑ × (o − c).
    auto velocity = [](const CoherentToothSearch::PlanarTwist& v, const Frame& fr, const Vector2d& o) {
      const Vector2d r = o - fr.pose.centre_m;
      return Vector2d(v.velocity_m_s.x() - v.angular_velocity_rad_s * r.y(), v.velocity_m_s.y() + v.angular_velocity_rad_s * r.x());
    };
    *closing = -n.dot(velocity(*vx, x, ox) - velocity(*vy, y, oy));
  }
  return b.gap_m + b.side * (dist - b.dist0_m) - 0.5 * (dcx * sx * sx + dcy * sy * sy) - kNearSolve_m;
}

}  // namespace
}  // namespace gearsim::contact

// Internal to contact/: the flank search that find_tooth_contacts() and CoherentToothSearch share
// (probe samples, coarse-to-fine skipping, parabola and golden-section refinement). Included by
// tooth_contact.cpp and coherent_contact.cpp only: an anonymous namespace, so each file compiles
// and inlines the same code as before it was shared. Not an interface.
#pragma once

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <tuple>
#include <vector>

#include "contact/fast_angle.hpp"
#include "contact/integer_round.hpp"
#include "contact/tooth_contact.hpp"

namespace gearsim::contact {
namespace {

using Eigen::Vector2d;

// Golden-section steps refining the deepest point where a parabola cannot (a maximum at the end
// of the sampled flank: a tip corner): the bracket shrinks by 0.618^20 ≈ 7e-5 of two sample
// spacings (≈ 10 nm at 16 samples over 2.25 mm).
constexpr int kGoldenIterations = 20;

// Parabola fits refining an interior maximum, each on a bracket kParabolaShrink times narrower
// than the last: the depth is smooth and flat at its maximum, so three fits (brackets of 150,
// 19 and 2.3 µm on a module-1 tooth) place it to a few nm along the flank.
constexpr int kParabolaFits = 3;
constexpr double kParabolaShrink = 1.0 / 8;

// Gap below which a flank's coarse maximum is refined, m, for probe samples up to
// kRefineStep_m apart: 5 µm. The skipping of samples below rests on it: between two samples
// s steps apart the depth rises at most s²·window above the higher, which holds where the
// two flanks' relative radius of curvature exceeds step²/(8·window) — 0.56 mm at 150 µm steps
// (16 samples over a 2.25 mm module-1 tooth; the sun–planet pair's is ~2.4 mm).
constexpr double kRefineWithin_m = 5e-6;
constexpr double kRefineStep_m = 150e-6;

// The window for a table whose probe samples lie `step` apart, m. Radii of curvature grow with
// the teeth as the step does, so the rise between samples grows as the step: on a module-4
// tooth (604 µm steps, 7.9 mm relative radius) the depth rose 21 µm above the higher of two
// samples two steps apart, beyond 4 × 5 µm, and a 1.2 µm contact went unseen for 4 steps.
// Never below kRefineWithin_m.
double refine_window_m(double step) { return kRefineWithin_m * std::max(1.0, step / kRefineStep_m); }

constexpr double kNone = FlankTable::kNoDepth;

// Step inward from golden section's last point that tells whether the depth still rises toward
// the bracket's end, m. Normally 0.1 nm: below the 2.3 nm between golden section's last two
// points (so the test speaks for the last comparison too), far above the depth's rounding
// (~1e-17 m at gear scale) times any flank slope that matters.
constexpr double kRisingCheck_m = 1e-10;

// The rotation of a pose: Eigen's Rotation2D (std::sin and std::cos of the angle), or the same
// two numbers where the caller has them for this angle (PlanarPose::has_rotation()).
Eigen::Matrix2d rotation_of(const PlanarPose& pose) {
  if (!pose.has_rotation()) return Eigen::Rotation2Dd(pose.angle_rad).toRotationMatrix();
  Eigen::Matrix2d m;
  m << pose.cos_angle, -pose.sin_angle, pose.sin_angle, pose.cos_angle;
  return m;
}

struct Frame {
  const FlankTable& table;
  PlanarPose pose;
  Eigen::Matrix2d to_world_m = rotation_of(pose), to_local_m = to_world_m.transpose();
  Vector2d to_world(const Vector2d& p) const { return pose.centre_m + to_world_m * p; }
  Vector2d to_local(const Vector2d& w) const { return to_local_m * (w - pose.centre_m); }
  Vector2d dir_to_world(const Vector2d& d) const { return to_world_m * d; }
};

// A Newton step on the smooth flanks shorter than this, m, may end the iteration from the
// flanks' expansions (flank_newton_impl.hpp, newton_solve()): 1 nm as a rule; 0.1 µm in a
// search that continues its contacts on smooth flanks (CoherentToothSearch,
// Continuation::replace), where the predicted next step decides. Faceted CAD flanks have several maxima near one
// another, and there the continuation keeps the 1 nm rule: the maximum it lands on depends on
// every step's point (tests/contact/test_coherent_contact.cpp, "OnFacetedFlanks").
constexpr double kNewtonTaylor_m = 1e-9;
constexpr double kNewtonTaylorSmooth_m = 1e-7;

// A probing pass: points of x tested against y, with x's frame expressed in y's once.
struct XY {
  const Frame& x;
  const Frame& y;
  double taylor_step_m = kNewtonTaylor_m;  // kNewtonTaylor_m or kNewtonTaylorSmooth_m
  Eigen::Matrix2d rot = y.to_local_m * x.to_world_m;
  Vector2d shift = y.to_local(x.pose.centre_m);
  // x's probe spacing and refinement window, m, taken once per pass.
  double spacing_m = x.table.probe_radius(1) - x.table.probe_radius(0);
  double window_m = refine_window_m(spacing_m);
  Vector2d in_y(const Vector2d& p_x) const { return shift + rot * p_x; }
};

// Could tooth k of `x` reach the toothed annulus of `y`? Bounding circle of the tooth against
// the annulus [r_min, r_max] of y (or y's whole disc beyond it on its body side).
bool tooth_near(const Frame& x, int k, const Frame& y) {
  const double radius = x.table.tooth_bound_radius_m();
  const double d2 = (x.to_world(x.table.tooth_centre(k)) - y.pose.centre_m).squaredNorm();
  const double outer = y.table.r_max_m() + radius, inner = y.table.r_min_m() - radius;
  return d2 < outer * outer && (inner < 0 || d2 > inner * inner);
}

// The teeth of x that tooth_near() can accept lie within an angular window about the direction
// from x's centre to y's, or about the opposite one for x inside an internal y (tooth centres all
// sit on one circle about x's centre, at the tooth angles): a tooth outside it is skipped
// without the test. The window holds `count` teeth from
// `first` on (modulo the teeth); count < 0: every tooth is tested.
struct ToothWindow {
  int first = 0, count = -1;
};

// Calls visit(k) for every tooth k of `teeth` the window holds, in increasing k (the order the
// probing's tooth hints follow), without testing the others.
template <class Visit>
void for_each_tooth(const ToothWindow& w, int teeth, Visit&& visit) {
  if (w.count < 0) {
    for (int k = 0; k < teeth; ++k) visit(k);
    return;
  }
  const int last = w.first + w.count - 1;  // count < teeth, 0 ≤ first < teeth
  if (last >= teeth) {
    for (int k = 0; k <= last - teeth; ++k) visit(k);
    for (int k = w.first; k < teeth; ++k) visit(k);
  } else {
    for (int k = w.first; k <= last; ++k) visit(k);
  }
}

// Angle added to the window's half width, rad: rough_atan2's error (≤ 1e-5 rad) and the rounding
// of the tooth angles (far below), with a wide margin; acos_above() is never below acos.
constexpr double kToothWindowMargin_rad = 1e-4;

// With the distance between the centres and the direction from x's centre to y's (rough_atan2()
// of it, or of its opposite plus π: within the margin alike) given.
ToothWindow tooth_window(const Frame& x, const Frame& y, double dist, double facing_rad) {
  ToothWindow w;
  const double r_c = x.table.tooth_centre(0).norm();
  const double outer = y.table.r_max_m() + x.table.tooth_bound_radius_m(), inner = y.table.r_min_m() - x.table.tooth_bound_radius_m();
  if (!(dist > 0 && r_c > 0)) return w;
  // |c_k − c_y|² = r_c² + dist² − 2·r_c·dist·cos Δ, Δ the angle between tooth k's centre and the
  // direction to y's centre: tooth_near() asks for it below outer² (cos Δ > cos_outer) and, where
  // inner > 0, above inner² (cos Δ < cos_inner).
  const double cos_outer = (r_c * r_c + dist * dist - outer * outer) / (2 * r_c * dist);
  const double cos_inner = (r_c * r_c + dist * dist - inner * inner) / (2 * r_c * dist);
  const double pitch = x.table.pitch_angle_rad();
  // Tooth k lies at k·pitch from tooth 0; y's centre at `facing`. The window: every k with
  // |k·pitch − centre| ≤ half (mod 2π), from angles without libm plus the margin. About the
  // direction to y where the outer circle bounds the teeth (y external: a tooth beyond it is
  // clear); else, where the inner one does (x inside an internal y: only the teeth facing away
  // from y's centre reach its teeth), about the opposite direction, Δ ≥ acos(cos_inner) — the
  // bound from acos_above() less its error (≤ 1.34e-4 rad above acos).
  double centre = facing_rad - x.pose.angle_rad - x.table.tooth_angle_rad(0), half;
  if (cos_outer > -1) {
    half = (cos_outer >= 1 ? 0.0 : acos_above(cos_outer)) + kToothWindowMargin_rad;
  } else if (inner > 0 && cos_inner < 1) {
    centre += 3.141592653589793;
    half = 3.141592653589793 - (cos_inner <= -1 ? 3.141592653589793 : acos_above(cos_inner) - 1.34e-4) + kToothWindowMargin_rad;
  } else {
    return w;
  }
  const int teeth = x.table.teeth();
  const double a = (centre - half) / pitch, b = (centre + half) / pitch;
  if (!(std::abs(a) < 1e15 && std::abs(b) < 1e15)) return w;
  const double lo = ceil_small(a), hi = floor_small(b);
  if (!(hi - lo + 1 < teeth)) return w;
  w.count = hi < lo ? 0 : static_cast<int>(hi - lo) + 1;
  const long long first = static_cast<long long>(lo) % teeth;
  w.first = static_cast<int>(first < 0 ? first + teeth : first);
  return w;
}

ToothWindow tooth_window(const Frame& x, const Frame& y) {
  const Vector2d to_y = y.pose.centre_m - x.pose.centre_m;
  return tooth_window(x, y, to_y.norm(), rough_atan2(to_y.y(), to_y.x()));
}

struct Hit {
  double depth = kNone;
  Vector2d point = Vector2d::Zero(), normal_into_x = Vector2d::Zero();  // world: the probed point and the surface normal of y there
  int tooth_y = -1;
  Flank flank_y = Flank::Ccw;
  // How the point was found: sampled (parabola or golden section), or solved by Newton's method
  // (flank_newton_impl.hpp) as an interior maximum or a corner at x's flank end; for a solved
  // hit, the radii of its point on x's flank and of the foot on y's (what a continued search
  // starts from next step).
  // kCrossing: a sampled maximum where x's flank crosses y's tip circle (flank_refine_impl.hpp,
  // Crossing): r_x the crossing's radius on x's flank, s_y the circle's radius.
  enum Solved : signed char { kSampled, kInterior, kCornerHigh, kCornerLow, kCrossing };
  Solved solved = kSampled;
  double r_x = 0, s_y = 0;
  // A solved hit whose flanks both curve there less sharply than x's probe spacing (radii of
  // curvature above it: flank_newton_impl.hpp, curvature_radius_above()).
  bool gentle = false;
};

// Exact depth of x's flank point at radius r inside y, with the contact geometry, in world terms.
Hit probe_at(const XY& xy, int k, Flank f, double r) {
  const Frame &x = xy.x, &y = xy.y;
  Hit h;
  const Vector2d w = x.to_world(x.table.flank_point(k, f, r));
  const FlankTable::Probe p = y.table.probe(y.to_local(w));
  if (!p.inside && !p.has_flank) return h;  // far from y's teeth: no gap to measure
  h.depth = p.depth_m;
  h.point = w;
  h.normal_into_x = y.dir_to_world(p.normal);
  h.tooth_y = p.tooth;
  h.flank_y = p.flank;
  return h;
}

// First-order depth of a point of x (gear frame of x) inside y, kNone where there is nothing to
// measure. `hint`: a tooth of y near the point (or −1), updated to the one it faces.
double depth_of(const XY& xy, const Vector2d& p_x, int& hint) { return xy.y.table.first_order_depth(xy.in_y(p_x), hint); }

// First-order depth of x's flank point at radius r, kNone where the flank has no material.
double depth_at(const XY& xy, int k, Flank f, double r, int& hint) {
  Vector2d p;
  return xy.x.table.flank_point_if_material(k, f, r, &p) ? depth_of(xy, p, hint) : kNone;
}

// The probe samples of one flank of x's tooth k: the depths measured so far (kNone where not
// probed or clear of material) and the deepest of them.
struct FlankSamples {
  static constexpr int n = FlankTable::kProbeRadii;
  FlankSamples(const XY& xy_, int k_, Flank f_, int& hint_)
      : xy(xy_), k(k_), f(f_), hint(hint_), material(xy_.x.table.probe_material(k_, f_)), step(xy_.spacing_m), window(xy_.window_m) {
    depth.fill(kNone);
  }
  bool missing(int i) const { return i < 0 || i >= n || !((material >> i) & 1u); }
  void probe(int i) {
    depth[i] = missing(i) ? kNone : depth_of(xy, xy.x.table.probe_point(k, f, i), hint);
    if (depth[i] > kNone && (best_i < 0 || depth[i] > depth[best_i])) best_i = i;
  }
  const XY& xy;
  int k;
  Flank f;
  int& hint;
  std::uint32_t material;
  double step, window;
  std::array<double, n> depth;
  int best_i = -1;
};

// The sample probe_tip() starts from, `end` (the tip's, or the first with material inward of
// it), and the direction inward along the flank, `dir` (+1 or −1 in sample index).
void tip_end(const FlankSamples& s, int& end, int& dir) {
  constexpr int n = FlankSamples::n;
  dir = s.xy.x.table.internal() ? 1 : -1;
  end = s.xy.x.table.internal() ? 0 : n - 1;
  while (s.missing(end) && end - 3 * dir >= 0 && end - 3 * dir < n) end += dir;
}

// The three samples nearest the tooth's free end (an internal gear's teeth point inward); a
// maximum at the farthest of them lies down the flank, where the other probing direction finds
// it, so the third is probed only when one of the first two is within the refinement window.
// False: no hit on this flank.
bool probe_tip(FlankSamples& s) {
  int end, dir;
  tip_end(s, end, dir);
  for (int j = 0; j < 2; ++j)
    if (!s.missing(end + j * dir)) s.probe(end + j * dir);
  if (s.best_i < 0 || s.depth[s.best_i] < -s.window) return false;
  if (!s.missing(end + 2 * dir)) s.probe(end + 2 * dir);
  return s.best_i != end + 2 * dir;
}

// probe_flank()'s first samples: every fourth, the last, and any next to a radius without material
// (bits of the material mask shifted onto their neighbours).
constexpr std::uint32_t first_samples(std::uint32_t material) {
  constexpr int n = FlankTable::kProbeRadii;
  constexpr std::uint32_t kAll = (std::uint32_t{1} << n) - 1;
  std::uint32_t every_fourth = std::uint32_t{1} << (n - 1);
  for (int i = 0; i < n; i += 4) every_fourth |= std::uint32_t{1} << i;
  const std::uint32_t without = ~material & kAll;
  return (every_fourth | (without << 1) | (without >> 1)) & kAll;
}

// The samples probe_flank() probes before it gives up on a flank more than 4·window clear: the
// first ones and every other between them (where they can matter).
constexpr std::uint32_t coarse_samples(std::uint32_t material) {
  constexpr int n = FlankTable::kProbeRadii;
  std::uint32_t m = first_samples(material);
  for (int i = 2; i < n - 1; i += 4) m |= std::uint32_t{1} << i;
  return m & material;
}

// Coarse to fine, probing a sample only where it can matter. Between two samples s·step apart
// the depth rises at most s²·window above the higher (the parabola bound window rests on, with
// room to spare); a stretch next to a sample that measured nothing has no such bound and is
// probed. The answer is that of probing every sample: the deepest one, and no refinement when it
// stays more than window clear (then false: no hit).
bool probe_flank(FlankSamples& s) {
  constexpr int n = FlankSamples::n;
  const double window = s.window;
  std::array<double, n>& depth = s.depth;
  // `top[i]`: what sample i can reach, its depth once probed, or a bound when it is skipped.
  std::array<double, n> top;
  std::uint32_t probed = 0;  // bit i: sample i probed
  auto has = [&](int i) { return ((s.material >> i) & 1u) != 0; };  // i within [0, n)
  auto probe_at_i = [&](int i) {
    s.probe(i);
    probed |= std::uint32_t{1} << i;
    top[i] = depth[i];
  };
  // Whether sample i, between samples lo and hi (s·step around it, both probed or bounded),
  // can reach `level`; if not, the bound is kept for the samples between.
  auto needed = [&](int i, int lo, int hi, double rise, double level) {
    const bool lo_probed = (probed >> lo) & 1u, hi_probed = (probed >> hi) & 1u;
    if (!has(lo) || !has(hi) || (lo_probed && depth[lo] <= kNone) || (hi_probed && depth[hi] <= kNone)) return true;
    const double reach = std::max(lo_probed ? depth[lo] + rise : top[lo], hi_probed ? depth[hi] + rise : top[hi]);
    if (reach >= level) return true;
    top[i] = reach;
    return false;
  };
  // Every fourth sample, the last, and any next to a radius without material, in increasing order.
  for (std::uint32_t todo = first_samples(s.material); todo != 0; todo &= todo - 1) probe_at_i(std::countr_zero(todo));
  // Every other: a flank whose best stays more than 4·window clear is done.
  for (int i = 2; i < n - 1; i += 4)
    if (!((probed >> i) & 1u) && has(i) &&
        needed(i, i - 2, std::min(i + 2, n - 1), 16 * window, std::max(s.best_i < 0 ? kNone : depth[s.best_i], -4 * window)))
      probe_at_i(i);
  if (s.best_i < 0 || depth[s.best_i] < -4 * window) return false;
  // The rest: where they could be the best or lift it into the refinement window.
  for (int i = 1; i < n - 1; i += 2)
    if (!((probed >> i) & 1u) && has(i) && needed(i, i - 1, i + 1, 4 * window, std::max(depth[s.best_i], -window))) probe_at_i(i);
  return depth[s.best_i] >= -window;
}

}  // namespace
}  // namespace gearsim::contact

#include "contact/flank_refine_impl.hpp"

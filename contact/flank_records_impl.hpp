// Internal to contact/, included by coherent_contact.cpp only (after flank_search_impl.hpp): what
// a full search of a flank proves for later calls — a clear flank's travel (sample_travel(),
// clear_travel(), renew_clear()), a tracked flank's per-sample bounds (track(), sample_bound(),
// probe_tracked()), the records' tests (record_holds(), tooth_record()) — and the stateless
// search's answer for a flank from its record or a full search (sampled_hit()).
// docs/tooth-contact.md, "Temporal coherence". Not an interface.
#pragma once

#include <cmath>
#include <limits>

#include "contact/coherent_contact.hpp"
#include "contact/flank_search_impl.hpp"

namespace gearsim::contact {
namespace {

// Added to every travel bound, m: the rounding of the poses' arithmetic (~1e-17 m at gear scale)
// and of the first-order depths, with a wide margin. Normally 1 nm.
constexpr double kTravelRounding_m = 1e-9;

// A flank without contact is measured fully (its skipped samples probed) for a record only when
// every sample it probed lies more than this many refinement windows clear: nearer flanks could
// be skipped for a step or two at most, not worth the probes (they are tracked instead).
// Normally 2 (chosen by instruction counts of the paper run at dt 1e-5 and 2e-5 s: 1, 3 and 4
// cost 1–2 % more).
constexpr double kRecordBeyondWindows = 2;
// The same for the second gear's flanks, which are not tracked (their search probes two or three
// samples at the tip): a record wherever the search did not refine. Normally 1 (instructions
// per paper step at 1e-5 s: 1.1 the same, 1.5 +0.2 %, 2 +0.5 %, 3 +1.3 %; at 2e-5 s 2 costs
// +0.14 %).
constexpr double kRecordBeyondWindowsTip = 1;

// Halvings (by 4) of the radial span a sample's bound is taken over: a narrower span leaves out
// the steep fillet bands that a wide one reaches.
constexpr int kSpanTries = 4;

// The longest arc of a circle (up to a half circle) against its chord.
constexpr double kArcOverChord = 1.5707963267948966;
constexpr double kChordOverArc = 0.6366197723675814;  // 1/kArcOverChord, to rounding

// An upper bound on e^x for x ≥ 0 without a libm call: 1/(1 − x) below x = 1/2 (e^x ≤ 1/(1 − x)
// for x < 1), infinite beyond (the bound is useless there anyway).
double exp_bound(double x) { return x < 0.5 ? 1 / (1 - x) : FlankTable::kInfinity; }

// How far the points of x's tooth may move in y's frame before a sample of this flank can reach
// the refinement window, m (0: it may reach it now). The sample measured nothing (free space
// beyond y's teeth) or first-order depth D < 0 there. The stateless search finds no contact on
// a flank all of whose samples stay below −window (probe_flank() and probe_tip() both return
// false: their best sample is one of them), so the flank may be skipped while no point of its
// tooth has moved by the least of these travels.
//
// The bound, for a sample at radius r of y with D(q0) < −T (T: the window):
//  - In a tooth space D is the nearer flank's by unscaled gaps; D̃ = the larger of the two
//    flanks' depths is continuous, D ≤ D̃ ≤ D + jump·|D| (FlankTable::first_order_rise), so
//    D̃(q0) ≤ −E with E = |D|·(1 − jump).
//  - On any path of length δ inside the teeth' annulus over radii within r ± span:
//    |∇D̃| ≤ slope + growth·|D̃|, hence (Grönwall) |D̃| ≤ (E + slope·s)·e^{growth·s} along it and
//    D̃ rises by at most δ·(slope + growth·(E + slope·δ)·e^{growth·δ}) (e^x taken as 1/(1 − x)). Below
//    travel = (E − T) / (slope + growth·(E + slope·span)·e^{growth·span}), capped at span, it
//    stays below −T. span stays clear of the root circle (past it D is radial). Beyond the
//    tips D is not measured: a straight path that leaves the annulus there and comes back is
//    replaced by one along the tip circle between the two crossings, at most π/2 times longer
//    (an arc of up to a half circle against its chord), so where r ± span reaches that circle
//    the travel is divided by π/2.
//  - A sample beyond y's tips (external y: r > r_max, internal: r < r_min) measures nothing
//    until it crosses that circle: its travel is its distance to it.
double sample_travel(const XY& xy, const Vector2d& p_x, double d, double window, int& hint) {
  const FlankTable& yt = xy.y.table;
  const Vector2d q = xy.in_y(p_x);
  const double r = q.norm();
  if (yt.internal() ? r < yt.r_min_m() : r > yt.r_max_m()) return yt.internal() ? yt.r_min_m() - r : r - yt.r_max_m();
  if (d <= kNone) d = depth_of(xy, p_x, hint);  // not probed by the search (or nothing there)
  if (d <= kNone || !(d < -window)) return 0;
  const double e = -d * (1 - yt.first_order_rise(r, r).jump), gap = e - window;
  if (!(gap > 0)) return 0;
  // Radii from the root circle (solid) to the tip circle (free), whichever way the teeth point.
  const double to_root = yt.internal() ? yt.r_max_m() - r : r - yt.r_min_m();
  const double to_tips = yt.internal() ? r - yt.r_min_m() : yt.r_max_m() - r;
  double span = std::min(gap, to_root), best = 0;
  for (int attempt = 0; attempt < kSpanTries && span > 0; ++attempt, span *= 0.25) {
    const FlankTable::FirstOrderRise rise = yt.first_order_rise(r - span, r + span);
    // gap / rate with rate = slope + growth·(e + slope·span)·exp_bound(growth·span), the bound's
    // 1/(1 − growth·span) cleared from the fraction: one division. No travel where that bound
    // is infinite.
    const double keep = 1 - rise.growth * span;
    if (!(keep > 0.5)) continue;
    const double travel = gap * keep / (rise.slope * keep + rise.growth * (e + rise.slope * span));
    if (!(travel > 0)) continue;
    best = std::max(best, std::min(travel, span) * (span > to_tips ? kChordOverArc : 1));
    if (travel >= 0.25 * span) break;  // a narrower span cannot allow more
  }
  return best;
}

using SampleTravels = CoherentToothSearch::SampleTravels;

// How far the flank's tooth may move before the stateless search could find anything on the
// flank, m (0: search it next time). `s`: the flank as the search left it (no contact). `t`: each
// sample's own travel (+∞ for those the search does not look at), where the result is > 0.
double clear_travel(const FlankSamples& s, bool tip_only, SampleTravels& t) {
  constexpr int n = FlankSamples::n;
  for (int i = 0; i < n; ++i)
    if (s.depth[i] > -(tip_only ? kRecordBeyondWindowsTip : kRecordBeyondWindows) * s.window) return 0;
  // The samples the search would look at: every one with material, or the two at the tip
  // (probe_tip() looks further only when one of these is within the window).
  std::uint32_t relevant = s.material;
  if (tip_only) {
    int end, dir;
    tip_end(s, end, dir);
    relevant = 0;
    for (int j = 0; j < 2; ++j)
      if (!s.missing(end + j * dir)) relevant |= std::uint32_t{1} << (end + j * dir);
  }
  int hint = s.hint;  // a copy: the search's own hint sequence stays as the stateless one
  double travel = std::numeric_limits<double>::infinity();
  t.fill(std::numeric_limits<double>::infinity());
  for (std::uint32_t todo = relevant; todo != 0; todo &= todo - 1) {
    const int i = std::countr_zero(todo);
    t[static_cast<std::size_t>(i)] = sample_travel(s.xy, s.xy.x.table.probe_point(s.k, s.f, i), s.depth[i], s.window, hint);
    travel = std::min(travel, t[static_cast<std::size_t>(i)]);
    if (!(travel > 0)) return 0;
  }
  return std::isfinite(travel) ? travel : 0;
}

// A renewal measures again, besides the samples whose travel ran out, those whose travel left
// would run out within as long a move again: fewer renewals for a few more measurements. Normally
// 1 (instructions per step, paper run: dt 1e-5 s −0.5 %, 2e-5 s −0.9 %; bench_contact_sweep 1.82
// → 1.72 µs per call, renewals 2.32 → 1.19 M; 2 gives no more).
constexpr double kRenewAhead = 1;

// A clear flank's record whose travel has run out, `moved` (a bound on how far every point of its
// tooth has moved since the record's pose): each sample's own bound (sample_travel()) concerns
// its own point only, so a sample whose travel exceeds `moved` is still clear, for what is left
// of its travel from the pose now (the moves from the record's pose and from now add up to at
// most the move from the record's). The others are measured again and bounded afresh as
// clear_travel() does. True: the flank is clear, `t` holds the samples' travels from now and
// `travel` their least — the stateless search finds nothing on it, as after a full search that
// makes a record. False: search it in full (a sample within kRecordBeyondWindows windows —
// kRecordBeyondWindowsTip on the second gear's flanks, `tip_only` —, or
// one without a bound); `t` is then stale. Samples whose travel left is short are measured again
// too (kRenewAhead).
bool renew_clear(const XY& xy, int k, Flank f, double moved, SampleTravels& t, double& travel, int hint, bool tip_only) {
  const FlankTable& xt = xy.x.table;
  const double window = xy.window_m;
  double least = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (!(t[i] < std::numeric_limits<double>::infinity())) continue;  // a sample the search does not look at
    double left = t[i] - moved;
    if (!(left > kRenewAhead * moved)) {
      const Vector2d p = xt.probe_point(k, f, static_cast<int>(i));
      const double d = depth_of(xy, p, hint);
      if (d > -(tip_only ? kRecordBeyondWindowsTip : kRecordBeyondWindows) * window) return false;
      left = sample_travel(xy, p, d, window, hint);
      if (!(left > 0)) return false;
    }
    t[i] = left;
    least = std::min(least, left);
  }
  if (!(least > 0 && std::isfinite(least))) return false;
  travel = least;
  return true;
}

// Travel up to which a tracked flank's bounds hold, in refinement windows: beyond it the flank is
// searched in full again (and tracked afresh). Normally 4 (20 µm on a module-1 tooth: a few
// simulation steps of the paper run): wider spans reach the steep fillet bands and loosen every
// bound (8 and 16 cost 4 % and 7 % more instructions at dt 1e-5 s, 3 the same as 4).
constexpr double kTrackSpanWindows = 4;

using Track = CoherentToothSearch::TrackedFlank;

// The bounds of a flank searched in full and found within the refinement window (s: as the
// search left it), valid for travels up to span: per sample, with F the depth of the branch
// nearest zero (in a tooth space the larger of its two flanks' depths, inside a tooth the
// smaller of the tooth's two), continuous, |D − F| ≤ jump·|D| and |∇F| ≤ slope + growth·|F|
// (FlankTable::first_order_rise), so after a travel δ ≤ span (Grönwall, as in
// sample_travel()) F ≤ top + δ·(slope + growth·(|top| + slope·δ)·e^{growth·span}) where top
// bounds F then: D(1 − jump) in a gap (D < 0), D inside. Samples near the teeth's circles
// (D's definition changes there) or over steep bands are always probed.
void track(const FlankSamples& s, Track& t, double span) {
  const FlankTable& yt = s.xy.y.table;
  t.best = s.best_i;
  t.span_m = span;
  int hint = s.hint;
  for (int i = 0; i < Track::n; ++i) {
    t.kind[i] = Track::kProbe;
    if (s.missing(i)) continue;
    const Vector2d p = s.xy.x.table.probe_point(s.k, s.f, i);
    const double r = s.xy.in_y(p).norm();
    if (yt.internal() ? r < yt.r_min_m() : r > yt.r_max_m()) {
      t.kind[i] = Track::kFree;
      t.free_m[i] = yt.internal() ? yt.r_min_m() - r : r - yt.r_max_m();
      continue;
    }
    const double to_root = yt.internal() ? yt.r_max_m() - r : r - yt.r_min_m();
    const double to_tips = yt.internal() ? r - yt.r_min_m() : yt.r_max_m() - r;
    if (to_root < span) continue;
    const double d = s.depth[i] > kNone ? s.depth[i] : depth_of(s.xy, p, hint);
    if (d <= kNone) continue;
    const FlankTable::FirstOrderRise rise = yt.first_order_rise(r - span, r + span);
    const double factor = exp_bound(rise.growth * span);
    if (!(rise.slope < FlankTable::kInfinity && factor < FlankTable::kInfinity && rise.jump < 1)) continue;
    t.kind[i] = Track::kBounded;
    t.top[i] = d < 0 ? d * (1 - rise.jump) : d;
    t.slope[i] = rise.slope;
    t.growth[i] = rise.growth;
    t.growth_factor[i] = factor;
    t.jump[i] = rise.jump;
    t.path[i] = to_tips < span ? kArcOverChord : 1;  // a path around the tips (sample_travel())
  }
}

// A bound on sample i's first-order depth after a travel ≤ the track's span: kNone when it
// measures nothing, +∞ when it must be probed.
double sample_bound(const Track& t, int i, double travel) {
  switch (t.kind[i]) {
    case Track::kFree:
      return travel < t.free_m[i] ? kNone : std::numeric_limits<double>::infinity();
    case Track::kProbe:
      return std::numeric_limits<double>::infinity();
    case Track::kBounded:
      break;
  }
  travel *= t.path[i];
  if (travel > t.span_m) return std::numeric_limits<double>::infinity();
  const double f = t.top[i] + travel * (t.slope[i] + t.growth[i] * (std::abs(t.top[i]) + t.slope[i] * travel) * t.growth_factor[i]);
  return f > 0 ? f * (1 + t.jump[i]) : f;
}

// probe_flank()'s answer for a tracked flank, probing only the samples that can be the deepest:
// the last best and its neighbours first, then every sample whose bound reaches the deepest of
// them, then the neighbours of the deepest (refined_radius() fits through them; the full search
// probes them too). The deepest probed sample is the deepest of all, which is the full search's
// (its skipping keeps the answer of probing every sample).
bool probe_tracked(FlankSamples& s, const Track& t, double travel) {
  constexpr int n = FlankSamples::n;
  std::uint32_t probed = 0;
  auto probe = [&](int i) {
    if (i < 0 || i >= n || ((probed >> i) & 1u) || s.missing(i)) return;
    s.probe(i);
    probed |= std::uint32_t{1} << i;
  };
  for (int i = t.best - 1; i <= t.best + 1; ++i) probe(i);
  const double level = s.best_i < 0 ? kNone : s.depth[s.best_i];
  for (int i = 0; i < n; ++i)
    if (!((probed >> i) & 1u) && !s.missing(i) && sample_bound(t, i, travel) >= level) probe(i);
  if (s.best_i < 0 || s.depth[s.best_i] < -s.window) return false;
  // The full search gives up on a flank whose coarse samples (every fourth, the last, those next
  // to a radius without material, then every other where it can matter) all lie more than
  // 4·window clear, even where a sample between them (next to one that measured nothing) is
  // deeper: the same answer here. Coarse samples it skips lie below that level (its rise bound).
  std::uint32_t coarse = coarse_samples(s.material);
  bool reaches = false;
  for (std::uint32_t todo = coarse; todo != 0 && !reaches; todo &= todo - 1) {
    const int i = std::countr_zero(todo);
    if (!((probed >> i) & 1u) && !s.missing(i) && sample_bound(t, i, travel) >= -4 * s.window) probe(i);
    reaches = ((probed >> i) & 1u) && s.depth[i] >= -4 * s.window;
  }
  if (!reaches) return false;
  probe(s.best_i - 1);
  probe(s.best_i + 1);
  return true;
}

// Whether a clear flank's record still holds (rec.travel_m > 0): every point of its tooth has
// moved by less than the record's travel since. Any point p of the tooth moves in y's frame by
// Δc + (R1 − R0)(p − c): at most the tooth centre's move plus |Δturn| times the tooth's bounding
// radius (|R1 − R0| = 2|sin(Δturn/2)| ≤ |Δturn|). Without a square root:
// |Δc| + |Δturn|·reach + rounding < travel_m.
bool record_holds(const CoherentToothSearch::FlankRecord& rec, const Vector2d& centre, double turn, double reach) {
  const double left = rec.travel_m - std::abs(turn - rec.turn_rad) * reach - kTravelRounding_m;
  return left > 0 && (centre - rec.tooth_centre_in_y_m).squaredNorm() < left * left;
}

// A travel from the tooth's pose now (its centre in y's frame, its turn) within which both its
// flank records still hold, where both are clear: each record's travel less how far every point
// of the tooth has moved since it was made (|Δc| + |Δturn|·reach + rounding, as record_holds()),
// the least of the two. By the triangle inequality a move within it from here is within each
// record's own travel from its pose: record_holds() on the tooth record implies it on both flank
// records (the same skips, one test). −1 where either flank is not clear or nothing is left.
CoherentToothSearch::ToothRecord tooth_record(const CoherentToothSearch::FlankRecord& ccw, const CoherentToothSearch::FlankRecord& cw,
                                              const Vector2d& centre, double turn, double reach) {
  CoherentToothSearch::ToothRecord t;
  if (!(ccw.travel_m > 0 && cw.travel_m > 0)) return t;
  auto left = [&](const CoherentToothSearch::FlankRecord& r) {
    return r.travel_m - ((centre - r.tooth_centre_in_y_m).norm() + std::abs(turn - r.turn_rad) * reach + kTravelRounding_m);
  };
  const double travel = std::min(left(ccw), left(cw));
  if (travel > 0) t = {centre, turn, travel};
  return t;
}

bool record_holds(const CoherentToothSearch::ToothRecord& rec, const Vector2d& centre, double turn, double reach) {
  const double left = rec.travel_m - std::abs(turn - rec.turn_rad) * reach - kTravelRounding_m;
  return left > 0 && (centre - rec.tooth_centre_in_y_m).squaredNorm() < left * left;
}

// The stateless search's answer for one flank, from its record where that holds (skipped: no
// hit; tracked: only the samples that can hold the deepest probed) or by a full search that
// makes the record afresh. No hit: depth kNone, tooth_y −1. `skip_tested`: record_holds() was
// found false already (find()).
Hit sampled_hit(const XY& xy, int k, Flank f, bool tip_only, const Vector2d& centre, double turn, double reach,
                CoherentToothSearch::FlankRecord& rec, SampleTravels& travels, CoherentToothSearch::TrackedFlank* track_of, int& hint,
                CoherentToothSearch::Counts& counts, bool skip_tested) {
  if (rec.travel_m > 0) {
    if (!skip_tested && record_holds(rec, centre, turn, reach)) {
      ++counts.skipped;
      return {};
    }
    const double moved = (centre - rec.tooth_centre_in_y_m).norm() + std::abs(turn - rec.turn_rad) * reach + kTravelRounding_m;
    double renewed = 0;
    if (renew_clear(xy, k, f, moved, travels, renewed, hint, tip_only)) {
      rec.tooth_centre_in_y_m = centre;
      rec.turn_rad = turn;
      rec.travel_m = renewed;
      ++counts.renewed;
      return {};
    }
  }
  const double travel =
      rec.tracked ? (centre - rec.tooth_centre_in_y_m).norm() + std::abs(turn - rec.turn_rad) * reach + kTravelRounding_m : 0;
  FlankSamples s(xy, k, f, hint);
  bool refine;
  if (rec.tracked && travel <= track_of->span_m) {  // only the first gear's flanks are tracked
    ++counts.tracked;
    refine = probe_tracked(s, *track_of, travel);
  } else {
    ++counts.searched;
    refine = tip_only ? probe_tip(s) : probe_flank(s);
    rec.tooth_centre_in_y_m = centre;
    rec.turn_rad = turn;
    rec.travel_m = refine ? -1 : clear_travel(s, tip_only, travels);
    // A flank of the first gear that cannot be skipped is tracked (its probing is what costs).
    rec.tracked = !tip_only && s.best_i >= 0 && !(rec.travel_m > 0);
    if (rec.tracked) track(s, *track_of, kTrackSpanWindows * s.window);
  }
  return refine ? refined_hit(s) : Hit{};
}

}  // namespace
}  // namespace gearsim::contact

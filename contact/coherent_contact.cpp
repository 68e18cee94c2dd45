#include "contact/coherent_contact.hpp"

#include <cmath>
#include <limits>

#include "contact/flank_search_impl.hpp"

namespace gearsim::contact {
namespace {

// Added to every travel bound, m: the rounding of the poses' arithmetic (~1e-17 m at gear scale)
// and of the first-order depths, with a wide margin. Normally 1 nm.
constexpr double kTravelRounding_m = 1e-9;

// A flank without contact is measured fully (its skipped samples probed) for a record only when
// every sample it probed lies more than this many refinement windows clear: nearer flanks could
// be skipped for a step or two at most, not worth the probes. Normally 4 (where the stateless
// search's coarse pass stops too).
constexpr double kRecordBeyondWindows = 4;

// Halvings (by 4) of the radial span a sample's bound is taken over: a narrower span leaves out
// the steep fillet bands that a wide one reaches.
constexpr int kSpanTries = 4;

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
//    D̃ rises by at most δ·(slope + growth·(E + slope·δ)·e^{growth·δ}). Below
//    travel = (E − T) / (slope + growth·(E + slope·span)·e^{growth·span}), capped at span, it
//    stays below −T. span is kept inside the annulus (no path leaves it: D is not measured
//    beyond the tips and is radial past the root).
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
  double span = std::min(gap, std::min(r - yt.r_min_m(), yt.r_max_m() - r)), best = 0;
  for (int attempt = 0; attempt < kSpanTries && span > 0; ++attempt, span *= 0.25) {
    const FlankTable::FirstOrderRise rise = yt.first_order_rise(r - span, r + span);
    const double rate = rise.slope + rise.growth * (e + rise.slope * span) * std::exp(rise.growth * span);
    const double travel = gap / rate;
    if (!(travel > 0)) continue;
    best = std::max(best, std::min(travel, span));
    if (travel >= 0.25 * span) break;  // a narrower span cannot allow more
  }
  return best;
}

// How far the flank's tooth may move before the stateless search could find anything on the
// flank, m (0: search it next time). `s`: the flank as the search left it (no contact).
double clear_travel(const FlankSamples& s, bool tip_only) {
  constexpr int n = FlankSamples::n;
  for (int i = 0; i < n; ++i)
    if (s.depth[i] > -kRecordBeyondWindows * s.window) return 0;
  // The samples the search would look at: every one with material, or the two at the tip
  // (probe_tip() looks further only when one of these is within the window).
  std::uint32_t relevant = s.material;
  if (tip_only) {
    const int dir = s.xy.x.table.internal() ? 1 : -1;
    int end = s.xy.x.table.internal() ? 0 : n - 1;
    while (s.missing(end) && end - 3 * dir >= 0 && end - 3 * dir < n) end += dir;
    relevant = 0;
    for (int j = 0; j < 2; ++j)
      if (!s.missing(end + j * dir)) relevant |= std::uint32_t{1} << (end + j * dir);
  }
  int hint = s.hint;  // a copy: the search's own hint sequence stays as the stateless one
  double travel = std::numeric_limits<double>::infinity();
  for (std::uint32_t todo = relevant; todo != 0; todo &= todo - 1) {
    const int i = std::countr_zero(todo);
    travel = std::min(travel, sample_travel(s.xy, s.xy.x.table.probe_point(s.k, s.f, i), s.depth[i], s.window, hint));
    if (!(travel > 0)) return 0;
  }
  return std::isfinite(travel) ? travel : 0;
}

}  // namespace

void CoherentToothSearch::reset() {
  for (std::vector<FlankRecord>& r : records_) r.assign(r.size(), FlankRecord{});
}

void CoherentToothSearch::find(const FlankTable& ta, const PlanarPose& pa, const FlankTable& tb, const PlanarPose& pb,
                               std::vector<ToothContact>& best) {
  if (tables_[0] != &ta || tables_[1] != &tb) {
    tables_[0] = &ta, tables_[1] = &tb;
    records_[0].assign(static_cast<std::size_t>(ta.teeth()) * 2, FlankRecord{});
    records_[1].assign(static_cast<std::size_t>(tb.teeth()) * 2, FlankRecord{});
  }
  const Frame a{ta, pa}, b{tb, pb};
  best.clear();
  // As find_tooth_contacts(), flank by flank, but a flank whose record still holds is skipped.
  for (int pass = 0; pass < 2; ++pass) {
    const Frame& x = pass == 0 ? a : b;
    const Frame& y = pass == 0 ? b : a;
    const XY xy{x, y};
    const ToothWindow window = tooth_window(x, y);
    const bool tip_only = pass == 1;
    const double turn = x.pose.angle_rad - y.pose.angle_rad, reach = x.table.tooth_bound_radius_m();
    std::vector<FlankRecord>& records = records_[pass];
    int hint = -1;
    for (int k = 0; k < x.table.teeth(); ++k) {
      if (!window.holds(k, x.table.teeth()) || !tooth_near(x, k, y)) continue;
      const Vector2d centre = xy.in_y(x.table.tooth_centre(k));
      for (Flank f : {Flank::Ccw, Flank::Cw}) {
        FlankRecord& rec = records[static_cast<std::size_t>(k) * 2 + (f == Flank::Cw)];
        // Any point p of the tooth moves in y's frame by Δc + (R1 − R0)(p − c): at most the
        // tooth centre's move plus |Δturn| times the tooth's bounding radius (|R1 − R0| =
        // 2|sin(Δturn/2)| ≤ |Δturn|).
        if (rec.travel_m > 0 &&
            (centre - rec.tooth_centre_in_y_m).norm() + std::abs(turn - rec.turn_rad) * reach + kTravelRounding_m <
                rec.travel_m) {
          ++counts_.skipped;
          continue;
        }
        ++counts_.searched;
        FlankSamples s(xy, k, f, hint);
        const bool refine = tip_only ? probe_tip(s) : probe_flank(s);
        rec.tooth_centre_in_y_m = centre;
        rec.turn_rad = turn;
        rec.travel_m = refine ? -1 : clear_travel(s, tip_only);
        if (!refine) continue;
        const Hit h = refined_hit(s);
        if (h.tooth_y < 0) continue;
        if (pass == 0) keep_contact(best, k, h.tooth_y, f, h, true);
        else keep_contact(best, h.tooth_y, k, h.flank_y, h, false);
      }
    }
  }
  sort_contacts(best);
}

}  // namespace gearsim::contact

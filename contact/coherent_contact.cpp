#include "contact/coherent_contact.hpp"

#include <cmath>
#include <limits>

#include "contact/contact_list_impl.hpp"
#include "contact/flank_search_impl.hpp"
#include "contact/continuation_impl.hpp"
#include "contact/flank_records_impl.hpp"
#include "contact/near_bound_impl.hpp"

namespace gearsim::contact {

namespace {

using Search = CoherentToothSearch;

// This flank's interior maximum continues on a's flank (sol.tooth_y, sol.flank_y). Where the
// first pass solved that flank's interior maximum in this call on this very flank of b, both are
// the one common normal of the two flanks (the foot of each point on the other flank, their
// tangents parallel), seen from either side: the same depth, point and normal to rounding
// (keep_contact() would keep either). That solution stands for this flank too, its radii
// swapped, and is not solved again: true then. Only where this pass would have kept the solution
// (continued_hit()): within 1.5 sample spacings of this flank's tip, and on flanks curved no
// more sharply than its own spacing allows (the first pass checked its own, so a spacing no
// wider here).
[[gnu::always_inline]] inline bool share_first_pass(const XY& xy, int k, Flank f, Search::Solution& sol, Search::NearBound& bound,
                                                    Search::FlankRecord& rec, const std::vector<Search::Solution>& first_pass,
                                                    const std::vector<Search::NearBound>& first_bounds, long calls, bool park,
                                                    Search::Counts& counts) {
  const std::size_t at = static_cast<std::size_t>(sol.tooth_y) * 2 + (sol.flank_y == Flank::Cw);
  const Search::Solution& first = first_pass[at];
  const double spacing = xy.spacing_m;
  double lo, hi;
  xy.x.table.flank_extent(k, f, &lo, &hi);
  if (!(first.call == calls && !first.parked && first.solved == Hit::kInterior && first.tooth_y == k && first.flank_y == f &&
        std::abs(first.s_y - (xy.x.table.internal() ? lo : hi)) <= 1.5 * spacing &&
        spacing <= xy.y.table.probe_radius(1) - xy.y.table.probe_radius(0)))
    return false;
  ++counts.shared;
  sol = {static_cast<signed char>(Hit::kInterior),
         sol.tooth_y,
         sol.flank_y,
         first.s_y,
         first.r_x,
         calls,
         sol.r_x,
         sol.s_y,
         sol.r_prev,
         sol.s_prev,
         sol.parked ? 0 : std::min(sol.history + 1, 2),
         sol.face,
         false};
  if (park) bound = swapped(first_bounds[at]);
  rec.travel_m = -1;  // searched in full when the continuation ends
  rec.tracked = false;
  return true;
}

// A near pair whose bound still proves it apart (and, where the near list is asked for
// (`near_asked`), unable to close within two steps at the present velocities) is not solved: no
// contact and no near pair, as the stateless search would find (near_bound_impl.hpp); true then.
// Its continuation goes on from its last solve's radii. Only while it is still the flank y's
// point faces (still_faces(), as a continued solution must). `parked`: where the parked pairs are
// recorded, or null.
[[gnu::always_inline]] inline bool park_near_pair(const XY& xy, int pass, int k, Flank f, bool tip_only, Search::Solution& sol,
                                                  const Search::NearBound& bound, Search::FlankRecord& rec, bool near_asked,
                                                  const Search::Motion* motion, std::vector<Search::ParkedPair>* parked, long calls,
                                                  Search::Counts& counts) {
  const Search::PlanarTwist* vx = motion ? (pass == 0 ? &motion->a : &motion->b) : nullptr;
  const Search::PlanarTwist* vy = motion ? (pass == 0 ? &motion->b : &motion->a) : nullptr;
  double closing = 0;
  const double gap_bound = near_bound(xy, k, f, bound, sol.tooth_y, sol.flank_y, tip_only, vx, vy, &closing);
  if (!(gap_bound > 0 && gap_bound < xy.window_m && (!near_asked || gap_bound > 2 * motion->step_s * std::max(0.0, closing)) &&
        still_faces(xy.y.table, xy.y.to_local(xy.x.to_world(bound.point_x)), sol.tooth_y, sol.flank_y, sol.face)))
    return false;
  ++counts.parked;
  if (parked) {
    // As keep_contact() keys a pair: a's tooth and flank, b's tooth.
    parked->push_back(pass == 0 ? Search::ParkedPair{k, sol.tooth_y, f, gap_bound, closing}
                                : Search::ParkedPair{sol.tooth_y, k, sol.flank_y, gap_bound, closing});
  }
  sol.call = calls;  // still live next call
  sol.history = 0;  // solved again from the last solve's radii
  sol.parked = true;
  rec.travel_m = -1;
  rec.tracked = false;
  return true;
}

// The last call's solution continued into this one (`h`): true where it is found within the
// window, the solution then updated (and, where the continued answer replaces the search, the
// near pair's snapshot kept and the flank's record cleared: it is searched in full when the
// continuation ends). Started where the last steps' motion, continued, takes the
// solution: the parabola through the last three solutions (the start is then off by the
// motion's third difference: ~1e-11 m for a contact rolling 12 µm per step along an involute of
// 10 mm radius, where the line through two was off by its second, ~1e-8 m, and Newton's method
// needed a second evaluation of the flanks), the line through two, or the last.
[[gnu::always_inline]] inline bool continue_solution(const XY& xy, int k, Flank f, bool tip_only, Search::Continuation continuation,
                                                     bool park, long calls, Search::Solution& sol, Search::NearBound& bound,
                                                     Search::FlankRecord& rec, Search::Counts& counts, int& hint, Hit& h) {
  const double r0 = sol.history >= 2 ? 3 * (sol.r_x - sol.r_prev) + sol.r_prev2 : sol.history == 1 ? 2 * sol.r_x - sol.r_prev : sol.r_x;
  const double s0 = sol.history >= 2 ? 3 * (sol.s_y - sol.s_prev) + sol.s_prev2 : sol.history == 1 ? 2 * sol.s_y - sol.s_prev : sol.s_y;
  Search::FaceReference face = sol.face;
  h = continued_hit(xy, k, f, static_cast<Hit::Solved>(sol.solved), sol.tooth_y, sol.flank_y, sol.r_x, sol.s_y, r0, s0, tip_only, face,
                    hint);
  if (!(h.depth >= -xy.window_m)) return false;
  ++counts.continued;
  counts.crossings += h.solved == Hit::kCrossing;
  // The same maximum continued: its history predicts the next start.
  const bool same = h.solved == sol.solved && h.tooth_y == sol.tooth_y && h.flank_y == sol.flank_y && !sol.parked;
  sol = {static_cast<signed char>(h.solved),
         h.tooth_y,
         h.flank_y,
         h.r_x,
         h.s_y,
         calls,
         sol.r_x,
         sol.s_y,
         sol.r_prev,
         sol.s_prev,
         same ? std::min(sol.history + 1, continuation == Search::Continuation::replace ? 2 : 1) : 0,
         face,
         false};
  if (continuation == Search::Continuation::replace) {
    if (park) keep_near_snapshot(bound, xy, k, f, h);
    rec.travel_m = -1;
    rec.tracked = false;
  }
  return true;
}

// The sampled search's answer kept as the flank's solution to continue, or none. A tip
// crossing's maximum is continued only where the continued answer replaces the search
// (`deeper` searches every flank anyway), and only on the first gear's flanks
// (samples_see_crossing() reproduces probe_flank()'s view, not probe_tip()'s).
[[gnu::always_inline]] inline void keep_sampled_solution(const XY& xy, int k, Flank f, int pass, const Hit& sampled,
                                                         Search::Continuation continuation, bool park, long calls, Search::Solution& sol,
                                                         Search::NearBound& bound) {
  using C = Search::Continuation;
  if (continuation != C::off && sampled.solved != Hit::kSampled &&
      (sampled.solved != Hit::kCrossing || (continuation == C::replace && pass == 0))) {
    sol = {static_cast<signed char>(sampled.solved),
           sampled.tooth_y,
           sampled.flank_y,
           sampled.r_x,
           sampled.s_y,
           calls,
           0,
           0,
           0,
           0,
           0,
           Search::FaceReference{},
           false};
    if (park && continuation == C::replace) keep_near_snapshot(bound, xy, k, f, sampled);
  } else {
    sol = Search::Solution{};
  }
}

// A flank's answer kept in `best` (and `near`), keyed as keep_contact() keys a pair: a's tooth
// and flank, b's tooth (pass 0: x is a; pass 1: x is b).
[[gnu::always_inline]] inline void emit(std::vector<ToothContact>& best, std::vector<ToothContact>* near, int pass, int k, Flank f,
                                        const Hit& h) {
  if (pass == 0)
    keep_contact(best, k, h.tooth_y, f, h, true, near);
  else
    keep_contact(best, h.tooth_y, k, h.flank_y, h, false, near);
}

}  // namespace

void CoherentToothSearch::reset() {
  for (std::vector<FlankRecord>& r : records_) r.assign(r.size(), FlankRecord{});
  for (std::vector<ToothRecord>& r : tooth_records_) r.assign(r.size(), ToothRecord{});
  for (std::vector<Solution>& s : solutions_) s.assign(s.size(), Solution{});
}

void CoherentToothSearch::adopt_tables(const FlankTable& ta, const FlankTable& tb) {
  tables_[0] = &ta, tables_[1] = &tb;
  records_[0].assign(static_cast<std::size_t>(ta.teeth()) * 2, FlankRecord{});
  records_[1].assign(static_cast<std::size_t>(tb.teeth()) * 2, FlankRecord{});
  tooth_records_[0].assign(static_cast<std::size_t>(ta.teeth()), ToothRecord{});
  tooth_records_[1].assign(static_cast<std::size_t>(tb.teeth()), ToothRecord{});
  tracks_.assign(records_[0].size(), TrackedFlank{});
  solutions_[0].assign(records_[0].size(), Solution{});
  solutions_[1].assign(records_[1].size(), Solution{});
  bounds_[0].assign(records_[0].size(), NearBound{});
  bounds_[1].assign(records_[1].size(), NearBound{});
  travels_[0].resize(records_[0].size());
  travels_[1].resize(records_[1].size());
}

void CoherentToothSearch::find(const FlankTable& ta, const PlanarPose& pa, const FlankTable& tb, const PlanarPose& pb,
                               std::vector<ToothContact>& best, std::vector<ToothContact>* near, const Motion* motion) {
  if (tables_[0] != &ta || tables_[1] != &tb) adopt_tables(ta, tb);
  ++calls_;
  const Frame a{ta, pa}, b{tb, pb};
  best.clear(), parked_.clear();
  if (near) near->clear();
  // As find_tooth_contacts(), flank by flank, but a flank whose record still holds is skipped or
  // probed only where it can hold its deepest sample. The centres' distance and direction once
  // for both passes' tooth windows.
  const Vector2d a_to_b = pb.centre_m - pa.centre_m;
  const double dist = a_to_b.norm(), facing_b = rough_atan2(a_to_b.y(), a_to_b.x());
  for (int pass = 0; pass < 2; ++pass) {
    const Frame &x = pass == 0 ? a : b, &y = pass == 0 ? b : a;
    const XY xy{x, y, continuation_ == Continuation::replace ? kNewtonTaylorSmooth_m : kNewtonTaylor_m};
    const ToothWindow window = tooth_window(x, y, dist, pass == 0 ? facing_b : facing_b + 3.141592653589793);
    const bool tip_only = pass == 1;
    const double turn = x.pose.angle_rad - y.pose.angle_rad, reach = x.table.tooth_bound_radius_m();
    std::vector<FlankRecord>& records = records_[pass];
    const double outer = y.table.r_max_m() + reach, outer2 = outer * outer, inner = y.table.r_min_m() - reach;
    int hint = -1;
    for_each_tooth(window, x.table.teeth(), [&](int k) {
      // tooth_near(x, k, y), from the tooth's centre in y's frame (y's centre at the origin).
      const Vector2d centre = xy.in_y(x.table.tooth_centre(k));
      if (const double d2 = centre.squaredNorm(); !(d2 < outer2 && (inner < 0 || d2 > inner * inner))) return;
      // Both flanks clear since their records were made (with `deeper` a clear flank may still
      // hold a solution: there each flank is looked at).
      ToothRecord& tooth_rec = tooth_records_[pass][static_cast<std::size_t>(k)];
      if (tooth_rec.travel_m > 0 && continuation_ != Continuation::deeper && record_holds(tooth_rec, centre, turn, reach)) {
        counts_.skipped += 2;
        return;
      }
      for (Flank f : {Flank::Ccw, Flank::Cw}) {
        const std::size_t at = static_cast<std::size_t>(k) * 2 + (f == Flank::Cw);
        FlankRecord& rec = records[at];
        Solution& sol = solutions_[pass][at];
        NearBound& bound = bounds_[pass][at];  // meaningful only with sol
        // A flank with last call's solution to continue, or without. A solution clears the flank's
        // record, so a clear one has none — except with `deeper`, where a faceted flank can be both.
        auto is_live = [&] { return continuation_ != Continuation::off && sol.solved != 0 && sol.call + 1 == calls_; };
        // Most flanks are clear and stay so: their record's test before anything else.
        const bool skip_tested = rec.travel_m > 0 && (continuation_ != Continuation::deeper || !is_live());
        if (skip_tested && record_holds(rec, centre, turn, reach)) {
          ++counts_.skipped;
          continue;
        }
        const bool live = !skip_tested && is_live();
        if (pass == 1 && continuation_ == Continuation::replace && sol.solved == Hit::kInterior && sol.call + 1 == calls_ &&
            share_first_pass(xy, k, f, sol, bound, rec, solutions_[0], bounds_[0], calls_, park_, counts_))
          continue;
        if (live && park_ && continuation_ == Continuation::replace && bound.valid && (!near || motion) &&
            park_near_pair(xy, pass, k, f, tip_only, sol, bound, rec, near != nullptr, motion, record_parked_ ? &parked_ : nullptr, calls_,
                           counts_))
          continue;
        Hit continued;  // depth kNone: none
        if (live && continue_solution(xy, k, f, tip_only, continuation_, park_, calls_, sol, bound, rec, counts_, hint, continued)) {
          if (continuation_ == Continuation::replace) {
            emit(best, near, pass, k, f, continued);
            continue;
          }
        } else {
          continued = Hit{};
        }
        const Hit sampled = sampled_hit(xy, k, f, tip_only, centre, turn, reach, rec, travels_[pass][at],
                                        pass == 0 ? &tracks_[at] : nullptr, hint, counts_, skip_tested);
        if (continued.depth > kNone && !(sampled.depth > continued.depth)) {
          emit(best, near, pass, k, f, continued);  // deeper: the continued maximum, which goes on being continued
        } else if (sampled.tooth_y >= 0) {
          keep_sampled_solution(xy, k, f, pass, sampled, continuation_, park_, calls_, sol, bound);
          emit(best, near, pass, k, f, sampled);
        }
      }
      if (continuation_ != Continuation::deeper)
        tooth_rec =
            tooth_record(records[static_cast<std::size_t>(k) * 2], records[static_cast<std::size_t>(k) * 2 + 1], centre, turn, reach);
    });
  }
  sort_contacts(best);
  finish_near(best, near);
}

}  // namespace gearsim::contact

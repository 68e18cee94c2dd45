// Tooth contact of one gear pair stepped through time: find_tooth_contacts() with a memory. Between
// two steps the gears move little, so a flank whose last measurement left it far from the other
// gear cannot touch it now; CoherentToothSearch skips such a flank until the relative motion since
// that measurement could have closed the gap, with a bound that holds for any motion (no
// velocities, no step size assumed: a jump of the poses makes it re-probe). Every flank it does
// not skip is searched exactly as find_tooth_contacts() searches it, so it returns the same
// contacts (docs/tooth-contact.md, "Temporal coherence"). One object per gear pair; not
// thread-safe; no allocation per call once warm.
#pragma once

#include <Eigen/Core>
#include <array>
#include <vector>

#include "contact/flank_table.hpp"
#include "contact/tooth_contact.hpp"

namespace gearsim::contact {

class CoherentToothSearch {
 public:
  // The contacts find_tooth_contacts(a, pa, b, pb, out) returns, into `out` (cleared first). The
  // tables must outlive the object; other tables than the last call's start it afresh.
  // With `near`: the near pairs find_tooth_contacts() gives there.
  //
  // Near pairs (Continuation::replace, set_park_near_pairs()): a continued solution that left
  // the two flanks apart (a gap) is not solved again while a bound proves them still apart — it
  // is "parked": no contact, and no entry in `near`. The bound (near_bound_impl.hpp,
  // near_bound(); docs/tooth-contact.md, "Near pairs: the osculating-circle bound") is taken
  // from the poses alone, whatever their motion since the solve. With `near` a pair is parked only when `motion` is given too, and
  // only while it also cannot close within two steps at the present velocities: the near list
  // is what predicts a contact's onset (physics' OnsetSplit::onset_s()), and a parked pair is one it
  // would not have split a step for.
  struct PlanarTwist {
    Eigen::Vector2d velocity_m_s = Eigen::Vector2d::Zero();  // the gear centre's (PlanarPose::centre_m), world
    double angular_velocity_rad_s = 0;
  };
  struct Motion {
    PlanarTwist a, b;
    double step_s = 0;  // the time step the poses advance by
  };
  void find(const FlankTable& a, const PlanarPose& pa, const FlankTable& b, const PlanarPose& pb, std::vector<ToothContact>& out,
            std::vector<ToothContact>* near = nullptr, const Motion* motion = nullptr);
  // Forget every measurement: the next call searches every flank.
  void reset();

  // Continuation (off by default): a flank whose deepest point the last call solved by Newton's
  // method (an interior maximum or a corner, flank_newton_impl.hpp) is solved again from that
  // solution, on the same flank of the other gear; where the solve fails, leaves the flank,
  // faces another flank, curves too sharply or lies outside the refinement window, it is not.
  // With `replace`, a first-gear flank whose maximum lay where it crosses the other gear's tip
  // circle is solved there again (Counts::crossings), while the stateless search would still
  // come to it (continuation_impl.hpp, continued_crossing()).
  //  - replace: the continued solution stands for the flank, which is not probed (smooth flanks
  //    with one maximum per contact: the stateless search's contacts to ~0.1 nm, not bit for bit);
  //  - deeper: the flank is also searched as the stateless search does, and the deeper of the two
  //    answers stands (faceted CAD flanks, whose contacts have several maxima: each way alone
  //    sometimes lands on a lower one).
  // docs/tooth-contact.md, "Continuation".
  enum class Continuation { off, replace, deeper };
  void set_continuation(Continuation c) { continuation_ = c; }
  void set_continuation(bool on) { continuation_ = on ? Continuation::replace : Continuation::off; }
  // Near pairs parked under their bound (on by default; only with Continuation::replace).
  void set_park_near_pairs(bool on) { park_ = on; }
  // The last call's parked pairs with their bounds, kept only when asked for (a record for
  // checking the bound: tests/contact/test_near_bound.cpp).
  struct ParkedPair {
    int tooth_a = -1, tooth_b = -1;
    Flank flank_a = Flank::Ccw;
    double bound_m = 0;  // ≤ the pair's gap
    double closing_m_s = 0;  // the circles' rate of approach (with `motion`)
  };
  void record_parked(bool on) { record_parked_ = on; }
  const std::vector<ParkedPair>& parked() const { return parked_; }

  // Flanks searched in full, tracked (only the samples that can hold the deepest probed),
  // skipped and continued since construction (both probing passes).
  // Renewed: a clear flank whose record ran out, found clear again by measuring only the samples
  // whose own travel had run out (coherent_contact.cpp, renew_clear()).
  // Shared: a second-pass flank whose continued interior maximum is the first pass's of this call
  // (the same two flanks' common normal, seen from the other side), taken from it instead of
  // solved again (Continuation::replace only; find()).
  // Crossings: continued flanks whose maximum is where they cross the other gear's tip circle
  // (the depth still rising toward it), solved there again (part of `continued`).
  // Parked: near pairs left unsolved under their bound (find()).
  struct Counts {
    long searched = 0, tracked = 0, skipped = 0, continued = 0, renewed = 0, shared = 0, crossings = 0, parked = 0;
    Counts& operator+=(const Counts& o) {  // several searches' counts summed (World::Profile)
      searched += o.searched, tracked += o.tracked, skipped += o.skipped, continued += o.continued;
      renewed += o.renewed, shared += o.shared, crossings += o.crossings, parked += o.parked;
      return *this;
    }
  };
  const Counts& counts() const { return counts_; }

  // What the last full search of a flank (pass, tooth, flank) proved, for any motion of its
  // tooth's points in the other gear's frame shorter than a travel: no contact (`travel_m`), or,
  // for a flank of the first gear then within the refinement window (`tracked`), a bound on each
  // probe sample's first-order depth.
  struct FlankRecord {
    Eigen::Vector2d tooth_centre_in_y_m = Eigen::Vector2d::Zero();  // its tooth's centre then
    double turn_rad = 0;  // the probed gear's angle less the other's, then
    double travel_m = -1;  // > 0: no contact within this travel
    bool tracked = false;  // the flank's TrackedFlank holds
  };
  // Both flanks of a tooth clear (their records hold travels): a travel from one pose of the
  // tooth within which both records still hold (coherent_contact.cpp, tooth_record()), so that
  // the tooth is skipped by one test instead of two. −1: not both clear.
  struct ToothRecord {
    Eigen::Vector2d tooth_centre_in_y_m = Eigen::Vector2d::Zero();
    double turn_rad = 0;
    double travel_m = -1;
  };
  // Per probe sample of a flank whose record holds a travel (`travel_m` > 0): the sample's own
  // travel from the record's pose (+∞: a sample the search does not look at); travel_m is their
  // least.
  using SampleTravels = std::array<double, FlankTable::kProbeRadii>;
  // Per probe sample of a tracked flank (coherent_contact.cpp, sample_bound()): how its depth D
  // can have risen since the full search, up to a travel of span_m.
  struct TrackedFlank {
    static constexpr int n = FlankTable::kProbeRadii;
    enum Kind : signed char { kBounded, kFree, kProbe };
    int best = -1;  // the best sample then
    double span_m = 0;
    std::array<Kind, n> kind{};
    // kBounded: top bounds F then; path: how much longer than the travel a path inside the
    // teeth' annulus may be (1, or π/2 around the tips).
    std::array<double, n> top, slope, growth, growth_factor, jump, path;
    std::array<double, n> free_m;  // kFree: distance to the teeth's circle
  };

  // A near pair as its last solve left it (x: the flank searched, y: the other gear; each in its
  // own gear's frame), what near_bound() bounds its gap from: both flanks replaced by their
  // osculating circles there — centres of curvature fixed in each gear —, whose distance is
  // exact for any motion, less how far each flank can depart from its circle over the slide of
  // its closest point. x's point may be the corner at its flank's end (rho_x = 0).
  struct NearBound {
    bool valid = false;
    double gap_m = 0;
    Eigen::Vector2d centre_x = Eigen::Vector2d::Zero(), centre_y = Eigen::Vector2d::Zero();  // m
    double rho_x = 0, rho_y = 0;  // signed radii of curvature, m (> 0 convex)
    double c_x = 0, c_y = 0;  // the convexities 1/rho, 1/m (0 at a corner)
    double dist0_m = 0;  // the centres' distance then
    double side = 1;  // +1: convex against convex (gap = dist − rho_x − rho_y); −1: one concave
    Eigen::Vector2d n_x = Eigen::Vector2d::Zero(), n_y = Eigen::Vector2d::Zero();  // the normal from y toward x
    Eigen::Vector2d point_x = Eigen::Vector2d::Zero(), point_y = Eigen::Vector2d::Zero();  // the two closest points
    Eigen::Vector2d into_flank_x = Eigen::Vector2d::Zero();  // a corner: unit tangent from it into its flank
    double r_x = 0, s_y = 0;  // their radii on x's and y's flank
    bool corner = false;
  };

  // Where a continued point last had its facing flank measured (FlankTable::face(), the other
  // gear's frame; its radius) and the margin found there (−1: none): later points within the
  // margin's reach skip the measurement (continuation_impl.hpp, continued_hit()).
  struct FaceReference {
    Eigen::Vector2d point = Eigen::Vector2d::Zero();
    double radius_m = 0;
    double margin_m = -1;
  };

  // A flank's solution of a call (flank_search_impl.hpp's Hit::solved, r_x, s_y, tooth_y,
  // flank_y), kept per pass and flank when continuation is on; continued only by the next call.
  struct Solution {
    signed char solved = 0;  // Hit::Solved; 0: none to continue
    int tooth_y = -1;
    Flank flank_y = Flank::Ccw;
    double r_x = 0, s_y = 0;
    long call = 0;  // the call that found it
    // The calls before's, where it was continued into this one: `history` of them (up to 2).
    double r_prev = 0, s_prev = 0, r_prev2 = 0, s_prev2 = 0;
    int history = 0;
    FaceReference face;
    bool parked = false;  // left unsolved by the call `call` (its radii are older)
  };

 private:
  // The records sized for a new pair of tables.
  void adopt_tables(const FlankTable& a, const FlankTable& b);

  const FlankTable* tables_[2] = {nullptr, nullptr};
  std::vector<FlankRecord> records_[2];  // per pass, [tooth * 2 + (flank == Cw)]
  std::vector<ToothRecord> tooth_records_[2];  // per pass, per tooth
  std::vector<TrackedFlank> tracks_;  // pass 0's flanks, indexed as records_[0]
  std::vector<SampleTravels> travels_[2];  // per pass, indexed as records_
  std::vector<Solution> solutions_[2];  // per pass, indexed as records_
  // Per pass, indexed as records_: a near pair's last solve, for parking it (valid where the
  // flank's solution is one; apart from Solution, whose copies it would lengthen).
  std::vector<NearBound> bounds_[2];
  Continuation continuation_ = Continuation::off;
  bool park_ = true;
  bool record_parked_ = false;
  std::vector<ParkedPair> parked_;
  long calls_ = 0;
  Counts counts_;
};

}  // namespace gearsim::contact

// Near pairs parked under the osculating-circle bound (CoherentToothSearch, near_bound_impl.hpp;
// docs/tooth-contact.md, "Near pairs: the osculating-circle bound"): the flanks' convexity the
// bound rests on, and, over a planet turn of the paper's meshes stepped as a simulation steps
// them (with a transmission-error wobble and a floating sun), that every parked pair's gap — as
// the same search without parking solves it — is at least its bound, that no parked pair is one
// the onset prediction would have split the step for, and that the contacts are the same.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "contact/coherent_contact.hpp"
#include "contact/flank_table.hpp"
#include "tests/support/paper_flank_tables.hpp"

namespace gearsim::contact {
namespace {

using test::Gear;
using test::named;
using test::paper_gears;

// An involute's radius of curvature at radius r: the length of its generating line's tangent to
// the base circle, sqrt(r² − r_b²).
double involute_rho(double r, double r_b) { return std::sqrt(r * r - r_b * r_b); }

// The paper's gears: module 1 mm, 20° pressure angle (assets/scenarios/paper_dynamics.yaml).
double base_radius(int teeth) { return 0.5e-3 * teeth * std::cos(20.0 * M_PI / 180); }

TEST(FlankConvexity, IsTheInvolutesCurvatureOnTheActiveFlanks) {
  // External teeth bend away from their outward normal (convexity +1/ρ), the ring's internal
  // ones toward it (−1/ρ). Radii: the involute part of each flank, from just past the form
  // circles where it meets the fillet (11.338, 17.221 and, on the ring, 49.018 mm) to below the
  // tips (the cubic beside a fillet takes its knots on one side of it: docs/tooth-contact.md,
  // "The cubic beside a fillet", so the ring's range reaches past its knot at 48.889 mm). The
  // interpolant's curvature follows
  // the involute to ≈ 0.1–1 % (C¹ cubics over samples 0.55 µm apart); where the cubic's second
  // derivative jumps between intervals it spikes (docs/tooth-contact.md: ρ off by up to 2.3 mm
  // at 17.82 and 18.04 mm on the planets) — a few radii of the 2 × 201 per gear.
  const std::vector<Gear>& g = paper_gears();
  struct Case {
    const char* name;
    int teeth;
    double r_lo, r_hi, sign;
  };
  for (const Case& c :
       {Case{"sun", 24, 11.36e-3, 12.9e-3, 1}, Case{"planet_1", 36, 17.24e-3, 18.9e-3, 1}, Case{"ring", 96, 47.3e-3, 49.0e-3, -1}}) {
    const FlankTable& t = *named(g, c.name).table;
    const double r_b = base_radius(c.teeth);
    std::vector<double> departures;
    for (int i = 0; i <= 200; ++i) {
      const double r = c.r_lo + (c.r_hi - c.r_lo) * i / 200;
      for (Flank f : {Flank::Ccw, Flank::Cw}) {
        FlankTable::FlankJet jet;
        ASSERT_TRUE(t.flank_jet(0, f, r, &jet)) << c.name << " r " << r;
        departures.push_back(std::abs(FlankTable::convexity(f, jet) * c.sign * involute_rho(r, r_b) - 1));
      }
    }
    std::sort(departures.begin(), departures.end());
    const double median = departures[departures.size() / 2], p95 = departures[departures.size() * 95 / 100];
    std::printf("%s: convexity against ±1/sqrt(r² − r_b²): median %.2g, 95th percentile %.2g, worst %.2g relative\n", c.name, median, p95,
                departures.back());
    EXPECT_LT(median, 0.005) << c.name;
    EXPECT_LT(p95, 0.02) << c.name;
  }
}

TEST(FlankConvexity, TheRangeOfABandHoldsEveryConvexityInIt) {
  // convexity_range() from its bands against flank_jet() at random radii inside the band: the
  // bands evaluate each cubic at four points, so a curvature between them may exceed the range
  // only by its variation within one 0.55 µm interval — far below the bound's use of it.
  const std::vector<Gear>& g = paper_gears();
  std::mt19937 rng(7);
  for (const char* name : {"sun", "planet_0", "ring"}) {
    const FlankTable& t = *named(g, name).table;
    std::uniform_real_distribution<double> radius(t.r_min_m() + 60e-6, t.r_max_m() - 60e-6), half(1e-6, 50e-6);
    long inside = 0, outside = 0;
    double most_out = 0;
    for (int trial = 0; trial < 400; ++trial) {
      const double r = radius(rng), w = half(rng);
      const int tooth = static_cast<int>(rng() % static_cast<unsigned>(t.teeth()));
      const Flank f = rng() % 2 ? Flank::Ccw : Flank::Cw;
      const FlankTable::ConvexityRange range = t.convexity_range(tooth, f, r - w, r + w);
      if (!(range.lo > -FlankTable::kInfinity)) continue;  // a band reaching a radius without material
      for (int i = 0; i <= 20; ++i) {
        FlankTable::FlankJet jet;
        if (!t.flank_jet(tooth, f, r - w + 2 * w * i / 20, &jet)) continue;
        const double c = FlankTable::convexity(f, jet);
        const double out = std::max(range.lo - c, c - range.hi);
        if (out > 0)
          ++outside, most_out = std::max(most_out, out / std::max(std::abs(c), 1.0));
        else
          ++inside;
      }
    }
    EXPECT_GT(inside, 4000) << name;
    EXPECT_LT(most_out, 1e-3) << name << ": a convexity beyond its band's range, relative";
    std::printf("%s: %ld of %ld convexities beyond their band's range, by %.2g relative at most\n", name, outside, inside + outside,
                most_out);
  }
}

// Gear a against gear b stepped at dt as the simulation steps the paper's set (sun 83.76 rad/s
// ahead of the carrier, the carrier at a quarter of that), a pressed by `press_m` at its tip
// circle and wobbling ±0.3 µm there at 320 Hz, the sun's centre wandering ±1 µm at the tooth
// frequency: poses and their exact velocities.
struct Stepper {
  const Gear &a, &b;
  double press_m;
  double kWobble_m = 0.3e-6, kWobbleHz = 320;
  static constexpr double kOmega = 83.76;
  void at(const Gear& g, double t, bool is_a, PlanarPose& p, CoherentToothSearch::PlanarTwist& v) const {
    const double phi = kOmega * t, carrier = 0.25 * phi, wc = 0.25 * kOmega;
    const Eigen::Rotation2Dd turn(carrier);
    Eigen::Vector2d c = g.pose.centre_m, dc = Eigen::Vector2d::Zero();
    if (g.name == "sun") {
      c += 1e-6 * Eigen::Vector2d(std::sin(24 * phi), std::cos(24 * phi));
      dc = 1e-6 * 24 * kOmega * Eigen::Vector2d(std::cos(24 * phi), -std::sin(24 * phi));
    }
    const Eigen::Vector2d rc = turn * c;
    p = g.pose;
    p.centre_m = rc;
    v.velocity_m_s = wc * Eigen::Vector2d(-rc.y(), rc.x()) + turn * dc;
    const double r = g.table->r_max_m(), w = 2 * M_PI * kWobbleHz;
    p.angle_rad += carrier + phi * g.ratio + (is_a ? (press_m + kWobble_m * std::sin(w * t)) / r : 0);
    v.angular_velocity_rad_s = wc + kOmega * g.ratio + (is_a ? kWobble_m * w * std::cos(w * t) / r : 0);
  }
};

struct NearSweep {
  long calls = 0, contacts = 0, different_sets = 0, reference_near = 0, parked = 0;
  long parked_unlisted = 0;  // parked pairs the reference lists no near pair for (its gap beyond the window)
  long lost = 0;  // reference near pairs neither listed nor parked
  long below_bound = 0;  // parked pairs whose gap is below their bound
  long would_split = 0;  // parked pairs the onset prediction would have split the step for
  long reference_splits = 0;  // near pairs the onset prediction splits a step for
  double max_depth_diff_m = 0, least_slack_m = 1e300, least_ratio = 1e300;
};

// The closing rate of a near pair as physics::OnsetSplit::onset_s() takes it: the two gears'
// velocities at the contact point along its normal.
double closing_rate(const ToothContact& c, const PlanarPose& pa, const CoherentToothSearch::PlanarTwist& va, const PlanarPose& pb,
                    const CoherentToothSearch::PlanarTwist& vb) {
  auto at = [&](const PlanarPose& p, const CoherentToothSearch::PlanarTwist& v) {
    const Eigen::Vector2d r = c.point_m - p.centre_m;
    return Eigen::Vector2d(v.velocity_m_s.x() - v.angular_velocity_rad_s * r.y(), v.velocity_m_s.y() + v.angular_velocity_rad_s * r.x());
  };
  return -(at(pa, va) - at(pb, vb)).dot(c.normal_on_b);
}

NearSweep sweep_near(const Gear& a, const Gear& b, double dt, long steps, const std::vector<double>& presses_m, double wobble_m = 0.3e-6,
                     double wobble_hz = 320) {
  NearSweep sw;
  for (double press : presses_m) {
    CoherentToothSearch parking, reference;
    parking.set_continuation(true);
    reference.set_continuation(true);
    reference.set_park_near_pairs(false);
    parking.record_parked(true);
    std::vector<ToothContact> c_park, c_ref, n_park, n_ref;
    const Stepper st{a, b, press, wobble_m, wobble_hz};
    for (long i = 0; i < steps; ++i) {
      const double t = static_cast<double>(i) * dt;
      CoherentToothSearch::Motion m;
      PlanarPose pa, pb;
      st.at(a, t, true, pa, m.a);
      st.at(b, t, false, pb, m.b);
      m.step_s = dt;
      parking.find(*a.table, pa, *b.table, pb, c_park, &n_park, &m);
      reference.find(*a.table, pa, *b.table, pb, c_ref, &n_ref, &m);
      ++sw.calls;
      sw.contacts += static_cast<long>(c_ref.size());
      bool same = c_park.size() == c_ref.size();
      for (std::size_t j = 0; same && j < c_ref.size(); ++j) {
        same = c_park[j].tooth_a == c_ref[j].tooth_a && c_park[j].tooth_b == c_ref[j].tooth_b && c_park[j].flank_a == c_ref[j].flank_a;
        if (same) sw.max_depth_diff_m = std::max(sw.max_depth_diff_m, std::abs(c_park[j].depth_m - c_ref[j].depth_m));
      }
      sw.different_sets += !same;
      sw.reference_near += static_cast<long>(n_ref.size());
      auto key = [](const auto& u, const auto& v) { return u.tooth_a == v.tooth_a && u.tooth_b == v.tooth_b && u.flank_a == v.flank_a; };
      for (const CoherentToothSearch::ParkedPair& p : parking.parked()) {
        ++sw.parked;
        const ToothContact* r = nullptr;
        for (const ToothContact& c : n_ref)
          if (key(c, p)) r = &c;
        if (!r) {
          ++sw.parked_unlisted;
          continue;
        }
        const double gap = -r->depth_m;
        sw.below_bound += gap < p.bound_m;
        sw.least_slack_m = std::min(sw.least_slack_m, gap - p.bound_m);
        sw.least_ratio = std::min(sw.least_ratio, p.bound_m / gap);
        const double closing = closing_rate(*r, pa, m.a, pb, m.b);
        sw.would_split += closing > 0 && gap / closing < dt;
      }
      for (const ToothContact& c : n_ref) {
        const double cl = closing_rate(c, pa, m.a, pb, m.b);
        sw.reference_splits += cl > 0 && -c.depth_m / cl < dt;
        bool found = false;
        for (const ToothContact& q : n_park) found = found || key(c, q);
        for (const CoherentToothSearch::ParkedPair& p : parking.parked()) found = found || key(c, p);
        sw.lost += !found;
      }
    }
  }
  return sw;
}

void expect_bounded(const NearSweep& sw, const std::string& what) {
  std::printf(
      "%s: %ld calls, %ld contacts, %ld near pairs, %ld parked (%ld beyond the window), %ld closing within a step; least gap − bound %.3g "
      "m, "
      "least bound/gap %.3g; depths within %.3g m\n",
      what.c_str(), sw.calls, sw.contacts, sw.reference_near, sw.parked, sw.parked_unlisted, sw.reference_splits, sw.least_slack_m,
      sw.least_ratio, sw.max_depth_diff_m);
  EXPECT_GT(sw.contacts, sw.calls / 2) << what;
  EXPECT_EQ(sw.different_sets, 0) << what << ": calls whose contact sets differ";
  // Parked pairs leave a continuation whose next solve starts from older radii: the same
  // maximum to Newton's tolerance.
  EXPECT_LT(sw.max_depth_diff_m, 1e-9) << what;
  EXPECT_EQ(sw.below_bound, 0) << what << ": parked pairs with a gap below their bound";
  EXPECT_EQ(sw.would_split, 0) << what << ": parked pairs the onset prediction would have split the step for";
  EXPECT_EQ(sw.lost, 0) << what << ": near pairs neither listed nor parked";
}

// The simulation's finer step, dt 1e-5 s: one relative planet turn (1.5 sun turns).
constexpr double kDt = 1e-5;
const long kTurnSteps = std::lround(2 * M_PI * 1.5 / (83.76 * kDt));

TEST(NearBound, ParkedSunPlanetPairsAreApartByAtLeastTheirBound) {
  const std::vector<Gear>& g = paper_gears();
  for (const char* planet : {"planet_0", "planet_1"}) {  // planet_0: the 43 µm flank error
    const NearSweep sw = sweep_near(named(g, "sun"), named(g, planet), kDt, kTurnSteps, {0.0, 1e-6});
    expect_bounded(sw, std::string("sun–") + planet);
    EXPECT_GT(sw.parked, sw.reference_near / 2) << "sun–" << planet << ": what it saves, most near pairs parked";
  }
}

TEST(NearBound, PairsClosingWithinAStepAreNotParked) {
  // A fast wobble, ±1.5 µm at 5 kHz at the sun's tip circle (up to 47 mm/s: a 0.5 µm gap closes
  // within one step of 1e-5 s): pairs that could close within the step are solved and listed for
  // the onset's prediction; those parked still hold their bound.
  const std::vector<Gear>& g = paper_gears();
  const NearSweep sw = sweep_near(named(g, "sun"), named(g, "planet_1"), kDt, kTurnSteps / 4, {0.0}, 1.5e-6, 5000);
  expect_bounded(sw, "sun–planet_1, fast wobble");
  EXPECT_GT(sw.parked, 0);
}

TEST(NearBound, AParkedPairAboutToCloseIsSolvedAndListedAgain) {
  // The guard on its own: 200 steps of the sun–planet mesh park its near pairs; then the same
  // poses with the sun's velocity raised by ±30 rad/s (its flanks at ±0.3 m/s: a 1 µm gap closes
  // in 3 µs): the bound is the same, but on the flanks now closing every near pair whose closing
  // rate takes it through within the step is solved and in the near list, not parked.
  const std::vector<Gear>& g = paper_gears();
  const Gear &sun = named(g, "sun"), &planet = named(g, "planet_1");
  for (double extra : {30.0, -30.0}) {
    CoherentToothSearch search, reference;
    search.set_continuation(true);
    reference.set_continuation(true);
    reference.set_park_near_pairs(false);
    search.record_parked(true);
    const Stepper st{sun, planet, 0.0};
    std::vector<ToothContact> c, n, c_ref, n_ref;
    CoherentToothSearch::Motion m;
    PlanarPose pa, pb;
    for (long i = 0; i < 200; ++i) {
      st.at(sun, static_cast<double>(i) * kDt, true, pa, m.a);
      st.at(planet, static_cast<double>(i) * kDt, false, pb, m.b);
      m.step_s = kDt;
      search.find(*sun.table, pa, *planet.table, pb, c, &n, &m);
    }
    const long parked_before = static_cast<long>(search.parked().size());
    m.a.angular_velocity_rad_s += extra;
    search.find(*sun.table, pa, *planet.table, pb, c, &n, &m);
    reference.find(*sun.table, pa, *planet.table, pb, c_ref, &n_ref, &m);
    long closing_fast = 0;
    for (const ToothContact& r : n_ref) {
      const double rate = closing_rate(r, pa, m.a, pb, m.b);
      if (!(rate > 0 && -r.depth_m / rate < 2 * kDt)) continue;
      ++closing_fast;
      bool listed = false;
      for (const ToothContact& q : n) listed = listed || (q.tooth_a == r.tooth_a && q.tooth_b == r.tooth_b && q.flank_a == r.flank_a);
      EXPECT_TRUE(listed) << "a near pair closing within two steps, gap " << -r.depth_m << " m at " << rate << " m/s, not listed";
    }
    EXPECT_GT(parked_before, 0);
    EXPECT_GT(closing_fast, 0) << "extra " << extra << " rad/s: no pair closing within two steps";
    EXPECT_LT(static_cast<long>(search.parked().size()), parked_before) << "extra " << extra << " rad/s";
  }
}

TEST(NearBound, ParkedPlanetRingPairsAreApartByAtLeastTheirBound) {
  // The ring's concave flanks: a convex circle inside a hollow one.
  const std::vector<Gear>& g = paper_gears();
  for (const char* planet : {"planet_0", "planet_1"}) {
    const NearSweep sw = sweep_near(named(g, planet), named(g, "ring"), kDt, kTurnSteps, {0.0, 1e-6});
    expect_bounded(sw, std::string(planet) + "–ring");
    EXPECT_GT(sw.parked, sw.reference_near / 2) << planet << "–ring: what it saves, most near pairs parked";
  }
}

}  // namespace
}  // namespace gearsim::contact

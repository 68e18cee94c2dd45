// CoherentToothSearch against find_tooth_contacts(): stepped through a full relative planet turn
// the way a simulation steps the paper's gear set (its own scenario's gears, the faulty planet
// included, like bench/bench_contact_sweep), and through a sudden jump of the poses, the coherent
// search returns the stateless search's contacts bit for bit: the flanks it searches, it searches
// the same way, and those it skips or probes in part are proven to give the same answer. With
// continuation (set_continuation), the same contacts to Newton's tolerance.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "contact/coherent_contact.hpp"
#include "contact/tooth_contact.hpp"
#include "input/scenario_file.hpp"
#include "physics/world_bodies.hpp"
#include "tests/support/asset_scenario.hpp"
#include "tests/support/paper_flank_tables.hpp"

namespace gearsim::contact {
namespace {

using test::Gear;
using test::gears_of;
using test::named;
using test::paper_gears;

// How the coherent search's answers differed from the stateless search's over a sweep.
struct Sweep {
  long calls = 0, contacts = 0;
  long different_sets = 0;  // calls whose (tooth_a, tooth_b, flank_a) lists differ
  long different_contacts = 0;  // contacts of equal keys whose depth, point or normal differ in any bit
  double max_depth_diff_m = 0;
  double most_shallower_m = 0;  // the largest stateless − coherent depth (coherent shallower)
  CoherentToothSearch::Counts counts;
};

bool same_bits(const ToothContact& u, const ToothContact& v) {
  return u.depth_m == v.depth_m && u.point_m == v.point_m && u.normal_on_b == v.normal_on_b;
}

// Compares one call of both searches into `sw`.
void compare(const std::vector<ToothContact>& stateless, const std::vector<ToothContact>& coherent, Sweep& sw) {
  ++sw.calls;
  sw.contacts += static_cast<long>(stateless.size());
  bool same_set = stateless.size() == coherent.size();
  for (std::size_t i = 0; same_set && i < stateless.size(); ++i) {
    const ToothContact &u = stateless[i], &v = coherent[i];
    if (u.tooth_a != v.tooth_a || u.tooth_b != v.tooth_b || u.flank_a != v.flank_a) {
      same_set = false;
      break;
    }
    sw.different_contacts += !same_bits(u, v);
    sw.max_depth_diff_m = std::max(sw.max_depth_diff_m, std::abs(u.depth_m - v.depth_m));
    sw.most_shallower_m = std::max(sw.most_shallower_m, u.depth_m - v.depth_m);
  }
  sw.different_sets += !same_set;
}

// Gear a against gear b stepped as a simulation steps them: the sun turning by `step_rad` per
// step relative to the carrier, the whole set turned with the carrier (a quarter of that, the
// paper's 5:1 train), a pressed by `press_m` at its tip circle, and the sun's centre wandering by
// ±1 µm (a floating sun) at the tooth frequency.
Sweep sweep_pair(const Gear& a, const Gear& b, double step_rad, long steps, const std::vector<double>& presses_m, bool continued = false) {
  Sweep sw;
  std::vector<ToothContact> stateless, coherent;
  for (double press : presses_m) {
    CoherentToothSearch search;
    search.set_continuation(continued);
    for (long i = 0; i < steps; ++i) {
      const double phi = static_cast<double>(i) * step_rad, carrier = 0.25 * phi;
      const Eigen::Rotation2Dd turn(carrier);
      auto place = [&](const Gear& g, double extra_rad) {
        PlanarPose p = g.pose;
        if (g.name == "sun") p.centre_m += 1e-6 * Eigen::Vector2d(std::sin(24 * phi), std::cos(24 * phi));
        p.centre_m = turn * p.centre_m;
        p.angle_rad += carrier + phi * g.ratio + extra_rad;
        return p;
      };
      const PlanarPose pa = place(a, press / a.table->r_max_m()), pb = place(b, 0);
      find_tooth_contacts(*a.table, pa, *b.table, pb, stateless);
      search.find(*a.table, pa, *b.table, pb, coherent);
      compare(stateless, coherent, sw);
    }
    sw.counts.searched += search.counts().searched;
    sw.counts.tracked += search.counts().tracked;
    sw.counts.skipped += search.counts().skipped;
    sw.counts.continued += search.counts().continued;
    sw.counts.renewed += search.counts().renewed;
    sw.counts.shared += search.counts().shared;
    sw.counts.crossings += search.counts().crossings;
  }
  return sw;
}

// The simulation's step: the sun at 104.7 rad/s is 83.76 rad/s ahead of the carrier; dt 2e-5 s.
constexpr double kStepRad = 83.76 * 2e-5;
// One relative turn of a planet (36 teeth) against the sun (24): 1.5 sun turns.
const long kPlanetTurnSteps = std::lround(2 * M_PI * 36.0 / 24.0 / kStepRad);
// Presses of the mesh, m: apart by 0.5 µm, through contact at 0 (no backlash) to 2 µm deep.
const std::vector<double> kPresses_m = {-0.5e-6, 0.0, 1e-6, 2e-6};

// Expect bit-identical contacts: the same refinement runs from the same samples.
void expect_identical(const Sweep& sw, const std::string& what) {
  EXPECT_GT(sw.contacts, sw.calls / 2) << what << ": the sweep should hold contacts";
  EXPECT_EQ(sw.different_sets, 0) << what << ": calls whose contact sets differ, of " << sw.calls;
  EXPECT_EQ(sw.different_contacts, 0) << what << ": contacts differing in any bit, of " << sw.contacts;
  EXPECT_EQ(sw.max_depth_diff_m, 0.0) << what;
}

TEST(CoherentToothSearch, SunPlanetMeshesOverAPlanetTurnMatchTheStatelessSearch) {
  const std::vector<Gear>& g = paper_gears();
  for (const char* planet : {"planet_0", "planet_1", "planet_2"})  // planet_0: the 43 µm flank error
    expect_identical(sweep_pair(named(g, "sun"), named(g, planet), kStepRad, kPlanetTurnSteps, kPresses_m), std::string("sun–") + planet);
}

TEST(CoherentToothSearch, PlanetRingMeshesOverAPlanetTurnMatchTheStatelessSearch) {
  const std::vector<Gear>& g = paper_gears();
  for (const char* planet : {"planet_0", "planet_1", "planet_2"})
    expect_identical(sweep_pair(named(g, planet), named(g, "ring"), kStepRad, kPlanetTurnSteps, kPresses_m), std::string(planet) + "–ring");
}

TEST(CoherentToothSearch, HalfTheStepAlsoMatches) {
  // dt = 1e-5 s: the sun–faulty planet mesh over the turn, pressed 1 µm.
  const std::vector<Gear>& g = paper_gears();
  expect_identical(sweep_pair(named(g, "sun"), named(g, "planet_0"), 0.5 * kStepRad, 2 * kPlanetTurnSteps, {1e-6}),
                   "sun–planet_0 at dt 1e-5 s");
}

TEST(CoherentToothSearch, SearchesMostFlanksOnlyInPart) {
  // What makes it faster: over the sun–planet turn, most flank visits are skipped or tracked.
  const std::vector<Gear>& g = paper_gears();
  const Sweep sw = sweep_pair(named(g, "sun"), named(g, "planet_1"), kStepRad, kPlanetTurnSteps, {1e-6});
  const double visits = static_cast<double>(sw.counts.searched + sw.counts.tracked + sw.counts.skipped + sw.counts.renewed);
  EXPECT_GT(static_cast<double>(sw.counts.skipped + sw.counts.tracked + sw.counts.renewed) / visits, 0.5);
  // A clear flank whose record runs out is mostly found clear again from the few samples whose
  // own travel ran out (renewed), not searched in full (the answers: the tests above).
  EXPECT_GT(sw.counts.renewed, sw.counts.searched);
}

// The sun–faulty planet mesh stepped 600 times; 300 steps in, the planet jumps by half a pitch
// and the sun's centre by 30 µm. `search`'s counts before the jump's call and after it go to
// `at_jump`; the comparison with the stateless search into the returned Sweep.
template <class AtJump>
Sweep sweep_with_jump(CoherentToothSearch& search, AtJump&& at_jump) {
  const std::vector<Gear>& g = paper_gears();
  const Gear &sun = named(g, "sun"), &planet = named(g, "planet_0");
  std::vector<ToothContact> stateless, coherent;
  Sweep sw;
  for (long i = 0; i < 600; ++i) {
    PlanarPose ps = sun.pose, pp = planet.pose;
    ps.angle_rad += static_cast<double>(i) * kStepRad + 1e-6 / sun.table->r_max_m();
    pp.angle_rad += static_cast<double>(i) * kStepRad * planet.ratio;
    if (i >= 300) {
      pp.angle_rad += 0.5 * planet.table->pitch_angle_rad();
      ps.centre_m += Eigen::Vector2d(30e-6, -10e-6);
    }
    const CoherentToothSearch::Counts before = search.counts();
    find_tooth_contacts(*sun.table, ps, *planet.table, pp, stateless);
    search.find(*sun.table, ps, *planet.table, pp, coherent);
    compare(stateless, coherent, sw);
    if (i == 300) at_jump(before, search.counts());
  }
  sw.counts = search.counts();
  return sw;
}

TEST(CoherentToothSearch, APoseJumpMakesItSearchEveryFlank) {
  // No record holds for such a travel, so no flank is skipped or tracked across it: each is
  // searched in full or renewed (every sample it looks at measured again, their travels having
  // run out), and the answers match.
  CoherentToothSearch search;
  const Sweep sw = sweep_with_jump(search, [](const CoherentToothSearch::Counts& before, const CoherentToothSearch::Counts& after) {
    EXPECT_EQ(after.skipped, before.skipped) << "flanks skipped across the jump";
    EXPECT_EQ(after.tracked, before.tracked) << "flanks tracked across the jump";
    EXPECT_GT(after.searched, before.searched);
  });
  expect_identical(sw, "sun–planet_0 with a jump");
}

// With continuation the contacts are Newton's solutions from last step's, not from this step's
// samples: the same tooth pairs, and depths that agree to well below a nanometre (a contact of
// the paper run is ~0.45 µm deep). Never shallower beyond the difference of the two flank
// interpolants (where the sampled search fell back to the table's straight segments, the
// continuation solves on the cubic: they differ by a chord's sag, h²/8ρ = 2e-11 m for the
// 0.55 µm samples on a 2 mm radius; measured 3.9e-11 m), at most 1 nm deeper (where the sampled
// search's start led to a lower maximum; measured over the paper's six meshes,
// bench_contact_sweep --continued: 0.10 nm). `continued`: how many flank visits the sweep
// continued at least.
void expect_continued(const Sweep& sw, const std::string& what, long continued) {
  EXPECT_GT(sw.contacts, sw.calls / 2) << what << ": the sweep should hold contacts";
  EXPECT_EQ(sw.different_sets, 0) << what << ": calls whose contact sets differ, of " << sw.calls;
  EXPECT_LT(sw.max_depth_diff_m, 1e-9) << what;
  EXPECT_LT(sw.most_shallower_m, 1e-10) << what;
  EXPECT_GE(sw.counts.continued, continued) << what << " (" << sw.contacts << " contacts)";
}

TEST(CoherentToothSearch, ContinuationFindsTheStatelessContactsOverAPlanetTurn) {
  const std::vector<Gear>& g = paper_gears();
  for (const char* planet : {"planet_0", "planet_1"}) {
    // Most flanks in contact are continued (the rest are searched: entering, leaving, too deep,
    // on a tip's rounding).
    const Sweep sun = sweep_pair(named(g, "sun"), named(g, planet), kStepRad, kPlanetTurnSteps, kPresses_m, true);
    expect_continued(sun, std::string("sun–") + planet + ", continued", sun.contacts / 2);
    const Sweep ring = sweep_pair(named(g, planet), named(g, "ring"), kStepRad, kPlanetTurnSteps, kPresses_m, true);
    expect_continued(ring, std::string(planet) + "–ring, continued", ring.contacts / 2);
    // Contacts near the second gear's tips are solved from both sides; the second pass takes
    // the first's solution there (Counts::shared) — with the same contacts as above.
    EXPECT_GT(sun.counts.shared, sun.contacts / 10) << "sun–" << planet;
    EXPECT_GT(ring.counts.shared, ring.contacts / 10) << planet << "–ring";
    // Where a planet flank's deepest point is its crossing of the ring's tip circle (the
    // ring's tip corner entering or leaving the mesh), the crossing is solved again instead of
    // the flank searched, while the stateless search would still come to it there (6 777 and
    // 6 873 of ≈ 46 000 contacts; on the sun–planet meshes ≈ 40, the planet's tip corner
    // holding those contacts from its own side).
    EXPECT_GT(ring.counts.crossings, ring.contacts / 10) << planet << "–ring";
  }
}

TEST(CoherentToothSearch, ContinuationAcrossAPoseJumpSearchesAfresh) {
  // The jump of APoseJumpMakesItSearchEveryFlank: a continued solution then faces another flank
  // or leaves its own, and the flank is searched in full.
  CoherentToothSearch search;
  search.set_continuation(true);
  const Sweep sw = sweep_with_jump(search, [](const CoherentToothSearch::Counts& before, const CoherentToothSearch::Counts& after) {
    EXPECT_EQ(after.continued, before.continued) << "flanks continued across the jump";
  });
  expect_continued(sw, "sun–planet_0 with a jump, continued", 1);
}

TEST(CoherentToothSearch, ResetForgetsEveryRecord) {
  const std::vector<Gear>& g = paper_gears();
  const Gear &sun = named(g, "sun"), &planet = named(g, "planet_1");
  CoherentToothSearch search;
  std::vector<ToothContact> out;
  search.find(*sun.table, sun.pose, *planet.table, planet.pose, out);
  const long first = search.counts().searched;
  search.reset();
  search.find(*sun.table, sun.pose, *planet.table, planet.pose, out);
  EXPECT_EQ(search.counts().searched, 2 * first);
  EXPECT_EQ(search.counts().skipped + search.counts().tracked, 0);
}

// OpenSCAD MCAD meshes (tests/data/mcad: z 12 drives z 24, module 1, 0.05 mm backlash each),
// recognised and tabled as a run builds them, turned at the ideal ratio through 1.2 turns of the
// pinion, its backlash closed by `closure_m` along the pitch circle and pressed by 0–2 µm; the
// coherent search (with or without continuation) against the stateless one.
struct CadPair {
  std::vector<Gear> gears;
  CadPair() {
    const std::filesystem::path dir = test::fresh_test_dir();
    const std::string data = std::string(GEARSIM_SOURCE_DIR) + "/tests/data/mcad/";
    std::ofstream(dir / "pair.yaml") << "name: mcad_pair\nduration_s: 0.01\n"
                                        "solver: {time_step_s: 1.0e-5}\n"
                                        "output: {sample_rate_hz: 2000, per_step_log: false}\n"
                                        "pair:\n"
                                        "  driver: {name: pinion, mesh: {file: "
                                     << data
                                     << "mcad_m1_z12_a20_f5_b005.stl, unit: mm, teeth: 12}, "
                                        "density_kg_m3: 7850}\n"
                                        "  driven: {name: wheel, mesh: {file: "
                                     << data
                                     << "mcad_m1_z24_a20_f5_b005.stl, unit: mm, teeth: 24}, "
                                        "density_kg_m3: 7850}\n"
                                        "  centre_distance_m: 0.018\n";
    const std::vector<Gear> g = gears_of(input::load_scenario(dir / "pair.yaml", {}), "pinion", 12);
    gears = {named(g, "pinion"), named(g, "wheel")};
  }
  // The pinion turned by φ (the wheel at the ideal ratio) and forward by `closure` along its
  // 6 mm pitch circle.
  std::pair<PlanarPose, PlanarPose> poses(double phi, double closure_m) const {
    PlanarPose pa = gears[0].pose, pb = gears[1].pose;
    pa.angle_rad += phi + closure_m / 6e-3;
    pb.angle_rad += phi * gears[1].ratio;
    return {pa, pb};
  }
};

// The deepest overlap of a contact's tooth pair measured along a's flank by brute force: n exact
// probes from root to tip (0.11 µm apart on a module-1 tooth at n = 20000).
double brute_force_depth(const FlankTable& ta, const PlanarPose& pa, const FlankTable& tb, const PlanarPose& pb, const ToothContact& c,
                         int n) {
  auto to_world = [](const PlanarPose& p, const Eigen::Vector2d& v) -> Eigen::Vector2d {
    return p.centre_m + Eigen::Rotation2Dd(p.angle_rad) * v;
  };
  auto to_local = [](const PlanarPose& p, const Eigen::Vector2d& w) -> Eigen::Vector2d {
    return Eigen::Rotation2Dd(-p.angle_rad) * (w - p.centre_m);
  };
  double best = -1;
  for (int i = 0; i < n; ++i) {
    const double r = ta.r_min_m() + (ta.r_max_m() - ta.r_min_m()) * i / (n - 1);
    Eigen::Vector2d q;
    if (!ta.flank_point_if_material(c.tooth_a, c.flank_a, r, &q)) continue;
    const FlankTable::Probe p = tb.probe(to_local(pb, to_world(pa, q)));
    if ((p.has_flank || p.inside) && p.tooth == c.tooth_b) best = std::max(best, p.depth_m);
  }
  return best;
}

// The same from b's side: the deepest of n exact probes along both flanks of b's tooth into a's
// flank of the contact (how a contact at a sharp turn of b's flank is measured: along a's normal,
// tooth_contact.hpp).
double brute_force_depth_from_b(const FlankTable& ta, const PlanarPose& pa, const FlankTable& tb, const PlanarPose& pb,
                                const ToothContact& c, int n) {
  auto to_world = [](const PlanarPose& p, const Eigen::Vector2d& v) -> Eigen::Vector2d {
    return p.centre_m + Eigen::Rotation2Dd(p.angle_rad) * v;
  };
  auto to_local = [](const PlanarPose& p, const Eigen::Vector2d& w) -> Eigen::Vector2d {
    return Eigen::Rotation2Dd(-p.angle_rad) * (w - p.centre_m);
  };
  double best = -1;
  for (Flank g : {Flank::Ccw, Flank::Cw})
    for (int i = 0; i < n; ++i) {
      const double r = tb.r_min_m() + (tb.r_max_m() - tb.r_min_m()) * i / (n - 1);
      Eigen::Vector2d q;
      if (!tb.flank_point_if_material(c.tooth_b, g, r, &q)) continue;
      const FlankTable::Probe p = ta.probe(to_local(pa, to_world(pb, q)));
      if ((p.has_flank || p.inside) && p.tooth == c.tooth_a && p.flank == c.flank_a) best = std::max(best, p.depth_m);
    }
  return best;
}

// `differ(pa, pb, stateless, coherent)`: called for each contact whose depths differ by > 1 nm.
template <class Differ>
Sweep cad_pair_sweep(const CadPair& cad, double closure_m, CoherentToothSearch::Continuation continued, Differ&& differ) {
  // The pinion at 20 rad/s, dt 1e-5 s; the set does not turn with a carrier here.
  Sweep sw;
  for (double press : {0.0, 1e-6, 2e-6}) {
    CoherentToothSearch search;
    search.set_continuation(continued);
    std::vector<ToothContact> stateless, coherent;
    for (long i = 0; i < 38000; ++i) {
      const auto [pa, pb] = cad.poses(static_cast<double>(i) * 2e-4, closure_m + press);
      find_tooth_contacts(*cad.gears[0].table, pa, *cad.gears[1].table, pb, stateless);
      search.find(*cad.gears[0].table, pa, *cad.gears[1].table, pb, coherent);
      compare(stateless, coherent, sw);
      if (stateless.size() == coherent.size())
        for (std::size_t q = 0; q < stateless.size(); ++q)
          if (std::abs(stateless[q].depth_m - coherent[q].depth_m) > 1e-9) differ(pa, pb, stateless[q], coherent[q]);
    }
    sw.counts.continued += search.counts().continued;
    sw.counts.renewed += search.counts().renewed;
  }
  return sw;
}

TEST(CoherentToothSearch, CadPairMatchesTheStatelessSearch) {
  // Closed by 0.1 mm: overlapping by ≈ 70 µm, deep contacts on the faceted flanks.
  expect_identical(cad_pair_sweep(CadPair(), 0.1e-3, CoherentToothSearch::Continuation::off, [](auto&&...) {}), "MCAD z12–z24");
}

TEST(FlankTable, AMoveWithinTheFacingMarginFacesTheSameFlankOnMcadMeshes) {
  // The same on tables of faceted STL flanks (OpenSCAD's MCAD, not made here).
  const CadPair cad;
  test::expect_facing_margin_holds(*cad.gears[0].table, "MCAD z12", 50000);
  test::expect_facing_margin_holds(*cad.gears[1].table, "MCAD z24", 50000);
}

// The MCAD pair closed just to its first touch (the least, over a tooth period, of the deepest
// overlap at 0.1 mm, taken back along the line of action: depth = r_b·Δφ, r_b = 6 mm·cos 20°), so
// that presses of 0–2 µm give contacts as deep as a run's.
double first_touch_closure(const CadPair& cad) {
  double least = 1;
  std::vector<ToothContact> found;
  for (long i = 0; i < 2700; ++i) {  // 2π/12 of a pinion turn
    const auto [pa, pb] = cad.poses(static_cast<double>(i) * 2e-4, 0.1e-3);
    find_tooth_contacts(*cad.gears[0].table, pa, *cad.gears[1].table, pb, found);
    double deepest = 0;
    for (const ToothContact& c : found) deepest = std::max(deepest, c.depth_m);
    least = std::min(least, deepest);
  }
  EXPECT_GT(least, 1e-6);
  return 0.1e-3 - least / std::cos(20 * M_PI / 180);
}

TEST(CoherentToothSearch, OnFacetedFlanksAContactHasSeveralMaxima) {
  // Why a continued contact does not stand alone on CAD meshes (physics::BuiltBody::
  // flanks_from_spec): MCAD's faceted flanks give a contact's depth profile maxima ~20 µm apart;
  // the continuation follows one, the sampled search picks another, and each is sometimes the
  // lower one, against the brute-force maximum of the tooth pair (measured: by up to 0.16 µm).
  const CadPair cad;
  double continued_low = 0, sampled_low = 0;
  const Sweep sw =
      cad_pair_sweep(cad, first_touch_closure(cad), CoherentToothSearch::Continuation::replace,
                     [&, n = 0L](const PlanarPose& pa, const PlanarPose& pb, const ToothContact& u, const ToothContact& v) mutable {
                       if (n++ % 20 != 0) return;  // every twentieth: the probes cost
                       const double brute = brute_force_depth(*cad.gears[0].table, pa, *cad.gears[1].table, pb, u, 20000);
                       continued_low = std::max(continued_low, brute - v.depth_m);
                       sampled_low = std::max(sampled_low, brute - u.depth_m);
                     });
  EXPECT_EQ(sw.different_sets, 0);
  EXPECT_GT(continued_low, 1e-8) << "the continuation on a lower maximum";
  EXPECT_GT(sampled_low, 1e-8) << "the sampled search on a lower maximum";
  RecordProperty("continued_below_brute_force_m", std::to_string(continued_low));
  RecordProperty("sampled_below_brute_force_m", std::to_string(sampled_low));
  std::printf("below the brute-force maximum: continued by up to %.3e m, sampled by up to %.3e m\n", continued_low, sampled_low);
}

TEST(CoherentToothSearch, OnFacetedFlanksTheDeeperOfBothIsTheBruteForceMaximum) {
  // Continuation::deeper (what a run does for CAD meshes): never shallower than the sampled
  // search, and where it is deeper, within 1 nm of the brute-force maximum of the tooth pair
  // (20000 exact probes along a's flank; the probes' spacing loses at most ~1e-13 m), or of b's
  // flanks into a's where the contact is measured from b's side (a sampled maximum at a facet
  // corner of b's flank: tooth_contact.hpp).
  const CadPair cad;
  long deeper = 0;
  double worst = 0;
  const Sweep sw = cad_pair_sweep(cad, first_touch_closure(cad), CoherentToothSearch::Continuation::deeper,
                                  [&](const PlanarPose& pa, const PlanarPose& pb, const ToothContact& u, const ToothContact& v) {
                                    if (deeper++ % 20 != 0) return;  // every twentieth: the probes cost
                                    const double brute = brute_force_depth(*cad.gears[0].table, pa, *cad.gears[1].table, pb, u, 20000);
                                    const double from_b =
                                        brute_force_depth_from_b(*cad.gears[0].table, pa, *cad.gears[1].table, pb, u, 20000);
                                    worst = std::max(worst, std::min(std::abs(brute - v.depth_m), std::abs(from_b - v.depth_m)));
                                  });
  EXPECT_EQ(sw.different_sets, 0);
  EXPECT_LE(sw.most_shallower_m, 0.0) << "never shallower than the sampled search";
  EXPECT_GT(deeper, 100) << "the sampled search's lower maxima should occur";
  EXPECT_LT(worst, 1e-9) << "against brute force, of " << deeper;
  std::printf("%ld contacts deeper than the sampled search's; against brute force (every 20th) within %.3e m\n", deeper, worst);
}

}  // namespace
}  // namespace gearsim::contact

// The gear table of two involute gears and where a pair without a given centre distance is
// placed: the zero-backlash distance's tolerance from the teeth's thickness tolerances, the
// standard distance preferred within it, never a distance tighter than the fits can tell.
#include <gtest/gtest.h>

#include <cmath>

#include "core/errors.hpp"
#include "geometry/involute.hpp"
#include "geometry/involute_pair.hpp"

namespace gearsim {
namespace test_involute_pair {

constexpr double kAlpha = 20 * M_PI / 180;

// Unshifted zero-backlash teeth of module 1 mm: the tooth is half the pitch on the reference
// circle, carried to the base circle along the involute.
InvoluteTeeth teeth(int z, bool internal = false) {
  InvoluteTeeth t;
  t.teeth = z;
  t.internal = internal;
  const double r = 0.5e-3 * z;
  t.base_radius_m = r * std::cos(kAlpha);
  const double half_at_r = M_PI / (2 * z);
  t.base_half_angle_rad = internal ? half_at_r - involute(kAlpha) : half_at_r + involute(kAlpha);
  t.tip_radius_m = internal ? r - 1e-3 : r + 1e-3;
  t.standard_module_m = 1e-3;
  return t;
}

// The teeth thinned by `thin_m` along the normal at the base circle (a ring's spaces widened).
InvoluteTeeth thinned(InvoluteTeeth t, double thin_m) {
  t.base_half_angle_rad -= 0.5 * thin_m / t.base_radius_m;
  return t;
}

TEST(InvolutePair, TheZeroBacklashToleranceIsTheThicknessTolerancesOverTwoSinAlpha) {
  InvoluteTeeth a = teeth(20), b = teeth(30);
  a.thickness_tolerance_m = 1.68e-6, b.thickness_tolerance_m = 1.2e-6;
  const InvolutePair p = involute_pair(a, b, 0.0, "t");
  EXPECT_NEAR(p.zero_backlash_centre_distance_m, 25e-3, 1e-15);  // standard teeth: m(z1 + z2)/2
  EXPECT_NEAR(p.zero_backlash_tolerance_m, 2.88e-6 / (2 * std::sin(kAlpha)), 1e-15);
  // Moved out by that tolerance, the pair opens a backlash of both thickness tolerances (to
  // first order: the operating angle changes by 1e-4 rad).
  const InvolutePair out = involute_pair(a, b, p.zero_backlash_centre_distance_m + p.zero_backlash_tolerance_m, "t");
  EXPECT_NEAR(out.normal_backlash_m, 2.88e-6, 0.005e-6);
  // Base radii known to 0.9 and 0.8 µm add (0.9 + 0.8) µm / cos α_w: a = (r_b1 + r_b2)/cos α_w.
  a.base_radius_tolerance_m = 0.9e-6, b.base_radius_tolerance_m = 0.8e-6;
  EXPECT_NEAR(involute_pair(a, b, 0.0, "t").zero_backlash_tolerance_m, 2.88e-6 / (2 * std::sin(kAlpha)) + 1.7e-6 / std::cos(kAlpha), 1e-15);
  a.base_radius_tolerance_m = b.base_radius_tolerance_m = 0;
  // Internal: the ring's side closes as the distance grows.
  InvoluteTeeth ring = teeth(80, true);
  ring.thickness_tolerance_m = 1.2e-6;
  const InvolutePair pr = involute_pair(a, ring, 0.0, "t");
  EXPECT_NEAR(pr.zero_backlash_centre_distance_m, 30e-3, 1e-15);
  const InvolutePair in = involute_pair(a, ring, pr.zero_backlash_centre_distance_m - pr.zero_backlash_tolerance_m, "t");
  EXPECT_NEAR(in.normal_backlash_m, 2.88e-6, 0.005e-6);
}

TEST(InvolutePair, TeethKnownExactlyArePlacedAtTheirZeroBacklashDistanceWithoutANote) {
  const InvoluteTeeth a = teeth(20), b = thinned(teeth(30), 10e-6);
  const PairPlacement p = place_pair(a, b, "t");
  EXPECT_EQ(p.centre_distance_m, involute_pair(a, b, 0.0, "t").zero_backlash_centre_distance_m);
  EXPECT_LT(p.centre_distance_m, 25e-3 - 10e-6);  // 10 µm thinner: 14.6 µm closer
  EXPECT_EQ(p.note, "");
}

TEST(InvolutePair, AFitWithinItsToleranceOfTheStandardDistanceIsPlacedThere) {
  // FreeCAD's default export: flanks fitted at 0.84 µm rms put the zero-backlash distance 1.5 µm
  // inside the true one (the standard distance, for its unshifted zero-backlash gears). Placed
  // there, both flanks of a tooth were loaded.
  const double thin = 2 * std::sin(kAlpha) * 1.5e-6 / 2;  // each gear: half the 1.03 µm of backlash
  InvoluteTeeth a = thinned(teeth(20), thin), b = thinned(teeth(30), thin);
  a.thickness_tolerance_m = b.thickness_tolerance_m = 2 * 0.84e-6;
  const InvolutePair fits = involute_pair(a, b, 0.0, "t");
  EXPECT_NEAR(fits.zero_backlash_centre_distance_m, 25e-3 - 1.5e-6, 1e-9);
  const PairPlacement p = place_pair(a, b, "pair 'a'–'b'");
  EXPECT_EQ(p.centre_distance_m, 25e-3);
  EXPECT_NE(p.note.find("pair 'a'–'b': placed at the standard distance 25 mm"), std::string::npos) << p.note;
  // The same teeth not recognised as standard: the loose end of the band, where the teeth
  // cannot overlap whatever their thickness within the tolerance.
  a.standard_module_m = b.standard_module_m = 0;
  const PairPlacement loose = place_pair(a, b, "t");
  EXPECT_NEAR(loose.centre_distance_m, fits.zero_backlash_centre_distance_m + fits.zero_backlash_tolerance_m, 1e-15);
  EXPECT_NEAR(involute_pair(a, b, loose.centre_distance_m, "t").normal_backlash_m, 4 * 0.84e-6, 0.005e-6);
  EXPECT_NE(loose.note.find("outside the flank fits' zero-backlash distance"), std::string::npos) << loose.note;
}

TEST(InvolutePair, AStandardDistanceBeyondTheToleranceIsNotUsed) {
  // MCAD's 0.05 mm of backlash: its zero-backlash distance lies 69 µm inside the standard one,
  // far beyond fits of 0.01 µm rms: the loose end of the band, 0.03 µm outside the fits' distance.
  InvoluteTeeth a = thinned(teeth(12), 0.025e-3 * std::cos(kAlpha)), b = thinned(teeth(24), 0.025e-3 * std::cos(kAlpha));
  a.thickness_tolerance_m = b.thickness_tolerance_m = 2 * 0.0093e-6;
  const InvolutePair fits = involute_pair(a, b, 0.0, "t");
  EXPECT_NEAR(fits.zero_backlash_centre_distance_m, 18e-3 - 0.069e-3, 0.001e-3);
  const PairPlacement p = place_pair(a, b, "t");
  EXPECT_NEAR(fits.zero_backlash_tolerance_m, 4 * 0.0093e-6 / (2 * std::sin(kAlpha)), 0.05 * fits.zero_backlash_tolerance_m);
  EXPECT_NEAR(p.centre_distance_m, fits.zero_backlash_centre_distance_m + fits.zero_backlash_tolerance_m, 1e-15);
  // Internal: inside the fits' distance (both thinned: 69 µm beyond the standard one).
  InvoluteTeeth ring = thinned(teeth(48, true), 0.025e-3 * std::cos(kAlpha));
  ring.thickness_tolerance_m = 2 * 0.0063e-6;
  const InvolutePair fr = involute_pair(a, ring, 0.0, "t");
  EXPECT_NEAR(fr.zero_backlash_centre_distance_m, 18e-3 + 0.068e-3, 0.002e-3);  // α_w 20.4° here
  const PairPlacement pr = place_pair(a, ring, "t");
  EXPECT_NEAR(pr.centre_distance_m, fr.zero_backlash_centre_distance_m - fr.zero_backlash_tolerance_m, 1e-15);
  EXPECT_NE(pr.note.find("inside the flank fits' zero-backlash distance"), std::string::npos) << pr.note;
}

// FreeCAD 0.20's default exports of a sun z 12, planets z 18 and a ring z 48 (m 1 mm, 20°), as
// their fits read: base radii 5.637244, 8.456415 and 22.552607 mm (0.91, 0.82 and 0.02 µm short
// of m·z·cos α/2), flank rms ≤ 0.014 µm. The zero-backlash distances conflict by 0.62 µm
// (sun–planet ≥ 15.00048 mm, planet–ring ≤ 14.99986 mm); the rms alone (0.06 µm) refused the set,
// which runs at its standard 15 mm.
TEST(InvolutePair, APlanetaryConflictWithinTheFitsToleranceIsMetAtTheStandardDistance) {
  // The fits as `gearsim inspect` printed them (ccw and cw flanks): base radius (mm), base
  // half-angle (°), rms (µm); involute_teeth(RecognisedGear) takes the means and the tolerances.
  auto fitted = [](int z, bool internal, double rb_ccw, double rb_cw, double half_ccw, double half_cw, double rms_ccw, double rms_cw,
                   double tip_mm) {
    InvoluteTeeth t = teeth(z, internal);
    t.base_radius_m = 0.5e-3 * (rb_ccw + rb_cw);
    t.base_half_angle_rad = 0.5 * (half_ccw + half_cw) * M_PI / 180;
    t.tip_radius_m = tip_mm * 1e-3;
    t.thickness_tolerance_m = (rms_ccw + rms_cw) * 1e-6;
    t.base_radius_tolerance_m = std::max(0.5e-3 * std::abs(rb_ccw - rb_cw), std::abs(t.base_radius_m - 0.5e-3 * z * std::cos(kAlpha)));
    return t;
  };
  const InvoluteTeeth sun =
      fitted(12, false, 5.63718609130974, 5.637301107598253, 8.35877916074773, 8.358205293587213, 0.0071004, 0.0135565, 7.0013693);
  const InvoluteTeeth planet =
      fitted(18, false, 8.456408760864623, 8.456421265714154, 5.856313774955483, 5.856296280616414, 0.0050494, 0.0036857, 10.0011339);
  const InvoluteTeeth ring =
      fitted(48, true, 22.55260655124676, 22.552606622995672, 1.0210282713010004, 1.021028339618041, 0.0003793, 0.0003186, 23.3999992);
  const InvolutePair sp = involute_pair(sun, planet, 0.0, "t"), pr = involute_pair(planet, ring, 0.0, "t");
  EXPECT_NEAR(sp.zero_backlash_centre_distance_m - pr.zero_backlash_centre_distance_m, 0.62e-6, 0.01e-6);  // the conflict
  const PairPlacement p = place_planetary(sun, planet, ring);
  EXPECT_EQ(p.centre_distance_m, 15e-3);
  EXPECT_NE(p.note.find("placed at the standard distance 15 mm"), std::string::npos) << p.note;
  // The same conflict with the base radii taken as exact: refused, naming it.
  InvoluteTeeth s2 = sun, p2 = planet, r2 = ring;
  s2.base_radius_tolerance_m = p2.base_radius_tolerance_m = r2.base_radius_tolerance_m = 0;
  try {
    place_planetary(s2, p2, r2);
    ADD_FAILURE() << "a conflict beyond the tolerances was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no centre distance meshes both"), std::string::npos) << e.what();
  }
  // Teeth known exactly (generated gears) with backlash: midway, no note.
  const InvoluteTeeth ts = thinned(teeth(12), 20e-6), tp = thinned(teeth(18), 20e-6), tr = thinned(teeth(48, true), 20e-6);
  const PairPlacement mid = place_planetary(ts, tp, tr);
  EXPECT_EQ(mid.centre_distance_m, 0.5 * (involute_pair(ts, tp, 0.0, "t").zero_backlash_centre_distance_m +
                                          involute_pair(tp, tr, 0.0, "t").zero_backlash_centre_distance_m));
  EXPECT_EQ(mid.note, "");
}

TEST(InvolutePair, TheStandardDistanceNeedsOneStandardModule) {
  InvoluteTeeth a = teeth(20), b = teeth(30), ring = teeth(70, true);
  EXPECT_EQ(standard_centre_distance(a, b), 25e-3);
  EXPECT_EQ(standard_centre_distance(a, ring), 25e-3);
  EXPECT_EQ(standard_centre_distance(ring, a), 25e-3);
  b.standard_module_m = 1.25e-3;
  EXPECT_EQ(standard_centre_distance(a, b), 0.0);
  b.standard_module_m = 0;
  EXPECT_EQ(standard_centre_distance(a, b), 0.0);
}

}  // namespace test_involute_pair
}  // namespace gearsim

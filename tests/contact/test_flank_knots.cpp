// Flank knots and flank tables from outlines nobody here made: OpenSCAD MCAD gears
// (tests/data/mcad: an involute above the base circle, a radial line below it, a flat chordal tip
// land, a polygonal root), with and without coordinate noise. The tables must follow the
// outline they came from; a radial piece next to an involute must stay straight.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "geometry/mesh_gear.hpp"
#include "geometry/mesh_io.hpp"
#include "geometry/prism.hpp"
#include "contact/flank_knots.hpp"
#include "contact/flank_table.hpp"
#include "contact/flank_table_store.hpp"
#include "tests/support/asymmetric_gear.hpp"
#include "tests/support/paper_flank_tables.hpp"

namespace gearsim::contact {
namespace test_flank_knots {

// The outer loop of an MCAD mesh's outline (about its own z axis), m.
Polygon2 mcad_loop(int teeth) {
  const TriMesh mesh = import_mesh(
      std::string(GEARSIM_SOURCE_DIR) + "/tests/data/mcad/mcad_m1_z" + std::to_string(teeth) + "_a20_f5_b005.stl", LengthUnit::Millimetre);
  const Result<Prism> pr = recover_prism(mesh, 0.1e-6);
  EXPECT_TRUE(pr) << pr.reason();
  return pr->outline.outer;
}

TEST(FlankKnots, ARadialPieceBesideAnInvoluteStaysStraight) {
  // MCAD's flank below the base circle: θ constant from the root (4.75 mm) to r_b = 5.638 mm,
  // then the involute θ = θ0 + inv α at coarse roll steps. A cubic through knots on both sides
  // would bow the straight piece by tens of µm; the shape-preserving cubic keeps it straight.
  const double rb = 5.638e-3, theta0 = -0.1;
  FlankKnots k;
  k.r_m = {4.75e-3};
  k.theta_rad = {theta0};
  for (int i = 0; i <= 5; ++i) {
    const double roll = 0.16 * i, r = rb * std::sqrt(1 + roll * roll);
    k.r_m.push_back(r);
    k.theta_rad.push_back(theta0 + (roll - std::atan(roll)));
  }
  const int n = 2000;
  const double r0 = k.r_m.front(), dr = (k.r_m.back() - r0) / (n - 1);
  std::vector<double> v(n);
  sample_flank(k, r0, dr, n, v.data());
  double worst = 0;
  for (int i = 0; i < n && r0 + i * dr <= rb; ++i) worst = std::max(worst, std::abs(v[i] - theta0) * (r0 + i * dr));
  EXPECT_LT(worst, 1e-12);  // m: straight to rounding
  // And the table follows the knots' polyline within the sagitta of the involute's chords.
  EXPECT_LT(flank_departure(k, r0, dr, n, v.data()).departure_m, 0.05e-6);
}

TEST(FlankTable, TurnsWithTheInvoluteAcrossItsKnotsUpToTheFillet) {
  // An involute's tangent turns by exactly its roll angle: between radii r1 < r2 by
  // tan α(r2) − tan α(r1), tan α = sqrt(r² − r_b²)/r_b. The table's tangent (its jet's d1, in the
  // tooth's frame) must turn the same over every 5 µm of the paper gears' involutes, knots
  // included, from where each meets its root fillet (the form circles: sun 11.338, planet
  // 17.221, ring 49.018 mm; the outline has a vertex there) to the tip. A cubic whose four knots
  // straddle that junction bent the involute's interval next to it instead: a turn off by
  // 5.8e-3 (sun, at 11.38 mm), 7.6e-3 (planet, 17.28 mm) and 1.3e-2 rad (ring, 48.885 mm: a
  // ridge the planets' tips locked onto, solved by golden section every step). Measured with
  // the stencil chosen away from the junction: 4.8e-4 (sun, 11.425 mm: between two stencils on
  // the involute alone, 0.09 mm above the form circle, where the involute's radius of curvature
  // is 1.7 mm and the knots 50 µm apart — the cubic's own error), 7.1e-5 and 1.2e-5 rad.
  const std::vector<test::Gear>& g = test::paper_gears();
  struct Case {
    const char* name;
    int teeth;
    double r_lo, r_hi;
  };
  for (const Case& c :
       {Case{"sun", 24, 11.34e-3, 12.99e-3}, Case{"planet_1", 36, 17.222e-3, 18.99e-3}, Case{"ring", 96, 47.21e-3, 49.017e-3}}) {
    const FlankTable& t = *test::named(g, c.name).table;
    const double r_b = 0.5e-3 * c.teeth * std::cos(20.0 * M_PI / 180);
    auto tan_alpha = [&](double r) { return std::sqrt(r * r - r_b * r_b) / r_b; };
    double worst = 0, at = 0;
    for (Flank f : {Flank::Ccw, Flank::Cw}) {
      auto tangent_angle = [&](double r) {
        FlankTable::FlankJet jet;
        EXPECT_TRUE(t.flank_jet(0, f, r, &jet)) << c.name << " r " << r;
        return std::atan2(jet.d1.y(), jet.d1.x());
      };
      constexpr double kWindow_m = 5e-6;
      for (double r = c.r_lo; r + kWindow_m <= c.r_hi; r += 1e-6) {
        const double turn = std::abs(std::remainder(tangent_angle(r + kWindow_m) - tangent_angle(r), 2 * M_PI));
        const double off = std::abs(turn - (tan_alpha(r + kWindow_m) - tan_alpha(r)));
        if (off > worst) worst = off, at = r;
      }
    }
    std::printf("%s: tangent turn over 5 µm against the involute's: worst %.3g rad at %.6g mm\n", c.name, worst, at * 1e3);
    EXPECT_LT(worst, 1e-3) << c.name << " at r " << at;
  }
}

TEST(FlankTable, FollowsAnMcadGearsOutline) {
  for (int z : {12, 24}) {
    const FlankTable t(mcad_loop(z), ToothLayout{z, 0.0}, false, 4096);
    // 5 facets per involute: the cubic through the vertices departs from their polyline by less
    // than the chords' own sagitta estimate allows, well inside the 2 µm a scenario accepts.
    EXPECT_LT(t.departure().departure_m, 0.5e-6) << "z " << z << " tooth " << t.departure().tooth;
    // Tip at m·(z/2 + 1), root at r_f = m·(z/2 − 1.25) (MCAD: clearance 0.25 mm), less the
    // table's 1e-4 edge margin; MCAD's root is a 2z-gon on r_f whose sides meet the radial flanks
    // between r_f·cos(90°/z) and r_f.
    const double rf = 1e-3 * (z / 2.0 - 1.25);
    EXPECT_NEAR(t.r_max_m(), 1e-3 * (z / 2.0 + 1), 1e-6);
    EXPECT_GT(t.r_min_m(), rf * std::cos(M_PI / 2 / z));
    EXPECT_LT(t.r_min_m(), rf);
    // Tooth 0 symmetric about +x: its flanks at the pitch radius are mirror images.
    const double rp = 1e-3 * z / 2;
    EXPECT_NEAR(t.flank_angle(0, Flank::Ccw, rp), -t.flank_angle(0, Flank::Cw, rp), 1e-9);
  }
}

TEST(FlankTable, FollowsTheInvoluteOfAFlankExportedAsOneLongChord) {
  // FreeCAD 0.20 at 0.1 mm linear deflection (tests/data/freecad, made by FreeCAD): z 40, m 1 mm,
  // 20°, each flank's involute from r 19.52 to the tip at 21.0 mm one chord of 1.59 mm, its
  // vertices on the involute of r_b = 18.794 mm. The cubic through the last four knots (two of
  // them on the fillet) bowed 229 µm off that chord, which the involute leaves by 43 µm: the table
  // departed 175.6 µm from the outline and the mesh was refused. The table must follow the
  // outline within the 2 µm a scenario accepts and lie closer to the involute than the chord does.
  const MeshGearFile f =
      read_mesh_gear(std::string(GEARSIM_SOURCE_DIR) + "/tests/data/freecad/fc_m1_z40_a20_l0p1r0p5.stl", LengthUnit::Millimetre);
  ASSERT_TRUE(f.gear) << f.prism.reason();
  ASSERT_TRUE(f.gear->recognition) << f.gear->recognition.reason();
  const Polygon2& loop = f.gear->outline.outer;
  const ToothLayout layout{40, 0.0};
  const FlankTable t(loop, layout, false, 4096);
  EXPECT_LT(t.departure().departure_m, 2e-6) << "tooth " << t.departure().tooth << " r " << t.departure().r_m;
  const double rb = 20e-3 * std::cos(20 * M_PI / 180);
  auto inv = [&](double r) {
    const double a = std::acos(rb / r);
    return std::tan(a) - a;
  };
  const std::vector<FlankKnots> knots = flank_knots(loop, layout, false, 1e-8);
  double worst_table = 0, worst_chord = 0;
  for (int tooth = 0; tooth < 40; ++tooth)
    for (int side = 0; side < 2; ++side) {
      const FlankKnots& k = knots[static_cast<std::size_t>(tooth) * 2 + side];
      const std::size_t n = k.r_m.size();
      const double r0 = k.r_m[n - 2], r1 = std::min(k.r_m[n - 1], t.r_max_m());
      ASSERT_LT(r0, 19.6e-3);  // one chord from below 19.6 mm to the tip
      // The involute through the tip knot (Ccw flank: θ falls as r grows).
      const double sign = side == 0 ? -1 : 1;
      auto involute = [&](double r) { return k.theta_rad[n - 1] + sign * (inv(r) - inv(k.r_m[n - 1])); };
      EXPECT_NEAR(involute(r0) * r0, k.theta_rad[n - 2] * r0, 0.2e-6) << "tooth " << tooth << " side " << side;
      const Flank flank = side == 0 ? Flank::Ccw : Flank::Cw;
      for (int i = 1; i < 50; ++i) {
        const double r = r0 + (r1 - r0) * i / 50;
        // The chord's angle at r: where the straight line between the knots crosses radius r.
        const Eigen::Vector2d a(r0 * std::cos(k.theta_rad[n - 2]), r0 * std::sin(k.theta_rad[n - 2]));
        const Eigen::Vector2d b(k.r_m[n - 1] * std::cos(k.theta_rad[n - 1]), k.r_m[n - 1] * std::sin(k.theta_rad[n - 1]));
        double lo = 0, hi = 1;
        for (int it = 0; it < 60; ++it) {
          const double mid = 0.5 * (lo + hi);
          ((a + mid * (b - a)).norm() < r ? lo : hi) = mid;
        }
        const Eigen::Vector2d c = a + lo * (b - a);
        const double chord_theta = std::atan2(c.y(), c.x());
        worst_chord = std::max(worst_chord, std::abs(chord_theta - involute(r)) * r);
        worst_table = std::max(worst_table, std::abs(t.flank_angle(tooth, flank, r) - involute(r)) * r);
      }
    }
  std::printf("FreeCAD 0.1 mm z 40: table within %.2f um of the involute, the mesh's chord within %.2f um\n", worst_table * 1e6,
              worst_chord * 1e6);
  EXPECT_LT(worst_table, 0.5 * worst_chord);
}

TEST(FlankTable, CoordinateNoiseOfHalfAMicrometreIsTolerated) {
  // ±0.5 µm uniform in-plane noise on every vertex (a flat tip land then rises and falls by up
  // to 1 µm between its corners): the table still follows the outline within 2 µm.
  Polygon2 loop = mcad_loop(24);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-0.5e-6, 0.5e-6);
  for (Eigen::Vector2d& p : loop.points) p += Eigen::Vector2d(u(rng), u(rng));
  const FlankTable t(loop, ToothLayout{24, 0.0}, false, 4096);
  EXPECT_LT(t.departure().departure_m, 2e-6);
  // 5 facets per involute: each knot is predicted by its neighbours' cubic only to ~2.5 µm (the
  // chords' curvature, not the noise), so knots closer than 4× that are merged; none are here.
  EXPECT_LT(t.knot_resolution_m(), 5e-6);
}

TEST(FlankTable, ATipLandWhoseCornersDifferByRoundingIsNoFlank) {
  // The failure: tip corners at radii 28 nm apart joined the flank run, and the cubic
  // through two knots 28 nm apart in r and 2° apart in angle swung by thousands of degrees.
  Polygon2 loop = mcad_loop(12);
  const double rmax = 7e-3;
  for (Eigen::Vector2d& p : loop.points)
    if (p.norm() > rmax - 1e-9) p *= (p.y() > 0 ? 1 + 28e-9 / rmax : 1.0);  // one corner 28 nm higher
  const FlankTable t(loop, ToothLayout{12, 0.0}, false, 4096);
  EXPECT_LT(t.departure().departure_m, 0.5e-6);
  for (int k = 0; k < 12; ++k)
    for (Flank f : {Flank::Ccw, Flank::Cw}) {
      const double a = t.flank_angle(k, f, t.r_max_m() - 1e-6);
      if (!std::isnan(a)) {
        EXPECT_LT(std::abs(a), M_PI / 12) << "tooth " << k;
      }
    }
}

// The flank table of asymmetric teeth follows each side: its angle at any radius is the side's
// own involute (the table interpolates between outline vertices 1/39 of the depth apart).
TEST(FlankTable, FollowsAsymmetricTeethSideBySide) {
  const test::AsymmetricGear a;
  const FlankTable t(a.outline(), ToothLayout{20, 0.0}, false, 4096);
  EXPECT_LT(t.departure().departure_m, 0.5e-6);
  for (double r : {9.7e-3, 10e-3, 10.5e-3}) {
    // Angle errors times the radius: within 0.1 µm along the circle.
    EXPECT_NEAR(r * t.flank_angle(3, Flank::Ccw, r), r * a.side_angle(a.rb_ccw_m, r), 0.1e-6) << r;
    EXPECT_NEAR(r * t.flank_angle(3, Flank::Cw, r), -r * a.side_angle(a.rb_cw_m, r), 0.1e-6) << r;
  }
}

TEST(FlankTableStore, GivesTheTableAFreshBuildGivesOnceForTheSameInputs) {
  // MCAD's z = 24 outline: the store's table describes the same flanks as one built afresh
  // (same_as: layout, radii and every sample bit for bit), the same inputs bit for bit give the
  // same object without a build, and a loop moved by one ulp, another layout or another side
  // give tables of their own.
  const Polygon2 loop = mcad_loop(24);
  const FlankTableStoreStats before = flank_table_store_stats();
  const std::shared_ptr<const FlankTable> a = shared_flank_table(loop, ToothLayout{24, 0.0}, false, 4096);
  const FlankTable fresh(loop, ToothLayout{24, 0.0}, false, 4096);
  EXPECT_TRUE(a->same_as(fresh));
  EXPECT_EQ(a->departure().departure_m, fresh.departure().departure_m);
  const std::shared_ptr<const FlankTable> again = shared_flank_table(loop, ToothLayout{24, 0.0}, false, 4096);
  EXPECT_EQ(again.get(), a.get());
  const FlankTableStoreStats after = flank_table_store_stats();
  EXPECT_EQ(after.builds - before.builds, 1);
  EXPECT_EQ(after.hits - before.hits, 1);
  Polygon2 moved = loop;
  moved.points[7].x() = std::nextafter(moved.points[7].x(), 1.0);
  EXPECT_NE(shared_flank_table(moved, ToothLayout{24, 0.0}, false, 4096).get(), a.get());
  const std::shared_ptr<const FlankTable> turned = shared_flank_table(loop, ToothLayout{24, 1e-3}, false, 4096);
  EXPECT_NE(turned.get(), a.get());
  EXPECT_FALSE(turned->same_as(*a));
  EXPECT_NE(shared_flank_table(loop, ToothLayout{24, 0.0}, false, 2048).get(), a.get());
  EXPECT_LE(flank_table_store_stats().bytes, kFlankTableStoreBytes);
}

}  // namespace test_flank_knots
}  // namespace gearsim::contact

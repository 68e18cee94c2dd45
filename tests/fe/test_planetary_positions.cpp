// Quasi-static FE positions of the paper's planetary set: the clearances closed by turning each
// planet against the ring and then the sun equal the backlash allowances along the line of action.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "geometry/gear_dimensions.hpp"
#include "fe/planetary_positions.hpp"

using namespace gearsim;
using namespace gearsim::fe;

namespace test_planetary_positions {

GearSpec gear(const std::string& name, GearKind kind, int z, double thinning) {
  GearSpec g;
  g.name = name;
  g.kind = kind;
  g.teeth = z;
  g.module_m = 1e-3;
  g.face_width_m = 10e-3;
  g.thinning_per_flank_m = thinning;
  if (kind == GearKind::External)
    g.bore_diameter_m = 8e-3;
  else {
    g.rim_diameter_m = 110e-3;
    g.addendum_coeff = 0.8;  // the paper scenarios' relieved ring (no fillet interference)
  }
  return g;
}

// Sun 24 / planet 36 / ring 96, m = 1 mm, x = 0, each flank thinned by t = 20 µm: the standard set
// meshes without backlash, so a planet turns (t_p + t_r)/r_b,p before it touches the ring and then
// the sun (t_s + 2 t_p + t_r)/r_b,s before it touches the planets; all three planets at once
// (equal spacing, (24 + 96)/3 = 40 in phase). Tolerance 0.5 %: the flank tables resolve depths to
// ~2 nm against clearances of 40–80 µm.
TEST(PlanetaryPositions, ClosingTurnsEqualTheBacklash) {
  const double t = 20e-6;
  PlanetarySpec ps{gear("sun", GearKind::External, 24, t), gear("planet", GearKind::External, 36, t),
                   gear("ring", GearKind::Internal, 96, t), 3};
  const PlanetaryGeometry geo = analyse_planetary(ps);
  const auto ts = flank_table_of(ps.sun), tp = flank_table_of(ps.planet), tr = flank_table_of(ps.ring);
  PlanetaryTables tables{&ts, {&tp, &tp, &tp}, &tr};
  const double rbs = 12e-3 * std::cos(20 * std::numbers::pi / 180);
  const double rbp = 18e-3 * std::cos(20 * std::numbers::pi / 180);
  for (double phi : {0.0, 0.1}) {
    const PlanetaryPosition pos = place_closed(ps, geo, tables, phi);
    for (double d : pos.planet_closing_rad) EXPECT_NEAR(d / (-2 * t / rbp), 1.0, 5e-3) << "φ = " << phi;
    EXPECT_NEAR(pos.sun_closing_rad / (4 * t / rbs), 1.0, 5e-3) << "φ = " << phi;
    // A hair further and every planet is touched by the sun.
    contact::PlanarPose s = pos.sun;
    s.angle_rad += 1e-6;
    for (int k = 0; k < 3; ++k) EXPECT_FALSE(contact::find_tooth_contacts(ts, s, tp, pos.planets[k]).empty()) << "planet " << k;
  }
}

}  // namespace test_planetary_positions

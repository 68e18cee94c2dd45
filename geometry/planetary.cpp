#include "geometry/planetary.hpp"

#include <cmath>
#include <numbers>
#include <sstream>

#include "core/errors.hpp"
#include "geometry/gear_dimensions.hpp"
#include "geometry/constants.hpp"

namespace gearsim {
namespace {

using gearsim::constants::kPi;

// Fractional part in [0, 1).
double frac(double v) { return v - std::floor(v); }

}  // namespace

void phase_planetary(const PlanetaryLayout& s, PlanetaryGeometry& g) {
  g.assembly_quotient = static_cast<double>(s.sun_teeth + s.ring_teeth) / s.planets;
  g.equally_spaced_assembly = std::abs(g.assembly_quotient - std::round(g.assembly_quotient)) < 1e-12;
  // Phasing. Tooth fraction f(angle) = (angle − tooth0 − body rotation)·z/2π (0 = tooth centre).
  // External mesh at the pitch point: f_sun + f_planet ≡ ½. Internal: f_ring − f_planet ≡ ½.
  const double zs = s.sun_teeth, zp = s.planet_teeth, zr = s.ring_teeth;
  for (int k = 0; k < s.planets; ++k) {
    PlanetPlacement p;
    p.carrier_angle_rad = 2 * kPi * k / s.planets;
    const double beta = p.carrier_angle_rad;
    const double f_sun = frac((beta - s.sun_tooth0_rad) * zs / (2 * kPi));
    const double f_planet = frac(0.5 - f_sun);  // at the planet's angle β + π (facing the sun)
    p.spin_angle_rad = beta + kPi - s.planet_tooth0_rad - f_planet * 2 * kPi / zp;
    g.placements.push_back(p);
  }
  // The ring's rotation from planet 0, then the mismatch every other planet leaves.
  auto ring_phase = [&](const PlanetPlacement& p) {
    const double beta = p.carrier_angle_rad;
    const double f_planet = frac((beta - s.planet_tooth0_rad - p.spin_angle_rad) * zp / (2 * kPi));
    return beta - s.ring_tooth0_rad - (f_planet + 0.5) * 2 * kPi / zr;
  };
  g.ring_angle_rad = ring_phase(g.placements.front());
  for (const PlanetPlacement& p : g.placements) {
    const double d = (ring_phase(p) - g.ring_angle_rad) * zr / (2 * kPi);
    g.phase_mismatch_teeth = std::max(g.phase_mismatch_teeth, std::abs(d - std::round(d)));
  }
}

PlanetaryGeometry analyse_planetary(const PlanetarySpec& s) {
  if (s.planets < 1) throw InputError("planetary set: planets: expected at least 1");
  if (s.sun.kind != GearKind::External) throw InputError("planetary set: sun: must be an external gear");
  if (s.planet.kind != GearKind::External) throw InputError("planetary set: planet: must be an external gear");
  if (s.ring.kind != GearKind::Internal) throw InputError("planetary set: ring: must be an internal gear");
  PlanetaryGeometry g;
  const double a_sp = zero_backlash_centre_distance(s.sun, s.planet);
  const double a_pr = zero_backlash_centre_distance(s.planet, s.ring);
  if (std::abs(a_sp - a_pr) > 1e-9) {
    std::ostringstream msg;
    msg << "planetary set: sun–planet centre distance " << a_sp * 1e3 << " mm differs from planet–ring " << a_pr * 1e3
        << " mm (expected z_r = z_s + 2·z_p for unshifted gears)";
    throw InputError(msg.str());
  }
  g.centre_distance_m = a_sp;
  g.ratio_sun_to_carrier = 1.0 + static_cast<double>(s.ring.teeth) / s.sun.teeth;
  const GearDimensions dp = gear_dimensions(s.planet);
  g.adjacency_clearance_m = 2 * g.centre_distance_m * std::sin(kPi / s.planets) - 2 * dp.tip_radius_m;
  g.sun_planet = analyse_mesh(s.sun, s.planet, a_sp);
  g.planet_ring = analyse_mesh(s.planet, s.ring, a_pr);

  phase_planetary(
      {s.sun.teeth, s.planet.teeth, s.ring.teeth, s.planets, s.sun.tooth0_angle_rad, s.planet.tooth0_angle_rad, s.ring.tooth0_angle_rad},
      g);
  std::ostringstream note;
  if (!g.equally_spaced_assembly) {
    note << "(z_s + z_r)/N = " << g.assembly_quotient << " is not an integer: " << s.planets
         << " planets cannot be equally spaced (phase mismatch " << g.phase_mismatch_teeth << " teeth)";
    g.problems.push_back(note.str());
  }
  if (g.adjacency_clearance_m <= 0) g.problems.push_back("neighbouring planets' tip circles overlap");
  for (const std::string& p : g.sun_planet.problems) g.problems.push_back("sun–planet: " + p);
  for (const std::string& p : g.planet_ring.problems) g.problems.push_back("planet–ring: " + p);
  return g;
}

}  // namespace gearsim

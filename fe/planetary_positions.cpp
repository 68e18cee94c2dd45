#include "fe/planetary_positions.hpp"

#include <cmath>
#include <functional>

#include "core/errors.hpp"
#include "geometry/gear_profile.hpp"
#include "fe/closing_turn.hpp"
#include "fe/constants.hpp"

namespace gearsim::fe {
namespace {

// True when some contact touches gear a on its `flank` (the leading flank in a's sense of turn;
// the trailing flank may touch too in a set without backlash, and does not count).
bool touches_on(const std::vector<contact::ToothContact>& contacts, Flank flank) {
  for (const auto& c : contacts)
    if (c.flank_a == flank) return true;
  return false;
}

}  // namespace

contact::FlankTable flank_table_of(const GearSpec& spec) {
  const GearOutline g = make_gear_outline(spec);
  const bool internal = spec.kind == GearKind::Internal;
  return contact::FlankTable(internal ? g.outline.holes.front() : g.outline.outer, ToothLayout{spec.teeth, spec.tooth0_angle_rad}, internal,
                             kFlankTableSamples);
}

PlanetaryPosition place_closed(const PlanetarySpec& spec, const PlanetaryGeometry& geo, const PlanetaryTables& tables,
                               double sun_turn_rad) {
  if (!tables.sun || !tables.ring || static_cast<int>(tables.planets.size()) != spec.planets ||
      static_cast<int>(geo.placements.size()) != spec.planets)
    throw InputError("planetary FE position: tables and placements must cover the sun, ring and " + std::to_string(spec.planets) +
                     " planets");
  const double zs = spec.sun.teeth, zp = spec.planet.teeth, zr = spec.ring.teeth;
  PlanetaryPosition pos;
  pos.sun_turn_rad = sun_turn_rad;
  // Kinematic angles in the carrier frame: sun +φ, planets −φ·z_s/z_p, ring −φ·z_s/z_r.
  pos.sun.angle_rad = sun_turn_rad;
  pos.ring.angle_rad = geo.ring_angle_rad - sun_turn_rad * zs / zr;
  for (int k = 0; k < spec.planets; ++k) {
    const PlanetPlacement& p = geo.placements[static_cast<size_t>(k)];
    contact::PlanarPose pp;
    pp.centre_m = geo.centre_distance_m * Eigen::Vector2d(std::cos(p.carrier_angle_rad), std::sin(p.carrier_angle_rad));
    pp.angle_rad = p.spin_angle_rad - sun_turn_rad * zs / zp;
    pos.planets.push_back(pp);
  }
  // Each planet turned clockwise (the sense the sun drives it) until it touches the ring.
  for (int k = 0; k < spec.planets; ++k) {
    contact::PlanarPose& pp = pos.planets[static_cast<size_t>(k)];
    const contact::FlankTable& tp = *tables.planets[static_cast<size_t>(k)];
    const double base = pp.angle_rad;
    auto touching = [&](double d) {
      contact::PlanarPose q = pp;
      q.angle_rad = base + d;
      return touches_on(contact::find_tooth_contacts(tp, q, *tables.ring, pos.ring), Flank::Cw);
    };
    const double d = closing_turn(touching, -1.0, "planet " + std::to_string(k) + " against the ring");
    pp.angle_rad = base + d;
    pos.planet_closing_rad.push_back(d);
  }
  // The sun turned counter-clockwise until it touches a planet.
  const double base = pos.sun.angle_rad;
  auto touching = [&](double d) {
    contact::PlanarPose s = pos.sun;
    s.angle_rad = base + d;
    for (int k = 0; k < spec.planets; ++k)
      if (touches_on(
              contact::find_tooth_contacts(*tables.sun, s, *tables.planets[static_cast<size_t>(k)], pos.planets[static_cast<size_t>(k)]),
              Flank::Ccw))
        return true;
    return false;
  };
  std::string closings;
  for (double d : pos.planet_closing_rad) closings += " " + std::to_string(d);
  pos.sun_closing_rad = closing_turn(touching, 1.0, "sun against the planets (planets closed by" + closings + " rad)");
  pos.sun.angle_rad = base + pos.sun_closing_rad;
  contact::PlanarPose s = pos.sun;
  for (int k = 0; k < spec.planets; ++k)
    if (touches_on(
            contact::find_tooth_contacts(*tables.sun, s, *tables.planets[static_cast<size_t>(k)], pos.planets[static_cast<size_t>(k)]),
            Flank::Ccw)) {
      pos.touching_planet = k;
      break;
    }
  return pos;
}

}  // namespace gearsim::fe

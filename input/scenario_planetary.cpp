// The `planetary:` scenario macro: sun, planet_0..planet_{N−1}, ring and a shapeless carrier
// with their hinges, the planets phased so that every mesh engages, the set checked for
// assembly (equal spacing, no overlapping planets), and the Willis ratio as the transmission.
// Not the members' reading (scenario_planetary_members.cpp).
#include <cmath>
#include <sstream>

#include "core/errors.hpp"
#include "geometry/constants.hpp"
#include "geometry/gear_dimensions.hpp"
#include "geometry/planetary.hpp"
#include "input/gear_train.hpp"
#include "input/scenario_macros_detail.hpp"

namespace gearsim::input::scenario_detail {
namespace {

namespace fs = std::filesystem;
using gearsim::constants::kPi;

// Polar angle of tooth 0 in a member's own frame, rad.
double tooth0_of_member(const physics::BodyDef& b) { return b.gear ? b.gear->tooth0_angle_rad : b.mesh->teeth->tooth0_angle_rad; }

// The geometry of a set of shapes: the centre distance (given, or midway between the sun–planet
// and planet–ring zero-backlash distances), both meshes checked there, the phasing.
PlanetaryGeometry shapes_geometry(const YamlMap& m, const PlanetaryMembers& s, std::vector<physics::PairTableDef>& tables) {
  const bool derived = !m.has("centre_distance_m");
  double a = derived ? 0.0 : number_within(m, "centre_distance_m", limits::kCentreDistance_m);
  std::string note;
  if (derived) try {
      const PairPlacement placed = place_planetary(*s.sun_teeth, *s.planet_teeth, *s.ring_teeth);
      a = placed.centre_distance_m;
      note = placed.note;
    } catch (const InputError& e) {
      m.fail("ring", e.what());
    }
  if (s.sun_teeth) {  // else the start checks alone judge the meshes (as the pair macro's)
    tables.push_back(checked_pair_table(m, "sun", "planet_0", *s.sun_teeth, *s.planet_teeth, a, derived, "ring"));
    tables.push_back(checked_pair_table(m, "planet_0", "ring", *s.planet_teeth, *s.ring_teeth, a, derived, "ring"));
    tables.front().placement_note = note;
  }
  PlanetaryGeometry g;
  g.centre_distance_m = a;
  g.ratio_sun_to_carrier = 1.0 + static_cast<double>(teeth_of(s.ring)) / teeth_of(s.sun);
  const double planet_tip_m = s.planet.gear ? gear_dimensions(*s.planet.gear).tip_radius_m : s.planet.mesh->recognised->tip_radius_m;
  g.adjacency_clearance_m = 2 * a * std::sin(kPi / s.count) - 2 * planet_tip_m;
  phase_planetary({teeth_of(s.sun), teeth_of(s.planet), teeth_of(s.ring), s.count, tooth0_of_member(s.sun), tooth0_of_member(s.planet),
                   tooth0_of_member(s.ring)},
                  g);
  return g;
}

// The set's geometry: from its shapes (shapes_geometry, which adds the two pairs' tables) or from
// its spec, refused (naming `ring`) when the spec's members cannot be assembled.
PlanetaryGeometry set_geometry(const YamlMap& m, const PlanetaryMembers& s, bool shapes, std::vector<physics::PairTableDef>& tables) {
  PlanetaryGeometry g;
  if (shapes) {
    g = shapes_geometry(m, s, tables);
  } else {
    try {
      g = analyse_planetary(*s.spec);
    } catch (const InputError& e) {
      m.fail("ring", std::string("sun, planets and ring cannot be assembled: ") + e.what());
    }
  }
  return g;
}

// Refuses (naming `planets`) a planet count that cannot be equally spaced or whose planets overlap.
void check_assembly(const YamlMap& m, const PlanetaryMembers& s, const PlanetaryGeometry& g) {
  const int zs = teeth_of(s.sun), zr = teeth_of(s.ring);
  if (!g.equally_spaced_assembly) {
    std::ostringstream msg;
    msg << "(z_s + z_r)/N = (" << zs << " + " << zr << ")/" << s.count << " = " << g.assembly_quotient
        << " is not a whole number: " << s.count << " equally spaced planets cannot all mesh with sun and ring (phase mismatch "
        << g.phase_mismatch_teeth << " teeth); choose N dividing z_s + z_r";
    m.fail("planets", msg.str());
  }
  if (g.adjacency_clearance_m <= 0) {
    std::ostringstream msg;
    msg << s.count << " planets on a " << g.centre_distance_m * 1e3 << " mm centre distance overlap: "
        << "their tip circles are " << -g.adjacency_clearance_m * 1e3 << " mm too close";
    m.fail("planets", msg.str());
  }
}

// The members' compliant supports (`supports:`, and the older `floating_sun:`, a sun's radial
// bearing): none given, a rigid hinge (or a welded fixed ring).
struct Supports {
  std::optional<physics::BearingDef> sun, planets, ring, carrier;
};

Supports parse_supports(const YamlMap& m) {
  Supports s;
  if (given(m, "floating_sun")) {
    const YamlMap b = m.map("floating_sun");
    s.sun = physics::BearingDef{number_within(b, "radial_stiffness_N_per_m", limits::kStiffness_N_per_m),
                                number_within_or(b, "radial_damping_N_s_per_m", 0.0, limits::kDamping_N_s_per_m), 0, 0};
    b.reject_unknown_keys();
  }
  if (!given(m, "supports")) return s;
  const YamlMap sup = m.map("supports");
  if (given(sup, "sun")) {
    if (s.sun) sup.fail("sun", "the sun's support is given twice: here and as floating_sun");
    s.sun = parse_bearing(sup.map("sun"));
  }
  if (given(sup, "planets")) s.planets = parse_bearing(sup.map("planets"));
  if (given(sup, "ring")) s.ring = parse_bearing(sup.map("ring"));
  if (given(sup, "carrier")) s.carrier = parse_bearing(sup.map("carrier"));
  sup.reject_unknown_keys();
  return s;
}

}  // namespace

Expansion expand_planetary(const YamlMap& m, const fs::path& dir) {
  // Members as mappings (shapes) or as names in a spec: all one way.
  const int shapes = m.has_map("sun") + m.has_map("planet") + m.has_map("ring");
  if (shapes != 0 && shapes != 3)
    m.fail_here("give sun, planet and ring all as gear names of `spec`, or all as shapes (mesh:, gear: or gear_from:)");
  PlanetaryMembers s = shapes ? members_from_shapes(m, dir) : members_from_spec(m, dir);
  const YamlMap c = m.map("carrier");
  const double carrier_mass_kg = number_within(c, "mass_kg", limits::kMass_kg);
  const double carrier_jz = number_within(c, "inertia_z_kg_m2", limits::kInertia_kg_m2);
  c.reject_unknown_keys();
  const Supports supports = parse_supports(m);
  // Which member stands: the ring (the default), the carrier (a star stage), the sun, or none.
  // `ring_fixed: false` is the older spelling of `fixed: none`.
  if (m.has("fixed") && m.has("ring_fixed")) m.fail("ring_fixed", "give fixed: ring|carrier|sun|none, not also ring_fixed");
  const std::string fixed = m.has("ring_fixed") ? (m.boolean_or("ring_fixed", true) ? "ring" : "none")
                                                : m.choice_or("fixed", {"ring", "carrier", "sun", "none"}, "ring");
  const bool ring_fixed = fixed == "ring";
  if (fixed == "carrier" && supports.carrier)
    m.map("supports").fail("carrier", "a fixed carrier is welded to the ground: no support (or fixed: none)");
  if (fixed == "sun" && supports.sun)
    m.fail(m.has("floating_sun") ? "floating_sun" : "supports", "a fixed sun is welded to the ground: no support (or fixed: none)");
  if (ring_fixed && supports.ring && !(supports.ring->torsional_stiffness_N_m_per_rad > 0))
    m.map("supports")
        .map("ring")
        .fail("torsional_stiffness_N_m_per_rad",
              "a fixed ring on a bearing is held against rotation by its torsional spring: expected a stiffness > 0 in N·m/rad "
              "(or ring_fixed: false for a ring free to turn)");
  const Eigen::Vector3d origin = vec3_within_or(m, "origin_m", Eigen::Vector3d::Zero(), limits::kPosition_m);
  std::vector<physics::PairTableDef> tables;
  // The set's geometry last: the mesh analysis is the slow part.
  const PlanetaryGeometry g = set_geometry(m, s, shapes != 0, tables);
  m.reject_unknown_keys();
  check_assembly(m, s, g);

  Expansion e;
  e.gearset_spec = s.spec_file;
  if (s.spec) {
    e.planetary = physics::PlanetaryTrainDef{*s.spec, {}, ring_fixed};
    for (const physics::BodyDef& p : s.planets) e.planetary->planet_gears.push_back(*p.gear);
  }
  e.pair_tables = tables;
  auto place = [&](physics::BodyDef b, const Eigen::Vector3d& at, double angle_rad) {
    b.pose.position_m = at;
    b.pose.orientation = about_z(angle_rad);
    e.bodies.push_back(std::move(b));
  };
  place(s.sun, origin, 0.0);
  e.bodies.back().fixed = fixed == "sun";
  if (fixed != "sun") {
    e.joints.push_back(hinge("sun", "ground", origin));
    e.joints.back().bearing = supports.sun;
  }
  if (fixed != "carrier") {
    e.joints.push_back(hinge("carrier", "ground", origin));  // before the planets it carries
    e.joints.back().bearing = supports.carrier;
  }
  physics::BodyDef carrier;
  carrier.name = "carrier";
  carrier.mass_kg = carrier_mass_kg;
  // Shapeless carrier: a thin disc's moments, J_x = J_y = J_z/2, about the sun axis.
  carrier.principal_inertia_kg_m2 = Eigen::Vector3d(carrier_jz / 2, carrier_jz / 2, carrier_jz);
  carrier.pose.position_m = origin;
  carrier.fixed = fixed == "carrier";
  for (int k = 0; k < s.count; ++k) {
    const PlanetPlacement& p = g.placements[static_cast<std::size_t>(k)];
    const physics::BodyDef& planet = s.planets[static_cast<std::size_t>(k)];
    const Eigen::Vector3d centre =
        origin + g.centre_distance_m * Eigen::Vector3d(std::cos(p.carrier_angle_rad), std::sin(p.carrier_angle_rad), 0);
    // The spin places the planet's tooth 0 as the phasing placed the healthy planet's.
    place(planet, centre, p.spin_angle_rad + tooth0_of_member(s.planet) - tooth0_of_member(planet));
    e.joints.push_back(hinge(planet.name, "carrier", centre));
    e.joints.back().bearing = supports.planets;
  }
  place(s.ring, origin, g.ring_angle_rad);
  // A fixed ring is welded to the ground, or held by its support's springs when it has one.
  e.bodies.back().fixed = ring_fixed && !supports.ring;
  if (!e.bodies.back().fixed) {
    e.joints.push_back(hinge("ring", "ground", origin));
    e.joints.back().bearing = supports.ring;
  }
  e.bodies.push_back(carrier);
  // Willis, ω_s − ω_c = −(z_r/z_s)·(ω_r − ω_c). Ring fixed: sun in, carrier out,
  // θ_sun = (1 + z_r/z_s)·θ_carrier. Carrier fixed (star): sun in, ring out, θ_sun = −(z_r/z_s)·θ_ring.
  // Sun fixed: ring in, carrier out, θ_ring = (1 + z_s/z_r)·θ_carrier.
  const double zs = teeth_of(s.sun), zr = teeth_of(s.ring);
  if (ring_fixed) e.transmission = physics::TransmissionDef{"sun", "carrier", g.ratio_sun_to_carrier};
  if (fixed == "carrier") e.transmission = physics::TransmissionDef{"sun", "ring", -zr / zs};
  if (fixed == "sun") e.transmission = physics::TransmissionDef{"ring", "carrier", 1 + zs / zr};
  return e;
}

}  // namespace gearsim::input::scenario_detail

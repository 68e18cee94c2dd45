// Scenario macros: `planetary` and `pair` expand into plain bodies and hinges placed so that
// every mesh engages (tooth centred in the mating gap), plus the ideal transmission.
#include <charconv>
#include <cmath>
#include <numbers>
#include <sstream>

#include "app/gear_train.hpp"
#include "app/gearset_file.hpp"
#include "app/input_limits.hpp"
#include "app/safe_name.hpp"
#include "app/scenario_parts.hpp"
#include "geometry/errors.hpp"
#include "geometry/gear_dimensions.hpp"
#include "geometry/involute_pair.hpp"
#include "geometry/planetary.hpp"
#include "physics/world.hpp"
#include "geometry/constants.hpp"

namespace gearsim::app::scenario_detail {
namespace {

namespace fs = std::filesystem;
using gearsim::constants::kPi;

Eigen::Quaterniond about_z(double angle_rad) {
  return Eigen::Quaterniond(Eigen::AngleAxisd(angle_rad, Eigen::Vector3d::UnitZ()));
}

// The gear called m[key] (or `fallback` when the key is absent and fallback is not empty).
const GearSpec& named_gear(const YamlMap& m, const std::string& key, const GearSetFile& f,
                           const std::string& fallback) {
  const std::string name = fallback.empty() ? m.string(key) : m.string_or(key, fallback);
  std::string names;
  for (const GearSpec& g : f.gears) {
    if (g.name == name) return g;
    names += (names.empty() ? "" : ", ") + g.name;
  }
  m.fail(key, "no gear named '" + name + "' in " + f.path.string() + " (it has: " + names + ")");
}

physics::JointDef hinge(const std::string& name, const std::string& parent, const Eigen::Vector3d& pivot_m) {
  physics::JointDef j;
  j.name = name;
  j.body = name;
  j.parent = parent;
  j.pivot_m = pivot_m;
  return j;  // axis +z
}

// faulty_planets: {index: gear}; every other planet is the train's planet gear.
std::vector<const GearSpec*> planet_gears(const YamlMap& m, const GearSetFile& f, const GearSpec& planet, int n) {
  std::vector<const GearSpec*> gears(static_cast<std::size_t>(n), &planet);
  if (!given(m, "faulty_planets")) return gears;  // absent or null: all healthy
  const YamlMap fp = m.map("faulty_planets");
  for (const std::string& key : fp.keys()) {
    int k = -1;
    const auto [end, ec] = std::from_chars(key.data(), key.data() + key.size(), k);
    if (ec != std::errc() || end != key.data() + key.size() || k < 0 || k >= n)
      fp.fail(key, "expected a planet index 0.." + std::to_string(n - 1) + " as the key");
    const GearSpec& g = named_gear(fp, key, f, "");
    if (g.kind != planet.kind || g.teeth != planet.teeth || g.module_m != planet.module_m ||
        g.pressure_angle_rad != planet.pressure_angle_rad || g.profile_shift != planet.profile_shift)
      fp.fail(key, "gear '" + g.name + "' cannot take planet " + key + "'s place: its kind, teeth, module, "
                   "pressure angle and profile shift must equal those of '" + planet.name + "'");
    gears[static_cast<std::size_t>(k)] = &g;
  }
  return gears;
}

// The involutes of a gear body: its spec's, or recognised from its mesh; none (and why) when the
// mesh shows no single involute (not a gear, flanks off the involute, asymmetric teeth).
std::optional<InvoluteTeeth> involutes_of(const physics::BodyDef& b, std::string& why) {
  if (b.gear) return involute_teeth(*b.gear);
  const physics::MeshSource& mesh = *b.mesh;
  if (mesh.recognised && mesh.recognised->involute) return involute_teeth(*mesh.recognised);
  std::ostringstream msg;
  msg << mesh.path.string();
  if (!mesh.recognised)
    msg << ": not recognised as a gear";
  else if (mesh.recognised->asymmetric)
    msg << ": its teeth are asymmetric (the two flank sides fit involutes of base radii "
        << mesh.recognised->ccw.base_radius_m * 1e3 << " and " << mesh.recognised->cw.base_radius_m * 1e3 << " mm)";
  else
    msg << ": its flanks are not recognised involutes";
  why = msg.str();
  return std::nullopt;
}

// The gear-table figures of gears a and b (a external) at `centre_distance_m` (≤ 0: their
// zero-backlash distance), refused (naming centre_distance_m, or `key` when it was derived) when
// the involutes cannot act there, the teeth overlap or the tips do not reach the line of action.
physics::PairTableDef checked_pair_table(const YamlMap& m, const std::string& a, const std::string& b, const InvoluteTeeth& ta,
                                         const InvoluteTeeth& tb, double centre_distance_m, bool derived, const std::string& key) {
  physics::PairTableDef table{a, b, derived, {}};
  try {
    table.figures = involute_pair(ta, tb, centre_distance_m, "pair '" + a + "'–'" + b + "'");
  } catch (const InputError& e) {
    m.fail(derived ? key : "centre_distance_m", e.what());
  }
  const double c = table.figures.centre_distance_m;
  if (table.figures.normal_backlash_m < -physics::World::kStartOverlapLimit_m) {
    std::ostringstream msg;
    msg << "'" << a << "'–'" << b << "': at " << c * 1e3 << " mm the teeth overlap by " << -table.figures.normal_backlash_m * 1e6
        << " um along the line of action (zero backlash at " << table.figures.zero_backlash_centre_distance_m * 1e3 << " mm)";
    m.fail(derived ? key : "centre_distance_m", msg.str());
  }
  if (!(table.figures.contact_ratio > 0)) {
    std::ostringstream msg;
    msg << "'" << a << "'–'" << b << "': at " << c * 1e3 << " mm the tips do not reach the line of action (contact ratio "
        << table.figures.contact_ratio << ")";
    m.fail(derived ? key : "centre_distance_m", msg.str());
  }
  return table;
}

}  // namespace

namespace {

// A planetary set's members before they are placed: from a gear-set spec (members named) or from
// shapes (CAD meshes, gear or gear_from; members given as mappings).
struct PlanetaryMembers {
  physics::BodyDef sun, planet, ring;           // unplaced; planet as planet_0
  std::vector<physics::BodyDef> planets;        // planet_0..: the spec's faulty ones in their place
  std::optional<PlanetarySpec> spec;            // spec members
  fs::path spec_file;
  InvoluteTeeth sun_teeth, planet_teeth, ring_teeth;  // shape members
  int count = 0;
};

physics::BodyDef spec_body(const std::string& name, const GearSpec& gear, double density) {
  physics::BodyDef b;
  b.name = name;
  b.gear = gear;
  b.density_kg_m3 = density;
  return b;
}

PlanetaryMembers members_from_spec(const YamlMap& m, const fs::path& dir) {
  PlanetaryMembers s;
  s.spec_file = resolve(dir, m.string("spec"));
  if (std::error_code ec; !fs::is_regular_file(s.spec_file, ec)) m.fail("spec", "gear-set spec file not found: " + s.spec_file.string());
  const GearSetFile f = load_gearset(s.spec_file);
  // Gear names and planet count default to the spec's planetary train.
  const auto& t = f.planetary;
  // The planet count is checked before planet_gears allocates a slot per planet.
  s.count = t ? integer_within_or(m, "planets", t->planets, limits::kPlanets) : integer_within(m, "planets", limits::kPlanets);
  s.spec = PlanetarySpec{named_gear(m, "sun", f, t ? t->sun.name : ""), named_gear(m, "planet", f, t ? t->planet.name : ""),
                         named_gear(m, "ring", f, t ? t->ring.name : ""), s.count};
  s.sun = spec_body("sun", s.spec->sun, f.density_kg_m3);
  s.planet = spec_body("planet_0", s.spec->planet, f.density_kg_m3);
  s.ring = spec_body("ring", s.spec->ring, f.density_kg_m3);
  int k = 0;
  for (const GearSpec* g : planet_gears(m, f, s.spec->planet, s.count))
    s.planets.push_back(spec_body("planet_" + std::to_string(k++), *g, f.density_kg_m3));
  return s;
}

// A member given as a shape: `internal` says which kind it must be.
physics::BodyDef shape_member(const YamlMap& m, const std::string& key, bool internal, const fs::path& dir) {
  const YamlMap s = m.map(key);
  physics::BodyDef b;
  b.name = key;
  parse_shape_and_mass(s, b, dir);
  s.reject_unknown_keys();
  if (!b.gear && !b.mesh) s.fail_here("a planetary member needs a shape: gear, gear_from or mesh");
  if (teeth_of(b) == 0) s.fail_here("a planetary member needs teeth (teeth: none cannot mesh)");
  if (is_internal(b) != internal)
    s.fail_here(internal ? "the ring must be an internal gear" : "the " + key + " must be an external gear");
  return b;
}

// The involutes of a member, refused naming it when its mesh shows none.
InvoluteTeeth member_involutes(const YamlMap& m, const std::string& key, const physics::BodyDef& b) {
  std::string why;
  const std::optional<InvoluteTeeth> t = involutes_of(b, why);
  if (!t) m.fail(key, why + ", so the set's meshes cannot be checked or placed");
  return *t;
}

PlanetaryMembers members_from_shapes(const YamlMap& m, const fs::path& dir) {
  PlanetaryMembers s;
  s.count = integer_within(m, "planets", limits::kPlanets);
  s.sun = shape_member(m, "sun", false, dir);
  s.planet = shape_member(m, "planet", false, dir);
  s.ring = shape_member(m, "ring", true, dir);
  s.sun_teeth = member_involutes(m, "sun", s.sun);
  s.planet_teeth = member_involutes(m, "planet", s.planet);
  s.ring_teeth = member_involutes(m, "ring", s.ring);
  for (int k = 0; k < s.count; ++k) {
    s.planets.push_back(s.planet);
    s.planets.back().name = "planet_" + std::to_string(k);
  }
  return s;
}

// Polar angle of tooth 0 in a member's own frame, rad.
double tooth0_of_member(const physics::BodyDef& b) {
  return b.gear ? b.gear->tooth0_angle_rad : b.mesh->teeth->tooth0_angle_rad;
}

// The geometry of a set of shapes: the centre distance (given, or midway between the sun–planet
// and planet–ring zero-backlash distances), both meshes checked there, the phasing.
PlanetaryGeometry shapes_geometry(const YamlMap& m, const PlanetaryMembers& s, std::vector<physics::PairTableDef>& tables) {
  const bool derived = !m.has("centre_distance_m");
  double a = derived ? 0.0 : positive(m, "centre_distance_m", "centre distance in m");
  if (derived) {
    double a_sp = 0, a_pr = 0;
    try {
      a_sp = involute_pair(s.sun_teeth, s.planet_teeth, 0.0, "sun–planet").zero_backlash_centre_distance_m;
      a_pr = involute_pair(s.planet_teeth, s.ring_teeth, 0.0, "planet–ring").zero_backlash_centre_distance_m;
    } catch (const InputError& e) {
      m.fail("ring", e.what());
    }
    // Sun–planet backlash grows with the distance, planet–ring backlash shrinks.
    if (a_sp > a_pr + 1e-9) {
      std::ostringstream msg;
      msg << "no centre distance meshes both: sun–planet needs at least " << a_sp * 1e3 << " mm (zero backlash), "
          << "planet–ring at most " << a_pr * 1e3 << " mm";
      m.fail("ring", msg.str());
    }
    a = 0.5 * (a_sp + a_pr);
  }
  tables.push_back(checked_pair_table(m, "sun", "planet_0", s.sun_teeth, s.planet_teeth, a, derived, "ring"));
  tables.push_back(checked_pair_table(m, "planet_0", "ring", s.planet_teeth, s.ring_teeth, a, derived, "ring"));
  PlanetaryGeometry g;
  g.centre_distance_m = a;
  g.ratio_sun_to_carrier = 1.0 + static_cast<double>(s.ring_teeth.teeth) / s.sun_teeth.teeth;
  const double planet_tip_m = s.planet.gear ? gear_dimensions(*s.planet.gear).tip_radius_m : s.planet.mesh->recognised->tip_radius_m;
  g.adjacency_clearance_m = 2 * a * std::sin(kPi / s.count) - 2 * planet_tip_m;
  phase_planetary({s.sun_teeth.teeth, s.planet_teeth.teeth, s.ring_teeth.teeth, s.count, tooth0_of_member(s.sun),
                   tooth0_of_member(s.planet), tooth0_of_member(s.ring)},
                  g);
  return g;
}

}  // namespace

Expansion expand_planetary(const YamlMap& m, const fs::path& dir) {
  // Members as mappings (shapes) or as names in a spec: all one way.
  const int shapes = m.has_map("sun") + m.has_map("planet") + m.has_map("ring");
  if (shapes != 0 && shapes != 3)
    m.fail_here("give sun, planet and ring all as gear names of `spec`, or all as shapes (mesh:, gear: or gear_from:)");
  PlanetaryMembers s = shapes ? members_from_shapes(m, dir) : members_from_spec(m, dir);
  const YamlMap c = m.map("carrier");
  const double carrier_mass_kg = positive(c, "mass_kg", "carrier mass in kg");
  const double carrier_jz = positive(c, "inertia_z_kg_m2", "carrier moment of inertia in kg·m²");
  c.reject_unknown_keys();
  std::optional<physics::BearingDef> floating;
  if (given(m, "floating_sun")) {
    const YamlMap b = m.map("floating_sun");
    floating = physics::BearingDef{positive(b, "radial_stiffness_N_per_m", "stiffness in N/m"),
                                   b.number_or("radial_damping_N_s_per_m", 0.0)};
    if (floating->radial_damping_N_s_per_m < 0) b.fail("radial_damping_N_s_per_m", "expected a damping ≥ 0 in N·s/m");
    b.reject_unknown_keys();
  }
  const bool ring_fixed = m.boolean_or("ring_fixed", true);
  const Eigen::Vector3d origin = vec3_or(m, "origin_m", Eigen::Vector3d::Zero());
  std::vector<physics::PairTableDef> tables;
  // The set's geometry last: the mesh analysis is the slow part.
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
  m.reject_unknown_keys();
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
  e.joints.push_back(hinge("sun", "ground", origin));
  e.joints.back().bearing = floating;
  e.joints.push_back(hinge("carrier", "ground", origin));  // before the planets it carries
  physics::BodyDef carrier;
  carrier.name = "carrier";
  carrier.mass_kg = carrier_mass_kg;
  // Shapeless carrier: a thin disc's moments, J_x = J_y = J_z/2, about the sun axis.
  carrier.principal_inertia_kg_m2 = Eigen::Vector3d(carrier_jz / 2, carrier_jz / 2, carrier_jz);
  carrier.pose.position_m = origin;
  for (int k = 0; k < s.count; ++k) {
    const PlanetPlacement& p = g.placements[static_cast<std::size_t>(k)];
    const physics::BodyDef& planet = s.planets[static_cast<std::size_t>(k)];
    const Eigen::Vector3d centre = origin + g.centre_distance_m * Eigen::Vector3d(std::cos(p.carrier_angle_rad),
                                                                                  std::sin(p.carrier_angle_rad), 0);
    // The spin places the planet's tooth 0 as the phasing placed the healthy planet's.
    place(planet, centre, p.spin_angle_rad + tooth0_of_member(s.planet) - tooth0_of_member(planet));
    e.joints.push_back(hinge(planet.name, "carrier", centre));
  }
  place(s.ring, origin, g.ring_angle_rad);
  e.bodies.back().fixed = ring_fixed;
  if (!ring_fixed) e.joints.push_back(hinge("ring", "ground", origin));
  e.bodies.push_back(carrier);
  // Ring fixed, sun in, carrier out: θ_sun = (1 + z_r/z_s)·θ_carrier (Willis).
  if (ring_fixed) e.transmission = physics::TransmissionDef{"sun", "carrier", g.ratio_sun_to_carrier};
  return e;
}

namespace {

physics::BodyDef pair_member(const YamlMap& m, const std::string& fallback_name, const fs::path& dir) {
  physics::BodyDef b;
  b.name = m.string_or("name", fallback_name);
  require_safe_name(m, "name", b.name, NameUse::Body);
  parse_shape_and_mass(m, b, dir);
  m.reject_unknown_keys();
  if (!b.gear && !b.mesh) m.fail_here("a pair member needs a shape: gear, gear_from or mesh");
  if (b.mesh && !b.mesh->teeth) m.fail("mesh", "a toothless mesh (teeth: none) cannot be a pair member");
  return b;
}

double tooth0_of(const physics::BodyDef& b) {
  return b.gear ? b.gear->tooth0_angle_rad : b.mesh->teeth->tooth0_angle_rad;
}

}  // namespace

Expansion expand_pair(const YamlMap& m, const fs::path& dir) {
  physics::BodyDef a = pair_member(m.map("driver"), "driver", dir);
  physics::BodyDef b = pair_member(m.map("driven"), "driven", dir);
  if (a.name == b.name) m.fail("driven", "driver and driven have the same name '" + a.name + "'");
  // An internal pair: a pinion inside a ring, either of them the driver. The mesh figures take
  // the external gear first (ext, in).
  const bool internal = is_internal(a) || is_internal(b);
  if (is_internal(a) && is_internal(b)) m.fail("driven", "two internal gears cannot mesh");
  const physics::BodyDef& ext = is_internal(a) ? b : a;
  const physics::BodyDef& in = is_internal(a) ? a : b;
  const char* ext_key = is_internal(a) ? "driven" : "driver";
  const char* in_key = is_internal(a) ? "driver" : "driven";
  double centre_distance_m = 0;
  std::optional<physics::PairTableDef> table;
  if (a.gear && b.gear) {
    // Generated gears: the zero-backlash distance unless given; either way the mesh must work.
    try {
      centre_distance_m = m.number_or("centre_distance_m", zero_backlash_centre_distance(*ext.gear, *in.gear));
      analyse_mesh(*ext.gear, *in.gear, centre_distance_m);
    } catch (const InputError& e) {
      m.fail(m.has("centre_distance_m") ? "centre_distance_m" : "driven", e.what());
    }
  } else {
    // A mesh member: its recognised involutes give the same figures (without them the centre
    // distance must be given, and the start checks alone judge the mesh).
    std::string why;
    const std::optional<InvoluteTeeth> te = involutes_of(ext, why);
    if (!te && !m.has("centre_distance_m")) m.fail(ext_key, why + ", so the centre distance cannot be derived: give centre_distance_m");
    const std::optional<InvoluteTeeth> ti = involutes_of(in, why);
    if (!ti && !m.has("centre_distance_m")) m.fail(in_key, why + ", so the centre distance cannot be derived: give centre_distance_m");
    centre_distance_m = m.number_or("centre_distance_m", 0.0);
    if (te && ti) {
      table = checked_pair_table(m, a.name, b.name, *te, *ti, centre_distance_m, !m.has("centre_distance_m"), "driven");
      centre_distance_m = table->figures.centre_distance_m;
    }
  }
  if (!(centre_distance_m > 0)) m.fail("centre_distance_m", "expected a positive centre distance in m");
  const Eigen::Vector3d origin = vec3_or(m, "origin_m", Eigen::Vector3d::Zero());
  m.reject_unknown_keys();

  // Placing: external, the driver at the origin and the driven on +x; internal, the ring at the
  // origin and the pinion on +x. The pitch point lies on the line of centres, seen from each
  // centre in direction phi: external +x from the driver and −x (π) from the driven; internal
  // +x from both. Tooth fractions f there (0 at a tooth centre, ½ in a gap) satisfy
  // f_driver + f_driven ≡ ½ externally (see planetary.cpp); internally the two turn the same way
  // and f_ring − f_pinion ≡ ½ (a pinion tooth in a ring gap). b is turned to match a.
  const double za = teeth_of(a), zb = teeth_of(b);
  const double phi_a = 0.0, phi_b = internal ? 0.0 : kPi;
  const double fa = (phi_a - tooth0_of(a)) * za / (2 * kPi);
  const double fa01 = fa - std::floor(fa), fb = internal ? fa01 + 0.5 : 0.5 - fa01;
  const double spin_b = phi_b - tooth0_of(b) - (fb - std::floor(fb)) * 2 * kPi / zb;
  const Eigen::Vector3d beside = origin + Eigen::Vector3d(centre_distance_m, 0, 0);
  a.pose.position_m = internal && !is_internal(a) ? beside : origin;
  b.pose.position_m = internal && is_internal(b) ? origin : beside;
  b.pose.orientation = about_z(spin_b);
  Expansion e;
  e.joints = {hinge(a.name, "ground", a.pose.position_m), hinge(b.name, "ground", b.pose.position_m)};
  // With te = θ_input − ratio·θ_output: an external pair turns opposite ways, θ_driver =
  // −(z_driven/z_driver)·θ_driven (ratio < 0); an internal one the same way (ratio > 0).
  e.transmission = physics::TransmissionDef{a.name, b.name, (internal ? zb : -zb) / za};
  e.bodies = {a, b};
  if (table) e.pair_tables.push_back(*table);
  return e;
}

}  // namespace gearsim::app::scenario_detail

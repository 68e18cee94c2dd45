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

}  // namespace

Expansion expand_planetary(const YamlMap& m, const fs::path& dir) {
  const fs::path spec = resolve(dir, m.string("spec"));
  if (!fs::is_regular_file(spec)) m.fail("spec", "gear-set spec file not found: " + spec.string());
  const GearSetFile f = load_gearset(spec);
  // Gear names and planet count default to the spec's planetary train.
  const auto& t = f.planetary;
  // The planet count is checked before planet_gears allocates a slot per planet.
  const int planet_count =
      t ? integer_within_or(m, "planets", t->planets, limits::kPlanets) : integer_within(m, "planets", limits::kPlanets);
  PlanetarySpec ps{named_gear(m, "sun", f, t ? t->sun.name : ""), named_gear(m, "planet", f, t ? t->planet.name : ""),
                   named_gear(m, "ring", f, t ? t->ring.name : ""), planet_count};
  const std::vector<const GearSpec*> planets = planet_gears(m, f, ps.planet, ps.planets);
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
  m.reject_unknown_keys();

  // The set's geometry last: the mesh analysis is the slow part.
  PlanetaryGeometry g;
  try {
    g = analyse_planetary(ps);
  } catch (const InputError& e) {
    m.fail("ring", std::string("sun, planets and ring cannot be assembled: ") + e.what());
  }
  if (!g.equally_spaced_assembly) {
    std::ostringstream msg;
    msg << "(z_s + z_r)/N = (" << ps.sun.teeth << " + " << ps.ring.teeth << ")/" << ps.planets << " = "
        << g.assembly_quotient << " is not a whole number: " << ps.planets
        << " equally spaced planets cannot all mesh with sun and ring (phase mismatch " << g.phase_mismatch_teeth
        << " teeth); choose N dividing z_s + z_r";
    m.fail("planets", msg.str());
  }
  if (g.adjacency_clearance_m <= 0) {
    std::ostringstream msg;
    msg << ps.planets << " planets on a " << g.centre_distance_m * 1e3 << " mm centre distance overlap: "
        << "their tip circles are " << -g.adjacency_clearance_m * 1e3 << " mm too close";
    m.fail("planets", msg.str());
  }

  Expansion e;
  e.gearset_spec = spec;
  e.planetary = physics::PlanetaryTrainDef{ps, {}, ring_fixed};
  for (const GearSpec* pg : planets) e.planetary->planet_gears.push_back(*pg);
  auto gear_body = [&](const std::string& name, const GearSpec& gear, const Eigen::Vector3d& at, double angle_rad) {
    physics::BodyDef b;
    b.name = name;
    b.gear = gear;
    b.density_kg_m3 = f.density_kg_m3;
    b.pose.position_m = at;
    b.pose.orientation = about_z(angle_rad);
    e.bodies.push_back(b);
  };
  gear_body("sun", ps.sun, origin, 0.0);
  e.joints.push_back(hinge("sun", "ground", origin));
  e.joints.back().bearing = floating;
  e.joints.push_back(hinge("carrier", "ground", origin));  // before the planets it carries
  physics::BodyDef carrier;
  carrier.name = "carrier";
  carrier.mass_kg = carrier_mass_kg;
  // Shapeless carrier: a thin disc's moments, J_x = J_y = J_z/2, about the sun axis.
  carrier.principal_inertia_kg_m2 = Eigen::Vector3d(carrier_jz / 2, carrier_jz / 2, carrier_jz);
  carrier.pose.position_m = origin;
  for (int k = 0; k < ps.planets; ++k) {
    const PlanetPlacement& p = g.placements[static_cast<std::size_t>(k)];
    const GearSpec& gear = *planets[static_cast<std::size_t>(k)];
    const Eigen::Vector3d centre = origin + g.centre_distance_m * Eigen::Vector3d(std::cos(p.carrier_angle_rad),
                                                                                  std::sin(p.carrier_angle_rad), 0);
    // The spin places the planet's tooth 0 as analyse_planetary placed the healthy planet's.
    const std::string name = "planet_" + std::to_string(k);
    gear_body(name, gear, centre, p.spin_angle_rad + ps.planet.tooth0_angle_rad - gear.tooth0_angle_rad);
    e.joints.push_back(hinge(name, "carrier", centre));
  }
  gear_body("ring", ps.ring, origin, g.ring_angle_rad);
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
    // A mesh member: its recognised involutes give the same figures.
    auto teeth = [&](const physics::BodyDef& x, const char* key) {
      if (x.gear) return involute_teeth(*x.gear);
      if (!x.mesh->recognised || !x.mesh->recognised->involute) {
        if (!m.has("centre_distance_m"))
          m.fail(key, x.mesh->path.string() + ": its flanks are not recognised involutes, so the centre distance "
                      "cannot be derived: give centre_distance_m");
        return InvoluteTeeth{};
      }
      return involute_teeth(*x.mesh->recognised);
    };
    const InvoluteTeeth te = teeth(ext, ext_key), ti = teeth(in, in_key);
    centre_distance_m = m.number_or("centre_distance_m", 0.0);
    if (te.teeth > 0 && ti.teeth > 0) {
      table = physics::PairTableDef{a.name, b.name, !m.has("centre_distance_m"), {}};
      try {
        table->figures = involute_pair(te, ti, centre_distance_m, "pair '" + a.name + "'–'" + b.name + "'");
      } catch (const InputError& e) {
        m.fail(m.has("centre_distance_m") ? "centre_distance_m" : "driven", e.what());
      }
      centre_distance_m = table->figures.centre_distance_m;
      if (table->figures.normal_backlash_m < -physics::World::kStartOverlapLimit_m) {
        std::ostringstream msg;
        msg << "at " << centre_distance_m * 1e3 << " mm the teeth overlap by " << -table->figures.normal_backlash_m * 1e6
            << " um along the line of action (zero backlash at " << table->figures.zero_backlash_centre_distance_m * 1e3
            << " mm)";
        m.fail("centre_distance_m", msg.str());
      }
      if (!(table->figures.contact_ratio > 0)) {
        std::ostringstream msg;
        msg << "at " << centre_distance_m * 1e3 << " mm the tips do not reach the line of action (contact ratio "
            << table->figures.contact_ratio << ")";
        m.fail("centre_distance_m", msg.str());
      }
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

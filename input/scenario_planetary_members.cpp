// The planetary macro's members before they are placed: sun, planet and ring named in a gear-set
// spec (with faulty planets in their places) or given as shapes (gear, gear_from or a CAD mesh),
// checked to be gears of the right kind with involutes. Not their placing (scenario_planetary.cpp).
#include <charconv>
#include <string>
#include <vector>

#include "input/gear_train.hpp"
#include "input/gearset_file.hpp"
#include "input/input_limits.hpp"
#include "input/scenario_macros_detail.hpp"

namespace gearsim::input::scenario_detail {
namespace {

namespace fs = std::filesystem;

// The gear called m[key] (or `fallback` when the key is absent and fallback is not empty).
const GearSpec& named_gear(const YamlMap& m, const std::string& key, const GearSetFile& f, const std::string& fallback) {
  const std::string name = fallback.empty() ? m.string(key) : m.string_or(key, fallback);
  std::string names;
  for (const GearSpec& g : f.gears) {
    if (g.name == name) return g;
    names += (names.empty() ? "" : ", ") + g.name;
  }
  m.fail(key, "no gear named '" + name + "' in " + f.path.string() + " (it has: " + names + ")");
}

// faulty_planets: {index: gear} or {index: {gear: name, errors: {...}}} (the named spec gear with
// these errors instead of its own: a fault depth a sweep can vary); every other planet is the
// train's planet gear.
std::vector<GearSpec> planet_gears(const YamlMap& m, const GearSetFile& f, const GearSpec& planet, int n) {
  std::vector<GearSpec> gears(static_cast<std::size_t>(n), planet);
  if (!given(m, "faulty_planets")) return gears;  // absent or null: all healthy
  const YamlMap fp = m.map("faulty_planets");
  for (const std::string& key : fp.keys()) {
    int k = -1;
    const auto [end, ec] = std::from_chars(key.data(), key.data() + key.size(), k);
    if (ec != std::errc() || end != key.data() + key.size() || k < 0 || k >= n)
      fp.fail(key, "expected a planet index 0.." + std::to_string(n - 1) + " as the key");
    GearSpec g;
    if (fp.has_map(key)) {
      const YamlMap entry = fp.map(key);
      g = named_gear(entry, "gear", f, "");
      g.errors = entry.has("errors") ? parse_gear_errors(entry.map("errors")) : GearErrors{};
      g.name += "_planet" + key;  // its own gear: not the spec's of that name
      entry.reject_unknown_keys();
      try {
        validate_gear_spec(g);
      } catch (const InputError& e) {
        entry.fail("errors", e.what());
      }
    } else {
      g = named_gear(fp, key, f, "");
    }
    if (g.kind != planet.kind || g.teeth != planet.teeth || g.module_m != planet.module_m ||
        g.pressure_angle_rad != planet.pressure_angle_rad || g.profile_shift != planet.profile_shift)
      fp.fail(key, "gear '" + g.name + "' cannot take planet " + key +
                       "'s place: its kind, teeth, module, "
                       "pressure angle and profile shift must equal those of '" +
                       planet.name + "'");
    gears[static_cast<std::size_t>(k)] = g;
  }
  return gears;
}

physics::BodyDef spec_body(const std::string& name, const GearSpec& gear, double density) {
  physics::BodyDef b;
  b.name = name;
  b.gear = gear;
  b.density_kg_m3 = density;
  return b;
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
  if (is_internal(b) != internal) s.fail_here(internal ? "the ring must be an internal gear" : "the " + key + " must be an external gear");
  return b;
}

// The involutes of a member; without them the set needs its centre distance, refused naming the
// member when not given.
std::optional<InvoluteTeeth> member_involutes(const YamlMap& m, const std::string& key, const physics::BodyDef& b) {
  std::string why;
  const std::optional<InvoluteTeeth> t = involutes_of(b, why);
  if (!t && !m.has("centre_distance_m")) m.fail(key, why + ", so the centre distance cannot be derived: give centre_distance_m");
  return t;
}

}  // namespace

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
  for (const GearSpec& g : planet_gears(m, f, s.spec->planet, s.count))
    s.planets.push_back(spec_body("planet_" + std::to_string(k++), g, f.density_kg_m3));
  return s;
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
  if (!s.sun_teeth || !s.planet_teeth || !s.ring_teeth) s.sun_teeth = s.planet_teeth = s.ring_teeth = std::nullopt;
  for (int k = 0; k < s.count; ++k) {
    s.planets.push_back(s.planet);
    s.planets.back().name = "planet_" + std::to_string(k);
  }
  return s;
}

}  // namespace gearsim::input::scenario_detail

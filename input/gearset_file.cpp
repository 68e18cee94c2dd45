#include "input/gearset_file.hpp"

#include <numbers>

#include "input/input_limits.hpp"
#include "input/safe_name.hpp"
#include "core/errors.hpp"
#include "geometry/constants.hpp"

namespace gearsim::input {
namespace {

using gearsim::constants::kRadPerDeg;

Flank parse_flank(const YamlMap& m) {
  return m.choice("flank", {"ccw", "cw"}) == "ccw" ? Flank::Ccw : Flank::Cw;
}

}  // namespace

GearErrors parse_gear_errors(const YamlMap& e) {
  GearErrors out;
  if (e.has("flank_offsets"))
    for (const YamlMap& f : e.list_of_maps("flank_offsets")) {
      out.flank_offsets.push_back({f.integer("tooth"), parse_flank(f), f.number("normal_offset_m")});
      f.reject_unknown_keys();
    }
  if (e.has("pitch_errors"))
    for (const YamlMap& p : e.list_of_maps("pitch_errors")) {
      out.pitch_errors.push_back({p.integer("tooth"), p.number("error_m")});
      p.reject_unknown_keys();
    }
  if (e.has("profile_slopes"))
    for (const YamlMap& p : e.list_of_maps("profile_slopes")) {
      out.profile_slopes.push_back({p.integer_or("tooth", -1), parse_flank(p), p.number("slope_m")});
      p.reject_unknown_keys();
    }
  if (e.has("eccentricity")) {
    const YamlMap ecc = e.map("eccentricity");
    out.eccentricity = {ecc.number("eccentricity_m"), angle_rad_or(ecc, "phase", 0.0)};
    ecc.reject_unknown_keys();
  }
  e.reject_unknown_keys();
  return out;
}


double angle_rad_or(const YamlMap& m, const std::string& base, double fallback_rad) {
  const bool deg = m.has(base + "_deg"), rad = m.has(base + "_rad");
  if (deg && rad) m.fail(base + "_deg", "give the angle once: " + base + "_deg or " + base + "_rad");
  if (deg) return m.number(base + "_deg") * kRadPerDeg;
  if (rad) return m.number(base + "_rad");
  m.number_or(base + "_deg", 0);  // mark both spellings as known keys
  m.number_or(base + "_rad", 0);
  return fallback_rad;
}

GearSpec parse_gear(const YamlMap& g, const std::string& name, const YamlMap* defaults) {
  // A value from the gear, else from the defaults block, else the built-in default.
  auto num = [&](const std::string& key, std::optional<double> fallback) -> double {
    if (g.has(key)) return g.number(key);
    g.number_or(key, 0);
    if (defaults && defaults->has(key)) return defaults->number(key);
    if (defaults) defaults->number_or(key, 0);
    if (!fallback) g.fail(key, "missing (required, here or in defaults)");
    return *fallback;
  };
  auto angle = [&](const std::string& base, double fallback) {
    if (g.has(base + "_deg") || g.has(base + "_rad")) return angle_rad_or(g, base, fallback);
    angle_rad_or(g, base, fallback);
    return defaults ? angle_rad_or(*defaults, base, fallback) : fallback;
  };
  GearSpec s;
  s.name = name;
  s.kind = g.choice("kind", {"external", "internal"}) == "internal" ? GearKind::Internal : GearKind::External;
  s.teeth = integer_within(g, "teeth", limits::kTeeth);
  s.module_m = num("module_m", std::nullopt);
  s.pressure_angle_rad = angle("pressure_angle", constants::kDefaultPressureAngle_rad);
  s.face_width_m = num("face_width_m", std::nullopt);
  s.profile_shift = num("profile_shift", 0.0);
  s.addendum_coeff = num("addendum_coeff", constants::kAddendumCoeff);
  s.dedendum_coeff = num("dedendum_coeff", constants::kDedendumCoeff);
  s.root_fillet_coeff = num("root_fillet_coeff", constants::kRootFilletCoeff);
  s.thinning_per_flank_m = num("thinning_per_flank_m", 0.0);
  s.chordal_deviation_m = num("chordal_deviation_m", constants::kDefaultChordalDeviation_m);
  if (!within(s.chordal_deviation_m, limits::kChordalDeviation_m))
    g.fail("chordal_deviation_m", limit_message(limits::kChordalDeviation_m, s.chordal_deviation_m));
  s.bore_diameter_m = g.number_or("bore_diameter_m", 0.0);
  s.rim_diameter_m = g.number_or("rim_diameter_m", 0.0);
  s.tooth0_angle_rad = angle_rad_or(g, "tooth0_angle", 0.0);
  if (g.has("errors")) s.errors = parse_gear_errors(g.map("errors"));
  g.reject_unknown_keys();
  try {
    validate_gear_spec(s);
  } catch (const InputError& e) {
    g.fail_here(e.what());
  }
  return s;
}

const GearSpec& GearSetFile::gear(const std::string& gear_name) const {
  for (const GearSpec& g : gears)
    if (g.name == gear_name) return g;
  throw InputError(path.string() + ": no gear named '" + gear_name + "'");
}

GearSetFile load_gearset(const std::filesystem::path& path) {
  const YamlMap top = YamlMap::load_file(path);
  GearSetFile f;
  f.path = path;
  f.name = top.string("name");
  require_label(top, "name", f.name);
  f.density_kg_m3 = top.number("density_kg_m3");
  if (!(f.density_kg_m3 > 0)) top.fail("density_kg_m3", "expected a positive density in kg/m³");
  std::optional<YamlMap> defaults;
  if (top.has("defaults")) defaults = top.map("defaults");
  const YamlMap gears = top.map("gears");
  for (const auto& [name, g] : gears.entries()) {
    require_safe_name(gears, name, name, NameUse::File);  // `gears --out DIR` writes DIR/<name>.stl
    f.gears.push_back(parse_gear(g, name, defaults ? &*defaults : nullptr));
  }
  if (f.gears.empty()) top.fail("gears", "expected at least one gear");
  if (defaults) defaults->reject_unknown_keys();
  auto named = [&](const YamlMap& m, const std::string& key) -> const GearSpec& {
    const std::string n = m.string(key);
    for (const GearSpec& g : f.gears)
      if (g.name == n) return g;
    m.fail(key, "no gear named '" + n + "' under gears");
  };
  if (top.has("train")) {
    const YamlMap t = top.map("train");
    const std::string type = t.choice("type", {"planetary", "pair"});
    if (type == "planetary") {
      PlanetarySpec p{named(t, "sun"), named(t, "planet"), named(t, "ring"), integer_within(t, "planets", limits::kPlanets)};
      f.planetary = p;
    } else {
      f.pair = std::make_pair(named(t, "driver").name, named(t, "driven").name);
    }
    t.reject_unknown_keys();
  }
  if (top.has("tolerance")) {
    const YamlMap t = top.map("tolerance");
    f.tolerance_quality = t.integer("quality");
    t.reject_unknown_keys();
  }
  if (top.has("reference")) {
    const YamlMap r = top.map("reference");
    f.reference_source = r.string("source");
    const YamlMap rgears = r.map("gears");
    for (const auto& [name, g] : rgears.entries()) {
      bool known = false;
      for (const GearSpec& s : f.gears) known = known || s.name == name;
      if (!known) rgears.fail(name, "no gear named '" + name + "' under gears");
      ReferenceGear rg;
      for (const char* key : {"reference_diameter_m", "tip_diameter_m", "root_diameter_m", "base_diameter_m"})
        if (auto v = g.optional_number(key)) rg.diameters_m[key] = *v;
      g.reject_unknown_keys();
      f.reference[name] = rg;
    }
    r.reject_unknown_keys();
  }
  top.reject_unknown_keys();
  return f;
}

}  // namespace gearsim::input

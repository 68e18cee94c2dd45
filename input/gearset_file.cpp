#include "input/gearset_file.hpp"

#include <numbers>

#include "input/input_limits.hpp"
#include "input/safe_name.hpp"
#include "input/utf8_text.hpp"
#include "core/errors.hpp"
#include "geometry/gear_profile.hpp"
#include "geometry/helical.hpp"
#include "geometry/constants.hpp"

namespace gearsim::input {
namespace {

using gearsim::constants::kRadPerDeg;

Flank parse_flank(const YamlMap& m) { return m.choice("flank", {"ccw", "cw"}) == "ccw" ? Flank::Ccw : Flank::Cw; }

}  // namespace

GearErrors parse_gear_errors(const YamlMap& e) {
  using limits::kToothError_m;
  GearErrors out;
  if (e.has("flank_offsets"))
    for (const YamlMap& f : e.list_of_maps("flank_offsets")) {
      out.flank_offsets.push_back({f.integer("tooth"), parse_flank(f), number_within(f, "normal_offset_m", kToothError_m)});
      f.reject_unknown_keys();
    }
  if (e.has("pitch_errors"))
    for (const YamlMap& p : e.list_of_maps("pitch_errors")) {
      out.pitch_errors.push_back({p.integer("tooth"), number_within(p, "error_m", kToothError_m)});
      p.reject_unknown_keys();
    }
  if (e.has("profile_slopes"))
    for (const YamlMap& p : e.list_of_maps("profile_slopes")) {
      out.profile_slopes.push_back({p.integer_or("tooth", -1), parse_flank(p), number_within(p, "slope_m", kToothError_m)});
      p.reject_unknown_keys();
    }
  if (e.has("eccentricity")) {
    const YamlMap ecc = e.map("eccentricity");
    out.eccentricity = {number_within(ecc, "eccentricity_m", limits::kEccentricity_m), angle_rad_or(ecc, "phase", 0.0)};
    ecc.reject_unknown_keys();
  }
  e.reject_unknown_keys();
  return out;
}

double angle_rad_or(const YamlMap& m, const std::string& base, double fallback_rad, const Limit& limit_rad) {
  const bool deg = m.has(base + "_deg"), rad = m.has(base + "_rad");
  if (deg && rad) m.fail(base + "_deg", "give the angle once: " + base + "_deg or " + base + "_rad");
  if (deg) return number_within(m, base + "_deg", limit_in_degrees(limit_rad)) * kRadPerDeg;
  if (rad) return number_within(m, base + "_rad", limit_rad);
  m.number_or(base + "_deg", 0);  // mark both spellings as known keys
  m.number_or(base + "_rad", 0);
  return fallback_rad;
}

GearSpec parse_gear(const YamlMap& g, const std::string& name, const YamlMap* defaults) {
  // A value from the gear, else from the defaults block, else the built-in default; each checked
  // against its limit where it is given.
  auto num = [&](const std::string& key, std::optional<double> fallback, const Limit& limit) -> double {
    if (g.has(key)) return number_within(g, key, limit);
    g.number_or(key, 0);
    if (defaults && defaults->has(key)) return number_within(*defaults, key, limit);
    if (defaults) defaults->number_or(key, 0);
    if (!fallback) g.fail(key, "missing (required, here or in defaults)");
    return *fallback;
  };
  auto angle = [&](const std::string& base, double fallback, const Limit& limit) {
    if (g.has(base + "_deg") || g.has(base + "_rad")) return angle_rad_or(g, base, fallback, limit);
    angle_rad_or(g, base, fallback, limit);
    return defaults ? angle_rad_or(*defaults, base, fallback, limit) : fallback;
  };
  GearSpec s;
  s.name = name;
  s.kind = g.choice("kind", {"external", "internal"}) == "internal" ? GearKind::Internal : GearKind::External;
  s.teeth = integer_within(g, "teeth", limits::kTeeth);
  // A helical gear is given by its normal values (ISO 21771) and converted to its transverse
  // section (helical.hpp); a spur gear by its module and pressure angle.
  const double helix = angle("helix_angle", 0.0, limits::kHelixAngle_rad);
  NormalValues n;  // a spur gear's are its own (β = 0)
  if (helix != 0.0) {
    for (const char* key : {"module_m", "pressure_angle_deg", "pressure_angle_rad"})
      if (g.has(key)) g.fail(key, "a helical gear is given by its normal values: normal_module_m and normal_pressure_angle_deg");
    n.helix_angle_rad = g.choice("hand", {"right", "left"}) == "right" ? helix : -helix;
    n.module_m = num("normal_module_m", std::nullopt, limits::kModule_m);
    n.pressure_angle_rad = angle("normal_pressure_angle", constants::kDefaultPressureAngle_rad, limits::kPressureAngle_rad);
  } else {
    for (const char* key : {"hand", "normal_module_m", "normal_pressure_angle_deg", "normal_pressure_angle_rad"})
      if (g.has(key)) g.fail(key, "only a helical gear (helix_angle_deg > 0) has a hand and normal values; a spur gear takes module_m");
    n.module_m = num("module_m", std::nullopt, limits::kModule_m);
    n.pressure_angle_rad = angle("pressure_angle", constants::kDefaultPressureAngle_rad, limits::kPressureAngle_rad);
  }
  n.profile_shift = num("profile_shift", 0.0, limits::kProfileShift);
  n.addendum_coeff = num("addendum_coeff", constants::kAddendumCoeff, limits::kToothDepthFactor);
  n.dedendum_coeff = num("dedendum_coeff", constants::kDedendumCoeff, limits::kToothDepthFactor);
  n.root_fillet_coeff = num("root_fillet_coeff", constants::kRootFilletCoeff, limits::kRootFilletFactor);
  set_transverse(s, n);
  s.face_width_m = num("face_width_m", std::nullopt, limits::kFaceWidth_m);
  // Lengths along the flank normal (normal plane) as the transverse section's.
  s.thinning_per_flank_m = normal_to_transverse_m(s, num("thinning_per_flank_m", 0.0, limits::kThinning_m));
  s.chordal_deviation_m = num("chordal_deviation_m", constants::kDefaultChordalDeviation_m, limits::kChordalDeviation_m);
  s.bore_diameter_m = number_within_or(g, "bore_diameter_m", 0.0, limits::kGearDiameter_m);
  s.rim_diameter_m = number_within_or(g, "rim_diameter_m", 0.0, limits::kGearDiameter_m);
  s.tooth0_angle_rad = angle_rad_or(g, "tooth0_angle", 0.0);
  if (g.has("errors")) {
    s.errors = parse_gear_errors(g.map("errors"));
    for (FlankOffset& f : s.errors.flank_offsets) f.normal_offset_m = normal_to_transverse_m(s, f.normal_offset_m);
    for (ProfileSlopeError& p : s.errors.profile_slopes) p.slope_m = normal_to_transverse_m(s, p.slope_m);
  }
  g.reject_unknown_keys();
  try {
    validate_gear_spec(s);
    // Errors and thinning can leave a tooth pointed or flanks crossing, which only drawing its
    // outline finds: drawn here, so that the refusal names the file and line (a gear without
    // them is checked in full by its dimensions above).
    const GearErrors& e = s.errors;
    if (!e.flank_offsets.empty() || !e.pitch_errors.empty() || !e.profile_slopes.empty() || e.eccentricity.eccentricity_m > 0 ||
        s.thinning_per_flank_m > 0)
      make_gear_outline(s);
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
  const YAML::Node root = load_yaml_mapping(path);
  require_utf8_tree(root, path.string());  // gear names reach gearset.json and the run records
  const YamlMap top = YamlMap::from_node(root, path.string());
  GearSetFile f;
  f.path = path;
  f.name = top.string("name");
  require_label(top, "name", f.name);
  f.density_kg_m3 = number_within(top, "density_kg_m3", limits::kDensity_kg_m3);
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
    f.tolerance_quality = integer_within(t, "quality", limits::kQualityClass);
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
        if (auto v = g.optional_number(key)) {
          if (!within(*v, limits::kGearDiameter_m)) g.fail(key, limit_message(limits::kGearDiameter_m, *v));
          rg.diameters_m[key] = *v;
        }
      g.reject_unknown_keys();
      f.reference[name] = rg;
    }
    r.reject_unknown_keys();
  }
  top.reject_unknown_keys();
  return f;
}

}  // namespace gearsim::input

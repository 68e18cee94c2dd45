// A scenario body's shape and mass: an inline gear, a gear of a gear-set spec file, a mesh file
// with its tooth layout, or nothing (a carrier-like body with given mass and inertia).
#include <cmath>
#include <numbers>
#include <sstream>

#include "input/gearset_file.hpp"
#include "input/input_limits.hpp"
#include "input/scenario_parts.hpp"
#include "core/errors.hpp"
#include "core/input_file.hpp"
#include "geometry/mesh_io.hpp"
#include "geometry/mesh_gear.hpp"

namespace gearsim::input::scenario_detail {
namespace fs = std::filesystem;

fs::path resolve(const fs::path& dir, const std::string& file) {
  const fs::path p(file);
  return (p.is_absolute() ? p : dir / p).lexically_normal();
}

double positive(const YamlMap& m, const std::string& key, const std::string& what) {
  const double v = m.number(key);
  if (!(v > 0)) m.fail(key, "expected a positive " + what + ", got " + m.string(key));
  return v;
}

bool given(const YamlMap& m, const std::string& key) {
  if (m.has(key)) return true;
  m.number_or(key, 0);  // absent or null: known, and the fallback is unused
  return false;
}

Eigen::Vector3d vec3_or(const YamlMap& m, const std::string& key, const Eigen::Vector3d& fallback) {
  if (!given(m, key)) return fallback;
  const std::vector<double> v = m.numbers(key, 3);
  return {v[0], v[1], v[2]};
}

Eigen::Vector3d vec3_within_or(const YamlMap& m, const std::string& key, const Eigen::Vector3d& fallback, const Limit& limit) {
  const Eigen::Vector3d v = vec3_or(m, key, fallback);
  if (!m.has(key)) return v;
  for (int i = 0; i < 3; ++i)
    if (!within(v[i], limit)) m.fail(key, std::string(1, "xyz"[i]) + ": " + limit_message(limit, v[i]));
  return v;
}

namespace {

// gear_from: {spec: FILE, gear: NAME}; also returns the spec's density.
GearSpec gear_from(const YamlMap& m, const fs::path& dir, double& density_kg_m3) {
  const fs::path spec = resolve(dir, m.string("spec"));
  if (std::error_code ec; !fs::is_regular_file(spec, ec)) m.fail("spec", "gear-set spec file not found: " + spec.string());
  const GearSetFile f = load_gearset(spec);
  const std::string name = m.string("gear");
  m.reject_unknown_keys();
  density_kg_m3 = f.density_kg_m3;
  std::string names;
  for (const GearSpec& g : f.gears) {
    if (g.name == name) return g;
    names += (names.empty() ? "" : ", ") + g.name;
  }
  m.fail("gear", "no gear named '" + name + "' in " + spec.string() + " (it has: " + names + ")");
}

// A gear mesh recognised: the tooth layout filled in when not given, refused when it disagrees
// with the mesh, when the mesh is no recognisable gear, or when its size says the unit is wrong.
void check_gear_mesh(const YamlMap& m, physics::MeshSource& src) {
  const std::string file = src.path.string();
  MeshGearFile f;
  try {
    f = read_mesh_gear(src.path, src.unit);
  } catch (const InputError& e) {
    m.fail("file", e.what());  // the mesh's own refusal, at the scenario's key
  }
  if (!f.gear)
    m.fail("file", file + " is not a prism (" + f.prism.reason() +
                       "): a gear must be a spur-gear extrusion; give `teeth: none` for a toothless body");
  if (!f.gear->recognition)
    m.fail(src.teeth ? "teeth" : "file", file + " is not recognised as a spur gear: " + f.gear->recognition.reason() +
                                             (src.teeth ? "" : "; give `teeth: none` for a toothless body"));
  const RecognisedGear& g = *f.gear->recognition;
  src.recognised = g;
  if (const Check u = check_unit(g, src.unit); !u) m.fail("unit", file + ": " + u.reason());
  if (!src.teeth) {
    src.teeth = ToothLayout{g.teeth, g.tooth0_angle_rad};
    src.teeth_recognised = true;
  } else if (const Check mm = check_layout(g, *src.teeth); !mm) {
    m.fail(src.teeth->teeth != g.teeth ? "teeth" : (m.has("tooth0_rad") ? "tooth0_rad" : "tooth0_deg"), file + ": " + mm.reason());
  } else {
    // A given tooth 0 within the tolerance names the tooth; its angle is the mesh's: a rounded
    // angle (0.3° on a 12-tooth pinion is 31 µm at its pitch circle) would phase a pair off by
    // more than the backlash of fine gears.
    const double pitch = 2 * std::numbers::pi / g.teeth;
    src.teeth->tooth0_angle_rad = g.tooth0_angle_rad + pitch * std::round((src.teeth->tooth0_angle_rad - g.tooth0_angle_rad) / pitch);
  }
}

physics::MeshSource mesh_source(const YamlMap& m, const fs::path& dir) {
  physics::MeshSource src;
  src.path = resolve(dir, m.string("file"));
  // The error_code overload: a path the system refuses (a name past NAME_MAX) is not found,
  // not a filesystem_error.
  if (std::error_code ec; !fs::exists(fs::symlink_status(src.path, ec))) m.fail("file", "mesh file not found: " + src.path.string());
  // A FIFO, a device, a folder, a link loop or an oversized file: refused here, naming the key.
  try {
    check_input_file(src.path, kMaxMeshFileBytes, "a mesh file");
  } catch (const InputError& e) {
    m.fail("file", e.what());
  }
  const std::string unit = m.string("unit");
  const std::optional<LengthUnit> u = parse_length_unit(unit);
  if (!u) m.fail("unit", "expected a length unit (m, cm, mm, um, in, ft), got '" + unit + "'");
  src.unit = *u;
  // Teeth: given (and checked against the mesh), `none` (a toothless body), or recognised.
  const bool toothless = given(m, "teeth") && m.string("teeth") == "none";
  if (given(m, "teeth") && !toothless) {
    const int z = integer_within(m, "teeth", limits::kTeeth);
    src.teeth = ToothLayout{z, angle_rad_or(m, "tooth0", 0.0)};
  } else {
    if (m.has("tooth0_deg") || m.has("tooth0_rad"))
      m.fail(m.has("tooth0_deg") ? "tooth0_deg" : "tooth0_rad", "a tooth angle needs `teeth`");
    angle_rad_or(m, "tooth0", 0.0);  // null spellings: known keys
  }
  if (!toothless) check_gear_mesh(m, src);
  m.reject_unknown_keys();
  return src;
}

// Principal moments must be within their limit and obey the triangle inequality (a real body's do).
Eigen::Vector3d principal_inertia(const YamlMap& m) {
  const Eigen::Vector3d j = vec3_within_or(m, "principal_inertia_kg_m2", Eigen::Vector3d::Zero(), limits::kInertia_kg_m2);
  if (j.x() + j.y() < j.z() || j.y() + j.z() < j.x() || j.z() + j.x() < j.y())
    m.fail("principal_inertia_kg_m2", "no rigid body has these moments (each must be ≤ the sum of the other two)");
  return j;
}

}  // namespace

void parse_shape_and_mass(const YamlMap& m, physics::BodyDef& b, const fs::path& dir) {
  const int shapes = int(m.has("gear")) + int(m.has("gear_from")) + int(m.has("mesh"));
  if (shapes > 1) m.fail_here("body '" + b.name + "' has more than one shape: give one of gear, gear_from, mesh");
  std::optional<double> spec_density;
  if (m.has("gear")) b.gear = parse_gear(m.map("gear"), b.name, nullptr);
  if (m.has("gear_from")) {
    double d = 0;
    b.gear = gear_from(m.map("gear_from"), dir, d);
    spec_density = d;
  }
  if (m.has("mesh")) b.mesh = mesh_source(m.map("mesh"), dir);
  for (const char* key : {"gear", "gear_from", "mesh"}) given(m, key);  // known keys

  // Mass: density × the shape's volume, or mass_kg (a shape then scales its own inertia).
  b.density_kg_m3 = m.optional_number("density_kg_m3");
  b.mass_kg = m.optional_number("mass_kg");
  if (b.density_kg_m3 && b.mass_kg) m.fail("mass_kg", "give density_kg_m3 or mass_kg, not both");
  if (b.density_kg_m3) number_within(m, "density_kg_m3", limits::kDensity_kg_m3);
  if (b.mass_kg) number_within(m, "mass_kg", limits::kMass_kg);
  if (given(m, "principal_inertia_kg_m2")) b.principal_inertia_kg_m2 = principal_inertia(m);
  if (shapes == 1) {
    if (b.principal_inertia_kg_m2 && !b.mass_kg)
      m.fail("principal_inertia_kg_m2", "moments that replace the shape's need mass_kg (not density_kg_m3) beside them");
    if (!b.density_kg_m3 && !b.mass_kg) b.density_kg_m3 = spec_density;  // gear_from: the spec's material
    if (!b.density_kg_m3 && !b.mass_kg) m.fail_here("body '" + b.name + "' needs density_kg_m3 or mass_kg");
  } else {
    if (b.density_kg_m3)
      m.fail("density_kg_m3", "body '" + b.name + "' has no shape, hence no volume: give mass_kg and principal_inertia_kg_m2");
    if (!b.mass_kg || !b.principal_inertia_kg_m2)
      m.fail_here("body '" + b.name + "' has no shape (gear, gear_from or mesh): it needs mass_kg and principal_inertia_kg_m2");
  }
}

}  // namespace gearsim::input::scenario_detail

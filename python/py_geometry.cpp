#include "python/py_geometry.hpp"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <cmath>
#include <filesystem>
#include <optional>
#include <string>

#include "app/gear_report.hpp"
#include "app/mesh_inspection.hpp"
#include "app/tolerance_report.hpp"
#include "contact/flank_table.hpp"
#include "core/errors.hpp"
#include "input/input_limits.hpp"
#include "python/py_arrays.hpp"
#include "python/py_json.hpp"

namespace gearsim::python {
namespace {

namespace fs = std::filesystem;

// The Hausdorff sample spacing of the decomposition check, m: the CLI's default (--hausdorff-spacing 0.5).
constexpr double kGearsHausdorffSpacing_m = 0.5e-3;

// A loop's x and y, m.
std::pair<py::array_t<double>, py::array_t<double>> loop_xy(const Polygon2& loop) {
  std::vector<double> x, y;
  for (const Eigen::Vector2d& p : loop.points) {
    x.push_back(p.x());
    y.push_back(p.y());
  }
  return {numpy_copy(x), numpy_copy(y)};
}

// The meshes a gear takes part in, by mate: the train's mesh entries of gearset.json.
py::dict gear_meshes(const app::json& doc, const std::string& name) {
  py::dict meshes;
  if (!doc.contains("train")) return meshes;
  const app::json& t = doc["train"];
  const auto add = [&](const std::string& a, const std::string& b, const app::json& mesh) {
    if (a == name) meshes[py::str(b)] = to_python(mesh);
    if (b == name) meshes[py::str(a)] = to_python(mesh);
  };
  if (t["type"] == "pair") add(t["driver"], t["driven"], t["mesh"]);
  if (t["type"] == "planetary") {
    add(t["sun"], t["planet"], t["sun_planet"]);
    add(t["planet"], t["ring"], t["planet_ring"]);
  }
  return meshes;
}

// Flank angles of every tooth at `radius` (teeth × samples), rad, NaN where no material.
py::array_t<double> flank_angles(const contact::FlankTable& t, Flank flank, const std::vector<double>& radius) {
  py::array_t<double> a({static_cast<py::ssize_t>(t.teeth()), static_cast<py::ssize_t>(radius.size())});
  auto v = a.mutable_unchecked<2>();
  for (int k = 0; k < t.teeth(); ++k)
    for (std::size_t i = 0; i < radius.size(); ++i) v(k, static_cast<py::ssize_t>(i)) = t.flank_angle(k, flank, radius[i]);
  return a;
}

py::dict gear_dict(const app::GearSetAnalysis& a, const std::string& name) {
  const GearBody& b = a.bodies.at(name);
  py::dict g;
  g["name"] = name;
  for (auto item : to_python(a.doc["gears"][name]).cast<py::dict>()) g[item.first] = item.second;
  const GearDimensions& d = b.outline.dims;
  g["reference_radius_m"] = d.reference_radius_m;
  g["base_radius_m"] = d.base_radius_m;
  g["tip_radius_m"] = d.tip_radius_m;
  g["root_radius_m"] = d.root_radius_m;
  g["form_radius_m"] = d.form_radius_m;
  g["pitch_m"] = d.pitch_m;
  g["base_pitch_m"] = d.base_pitch_m;
  g["space_width_m"] = d.space_width_m;
  g["meshes"] = gear_meshes(a.doc, name);
  // The outline: the toothed loop, then the others (an external gear's bore, an internal gear's rim).
  const bool internal = b.spec.kind == GearKind::Internal;
  const Outline2& o = b.outline.outline;
  const Polygon2& toothed = internal ? o.holes.front() : o.outer;
  const auto [x, y] = loop_xy(toothed);
  g["outline_x_m"] = x;
  g["outline_y_m"] = y;
  py::list others;
  const auto other = [&](const Polygon2& loop) {
    const auto [ox, oy] = loop_xy(loop);
    others.append(py::make_tuple(ox, oy));
  };
  if (internal) other(o.outer);
  for (std::size_t h = internal ? 1 : 0; h < o.holes.size(); ++h) other(o.holes[h]);
  g["other_loops_m"] = others;
  // The flank table the physics builds from that loop.
  const contact::FlankTable t(toothed, ToothLayout{b.spec.teeth, b.spec.tooth0_angle_rad}, internal, kGearFlankSamples);
  std::vector<double> radius(kGearFlankSamples), centre(static_cast<std::size_t>(t.teeth()));
  for (int i = 0; i < kGearFlankSamples; ++i)
    radius[static_cast<std::size_t>(i)] =
        i + 1 == kGearFlankSamples ? t.r_max_m() : t.r_min_m() + i * (t.r_max_m() - t.r_min_m()) / (kGearFlankSamples - 1);
  for (int k = 0; k < t.teeth(); ++k) centre[static_cast<std::size_t>(k)] = t.tooth_angle_rad(k);
  g["flank_radius_m"] = numpy_copy(radius);
  g["tooth_angle_rad"] = numpy_copy(centre);
  g["flank_ccw_rad"] = flank_angles(t, Flank::Ccw, radius);
  g["flank_cw_rad"] = flank_angles(t, Flank::Cw, radius);
  return g;
}

py::object gear(const fs::path& spec, std::optional<std::string> name) {
  std::optional<input::GearSetFile> file;
  std::optional<app::GearSetAnalysis> a;
  {
    py::gil_scoped_release released;
    file = input::load_gearset(spec);
    if (name) {
      bool found = false;
      std::string names;
      for (const GearSpec& s : file->gears) {
        found = found || s.name == *name;
        names += (names.empty() ? "" : ", ") + s.name;
      }
      if (!found) throw InputError(spec.string() + ": name: no gear '" + *name + "' (the spec has " + names + ")");
    }
    a = app::analyse_gearset(*file, kGearsHausdorffSpacing_m);
  }
  if (name) return gear_dict(*a, *name);
  py::dict all;
  for (const GearSpec& s : file->gears) all[py::str(s.name)] = gear_dict(*a, s.name);
  return all;
}

py::object inspect(const fs::path& mesh, const std::string& unit, std::optional<int> teeth, double tooth0_deg, double density_kg_m3,
                   double prism_tolerance_um, double hausdorff_spacing_mm) {
  // The CLI's option checks (cmd_inspect.cpp), with the argument's name.
  using namespace input::limits;
  if (teeth) input::require_within("teeth", *teeth, kTeeth);
  input::require_within("tooth0_deg", tooth0_deg, input::limit_in_degrees(kAngle_rad));
  input::require_within("density_kg_m3", density_kg_m3, kDensity_kg_m3);
  input::require_within("prism_tolerance_um", prism_tolerance_um, kPrismTolerance_um);
  input::require_within("hausdorff_spacing_mm", hausdorff_spacing_mm, kSampleSpacing_mm);
  app::InspectOptions o;
  o.mesh = mesh.string();
  o.unit = unit;
  o.teeth = teeth.value_or(0);
  o.tooth0_deg = tooth0_deg;
  o.density_kg_m3 = density_kg_m3;
  o.prism_tolerance_um = prism_tolerance_um;
  o.spacing_mm = hausdorff_spacing_mm;
  app::json j;
  {
    py::gil_scoped_release released;
    j = app::inspect_mesh(o);
  }
  return to_python(j);
}

py::object tolerance(double module_mm, int teeth, double reference_diameter_mm, int quality, const std::string& standard,
                     std::optional<double> contact_ratio) {
  ToleranceInput in{module_mm, teeth, reference_diameter_mm, quality, contact_ratio};
  return to_python(app::tolerance_json(in, standard));
}

constexpr const char* kGearDoc = R"(The gears of a gear-set spec file (assets/specs/*.yaml), as `gearsim gears SPEC` computes them.

With name: that gear's dict; without: {name: dict} for every gear of the spec, in file order.
Each dict holds the gear's entry of `gearsim gears --json` / gearset.json (kind, teeth, module_m,
pressure_angle_deg, face_width_m, profile_shift, reference/base/tip/root/form_diameter_m,
tooth_thickness_m, tip_thickness_m, span_teeth and span_m for external gears, errors, mesh
(triangles, watertight, volume_m3, mass_kg, inertia_zz_kg_m2, …), decomposition), and:
  reference_radius_m, base_radius_m, tip_radius_m, root_radius_m, form_radius_m, pitch_m,
  base_pitch_m, space_width_m: the gear table's radii and pitches, m;
  meshes: {mate: the train's mesh entry} (centre_distance_m, working_pressure_angle_deg,
    contact_ratio, effective_contact_ratio, …; a planetary planet has two mates);
  outline_x_m, outline_y_m: the toothed loop of the 2-D profile (the outline the mesh is
    extruded from), numpy float64, m, in the gear frame (axis at the origin);
  other_loops_m: [(x_m, y_m), …] the outline's other loops (an external gear's bore, an
    internal gear's rim);
  flank_radius_m (4096 radii, root to tip), tooth_angle_rad (teeth,), flank_ccw_rad and
    flank_cw_rad (teeth × 4096): the flank table the contact model builds from the outline,
    each flank's polar angle relative to its tooth's centre line, rad (cw < 0 < ccw), NaN where
    the tooth has no material at that radius.
gearsim.InputError naming the file and key for a bad spec, or an unknown name.)";

constexpr const char* kInspectDoc = R"(Inspect a CAD mesh as `gearsim inspect MESH --json` does; returns its JSON as a dict.

unit: the file's length unit (m, cm, mm, um, in, ft; default mm); teeth, tooth0_deg: cut the
decomposition into tooth sectors (tooth 0's centre line in deg); density_kg_m3 for the mass
properties; prism_tolerance_um: how far a vertex may lie off the cap planes of a prism, µm;
hausdorff_spacing_mm: deviation sample spacing, mm. The dict's keys carry the CLI's units:
triangles, watertight, manifold, outward_oriented, volume_mm3, mass_kg, centre_of_mass_mm,
inertia_com_kg_m2, principal_moments_kg_m2, prismatic, convex_pieces, max_deviation_um, and
for a prism the recognised gear (gear.teeth, module_mm, pressure_angle_deg, flank fits,
flank_table departure_um). decompose_seconds is a timing. gearsim.InputError naming the file
(and the first offending face or edge) when it cannot be read or is not a valid solid.)";

constexpr const char* kToleranceDoc = R"(Gear accuracy tolerances (DIN 3961/3962, ISO 1328-1:1995) of one gear at one quality class,
as `gearsim tolerance --json` prints them; in the standards' units: mm in, µm out.

module_mm: normal module m_n, mm; teeth: z; reference_diameter_mm: d = z·m_n/cos β, mm;
quality: class Q (DIN 1 to 12, ISO 0 to 12); standard: "din", "iso" or "both" (the default:
DIN's answer on top, each standard's object under din3961 and iso1328); contact_ratio: ε_γ, for
ISO's Annex A f_i' and F_i' (left out without it). Every tolerance under a key ending in _um,
with single_flank_error_um (the paper's F_i'), step_factor and components. gearsim.InputError
naming the parameter for out-of-range input.)";

}  // namespace

void bind_geometry(py::module_& m) {
  m.def("gear", &gear, py::arg("spec_path"), py::arg("name") = py::none(), kGearDoc);
  m.def("inspect", &inspect, py::arg("mesh_path"), py::arg("unit") = "mm", py::arg("teeth") = py::none(), py::arg("tooth0_deg") = 0.0,
        py::arg("density_kg_m3") = app::InspectOptions{}.density_kg_m3,
        py::arg("prism_tolerance_um") = app::InspectOptions{}.prism_tolerance_um,
        py::arg("hausdorff_spacing_mm") = app::InspectOptions{}.spacing_mm, kInspectDoc);
  m.def("tolerance", &tolerance, py::arg("module_mm"), py::arg("teeth"), py::arg("reference_diameter_mm"), py::arg("quality"),
        py::arg("standard") = "both", py::arg("contact_ratio") = py::none(), kToleranceDoc);
}

}  // namespace gearsim::python

#include "app/gear_report.hpp"

#include <cmath>
#include <numbers>

#include "geometry/extrude.hpp"
#include "geometry/gear_mesh.hpp"
#include "geometry/helical.hpp"
#include "geometry/hausdorff.hpp"
#include "geometry/mesh_validate.hpp"
#include "geometry/planetary.hpp"
#include "geometry/constants.hpp"

namespace gearsim::app {
namespace {

using gearsim::constants::kDegPerRad;
using gearsim::constants::kPi;

json gear_json(const GearBody& b, double spacing) {
  const GearSpec& s = b.spec;
  const GearDimensions& d = b.outline.dims;
  json g;
  g["kind"] = s.kind == GearKind::External ? "external" : "internal";
  g["teeth"] = s.teeth;
  g["module_m"] = s.module_m;
  g["pressure_angle_deg"] = s.pressure_angle_rad * kDegPerRad;
  if (s.helix_angle_rad != 0) {
    // The transverse values above; the normal ones the gear was given by, and its helix.
    g["helix_angle_deg"] = std::abs(s.helix_angle_rad) * kDegPerRad;
    g["hand"] = s.helix_angle_rad > 0 ? "right" : "left";
    g["normal_module_m"] = normal_module_m(s);
    g["normal_pressure_angle_deg"] = normal_pressure_angle_rad(s) * kDegPerRad;
    g["base_helix_angle_deg"] = std::abs(base_helix_angle_rad(s)) * kDegPerRad;
    g["axial_pitch_m"] = kPi * normal_module_m(s) / std::sin(std::abs(s.helix_angle_rad));
    g["lead_m"] = 2 * kPi * d.reference_radius_m / std::tan(std::abs(s.helix_angle_rad));
  }
  g["face_width_m"] = s.face_width_m;
  g["profile_shift"] = s.profile_shift;
  g["reference_diameter_m"] = 2 * d.reference_radius_m;
  g["base_diameter_m"] = 2 * d.base_radius_m;
  g["tip_diameter_m"] = 2 * d.tip_radius_m;
  g["root_diameter_m"] = 2 * d.root_radius_m;
  g["form_diameter_m"] = 2 * d.form_radius_m;
  g["tooth_thickness_m"] = d.tooth_thickness_m;
  g["tip_thickness_m"] = d.tip_thickness_m;
  if (s.kind == GearKind::External) {
    g["span_teeth"] = d.span_teeth;
    g["span_m"] = d.span_m;
  }
  g["errors"] = {{"flank_offsets", s.errors.flank_offsets.size()},
                 {"pitch_errors", s.errors.pitch_errors.size()},
                 {"profile_slopes", s.errors.profile_slopes.size()},
                 {"eccentricity_m", s.errors.eccentricity.eccentricity_m}};
  const MeshReport r = validate_mesh(b.mesh);
  g["mesh"] = {{"triangles", r.triangle_count},
               {"vertices", r.vertex_count},
               {"watertight", r.watertight()},
               {"manifold", r.manifold()},
               {"outward_oriented", r.outward_oriented()},
               {"chordal_deviation_m", s.chordal_deviation_m},
               {"volume_m3", b.mass.volume_m3},
               {"mass_kg", b.mass.mass_kg},
               {"inertia_zz_kg_m2", b.mass.inertia_com_kg_m2(2, 2)}};
  // The pieces are the transverse section's prism: against that (a helical gear's own mesh twists).
  const double half = 0.5 * s.face_width_m;
  const DecompositionDeviation dev =
      decomposition_deviation(s.helix_angle_rad == 0 ? b.mesh : extrude(b.outline.outline, -half, half), b.pieces, spacing);
  std::size_t max_vertices = 0;
  for (const ConvexPiece2& p : b.decomposition.pieces) max_vertices = std::max(max_vertices, p.polygon.points.size());
  g["decomposition"] = {{"pieces", b.decomposition.pieces.size()}, {"sectors_exact", b.decomposition.sectors_exact},
                        {"max_piece_vertices", max_vertices},      {"hausdorff_m", dev.hausdorff_m},
                        {"hausdorff_sample_spacing_m", spacing},   {"relative_volume_error", dev.relative_volume_error}};
  return g;
}

json mesh_json(const MeshGeometry& m) {
  return {{"centre_distance_m", m.centre_distance_m},
          {"working_pressure_angle_deg", m.working_pressure_angle_rad * kDegPerRad},
          {"contact_ratio", m.contact_ratio},
          {"overlap_ratio", m.overlap_ratio},
          {"total_contact_ratio", m.contact_ratio + m.overlap_ratio},
          {"effective_contact_ratio", m.effective_contact_ratio},
          {"active_start_roll_a_m", m.active_start_roll_a_m},
          {"form_roll_a_m", m.form_roll_a_m},
          {"tip_interference_a_m", m.tip_interference_a_m},
          {"tip_interference_b_m", m.tip_interference_b_m},
          {"problems", m.problems}};
}

// Names one of our diameters equal (within 1 µm) to a published value, or "".
std::string matching_diameter(const json& gear, double value_m) {
  for (const char* k : {"reference_diameter_m", "tip_diameter_m", "root_diameter_m", "base_diameter_m", "form_diameter_m"})
    if (std::abs(gear[k].get<double>() - value_m) < 1e-6) return k;
  return "";
}

}  // namespace

GearSetAnalysis analyse_gearset(const input::GearSetFile& f, double spacing) {
  GearSetAnalysis a;
  a.file = &f;
  json& doc = a.doc;
  doc["name"] = f.name;
  doc["spec_file"] = f.path.string();
  doc["density_kg_m3"] = f.density_kg_m3;
  doc["gears"] = json::object();
  for (const GearSpec& s : f.gears) {
    GearBody b = make_gear_body(s, f.density_kg_m3);
    doc["gears"][s.name] = gear_json(b, spacing);
    a.bodies.emplace(s.name, std::move(b));
  }
  if (f.planetary) {
    const PlanetaryGeometry p = analyse_planetary(*f.planetary);
    json placements = json::array();
    for (const PlanetPlacement& pl : p.placements)
      placements.push_back({{"carrier_angle_deg", pl.carrier_angle_rad * kDegPerRad}, {"spin_angle_deg", pl.spin_angle_rad * kDegPerRad}});
    doc["train"] = {{"type", "planetary"},
                    {"sun", f.planetary->sun.name},
                    {"planet", f.planetary->planet.name},
                    {"ring", f.planetary->ring.name},
                    {"planets", f.planetary->planets},
                    {"ratio_sun_to_carrier", p.ratio_sun_to_carrier},
                    {"centre_distance_m", p.centre_distance_m},
                    {"assembly_quotient", p.assembly_quotient},
                    {"equally_spaced_assembly", p.equally_spaced_assembly},
                    {"adjacency_clearance_m", p.adjacency_clearance_m},
                    {"ring_angle_deg", p.ring_angle_rad * kDegPerRad},
                    {"placements", placements},
                    {"sun_planet", mesh_json(p.sun_planet)},
                    {"planet_ring", mesh_json(p.planet_ring)},
                    {"problems", p.problems}};
  } else if (f.pair) {
    const GearSpec &a1 = f.gear(f.pair->first), &b1 = f.gear(f.pair->second);
    const MeshGeometry m = analyse_mesh(a1, b1, zero_backlash_centre_distance(a1, b1));
    doc["train"] = {{"type", "pair"}, {"driver", a1.name}, {"driven", b1.name}, {"ratio", m.ratio}, {"mesh", mesh_json(m)}};
  }
  if (f.tolerance_quality) {
    json tol = json::object();
    for (const GearSpec& s : f.gears) {
      ToleranceInput in{s.module_m * 1e3, s.teeth, s.module_m * s.teeth * 1e3, *f.tolerance_quality, std::nullopt};
      tol[s.name] = {{"din3961", tolerance_result_json(paper_tolerances(in, ToleranceStandard::Din3961))},
                     {"iso1328", tolerance_result_json(paper_tolerances(in, ToleranceStandard::Iso1328))}};
    }
    doc["tolerance"] = {{"quality", *f.tolerance_quality}, {"gears", tol}};
  }
  if (!f.reference.empty()) {
    json rows = json::array();
    for (const auto& [name, ref] : f.reference)
      for (const auto& [key, value] : ref.diameters_m) {
        const json& g = doc["gears"][name];
        const double ours = g[key].get<double>();
        const std::string same = matching_diameter(g, value);
        std::string note = std::abs(ours - value) < 1e-6 ? "agrees"
                           : !same.empty()               ? "the published value is our " + same
                                                         : "matches none of our diameters";
        rows.push_back(
            {{"gear", name}, {"key", key}, {"published_m", value}, {"ours_m", ours}, {"difference_m", value - ours}, {"note", note}});
      }
    doc["reference"] = {{"source", f.reference_source}, {"rows", rows}};
  }
  return a;
}

}  // namespace gearsim::app

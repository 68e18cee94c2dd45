#include "app/mesh_inspection.hpp"

#include <chrono>
#include <numbers>

#include "contact/flank_table.hpp"
#include "core/errors.hpp"
#include "geometry/approx_decomposition.hpp"
#include "geometry/convex_decomposition.hpp"
#include "geometry/hausdorff.hpp"
#include "geometry/mass_properties.hpp"
#include "geometry/mesh_io.hpp"
#include "geometry/mesh_validate.hpp"
#include "geometry/prism.hpp"

namespace gearsim::app {
namespace {

using gearsim::constants::kDegPerRad;

json flank_fit_json(const InvoluteFit& f) {
  json j;
  j["involute"] = f.involute;
  j["base_radius_mm"] = f.base_radius_m * 1e3;
  j["base_half_angle_deg"] = f.base_half_angle_rad * kDegPerRad;
  j["rms_um"] = f.rms_m * 1e6;
  j["active_from_mm"] = f.active_from_m * 1e3;
  j["active_to_mm"] = f.active_to_m * 1e3;
  j["points"] = f.points;
  j["outlier_teeth"] = f.outlier_teeth;
  j["largest_outlier_um"] = f.largest_outlier_m * 1e6;
  return j;
}

// The gear the outline is, and how faithfully the contact's flank table follows its teeth.
json gear_json(const MeshGear& mg, const std::optional<ToothLayout>& given, LengthUnit unit) {
  json j;
  if (!mg.recognition) {
    j["recognised"] = false;
    j["reason"] = mg.recognition.reason();
    return j;
  }
  const RecognisedGear& g = *mg.recognition;
  j["recognised"] = true;
  j["teeth"] = g.teeth;
  j["tooth0_deg"] = g.tooth0_angle_rad * kDegPerRad;
  j["internal"] = g.internal;
  j["toothed_loop"] = g.loop < 0 ? std::string("outer") : "hole " + std::to_string(g.loop);
  j["axis_offset_mm"] = {mg.axis_offset_m.x() * 1e3, mg.axis_offset_m.y() * 1e3};
  j["tip_radius_mm"] = g.tip_radius_m * 1e3;
  j["root_radius_mm"] = g.root_radius_m * 1e3;
  j["symmetry_residual_um"] = g.symmetry_residual_m * 1e6;
  j["involute"] = g.involute;
  j["asymmetric"] = g.asymmetric;
  j["flank_ccw"] = flank_fit_json(g.ccw);
  j["flank_cw"] = flank_fit_json(g.cw);
  if (g.involute) {
    j["base_radius_mm"] = g.base_radius_m * 1e3;
    j["base_pitch_mm"] = g.base_pitch_m * 1e3;
    j["module_mm"] = g.module_m * 1e3;
    j["pressure_angle_deg"] = g.pressure_angle_rad * kDegPerRad;
    j["standard_module_and_angle"] = g.standard;
    j["reference_radius_mm"] = g.reference_radius_m * 1e3;
    j["reference_thickness_mm"] = g.reference_thickness_m * 1e3;
    if (!g.internal) j["profile_shift_incl_backlash_allowance"] = g.profile_shift;
  }
  json warnings = json::array();
  if (const Check u = check_unit(g, unit); !u) warnings.push_back(u.reason());
  const ToothLayout layout = given.value_or(ToothLayout{g.teeth, g.tooth0_angle_rad});
  if (given)
    if (const Check m = check_layout(g, *given); !m) warnings.push_back("--teeth/--tooth0-deg: " + m.reason());
  if (layout.teeth == g.teeth) {
    // The contact's flank table of these teeth, and how far it strays from the outline.
    const Polygon2& loop = g.loop < 0 ? mg.outline.outer : mg.outline.holes[static_cast<std::size_t>(g.loop)];
    try {
      const contact::FlankTable t(loop, layout, g.internal, 4096);
      const contact::FlankTable::Departure& d = t.departure();
      j["flank_table"] = {{"departure_um", d.departure_m * 1e6},
                          {"at_tooth", d.tooth},
                          {"at_flank", d.flank == Flank::Ccw ? "ccw" : "cw"},
                          {"at_radius_mm", d.r_m * 1e3},
                          {"outline_resolution_um", t.knot_resolution_m() * 1e6}};
    } catch (const InputError& e) {
      warnings.push_back(std::string("flank table: ") + e.what());
    }
  }
  j["warnings"] = warnings;
  return j;
}

}  // namespace

json inspect_mesh(const InspectOptions& o) {
  const std::optional<LengthUnit> unit = parse_length_unit(o.unit);
  if (!unit) throw InputError("--unit: unknown length unit '" + o.unit + "' (expected m, cm, mm, um, in, ft)");
  const TriMesh mesh = import_mesh(o.mesh, *unit);
  const MeshReport r = validate_mesh(mesh);
  json j;
  j["file"] = o.mesh;
  j["unit"] = o.unit;
  j["triangles"] = r.triangle_count;
  j["vertices"] = r.vertex_count;
  j["watertight"] = r.watertight();
  j["manifold"] = r.manifold();
  j["consistently_oriented"] = r.consistently_oriented();
  j["outward_oriented"] = r.outward_oriented();
  j["finite"] = r.finite();
  j["degenerate_faces"] = r.degenerate_face_count;
  require_valid_solid(r, o.mesh);  // a clear error naming the first offending face or edge
  const MassProperties m = mass_properties(mesh, o.density_kg_m3);
  j["volume_mm3"] = m.volume_m3 * 1e9;
  j["density_kg_m3"] = o.density_kg_m3;
  j["mass_kg"] = m.mass_kg;
  j["centre_of_mass_mm"] = {m.centre_of_mass_m.x() * 1e3, m.centre_of_mass_m.y() * 1e3, m.centre_of_mass_m.z() * 1e3};
  json inertia = json::array();
  for (int i = 0; i < 3; ++i) inertia.push_back({m.inertia_com_kg_m2(i, 0), m.inertia_com_kg_m2(i, 1), m.inertia_com_kg_m2(i, 2)});
  j["inertia_com_kg_m2"] = inertia;
  j["principal_moments_kg_m2"] = {m.principal_moments_kg_m2.x(), m.principal_moments_kg_m2.y(), m.principal_moments_kg_m2.z()};

  const Result<Prism> pr = recover_prism(mesh, o.prism_tolerance_um * 1e-6);
  j["prismatic"] = pr.ok();
  if (!pr) {
    // No exact decomposition: Bullet's HACD, with its deviation measured against the mesh.
    j["not_prismatic_because"] = pr.reason();
    ApproxDecompositionOptions opt;
    if (o.teeth > 0) opt.tooth_layout = ToothLayout{o.teeth, o.tooth0_deg * std::numbers::pi / 180.0};
    opt.sample_spacing_m = o.spacing_mm * 1e-3;
    const ApproxDecomposition ad = approximate_decomposition(mesh, opt);
    j["convex_pieces"] = ad.pieces.pieces.size();
    j["decomposition_method"] = ad.method;
    j["max_deviation_um"] = ad.deviation_m * 1e6;
    j["deviation_sample_spacing_mm"] = ad.sample_spacing_m * 1e3;
    json warnings = json::array();
    warnings.push_back("not a prism: no exact decomposition (" + pr.reason() + ")");
    for (const std::string& w : ad.warnings) warnings.push_back(w);
    j["warnings"] = warnings;
    return j;
  }
  DecompositionOptions opt;
  if (o.teeth > 0) opt.tooth_layout = ToothLayout{o.teeth, o.tooth0_deg * std::numbers::pi / 180.0};
  const auto t0 = std::chrono::steady_clock::now();
  const ConvexDecomposition d = decompose(pr->outline, opt);
  const ConvexPieces3 pieces = extrude_pieces(d, *pr);
  const double decompose_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const DecompositionDeviation dev = decomposition_deviation(mesh, pieces, o.spacing_mm * 1e-3);
  j["prism_height_mm"] = pr->height_m * 1e3;
  // How far the side walls' own vertices lie from the outline (an exporter's tessellation of a curved
  // wall between the caps; 0 for an exact prism).
  j["prism_wall_deviation_um"] = pr->wall_deviation_m * 1e6;
  j["outline_holes"] = pr->outline.holes.size();
  j["convex_pieces"] = d.pieces.size();
  j["tooth_sectors_exact"] = d.sectors_exact;
  if (!d.fallback_reason.empty()) j["sector_fallback_reason"] = d.fallback_reason;
  j["decompose_seconds"] = decompose_s;
  j["max_deviation_um"] = dev.hausdorff_m * 1e6;
  j["deviation_sample_spacing_mm"] = o.spacing_mm;
  j["relative_volume_error"] = dev.relative_volume_error;
  j["warnings"] = json::array();
  std::optional<ToothLayout> given;
  if (o.teeth > 0) given = ToothLayout{o.teeth, o.tooth0_deg * std::numbers::pi / 180.0};
  j["gear"] = gear_json(mesh_gear(*pr), given, *unit);
  return j;
}

}  // namespace gearsim::app

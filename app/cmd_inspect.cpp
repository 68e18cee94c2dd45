// gearsim inspect MESH: what a CAD mesh is, before it becomes a body. Topology checks, exact mass
// properties, and the convex decomposition the physics would use (exact for prisms), with the
// decomposition's deviation measured against the mesh.
#include <chrono>
#include <iostream>
#include <memory>
#include <numbers>

#include "app/commands.hpp"
#include "app/tolerance_report.hpp"
#include "geometry/approx_decomposition.hpp"
#include "geometry/constants.hpp"
#include "geometry/convex_decomposition.hpp"
#include "geometry/errors.hpp"
#include "geometry/hausdorff.hpp"
#include "geometry/mass_properties.hpp"
#include "geometry/mesh_io.hpp"
#include "geometry/mesh_validate.hpp"
#include "geometry/prism.hpp"

namespace gearsim::app {
namespace {

struct InspectOptions {
  std::string mesh;
  std::string unit = "mm";
  double density_kg_m3 = constants::kPaperSteelDensity_kg_m3;
  int teeth = 0;
  double tooth0_deg = 0;
  double prism_tolerance_um = 0.1;
  double spacing_mm = 0.5;
  bool json_only = false;
};

json inspect(const InspectOptions& o) {
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
  for (int i = 0; i < 3; ++i)
    inertia.push_back({m.inertia_com_kg_m2(i, 0), m.inertia_com_kg_m2(i, 1), m.inertia_com_kg_m2(i, 2)});
  j["inertia_com_kg_m2"] = inertia;
  j["principal_moments_kg_m2"] = {m.principal_moments_kg_m2.x(), m.principal_moments_kg_m2.y(), m.principal_moments_kg_m2.z()};

  const PrismRecovery pr = recover_prism(mesh, o.prism_tolerance_um * 1e-6);
  j["prismatic"] = pr.prism.has_value();
  if (!pr.prism) {
    // No exact decomposition: Bullet's HACD, with its deviation measured against the mesh.
    j["not_prismatic_because"] = pr.reason;
    ApproxDecompositionOptions opt;
    if (o.teeth > 0) opt.tooth_layout = ToothLayout{o.teeth, o.tooth0_deg * std::numbers::pi / 180.0};
    opt.sample_spacing_m = o.spacing_mm * 1e-3;
    const ApproxDecomposition ad = approximate_decomposition(mesh, opt);
    j["convex_pieces"] = ad.pieces.pieces.size();
    j["decomposition_method"] = ad.method;
    j["max_deviation_um"] = ad.deviation_m * 1e6;
    j["deviation_sample_spacing_mm"] = ad.sample_spacing_m * 1e3;
    json warnings = json::array();
    warnings.push_back("not a prism: no exact decomposition (" + pr.reason + ")");
    for (const std::string& w : ad.warnings) warnings.push_back(w);
    j["warnings"] = warnings;
    return j;
  }
  DecompositionOptions opt;
  if (o.teeth > 0) opt.tooth_layout = ToothLayout{o.teeth, o.tooth0_deg * std::numbers::pi / 180.0};
  const auto t0 = std::chrono::steady_clock::now();
  const ConvexDecomposition d = decompose(pr.prism->outline, opt);
  const ConvexPieces3 pieces = extrude_pieces(d, *pr.prism);
  const double decompose_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const DecompositionDeviation dev = decomposition_deviation(mesh, pieces, o.spacing_mm * 1e-3);
  j["prism_height_mm"] = pr.prism->height_m * 1e3;
  j["outline_holes"] = pr.prism->outline.holes.size();
  j["convex_pieces"] = d.pieces.size();
  j["tooth_sectors_exact"] = d.sectors_exact;
  if (!d.fallback_reason.empty()) j["sector_fallback_reason"] = d.fallback_reason;
  j["decompose_seconds"] = decompose_s;
  j["max_deviation_um"] = dev.hausdorff_m * 1e6;
  j["deviation_sample_spacing_mm"] = o.spacing_mm;
  j["relative_volume_error"] = dev.relative_volume_error;
  j["warnings"] = json::array();
  return j;
}

void print(const json& j) {
  for (const auto& [k, v] : j.items()) std::cout << "  " << pad(k, 28) << v.dump() << "\n";
}

}  // namespace

void register_inspect(CLI::App& app) {
  auto o = std::make_shared<InspectOptions>();
  CLI::App* sub = app.add_subcommand(
      "inspect",
      "Inspect a CAD mesh (any format Assimp reads: STL, OBJ, PLY, ...): topology checks, mass "
      "properties, and the convex decomposition Bullet would get, with its measured deviation.");
  sub->add_option("mesh", o->mesh, "Mesh file.")->required()->check(CLI::ExistingFile);
  sub->add_option("--unit", o->unit, "Length unit of the file's coordinates: m, cm, mm, um, in, ft. Default mm (CAD).");
  sub->add_option("--density", o->density_kg_m3, "Density in kg/m³ for the mass properties. Default 7580 (the paper's steel).")
      ->check(CLI::PositiveNumber);
  sub->add_option("--teeth", o->teeth, "Number of teeth: cut the decomposition into per-tooth sectors (tooth index per piece).")
      ->check(CLI::Range(3, 100000));
  sub->add_option("--tooth0-deg", o->tooth0_deg, "Polar angle of tooth 0's centre line, in degrees. Default 0.");
  sub->add_option("--prism-tolerance", o->prism_tolerance_um,
                  "How far, in µm, a vertex may lie off the two cap planes and still count as a prism. Default 0.1 "
                  "(STL stores float32: ~0.003 µm at gear scale).")
      ->check(CLI::PositiveNumber);
  sub->add_option("--hausdorff-spacing", o->spacing_mm, "Sample spacing, in mm, of the deviation measurement (every vertex is sampled; edges and faces at this spacing). Default 0.5.")
      ->check(CLI::PositiveNumber);
  sub->add_flag("--json", o->json_only, "Print JSON instead of a list.");
  sub->callback([o] {
    const json j = inspect(*o);
    if (o->json_only) std::cout << j.dump(2) << "\n";
    else print(j);
  });
}

}  // namespace gearsim::app

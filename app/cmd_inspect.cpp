// gearsim inspect MESH: what a CAD mesh is, before it becomes a body (app/mesh_inspection.hpp):
// topology checks, exact mass properties, and the convex decomposition the physics would use
// (exact for prisms), with the decomposition's deviation measured against the mesh.
#include <algorithm>
#include <iostream>
#include <memory>

#include "app/commands.hpp"
#include "app/mesh_inspection.hpp"
#include "input/input_limits.hpp"

namespace gearsim::app {
namespace {

struct InspectCliOptions : InspectOptions {
  bool json_only = false;
};

void print(const json& j, const std::string& indent = "  ") {
  for (const auto& [k, v] : j.items()) {
    if (v.is_object()) {
      std::cout << indent << k << ":\n";
      print(v, indent + "  ");
    } else {
      std::cout << indent << pad(k, static_cast<std::size_t>(std::max(8, 30 - static_cast<int>(indent.size())))) << v.dump() << "\n";
    }
  }
}

}  // namespace

void register_inspect(CLI::App& app) {
  auto o = std::make_shared<InspectCliOptions>();
  CLI::App* sub =
      app.add_subcommand("inspect",
                         "Inspect a CAD mesh (any format Assimp reads: STL, OBJ, PLY, ...): topology checks, mass "
                         "properties, the convex decomposition Bullet would get with its measured deviation, and the gear "
                         "recognised from the outline (tooth count, tooth 0, involute fit, module, pressure angle, thickness) with "
                         "the departure of the contact's flank table from it.");
  sub->add_option("mesh", o->mesh, "Mesh file.")->required()->check(CLI::ExistingFile);
  sub->add_option("--unit", o->unit, "Length unit of the file's coordinates: m, cm, mm, um, in, ft. Default mm (CAD).");
  using namespace input::limits;
  sub->add_option("--density", o->density_kg_m3, "Density in kg/m³ for the mass properties. Default 7580 (the paper's steel).")
      ->check(input::cli_within(kDensity_kg_m3));
  sub->add_option("--teeth", o->teeth, "Number of teeth: cut the decomposition into per-tooth sectors (tooth index per piece).")
      ->check(input::cli_within(kTeeth));
  sub->add_option("--tooth0-deg", o->tooth0_deg, "Polar angle of tooth 0's centre line, in degrees. Default 0.")
      ->check(input::cli_within(input::limit_in_degrees(kAngle_rad)));
  sub->add_option("--prism-tolerance", o->prism_tolerance_um,
                  "How far, in µm, a vertex may lie off the two cap planes and still count as a prism. Default 2, "
                  "as for scenario meshes (STL stores float32: ~0.003 µm at gear scale; CAD noise ~1 µm).")
      ->check(input::cli_within(kPrismTolerance_um));
  sub->add_option(
         "--hausdorff-spacing", o->spacing_mm,
         "Sample spacing, in mm, of the deviation measurement (every vertex is sampled; edges and faces at this spacing). Default 0.5.")
      ->check(input::cli_within(kSampleSpacing_mm));
  sub->add_flag("--json", o->json_only, "Print JSON instead of a list.");
  sub->callback([o] {
    const json j = inspect_mesh(*o);
    if (o->json_only)
      std::cout << j.dump(2) << "\n";
    else
      print(j);
  });
}

}  // namespace gearsim::app

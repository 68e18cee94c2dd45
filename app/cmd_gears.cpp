// gearsim gears SPEC [--out DIR]: generate every gear of a gear-set spec file, check meshes,
// decomposition and the train, print the gear table (with published values and tolerances when
// the spec carries them), and write STL/OBJ meshes and gearset.json to DIR.
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>

#include "app/commands.hpp"
#include "app/gear_report.hpp"
#include "app/output_folder.hpp"
#include "input/input_limits.hpp"
#include "input/safe_name.hpp"
#include "core/errors.hpp"
#include "geometry/mesh_io.hpp"
#include "core/output_file.hpp"

namespace gearsim::app {
namespace {

struct GearsOptions {
  std::string spec;
  std::string out_dir;
  std::vector<std::string> formats{"stl", "obj"};
  bool json_only = false;
  double hausdorff_spacing_mm = 0.5;
};

// The file name ending of a --formats value.
std::string extension_of(const std::string& format) { return format == "obj" ? ".obj" : format == "stl-ascii" ? ".ascii.stl" : ".stl"; }

void write_outputs(const GearsOptions& o, const GearSetAnalysis& a) {
  const std::filesystem::path dir(o.out_dir);
  OutputFolder folder(dir, "gearsim gears");
  std::vector<std::string> names{"gearset.json"};
  for (const auto& [name, body] : a.bodies) {
    // Files only inside DIR: the spec reader refuses other names; this guards every other source.
    if (!input::is_safe_name(name, input::NameUse::File))
      throw InputError("gear '" + input::shown_name(name) + "': expected " + input::safe_name_rule(input::NameUse::File) +
                       " (it names a file in " + dir.string() + ")");
    for (const std::string& f : o.formats) names.push_back(name + extension_of(f));
  }
  folder.declare(names);
  for (const auto& [name, body] : a.bodies) {
    for (const std::string& f : o.formats) {
      const MeshFormat fmt = f == "obj" ? MeshFormat::Obj : f == "stl-ascii" ? MeshFormat::StlAscii : MeshFormat::StlBinary;
      export_mesh(body.mesh, dir / (name + extension_of(f)), fmt, LengthUnit::Millimetre);
    }
  }
  json doc = a.doc;
  doc["mesh_files"] = {{"folder", dir.string()}, {"unit", "mm"}, {"formats", o.formats}};
  write_output_file(dir / "gearset.json", doc.dump(2) + "\n");
}

void run(const GearsOptions& o) {
  const input::GearSetFile file = input::load_gearset(o.spec);
  const GearSetAnalysis a = analyse_gearset(file, o.hausdorff_spacing_mm * 1e-3);
  if (o.json_only)
    std::cout << a.doc.dump(2) << "\n";
  else
    print_gearset(std::cout, a.doc);
  if (!o.out_dir.empty()) {
    write_outputs(o, a);
    if (!o.json_only) std::cout << "\nWrote meshes (mm) and gearset.json to " << o.out_dir << "\n";
  }
}

}  // namespace

void register_gears(CLI::App& app) {
  auto o = std::make_shared<GearsOptions>();
  CLI::App* sub = app.add_subcommand("gears",
                                     "Generate the gears of a gear-set spec file (YAML): gear table from first principles, "
                                     "mesh and train checks (contact ratio, interference, assembly), exact convex "
                                     "decomposition, tolerances, and STL/OBJ meshes.");
  sub->add_option("spec", o->spec, "Gear-set spec file (YAML), e.g. assets/specs/paper_gearset.yaml.")
      ->required()
      ->check(CLI::ExistingFile);
  sub->add_option("--out", o->out_dir, "Folder for <gear>.stl/.obj (in mm) and gearset.json; created if missing.");
  sub->add_option("--formats", o->formats, "Mesh formats to write: stl (binary), stl-ascii, obj. Default: stl obj.")
      ->check(CLI::IsMember({"stl", "stl-ascii", "obj"}));
  sub->add_option("--hausdorff-spacing", o->hausdorff_spacing_mm,
                  "Sample spacing, in mm, of the Hausdorff measurement between each mesh and the union of "
                  "its convex pieces. Every outline vertex is sampled; edges and faces at this spacing. Default 0.5.")
      ->check(input::cli_within(input::limits::kSampleSpacing_mm));
  sub->add_flag("--json", o->json_only, "Print the analysis as JSON (lengths in m) instead of tables.");
  sub->callback([o] { run(*o); });
}

}  // namespace gearsim::app

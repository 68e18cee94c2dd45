// gearsim modes SCENARIO: the scenario's model linearised about its start (linear/): natural
// frequencies with their multiplicity and type, strain energy shares, mode shapes, and the
// drive speeds at which mesh harmonics meet them.
#include <filesystem>
#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <limits>

#include "app/commands.hpp"
#include "app/modes_analysis.hpp"
#include "app/modes_outputs.hpp"
#include "app/output_folder.hpp"
#include "core/errors.hpp"
#include "input/input_limits.hpp"
#include "input/scenario_file.hpp"
#include "linear/campbell.hpp"
#include "linear/lumped_model.hpp"
#include "linear/modes.hpp"
#include "physics/world.hpp"
#include "core/output_file.hpp"

namespace gearsim::app {
namespace {

struct ModesOptions {
  std::string scenario;
  std::string out_dir;
  std::vector<std::string> sets;
  std::string drive;  // BODY=ccw|cw
  bool json_only = false;
  int harmonics = 3;
  int phases = 64;
  int pictured = 6;
  double max_speed_rad_s = std::numeric_limits<double>::infinity();
};

void print_table(const linear::LumpedModel& m, const linear::ModalAnalysis& a, const linear::Campbell& c) {
  std::cout << "drive: " << m.drive << "\n" << m.dofs() << " coordinates, " << a.free_coordinates << " free\n";
  for (const linear::MeshInfo& mi : m.meshes)
    std::cout << "  mesh " << m.bodies[mi.a].name << "–" << m.bodies[mi.b].name << ": mean " << mi.mean_N_per_m << " N/m ("
              << mi.min_N_per_m << "…" << mi.max_N_per_m << "), " << std::setprecision(4) << mi.mean_pairs << " tooth pairs\n";
  std::cout << std::setprecision(6) << "  #  frequency_Hz  mult  type           largest strain energy\n";
  for (std::size_t g = 0; g < a.groups.size(); ++g) {
    const linear::ModeGroup& grp = a.groups[g];
    std::cout << std::setw(3) << g << std::setw(14) << grp.frequency_hz << std::setw(6) << grp.multiplicity << "  " << std::left
              << std::setw(15) << linear::to_string(grp.type) << std::right;
    const linear::Mode& md = a.modes[static_cast<std::size_t>(grp.modes.front())];
    if (!md.energy_share.empty()) {
      std::size_t best = 0;
      for (std::size_t e = 1; e < md.energy_share.size(); ++e)
        if (md.energy_share[e] > md.energy_share[best]) best = e;
      std::cout << m.elements[best].name << " " << std::setprecision(3) << 100 * md.energy_share[best] << " %" << std::setprecision(6);
    }
    std::cout << "\n";
  }
  if (!c.why_not.empty())
    std::cout << "Campbell: " << c.why_not << "\n";
  else if (c.operating_speed_rad_s && !c.rates.empty()) {
    // Each distinct mesh frequency (a planetary set's meshes share one; each stage has its own).
    std::cout << "mesh frequency at the motor's " << *c.operating_speed_rad_s << " rad/s:";
    std::vector<double> seen;
    for (const linear::MeshRate& r : c.rates) {
      const double f = r.hz_per_rad_s * *c.operating_speed_rad_s;
      if (std::any_of(seen.begin(), seen.end(), [&](double g) { return std::abs(g - f) <= 1e-9 * f; })) continue;
      seen.push_back(f);
      const linear::MeshInfo& mi = m.meshes[static_cast<std::size_t>(r.mesh)];
      std::cout << (seen.size() > 1 ? "," : "") << " " << f << " Hz (" << m.bodies[mi.a].name << "–" << m.bodies[mi.b].name << ")";
    }
    std::cout << "\n";
  }
}

void modes(const ModesOptions& o) {
  const physics::Scenario s = input::load_scenario(o.scenario, o.sets);
  const ModesResult r = analyse_modes(s, ModesSettings{o.drive, o.harmonics, o.phases, o.max_speed_rad_s});
  const linear::LumpedModel& model = r.model;
  const linear::ModalAnalysis& a = r.modes;
  const linear::Campbell& c = r.campbell;
  const nlohmann::json j = modes_json(s.name, model, a, c);
  if (o.json_only)
    std::cout << j.dump(2) << "\n";
  else
    print_table(model, a, c);
  if (o.out_dir.empty()) return;
  const std::filesystem::path dir(o.out_dir);
  OutputFolder folder(dir, "gearsim modes");
  folder.declare({"modes.json", "mode_shapes.csv", "campbell.csv", "modes.svg"});
  write_output_file(dir / "modes.json", j.dump(2) + "\n");
  write_mode_shapes_csv(dir / "mode_shapes.csv", model, a);
  write_campbell_csv(dir / "campbell.csv", model, c);
  write_modes_svg(dir / "modes.svg", model, a, o.pictured);
  if (!o.json_only) std::cout << "wrote modes.json, mode_shapes.csv, campbell.csv, modes.svg to " << dir.string() << "\n";
}

}  // namespace

void register_modes(CLI::App& app) {
  auto o = std::make_shared<ModesOptions>();
  CLI::App* sub =
      app.add_subcommand("modes", "Natural frequencies, mode types and shapes of a scenario's model linearised about its start.");
  sub->add_option("scenario", o->scenario, "Scenario file (YAML).")->required()->check(CLI::ExistingFile);
  sub->add_option("--out", o->out_dir, "Also write modes.json, mode_shapes.csv, campbell.csv and modes.svg here.");
  sub->add_option("--set", o->sets, "Override a scenario value: key.path=value (repeatable).");
  sub->add_option("--drive", o->drive,
                  "The gear whose torque drives the train and its sense, BODY=ccw|cw (default: the motor's body, "
                  "else the transmission input's load).");
  sub->add_flag("--json", o->json_only, "Print the JSON (modes.json) instead of the table.");
  sub->add_option("--harmonics", o->harmonics, "Mesh harmonics in the Campbell table (default 3).")
      ->check(input::cli_within(input::limits::kModeHarmonics));
  sub->add_option("--phases", o->phases, "Mesh positions per pitch the mean mesh stiffness is taken over (default 64).")
      ->check(input::cli_within(input::limits::kModePhases));
  sub->add_option("--max-speed", o->max_speed_rad_s, "Leave out crossings above this drive speed, rad/s (default: none).")
      ->check(input::cli_within(input::limits::kDriveSpeed_rad_s));
  sub->add_option("--pictured", o->pictured, "Elastic natural frequencies drawn in modes.svg (default 6).")->check(CLI::Range(1, 60));
  sub->callback([o] { modes(*o); });
}

}  // namespace gearsim::app

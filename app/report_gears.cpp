// Report section (for a scenario built from a gear-set spec): the gear table from first
// principles beside the published one, and the
// tolerance table (DIN 3961 and ISO 1328-1), from the gear-set spec the scenario was built from.
#include "app/gear_report.hpp"
#include "input/gearset_file.hpp"
#include "app/html.hpp"
#include "app/report.hpp"

namespace gearsim::app {

using json = nlohmann::ordered_json;

std::string report_gears_section(const RunDir& run) {
  // The gears themselves are in the gearbox section (report_train.cpp) for any scenario.
  if (run.scenario.gearset_spec.empty()) return "";
  std::string h = "<h2>The gear-set spec</h2>\n";
  const input::GearSetFile file = input::load_gearset(run.scenario.gearset_spec);
  // Decomposition deviation sampled coarsely: the report shows the gear table, not the pieces.
  const GearSetAnalysis a = analyse_gearset(file, 2e-3);
  const json& doc = a.doc;
  h += "<p>From <code>" + html_escape(run.scenario.gearset_spec.string()) +
       "</code>, computed from first principles (d = m·z, d<sub>a</sub>, d<sub>f</sub> from the basic rack).</p>\n";
  std::vector<std::vector<std::string>> rows;
  for (const auto& [name, g] : doc["gears"].items())
    rows.push_back({html_escape(name), g["kind"].get<std::string>(), std::to_string(g["teeth"].get<int>()),
                    num(g["module_m"].get<double>() * 1e3), num(g["reference_diameter_m"].get<double>() * 1e3, 6),
                    num(g["base_diameter_m"].get<double>() * 1e3, 6), num(g["tip_diameter_m"].get<double>() * 1e3, 6),
                    num(g["root_diameter_m"].get<double>() * 1e3, 6), num(g["face_width_m"].get<double>() * 1e3)});
  h += html_table({"gear", "kind", "z", "m, mm", "d, mm", "d<sub>b</sub>, mm", "d<sub>a</sub>, mm", "d<sub>f</sub>, mm", "b, mm"}, rows);
  if (doc.contains("reference")) {
    h += "<h3>Against the paper's Table 1</h3>\n";
    rows.clear();
    for (const auto& r : doc["reference"]["rows"])
      rows.push_back({html_escape(r["gear"].get<std::string>()), html_escape(r["key"].get<std::string>()),
                      num(r["published_m"].get<double>() * 1e3, 6), num(r["ours_m"].get<double>() * 1e3, 6),
                      html_escape(r["note"].get<std::string>())});
    h += html_table({"gear", "quantity", "paper, mm", "ours, mm", "why"}, rows);
    h += "<p class=\"note\">An internal gear's root lies outside its reference circle (d<sub>f</sub> = d + 2·1.25·m), "
         "so the paper's ring values are its root and tip diameters under other names; the paper's planet root "
         "diameter matches no diameter of the planet.</p>\n";
  }
  if (doc.contains("tolerance")) {
    h += "<h3>Single flank error, quality " + std::to_string(doc["tolerance"]["quality"].get<int>()) + "</h3>\n";
    rows.clear();
    for (const auto& [name, t] : doc["tolerance"]["gears"].items())
      for (const auto& [standard, r] : t.items())
        rows.push_back({html_escape(name), html_escape(r["standard_name"].get<std::string>()),
                        html_escape(r["step_rule"].get<std::string>()), num(r["single_flank_error_um"].get<double>()),
                        num(r["total_pitch_um"].get<double>()), num(r["total_profile_um"].get<double>())});
    h += html_table({"gear", "standard", "class step", "f'<sub>i</sub>, µm", "F<sub>p</sub>, µm", "F<sub>α</sub>, µm"}, rows);
  }
  return h;
}

}  // namespace gearsim::app

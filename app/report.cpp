#include "app/report.hpp"

#include <algorithm>
#include <filesystem>

#include "app/html.hpp"
#include "app/run_analysis.hpp"

namespace gearsim::app {

using json = nlohmann::ordered_json;
namespace {

// Rendered frames of the run (render/ writes them under DIR/frames/), a few embedded.
std::string frames_section(const RunDir& run) {
  const std::filesystem::path dir = run.dir / "frames";
  std::string h = "<h2>Rendered frames</h2>\n";
  if (!std::filesystem::is_directory(dir)) return h + "<p class=\"note\">This run has no rendered frames.</p>\n";
  // The contact sheets `render` made (one per camera), else the first few frames.
  std::vector<std::filesystem::path> pngs, sheets;
  for (const auto& e : std::filesystem::directory_iterator(dir))
    if (e.path().extension() == ".png")
      (e.path().filename().string().find("_sheet") != std::string::npos ? sheets : pngs).push_back(e.path());
  std::sort(pngs.begin(), pngs.end());
  std::sort(sheets.begin(), sheets.end());
  for (const auto& p : sheets) h += "<p>" + html_png(p, p.filename().string(), 960) + "</p>\n";
  for (std::size_t i = 0; sheets.empty() && i < pngs.size() && i < 4; ++i) h += html_png(pngs[i], pngs[i].filename().string(), 440) + "\n";
  return h;
}

std::string run_section(const RunDir& run) {
  const json& s = run.summary;
  std::vector<std::vector<std::string>> rows{
      {"scenario", html_escape(run.scenario.name) + " (<code>" + html_escape(run.scenario.source.string()) + "</code>)"},
      {"simulated", num(s.value("sim_seconds", 0.0)) + " s in " + std::to_string(s.value("steps", 0L)) + " steps of " +
                        num(s.value("time_step_s", 0.0)) + " s; " + num(s.value("wall_seconds", 0.0), 3) + " s wall"},
      {"speed ratio in/out", s.contains("ratio") ? num(s["ratio"].get<double>(), 9) : "–"}};
  if (s.contains("power_W"))
    rows.push_back({"power balance", "motor " + num(s["power_W"]["motor_input"].get<double>(), 5) + " W = load " +
                                         num(s["power_W"]["load_output"].get<double>(), 5) + " W + contacts " +
                                         num(s["power_W"]["contact_dissipation"].get<double>(), 3) + " W + joints " +
                                         num(s["power_W"]["joint_dissipation"].get<double>(), 3) + " W (imbalance " +
                                         num(s["power_W"]["imbalance_fraction"].get<double>(), 2) + ")"});
  rows.push_back({"warnings", s.contains("warnings") && !s["warnings"].empty() ? html_escape(s["warnings"].dump()) : "none"});
  return "<h2>The run</h2>\n" + html_table({"", ""}, rows);
}

}  // namespace

std::string build_report(const RunDir& run, const std::optional<RunDir>& compare) {
  std::string body = "<h1>Gearsim report: " + html_escape(run.scenario.name) + "</h1>\n";
  if (compare)
    body += "<p>Compared with <b>" + html_escape(compare->scenario.name) + "</b> (" + html_escape(compare->dir.string()) + ").</p>\n";
  body += run_section(run) + report_train_section(run) + (reproduces_paper(run) ? report_paper_section(run) : std::string()) +
          report_gears_section(run) + report_signals_section(run, compare) + report_sensors_section(run, compare) +
          report_sampling_section(run) + frames_section(run);
  return html_document("Gearsim report: " + run.scenario.name, body);
}

}  // namespace gearsim::app

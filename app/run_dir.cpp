#include "app/run_dir.hpp"

#include <fstream>
#include <iomanip>

#include "input/scenario_file.hpp"
#include "core/errors.hpp"

namespace gearsim::app {

RunDir open_run_dir(const std::filesystem::path& dir) {
  RunDir run;
  run.dir = dir;
  const std::filesystem::path summary_path = dir / "summary.json";
  std::ifstream in(summary_path);
  if (!in) throw InputError(summary_path.string() + ": cannot read (is " + dir.string() + " the --out folder of a `gearsim run`?)");
  try {
    run.summary = nlohmann::ordered_json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw InputError(summary_path.string() + ": not valid JSON: " + e.what());
  }
  if (!run.summary.contains("scenario_file") || !run.summary["scenario_file"].is_string())
    throw InputError(summary_path.string() + ": key 'scenario_file': expected the path of the run's scenario (written by gearsim run)");
  const std::filesystem::path scenario_file = run.summary["scenario_file"].get<std::string>();
  if (!std::filesystem::exists(scenario_file))
    throw InputError(summary_path.string() + ": key 'scenario_file': " + scenario_file.string() + " no longer exists");
  std::vector<std::string> overrides;
  if (run.summary.contains("overrides")) {
    if (!run.summary["overrides"].is_array())
      throw InputError(summary_path.string() + ": key 'overrides': expected a list of key.path=value strings");
    for (const auto& o : run.summary["overrides"]) {
      if (!o.is_string()) throw InputError(summary_path.string() + ": key 'overrides': expected strings");
      overrides.push_back(o.get<std::string>());
    }
  }
  run.scenario = input::load_scenario(scenario_file, overrides);
  if (run.summary.contains("sim_seconds") && run.summary["sim_seconds"].is_number())
    run.scenario.duration_s = run.summary["sim_seconds"].get<double>();
  return run;
}

void save_summary(const RunDir& run) {
  const std::filesystem::path p = run.dir / "summary.json";
  std::ofstream out(p);
  if (!out) throw InputError(p.string() + ": cannot write");
  out << run.summary.dump(2) << "\n";
}

std::ofstream open_output(const std::filesystem::path& p, int precision) {
  std::ofstream f(p);
  if (!f) throw InputError(p.string() + ": cannot write");
  f << std::setprecision(precision);
  return f;
}

}  // namespace gearsim::app

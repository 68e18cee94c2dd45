#include "app/run_dir.hpp"

#include <fstream>
#include <iomanip>

#include "input/scenario_record.hpp"
#include "core/errors.hpp"
#include "core/output_file.hpp"

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
  run.scenario = input::read_scenario_record(dir);
  if (run.summary.contains("sim_seconds") && run.summary["sim_seconds"].is_number())
    run.scenario.duration_s = run.summary["sim_seconds"].get<double>();
  return run;
}

void save_summary(const RunDir& run) {
  const std::filesystem::path p = run.dir / "summary.json";
  std::ofstream out = open_output_file(p);
  if (!out) throw InputError(p.string() + ": cannot write");
  out << run.summary.dump(2) << "\n";
}

std::ofstream open_output(const std::filesystem::path& p, int precision) {
  std::ofstream f = open_output_file(p);
  if (!f) throw InputError(p.string() + ": cannot write");
  f << std::setprecision(precision);
  return f;
}

}  // namespace gearsim::app

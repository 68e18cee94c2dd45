#include "app/run_dir.hpp"

#include <fstream>
#include <iomanip>

#include "input/scenario_record.hpp"
#include "core/errors.hpp"
#include "core/input_file.hpp"
#include "core/output_file.hpp"
#include "input/input_limits.hpp"
#include "input/run_record_check.hpp"

namespace gearsim::app {

RunDir open_run_dir(const std::filesystem::path& dir) {
  RunDir run;
  run.dir = dir;
  const std::filesystem::path summary_path = dir / "summary.json";
  if (!std::filesystem::exists(std::filesystem::symlink_status(summary_path)))
    throw InputError(summary_path.string() + ": not found (is " + dir.string() + " the --out folder of a `gearsim run`?)");
  const std::string text = read_input_file(summary_path, input::limits::kMaxRecordBytes, "a run's summary record");
  try {
    run.summary = nlohmann::ordered_json::parse(text);
  } catch (const nlohmann::json::exception& e) {
    throw InputError(summary_path.string() + ": not valid JSON: " + e.what());
  }
  input::validate_summary_record(run.summary, summary_path.string());
  run.scenario = input::read_scenario_record(dir);
  if (run.summary.contains("sim_seconds") && run.summary["sim_seconds"].is_number())
    run.scenario.duration_s = run.summary["sim_seconds"].get<double>();
  return run;
}

nlohmann::ordered_json read_json_record(const std::filesystem::path& file) {
  const std::string text = read_input_file(file, input::limits::kMaxRecordBytes, "a JSON record");
  try {
    return nlohmann::ordered_json::parse(text);
  } catch (const nlohmann::json::exception& e) {
    throw InputError(file.string() + ": not valid JSON: " + e.what());
  }
}

void save_summary(const RunDir& run) { write_output_file(run.dir / "summary.json", run.summary.dump(2) + "\n", Durability::Record); }

}  // namespace gearsim::app

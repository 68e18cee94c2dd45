// A scenario run into a folder, as `gearsim run` does it, callable as a library function: the
// CLI (cmd_run.cpp) and the Python module (python/) both call it, so both write the same files.
// prepare_run_dir clears a previous run's outputs; run_into_dir writes the scenario record
// (scenario.json, gearset.yaml), the logs through sim::simulate's observers (state.csv,
// contacts.csv, sensors.csv, steps.h5) and summary.json. Prints nothing, installs no signal
// handler (the caller's SimOptions::stop_requested decides when to stop), analyses nothing.
#pragma once

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <vector>

#include "physics/scenario.hpp"
#include "sim/simulate.hpp"

namespace gearsim::app {

// Where a run's scenario came from, as summary.json records it.
struct RunSource {
  std::filesystem::path scenario_file;
  std::vector<std::string> overrides;  // key.path=value, in the order applied
};

struct DirRun {
  sim::RunSummary result;
  nlohmann::ordered_json summary;  // what DIR/summary.json holds
};

// A duration in place of the scenario's duration_s (--duration): longer than a time step, and at
// least one output row. InputError naming the scenario file otherwise.
void set_duration(physics::Scenario& s, double duration_s);

// Creates DIR when missing and removes a previous run's outputs from it (summary, record, logs,
// analysis files, report, videos, frames; other files stay). Returns how many were removed.
// InputError naming DIR when it cannot be created.
int prepare_run_dir(const std::filesystem::path& dir);

// summary.json of a run: what simulate() measured, in SI, with the scenario's pair tables.
nlohmann::ordered_json summary_json(const RunSource& source, const physics::Scenario& s, const sim::RunSummary& r);

// Runs the scenario into DIR (prepared by prepare_run_dir) and writes summary.json. InputError as
// sim::simulate and the log writers throw it.
DirRun run_into_dir(const physics::Scenario& s, const RunSource& source, const std::filesystem::path& dir,
                    const sim::SimOptions& options);

}  // namespace gearsim::app

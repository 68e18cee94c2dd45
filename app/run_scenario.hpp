// A scenario run into a folder, as `gearsim run` does it, callable as a library function: the
// CLI (cmd_run.cpp) and the Python module (python/) both call it, so both write the same files.
// The caller holds the folder (output_folder.hpp: locked, a previous run's outputs cleared);
// run_into_dir writes the scenario record (scenario.json, gearset.yaml), the logs through
// sim::simulate's observers (state.csv, contacts.csv, sensors.csv, steps.h5) and summary.json,
// each named in the folder's manifest before it is written. Prints nothing, installs no signal
// handler (the caller's SimOptions::stop_requested decides when to stop), analyses nothing.
#pragma once

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <vector>

#include "app/output_folder.hpp"
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

// summary.json of a run: what simulate() measured, in SI, with the scenario's pair tables.
nlohmann::ordered_json summary_json(const RunSource& source, const physics::Scenario& s, const sim::RunSummary& r);

// Runs the scenario into the folder and writes summary.json. InputError as sim::simulate throws
// it; OutputError when the record cannot be written. A log that could not be written ends the run
// with status OutputFailed, summary.json naming it under not_written (and leaving it out of
// outputs).
DirRun run_into_dir(const physics::Scenario& s, const RunSource& source, OutputFolder& folder, const sim::SimOptions& options);

}  // namespace gearsim::app

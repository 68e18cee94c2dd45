// A finished run's folder (what `gearsim run --out DIR` wrote) as the later commands see it:
// `analyze`, `report` and `render` read the expanded scenario the run recorded in DIR/scenario.json
// (input/scenario_record.hpp: never the original scenario file, which may have changed since) and
// its logs. Not the writer: cmd_run.cpp writes the folder.
#pragma once

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "physics/scenario.hpp"

namespace gearsim::app {

struct RunDir {
  std::filesystem::path dir;
  nlohmann::ordered_json summary;  // DIR/summary.json as written by run (and added to later)
  physics::Scenario scenario;  // the run's own, from DIR/scenario.json
};

// Reads DIR/summary.json and DIR/scenario.json. InputError (naming the file and key) when DIR is
// not a run folder, the record is damaged, or a mesh it names changed since the run.
RunDir open_run_dir(const std::filesystem::path& dir);

// A JSON record of an output folder (analysis.json, summary.json) read through the bounded
// reader; InputError naming the file when it is missing, too large or not JSON.
nlohmann::ordered_json read_json_record(const std::filesystem::path& file);

// Writes DIR/summary.json back (2-space JSON), e.g. after analyze added its keys: a new file
// renamed over the old (core/output_file.hpp), so a failed write leaves the record as it was.
void save_summary(const RunDir& run);

}  // namespace gearsim::app

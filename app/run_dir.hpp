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
  nlohmann::ordered_json summary;   // DIR/summary.json as written by run (and added to later)
  physics::Scenario scenario;       // the run's own, from DIR/scenario.json
};

// Reads DIR/summary.json and DIR/scenario.json. InputError (naming the file and key) when DIR is
// not a run folder, the record is damaged, or a mesh it names changed since the run.
RunDir open_run_dir(const std::filesystem::path& dir);

// Writes DIR/summary.json back (2-space JSON), e.g. after analyze added its keys.
void save_summary(const RunDir& run);

// An output file of a run folder, opened for writing with `precision` significant digits;
// InputError naming the path when it cannot be written.
std::ofstream open_output(const std::filesystem::path& p, int precision);

}  // namespace gearsim::app

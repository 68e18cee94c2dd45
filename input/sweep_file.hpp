// Sweep files (YAML) → a checked SweepFile: a base scenario, the --set overrides every case gets,
// the swept parameters (a grid whose cartesian product is the case list, or an explicit list of
// cases) and what to collect from each case. Untrusted text like a scenario: strict keys with
// file:line:col messages, the case count bounded before anything is expanded, values that reach
// a `gearsim run` argument list checked (never a shell). Not the runner: sweep/ expands the
// cases, validates them against the scenario and runs them. The format is in the README.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace gearsim::input {

// A swept parameter: its key path into the scenario (as `--set` takes it) and its values, each
// the exact text an override gets: numbers written in their shortest form that reads back to the
// same double (std::to_chars), any other scalar as written.
struct SweepParameter {
  std::string key;  // e.g. motors[0].target_speed_rad_s
  std::string where;  // "file:line:col: grid.<key>" for messages about it
  std::vector<std::string> values;  // Grid: the axis; Cases: unused
};

// One case of a `cases:` list: a value for some of the keys (the others keep the scenario's).
struct SweepListedCase {
  std::string where;  // "file:line:col: cases[i]"
  std::vector<std::pair<std::string, std::string>> values;  // (key, value text), file order
};

// What each case reports into the gathered table.
struct SweepCollect {
  std::vector<std::string> summary;  // JSON paths into the case's summary.json
  std::vector<std::string> analysis;  // JSON paths into analysis.json (the case is then analysed)
  std::vector<std::string> metrics;  // named metrics, of sweep_metric_names()
};

struct SweepFile {
  std::filesystem::path file;  // the sweep file, absolute
  std::string name;  // a label (free one-line text)
  std::filesystem::path scenario;  // the base scenario, absolute (relative to the sweep file's folder)
  std::vector<std::string> set;  // "key=value" overrides every case gets, before its own
  bool grid = true;  // true: `grid:` (cartesian product); false: `cases:`
  // The parameters in column order: the grid's keys in file order (first slowest), or every key
  // of the case list in order of first appearance.
  std::vector<SweepParameter> parameters;
  std::vector<SweepListedCase> cases;  // `cases:` only
  SweepCollect collect;
  std::size_t case_count = 0;  // ≤ limits::kMaxSweepCases
  std::string content_hash;  // FNV-1a 64 of the file's bytes, 16 hex digits: detects an edit
};

// The named metrics a sweep can collect: dynamic_factor_band_limited, dynamic_factor_per_step,
// mean_force_N, mesh_frequency_hz, rms_dynamic_te_rad.
const std::vector<std::string>& sweep_metric_names();

// Reads and checks a sweep file. InputError naming file:line:col and key when the YAML is bad, a
// key is unknown or missing, a value is not what the key takes, the base scenario is missing, a
// key path or value could not be one `--set` argument, or the cases number more than
// limits::kMaxSweepCases (checked before any list is built).
SweepFile load_sweep_file(const std::filesystem::path& file);

// The number's text as a sweep writes it into an override: the shortest form that reads back to
// the same double ("10", "0.1", "1e-05"), the same on every machine.
std::string override_number(double value);

}  // namespace gearsim::input

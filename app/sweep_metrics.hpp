// What a sweep collects from one case's run folder (the collector sweep/case_runner.hpp calls):
// summary.json and analysis.json values by key path, and the named metrics computed from the run's
// logs over the steady window `gearsim analyze` uses (app/run_analysis.hpp). Column names carry
// units: `summary.<path>`, `analysis.<path>`, `dynamic_factor_band_limited` and
// `dynamic_factor_per_step` (max over pairs) with `.<pair>` per pair, `mean_force_N.<pair>`,
// `mesh_frequency_hz` (per stage `.<stage>` for a train), `rms_dynamic_te_rad`.
#pragma once

#include <nlohmann/json.hpp>

#include <filesystem>

#include "input/sweep_file.hpp"

namespace gearsim::app {

// {column: number or null}, in the collect lists' order. InputError naming the file and key when
// a value is missing or not a number, or the run is too short to analyse.
nlohmann::ordered_json collect_case_metrics(const std::filesystem::path& case_dir, const input::SweepCollect& collect);

}  // namespace gearsim::app

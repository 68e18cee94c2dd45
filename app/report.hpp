// `gearsim report DIR [--compare DIR2]`: one self-contained HTML page for a run — the gearbox
// that was run (its stages and gears), the gear table of its gear-set spec with tolerances,
// characteristic frequencies, the contact force of each stage, its spectrum with harmonics and
// sidebands, the transmission error, per-tooth loads, rendered frames when the run has them; and
// for a scenario that reproduces the paper (`reference: paper`) the paper's figures beside ours
// with the reasons for every difference. Plots by gnuplot (SVG, inline). Analyses the run first
// when it has not been.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "app/run_dir.hpp"

namespace gearsim::app {

// Returns the HTML; the caller writes it.
std::string build_report(const RunDir& run, const std::optional<RunDir>& compare);

// `gearsim report DIR` on a sweep folder (DIR/sweep.json): the gathered table and each metric
// plotted against the swept parameter or mesh_frequency_hz, with f_n/k lines from DIR/modes.json
// when present (report_sweep.cpp). Returns the HTML; InputError when DIR is not a sweep folder.
std::string build_sweep_report(const std::filesystem::path& dir);

// Sections (report_*.cpp), each an HTML fragment.
std::string report_gears_section(const RunDir& run);
std::string report_signals_section(const RunDir& run, const std::optional<RunDir>& compare);
std::string report_paper_section(const RunDir& run);
std::string report_sampling_section(const RunDir& run);
std::string report_sensors_section(const RunDir& run, const std::optional<RunDir>& compare);
std::string report_train_section(const RunDir& run);

// The mesh frequency of the stage `pair` meshes in (analysis.json's pairs[pair].stage), else the
// train's, Hz.
double pair_mesh_hz(const nlohmann::ordered_json& analysis, const std::string& pair);
// The scenario reproduces the reference paper's gearbox (`reference: paper`).
bool reproduces_paper(const RunDir& run);

}  // namespace gearsim::app

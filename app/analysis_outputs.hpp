// The tables and summary keys `gearsim analyze` leaves in a run folder, written from its typed
// analysis (analysis/run_analysis.hpp): spectrum.csv (frequency_hz, one <pair>_amplitude_N column
// per gear pair, to 1000 Hz), sidebands.csv (one row per sideband of each found harmonic),
// teeth.csv (one row per tooth of each gear with tooth loads), and in summary.json:
// mesh_frequency_hz, peaks_hz, sidebands, te, faulty_teeth. Pairs are named a__b (analysis_json.hpp).
#pragma once

#include <nlohmann/json.hpp>

#include <filesystem>

#include "analysis/run_analysis.hpp"

namespace gearsim::app {

void write_spectrum_csv(const std::filesystem::path& path, const RunAnalysis& analysis, double top_hz);
void write_sidebands_csv(const std::filesystem::path& path, const RunAnalysis& analysis);
void write_teeth_csv(const std::filesystem::path& path, const RunAnalysis& analysis);
// Adds the analysis keys to a run's summary (replacing earlier ones); mesh_hz: the train's f_m.
void add_to_summary(nlohmann::ordered_json& summary, const RunAnalysis& analysis, double mesh_hz);

}  // namespace gearsim::app

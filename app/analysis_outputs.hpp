// The tables and summary keys `gearsim analyze` leaves in a run folder, written from its
// analysis: spectrum.csv (frequency_hz, one <pair>_amplitude_N column per gear pair, to 1000 Hz),
// sidebands.csv (one row per sideband), teeth.csv (one row per tooth of each analysed gear), and
// in summary.json: mesh_frequency_hz, peaks_hz, sidebands, te, faulty_teeth.
#pragma once

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "analysis/spectrum.hpp"

namespace gearsim::app {

void write_spectrum_csv(const std::filesystem::path& path, const std::vector<std::pair<std::string, Spectrum>>& spectra,
                        double top_hz);
void write_sidebands_csv(const std::filesystem::path& path, const nlohmann::ordered_json& analysis);
void write_teeth_csv(const std::filesystem::path& path, const nlohmann::ordered_json& analysis);
// Adds the analysis keys to a run's summary (replacing earlier ones).
void add_to_summary(nlohmann::ordered_json& summary, const nlohmann::ordered_json& analysis);

}  // namespace gearsim::app

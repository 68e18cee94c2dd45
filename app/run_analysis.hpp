// `gearsim analyze DIR`: the analysis of a finished run folder — the gear train's characteristic
// frequencies; per gear pair the contact-force spectrum, its mesh harmonics over the median
// floor, their sidebands matched to characteristic frequencies, and the amplitudes of the planet
// local-fault family; the transmission error; per-tooth loads from the per-step log. Writes
// DIR/analysis.json, spectrum.csv, sidebands.csv, teeth.csv and adds its keys to summary.json
// (analysis_outputs.hpp); returns the JSON. Prints nothing.
#pragma once

#include <nlohmann/json.hpp>

#include "app/run_dir.hpp"

namespace gearsim::app {

struct AnalyzeOptions {
  // Start of the analysed window, s; negative: the end of the motors' ramp.
  double from_s = -1;
};

nlohmann::ordered_json analyze_run(const RunDir& run, const AnalyzeOptions& options = {});

}  // namespace gearsim::app

// `gearsim analyze DIR`: a finished run folder read into typed signals and analysed by the
// analysis library (analysis/run_analysis.hpp) — the gear pairs are summary.json's gear_pairs, their
// forces contacts.csv's a__b_force_N columns, the angles and TE state.csv's, the tooth contacts
// steps.h5's. The result is written as DIR/analysis.json (analysis_json.hpp), spectrum.csv,
// sidebands.csv, teeth.csv and the analysis keys of summary.json (analysis_outputs.hpp); returns
// the JSON. Prints nothing. (analyze_run_dir: the same analysis typed, nothing written;
// analysis::analyze_signals: the analysis of signals already read.)
#pragma once

#include <nlohmann/json.hpp>

#include "analysis/run_analysis.hpp"
#include "app/run_dir.hpp"
#include "input/gear_train.hpp"

namespace gearsim::app {

struct AnalyzeOptions {
  // Start of the analysed window, s; negative: the end of the motors' ramp.
  double from_s = -1;
};

nlohmann::ordered_json write_run_analysis(const RunDir& run, const AnalyzeOptions& options = {});

// The same analysis as a typed result, writing nothing (e.g. for a sweep's metrics): the window
// from the end of the ramps (or the force filter's edge, or options.from_s) to the end of the
// record less the filter's edge, as write_run_analysis takes it. InputError as write_run_analysis.
RunAnalysis analyze_run_dir(const RunDir& run, const AnalyzeOptions& options = {});

// The run's gear train: its scenario's bodies with summary.json's gear_pairs as the meshes.
// InputError as input::gear_train_of, or naming summary.json when gear_pairs is missing or malformed.
input::GearTrain run_gear_train(const RunDir& run);

}  // namespace gearsim::app

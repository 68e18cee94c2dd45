// analysis.json: a run's typed analysis (analysis/run_analysis.hpp) as the JSON `gearsim analyze`
// writes — the gear train and its characteristic frequencies; per pair, keyed by its log name
// a__b, the spectrum's scales, mesh harmonics with sidebands, planet fault family, mean force and
// zero-force share; the transmission error's statistics; the synchronous averages and the tooth
// loads. Formatting only: every number is the analysis's own.
#pragma once

#include <nlohmann/json.hpp>

#include <string>

#include "analysis/run_analysis.hpp"
#include "input/gear_train.hpp"

namespace gearsim::app {

// "a__b": the pair's name in contacts.csv's columns, steps.h5 and every analysis output.
std::string pair_name(const PairId& pair);

// "3xcarrier_shaft": a sideband's match as analysis.json and sidebands.csv write it.
std::string match_label(const SidebandMatch& match);

nlohmann::ordered_json analysis_json(const RunAnalysis& analysis, const input::GearTrain& train, const std::string& scenario_name);

}  // namespace gearsim::app

// The checks of a run folder's summary.json before `analyze`, `report` and `render` read it: the
// keys they use, with the type and range `gearsim run` writes. A hand-edited or damaged record
// ("sim_seconds": "abc") is refused naming the file and key, instead of failing later as a JSON
// type error. Not the writer (app/run_scenario.cpp) and not the scenario record
// (scenario_record.hpp).
#pragma once

#include <nlohmann/json.hpp>

#include <string>

namespace gearsim::input {

// InputError "FILE: key gear_pairs[1].stiffness_N_per_m: expected …" for the first of these that
// is missing (where required) or has the wrong type or range: sim_seconds in kDuration_s,
// time_step_s in kTimeStep_s, steps a whole number ≥ 0, status a string, wall_seconds ≥ 0;
// ratio, power_W.*, warnings (strings), gear_pairs[] (a, b names; stiffness, reduced mass,
// damping, mean flank forces), force_filter (rates in kRate_Hz, taps, edge_held_s) when present.
void validate_summary_record(const nlohmann::ordered_json& summary, const std::string& file);

}  // namespace gearsim::input

// Every case's overrides checked against the base scenario before any case runs, by loading it
// with them as `gearsim run --set` does (input::load_scenario): a bad key or value is one error
// naming the sweep file, the case and the key, instead of a failed case after hours. Loading the
// scenario reads its meshes, so not every case is loaded: case 0, and for each parameter the
// first case holding each of its values when it takes at most kMaxValuesLoaded values, else the
// cases holding its first, smallest, largest and last value.
#pragma once

#include <cstddef>
#include <vector>

#include "input/sweep_file.hpp"
#include "sweep/case_list.hpp"

namespace gearsim::sweep {

// A parameter's values are each loaded when it has at most this many (a grid axis is usually a
// handful; a 1000-value axis would load the scenario 1000 times).
constexpr std::size_t kMaxValuesLoaded = 16;

// The indices of the cases validate_cases loads, ascending.
std::vector<std::size_t> cases_to_validate(const input::SweepFile& file, const std::vector<Case>& cases);

// InputError "SWEEP:line:col: grid.<key>: case N (k=v, …): <the scenario's error>" for the first
// case refused.
void validate_cases(const input::SweepFile& file, const std::vector<Case>& cases);

}  // namespace gearsim::sweep

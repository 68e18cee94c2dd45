// The cases of a sweep: the sweep file's grid expanded (cartesian product, first key slowest) or
// its list taken in order, each with its parameter values and the full `--set` list its run gets
// (the sweep's `set:` first, then its own). Not the runner: case_runner.hpp runs one.
#pragma once

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "input/sweep_file.hpp"

namespace gearsim::sweep {

struct Case {
  std::size_t index = 0;
  // One (key, value text) per parameter column of the sweep, in column order; in a `cases:` list
  // a key the case does not set has value "" (the scenario's own) and no override.
  std::vector<std::pair<std::string, std::string>> parameters;
  std::vector<std::string> overrides;  // "key=value", as `gearsim run --set` takes them
};

// Every case, index order. The count is the file's case_count (already bounded by the reader).
std::vector<Case> expand_cases(const input::SweepFile& file);

// The case's folder name under DIR/cases/: its index zero-padded to 5 digits ("00007"), enough
// for limits::kMaxSweepCases, so that names sort in index order.
std::string case_folder_name(std::size_t index);

}  // namespace gearsim::sweep

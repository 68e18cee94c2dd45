// Per-tooth loads of a finished run, from its per-step log: for each gear of a mesh, the mean
// force each of its teeth carried over a window of whole revolutions (relative to the body that
// carries its axis), and how far each tooth stands from the others (leave-one-out z-score).
// A tooth that carries less than the rest — a flank relieved by an error — stands out. This is
// the angle-synchronous mean per tooth, taken exactly from the logged tooth indices instead of
// from angle windows.
#pragma once

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include "sim/step_log_reader.hpp"

namespace gearsim::app {

struct ToothLoads {
  std::string pair;          // "a__b"
  std::string gear;          // whose teeth: a or b of the pair
  double from_s = 0, to_s = 0;  // the window: whole revolutions of `gear`
  double revolutions = 0;
  std::vector<double> mean_force_N;  // per tooth: impulse carried / window length
  std::vector<double> z_score;
  std::vector<int> flagged;  // |z| > z_threshold and apart from the others' mean by > min_relative_deviation
  double z_threshold = 0, min_relative_deviation = 0;
};

// Teeth of `gear` (side a or b of pair `pair_index`) over [from_s, to_s], which the caller chose
// to hold whole revolutions of that gear.
ToothLoads tooth_loads(const sim::StepLogContacts& log, int pair_index, bool side_a, int teeth, double from_s,
                       double to_s, double revolutions);

nlohmann::ordered_json to_json(const ToothLoads& t);

}  // namespace gearsim::app

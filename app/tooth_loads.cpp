#include "app/tooth_loads.hpp"

#include <cmath>

#include "analysis/constants.hpp"
#include "analysis/tooth_statistics.hpp"
#include "core/errors.hpp"

namespace gearsim::app {

ToothLoads tooth_loads(const sim::StepLogContacts& log, int pair_index, bool side_a, int teeth, double from_s,
                       double to_s, double revolutions) {
  ToothLoads t;
  t.pair = log.pairs.at(static_cast<std::size_t>(pair_index));
  t.gear = side_a ? t.pair.substr(0, t.pair.find("__")) : t.pair.substr(t.pair.find("__") + 2);
  t.from_s = from_s;
  t.to_s = to_s;
  t.revolutions = revolutions;
  t.mean_force_N.assign(static_cast<std::size_t>(teeth), 0.0);
  for (std::size_t c = 0; c < log.time_s.size(); ++c) {
    if (log.pair[c] != pair_index || log.time_s[c] < from_s || log.time_s[c] >= to_s) continue;
    const std::int64_t tooth = side_a ? log.tooth_a[c] : log.tooth_b[c];
    if (tooth < 0 || tooth >= teeth)
      throw InputError("step log: pair " + t.pair + " names tooth " + std::to_string(tooth) + " of a " +
                       std::to_string(teeth) + "-tooth gear");
    t.mean_force_N[static_cast<std::size_t>(tooth)] += log.normal_impulse_N_s[c];
  }
  for (double& f : t.mean_force_N) f /= (to_s - from_s);
  t.z_score = leave_one_out_z_scores(t.mean_force_N);
  t.z_threshold = analysis_constants::kDefaultToothZThreshold;
  t.min_relative_deviation = analysis_constants::kDefaultToothMinRelativeDeviation;
  t.flagged = teeth_standing_apart(t.mean_force_N, t.z_score, t.z_threshold, t.min_relative_deviation);
  return t;
}

nlohmann::ordered_json to_json(const ToothLoads& t) {
  nlohmann::ordered_json j;
  j["pair"] = t.pair;
  j["gear"] = t.gear;
  j["window_s"] = {t.from_s, t.to_s};
  j["revolutions"] = t.revolutions;
  j["z_threshold"] = t.z_threshold;
  j["min_relative_deviation"] = t.min_relative_deviation;
  j["flagged_teeth"] = t.flagged;
  nlohmann::ordered_json teeth = nlohmann::ordered_json::array();
  for (std::size_t k = 0; k < t.mean_force_N.size(); ++k)
    teeth.push_back({{"tooth", k}, {"mean_force_N", t.mean_force_N[k]}, {"z_score", t.z_score[k]}});
  j["teeth"] = teeth;
  return j;
}

}  // namespace gearsim::app

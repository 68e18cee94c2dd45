#include "analysis/tooth_loads.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "analysis/constants.hpp"
#include "analysis/tooth_statistics.hpp"
#include "core/errors.hpp"

namespace gearsim {

WholeRevolutions whole_revolutions(const std::vector<double>& t, const std::vector<double>& angle, double from_s) {
  constexpr double kTurn = 2 * std::numbers::pi;
  // The angle where the window starts, interpolated between the samples around from_s.
  std::size_t i0 = 0;
  while (i0 < t.size() && t[i0] < from_s) ++i0;
  if (i0 == 0 || i0 >= t.size()) return {from_s, 0};
  const double a0 = angle[i0 - 1] + (angle[i0] - angle[i0 - 1]) * (from_s - t[i0 - 1]) / (t[i0] - t[i0 - 1]);
  const int turns = static_cast<int>(std::floor(std::abs(angle.back() - a0) / kTurn));
  if (turns < 1) return {from_s, 0};
  // The first sample past the last whole turn, and the time between it and the one before.
  const double target = turns * kTurn;
  std::size_t i1 = i0;
  while (i1 + 1 < t.size() && std::abs(angle[i1] - a0) < target) ++i1;
  const double d0 = std::abs(angle[i1 - 1] - a0), d1 = std::abs(angle[i1] - a0);
  return {t[i1 - 1] + (t[i1] - t[i1 - 1]) * (target - d0) / (d1 - d0), turns};
}

ToothLoads tooth_loads(const ToothContactLog& log, std::size_t pair_index, bool side_a, int teeth, double from_s, double to_s,
                       double revolutions) {
  ToothLoads t;
  t.pair = log.pairs.at(pair_index);
  t.gear = side_a ? t.pair.a : t.pair.b;
  t.from_s = from_s;
  t.to_s = to_s;
  t.revolutions = revolutions;
  t.mean_force_N.assign(static_cast<std::size_t>(teeth), 0.0);
  // The impulse each tooth carried inside the window, then per second of it.
  const auto pair = static_cast<std::int64_t>(pair_index);
  for (std::size_t c = 0; c < log.time_s.size(); ++c) {
    if (log.pair[c] != pair || log.time_s[c] < from_s || log.time_s[c] >= to_s) continue;
    const std::int64_t tooth = side_a ? log.tooth_a[c] : log.tooth_b[c];
    if (tooth < 0 || tooth >= teeth)
      throw InputError("tooth-contact log: pair " + pair_label(t.pair) + " names tooth " + std::to_string(tooth) + " of " + t.gear +
                       ", a " + std::to_string(teeth) + "-tooth gear");
    t.mean_force_N[static_cast<std::size_t>(tooth)] += log.normal_impulse_N_s[c];
  }
  for (double& f : t.mean_force_N) f /= (to_s - from_s);
  // Shares of the mesh: each step's contacts of this pair are contiguous in the log (one step
  // after another), so a step's total is summed first, then handed out.
  const int revs = std::max(1, static_cast<int>(std::lround(revolutions)));
  t.share_steps.assign(static_cast<std::size_t>(teeth), 0.0);
  t.share_per_revolution.assign(static_cast<std::size_t>(revs), std::vector<double>(static_cast<std::size_t>(teeth), 0.0));
  for (std::size_t c = 0; c < log.time_s.size();) {
    std::size_t end = c;
    double total = 0;
    while (end < log.time_s.size() && log.time_s[end] == log.time_s[c]) {
      if (log.pair[end] == pair) total += log.normal_impulse_N_s[end];
      ++end;
    }
    const double t_step = log.time_s[c];
    if (total > 0 && t_step >= from_s && t_step < to_s) {
      const auto r = static_cast<std::size_t>(std::min<double>(revs - 1, std::floor((t_step - from_s) / (to_s - from_s) * revs)));
      for (std::size_t i = c; i < end; ++i) {
        if (log.pair[i] != pair) continue;
        const auto tooth = static_cast<std::size_t>(side_a ? log.tooth_a[i] : log.tooth_b[i]);
        const double share = log.normal_impulse_N_s[i] / total;
        t.share_steps[tooth] += share;
        t.share_per_revolution[r][tooth] += share;
      }
    }
    c = end;
  }
  t.share_z = leave_one_out_z_scores(t.share_steps);
  t.share_flagged = teeth_standing_apart(t.share_steps, t.share_z, analysis_constants::kDefaultToothZThreshold,
                                         analysis_constants::kDefaultToothMinRelativeDeviation);
  // How far each tooth stands from the others.
  t.z_score = leave_one_out_z_scores(t.mean_force_N);
  t.z_threshold = analysis_constants::kDefaultToothZThreshold;
  t.min_relative_deviation = analysis_constants::kDefaultToothMinRelativeDeviation;
  t.flagged = teeth_standing_apart(t.mean_force_N, t.z_score, t.z_threshold, t.min_relative_deviation);
  return t;
}

}  // namespace gearsim

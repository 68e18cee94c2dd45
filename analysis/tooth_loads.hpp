// Per-tooth loads of a finished run, from its per-step tooth-contact log: for one gear of a logged
// pair, the mean force each of its teeth carried over a window of whole revolutions (relative to
// the body that carries its axis), and how far each tooth stands from the others (leave-one-out
// z-score). A tooth that carries less than the rest — a flank relieved by an error — stands out.
// This is the angle-synchronous mean per tooth, taken exactly from the logged tooth indices
// instead of from angle windows (synchronous_teeth.hpp). Not a contact model: it sums what was
// logged.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "analysis/run_signals.hpp"

namespace gearsim {

struct ToothLoads {
  PairId pair;
  std::string gear;  // whose teeth: pair.a or pair.b
  double from_s = 0, to_s = 0;  // the window, s: whole revolutions of `gear`
  double revolutions = 0;
  std::vector<double> mean_force_N;  // per tooth k: impulse carried / window length, N
  std::vector<double> z_score;  // per tooth k, leave-one-out
  std::vector<int> flagged;  // |z| > z_threshold and apart from the others' mean by > min_relative_deviation
  double z_threshold = 0, min_relative_deviation = 0;
  // Each tooth's share of its own mesh: Σ over the logged steps of its impulse over the pair's
  // total impulse that step (in steps). Healthy teeth carry equal shares whatever the mesh's total
  // does; a flank that is not where the geometry puts it carries less, its neighbours more.
  // Load moved between meshes (planets meshing in phase) changes mean_force_N, not the shares.
  std::vector<double> share_steps;  // per tooth k
  std::vector<double> share_z;  // per tooth k, leave-one-out
  std::vector<int> share_flagged;  // by the same rule as `flagged`
  // Per whole revolution r (the window cut into `revolutions` equal spans), per tooth k.
  std::vector<std::vector<double>> share_per_revolution;
};

// The window [from_s, to_s] over which `angle_rad` (unwrapped, sampled at time_s) turns a whole
// number of revolutions, the most the record holds: to_s interpolated where the angle completes
// them, so that every tooth passes its mesh equally often (to within one logged step). turns = 0
// (and to_s = from_s) when from_s is not inside the record or it holds less than one revolution.
struct WholeRevolutions {
  double to_s = 0;
  int turns = 0;
};
WholeRevolutions whole_revolutions(const std::vector<double>& time_s, const std::vector<double>& angle_rad, double from_s);

// Teeth of side a (side_a) or b of log.pairs[pair_index] over [from_s, to_s), which the caller
// chose to hold `revolutions` whole revolutions of that gear; `teeth` its tooth count (≥ 3).
// InputError naming the pair when the log names a tooth outside 0 … teeth − 1.
ToothLoads tooth_loads(const ToothContactLog& log, std::size_t pair_index, bool side_a, int teeth, double from_s, double to_s,
                       double revolutions);

}  // namespace gearsim

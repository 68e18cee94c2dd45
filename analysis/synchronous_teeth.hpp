// The standard condition-monitoring view of a planet's teeth: the sun–planet contact force
// averaged synchronously with the planet's rotation relative to the carrier (angle_average.hpp),
// cut into one window per tooth centred where that tooth faces the sun, with per-tooth means and
// leave-one-out z-scores (tooth_statistics.hpp). A cross-check of the exact per-tooth loads from
// the per-step log (tooth_loads.hpp), from the output-rate signals alone.
#pragma once

#include "analysis/condition_indicators.hpp"

#include <string>
#include <vector>

#include "analysis/run_signals.hpp"

namespace gearsim {

struct SynchronousTeeth {
  PairId pair;  // the sun–planet pair whose force was averaged
  std::string planet;  // whose teeth
  int revolutions = 0;  // whole revolutions relative to the carrier averaged
  int samples_per_revolution = 0;  // of the angle-domain average
  double z_threshold = 0, min_relative_deviation = 0;
  std::vector<double> mean_force_N;  // per tooth k (the planet's own numbering), N
  std::vector<double> z_score;  // per tooth k, leave-one-out
  std::vector<int> flagged_teeth;  // by the same rule as ToothLoads::flagged, increasing
  // The standard indicators of the averaged revolution (condition_indicators.hpp), mesh order z_p.
  ConditionIndicators indicators;
};

// force_N and planet_angle_rad (relative to the carrier, unwrapped) sampled at the same times over
// the analysed window; planet.teeth its tooth count, planet.sun_direction_rad where tooth 0 faces
// the sun. InputError when the record holds less than one revolution.
SynchronousTeeth synchronous_teeth(const PairId& pair, const PlanetGear& planet, const std::vector<double>& force_N,
                                   const std::vector<double>& planet_angle_rad);

}  // namespace gearsim

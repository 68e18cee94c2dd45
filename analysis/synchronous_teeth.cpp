#include "analysis/synchronous_teeth.hpp"

#include <cmath>
#include <numbers>

#include "analysis/angle_average.hpp"
#include "analysis/constants.hpp"
#include "analysis/tooth_statistics.hpp"

namespace gearsim {

SynchronousTeeth synchronous_teeth(const PairId& pair, const PlanetGear& planet, const std::vector<double>& force_N,
                                   const std::vector<double>& planet_angle_rad) {
  const int teeth = planet.teeth;
  const double pitch = 2 * std::numbers::pi / teeth;
  const AngleAverage avg = angle_synchronous_average(force_N, planet_angle_rad);
  // Tooth k faces the sun when the planet's relative angle is sun_direction − k·pitch. Windows
  // run in increasing angle: window j, centred at sun_direction + j·pitch, belongs to tooth −j.
  ToothStatisticsOptions o;
  o.teeth = teeth;
  o.tooth0_start_rad = planet.sun_direction_rad - pitch / 2;
  const ToothStatistics st = tooth_statistics(avg, o);
  SynchronousTeeth r;
  r.pair = pair;
  r.planet = planet.body;
  r.revolutions = avg.revolutions;
  r.samples_per_revolution = avg.samples_per_revolution;
  r.z_threshold = st.z_threshold;
  r.min_relative_deviation = analysis_constants::kDefaultToothMinRelativeDeviation;
  // Per tooth (window j belongs to tooth −j), flagged by the same rule as the step-log loads.
  r.mean_force_N.assign(static_cast<std::size_t>(teeth), 0.0);
  r.z_score.assign(static_cast<std::size_t>(teeth), 0.0);
  for (const ToothStatistic& t : st.teeth) {
    const auto tooth = static_cast<std::size_t>((teeth - t.tooth) % teeth);
    r.mean_force_N[tooth] = t.mean;
    r.z_score[tooth] = t.z_score;
  }
  r.flagged_teeth = teeth_standing_apart(r.mean_force_N, r.z_score, r.z_threshold, r.min_relative_deviation);
  r.indicators = condition_indicators(avg.mean, teeth);
  return r;
}

}  // namespace gearsim

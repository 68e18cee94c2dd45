#include "app/synchronous_teeth.hpp"

#include <cmath>
#include <numbers>

#include "analysis/angle_average.hpp"
#include "analysis/constants.hpp"
#include "analysis/tooth_statistics.hpp"

namespace gearsim::app {

nlohmann::ordered_json synchronous_teeth(const std::string& pair, const std::string& planet,
                                         const std::vector<double>& force_N, const std::vector<double>& planet_angle_rad,
                                         int teeth, double sun_direction_rad) {
  const double pitch = 2 * std::numbers::pi / teeth;
  const AngleAverage avg = angle_synchronous_average(force_N, planet_angle_rad);
  // Tooth k faces the sun when the planet's relative angle is sun_direction − k·pitch. Windows
  // run in increasing angle: window j, centred at sun_direction + j·pitch, belongs to tooth −j.
  ToothStatisticsOptions o;
  o.teeth = teeth;
  o.tooth0_start_rad = sun_direction_rad - pitch / 2;
  const ToothStatistics st = tooth_statistics(avg, o);
  nlohmann::ordered_json j;
  j["pair"] = pair;
  j["gear"] = planet;
  j["method"] = "angle-synchronous average of the pair force over the planet's rotation relative to the carrier";
  j["revolutions"] = avg.revolutions;
  j["samples_per_revolution"] = avg.samples_per_revolution;
  j["z_threshold"] = st.z_threshold;
  // Per tooth (window j belongs to tooth −j), flagged by the same rule as the step-log loads.
  std::vector<double> mean(static_cast<std::size_t>(teeth)), z(static_cast<std::size_t>(teeth));
  for (const ToothStatistic& t : st.teeth) {
    const auto tooth = static_cast<std::size_t>((teeth - t.tooth) % teeth);
    mean[tooth] = t.mean;
    z[tooth] = t.z_score;
  }
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (int k = 0; k < teeth; ++k)
    list.push_back({{"tooth", k}, {"mean_force_N", mean[static_cast<std::size_t>(k)]}, {"z_score", z[static_cast<std::size_t>(k)]}});
  j["min_relative_deviation"] = analysis_constants::kDefaultToothMinRelativeDeviation;
  j["flagged_teeth"] = teeth_standing_apart(mean, z, st.z_threshold, analysis_constants::kDefaultToothMinRelativeDeviation);
  j["teeth"] = list;
  return j;
}

}  // namespace gearsim::app

// The standard condition-monitoring view of a planet's teeth: the sun–planet contact force
// averaged synchronously with the planet's rotation relative to the carrier (analysis/
// angle_average), cut into one window per tooth centred where that tooth faces the sun, with
// per-tooth means and leave-one-out z-scores (analysis/tooth_statistics). A cross-check of the
// exact per-tooth loads from the step log (tooth_loads.hpp), from the output-rate logs alone.
#pragma once

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace gearsim::app {

// force_N and planet_angle_rad (relative to the carrier, unwrapped) sampled at the same times,
// over the analysed window; teeth: the planet's tooth count; sun_direction_rad: where the sun
// lies seen from the planet, in the carrier frame, less the planet's tooth-0 angle (tooth k faces
// the sun when the planet's relative angle is sun_direction_rad − k·pitch). InputError when the
// record holds less than one revolution.
nlohmann::ordered_json synchronous_teeth(const std::string& pair, const std::string& planet,
                                         const std::vector<double>& force_N, const std::vector<double>& planet_angle_rad,
                                         int teeth, double sun_direction_rad);

}  // namespace gearsim::app

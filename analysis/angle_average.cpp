#include "analysis/angle_average.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "analysis/resample.hpp"
#include "core/errors.hpp"

namespace gearsim {

long long synchronous_revolutions(const std::vector<double>& angle_rad, int samples_per_revolution) {
  if (angle_rad.size() < 2 || samples_per_revolution < 1) return 0;
  const double sign = angle_rad.back() < angle_rad.front() ? -1.0 : 1.0;
  const double step_rad = 2.0 * std::numbers::pi / samples_per_revolution;
  const long long first = static_cast<long long>(std::ceil(sign * angle_rad.front() / step_rad));
  const long long last = static_cast<long long>(std::floor(sign * angle_rad.back() / step_rad));
  return (last - first + 1) / static_cast<long long>(samples_per_revolution);
}

AngleAverage angle_synchronous_average(const std::vector<double>& signal, const std::vector<double>& angle_rad,
                                       int samples_per_revolution) {
  const char* what = "angle-synchronous average";
  if (signal.size() != angle_rad.size())
    throw InputError(std::string(what) + ": " + std::to_string(signal.size()) + " signal samples but " + std::to_string(angle_rad.size()) +
                     " angle samples; they must be sampled together");
  if (signal.size() < 2) throw InputError(std::string(what) + ": expected at least 2 samples");
  for (std::size_t i = 0; i < signal.size(); ++i)
    if (!std::isfinite(signal[i])) throw InputError(std::string(what) + ": signal sample " + std::to_string(i) + " is not finite");
  if (samples_per_revolution < 4)
    throw InputError(std::string(what) + ": samples per revolution must be at least 4, got " + std::to_string(samples_per_revolution));
  // Travel along the rotation: a decreasing angle is mirrored so interpolation sees increasing x.
  const bool decreasing = angle_rad.back() < angle_rad.front();
  const double sign = decreasing ? -1.0 : 1.0;
  std::vector<double> travel(angle_rad.size());
  for (std::size_t i = 0; i < angle_rad.size(); ++i) travel[i] = sign * angle_rad[i];
  const double step_rad = 2.0 * std::numbers::pi / samples_per_revolution;
  const auto n = static_cast<long long>(samples_per_revolution);
  // First grid index inside the record, and how many whole revolutions follow it.
  const long long first = static_cast<long long>(std::ceil(travel.front() / step_rad));
  const long long revolutions = synchronous_revolutions(angle_rad, samples_per_revolution);
  if (revolutions < 1)
    throw InputError(std::string(what) + ": the angle covers " +
                     std::to_string((travel.back() - travel.front()) / (2.0 * std::numbers::pi)) +
                     " revolutions; at least one whole revolution is needed");
  std::vector<double> query(static_cast<std::size_t>(revolutions * n));
  for (std::size_t q = 0; q < query.size(); ++q)
    query[q] = std::clamp(static_cast<double>(first + static_cast<long long>(q)) * step_rad, travel.front(), travel.back());
  // interpolate_linear checks that the travel increases strictly (the angle is monotone).
  const std::vector<double> resampled = interpolate_linear(travel, signal, query);
  AngleAverage avg;
  avg.samples_per_revolution = samples_per_revolution;
  avg.revolutions = static_cast<int>(revolutions);
  avg.mean.assign(static_cast<std::size_t>(n), 0.0);
  avg.angle_rad.resize(static_cast<std::size_t>(n));
  for (long long j = 0; j < n; ++j) avg.angle_rad[static_cast<std::size_t>(j)] = static_cast<double>(j) * step_rad;
  for (std::size_t q = 0; q < query.size(); ++q) {
    // Grid index g is travel g·step; the body angle is sign·g·step, reduced to [0, 2π) as j·step.
    const long long g = first + static_cast<long long>(q);
    const long long j = ((static_cast<long long>(sign) * g) % n + n) % n;
    avg.mean[static_cast<std::size_t>(j)] += resampled[q];
  }
  for (double& m : avg.mean) m /= static_cast<double>(revolutions);
  return avg;
}

}  // namespace gearsim

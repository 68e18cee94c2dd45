#include "analysis/tooth_statistics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "geometry/errors.hpp"

namespace gearsim {

ToothStatistics tooth_statistics(const AngleAverage& avg, const ToothStatisticsOptions& o) {
  const char* what = "tooth statistics";
  const int z = o.teeth;
  if (z < 3) throw InputError(std::string(what) + ": teeth: expected at least 3, got " + std::to_string(z));
  if (avg.mean.size() < static_cast<std::size_t>(z) || avg.angle_rad.size() != avg.mean.size())
    throw InputError(std::string(what) + ": the average holds " + std::to_string(avg.mean.size()) +
                     " samples, fewer than the " + std::to_string(z) + " teeth");
  if (!(o.z_threshold > 0.0)) throw InputError(std::string(what) + ": z threshold must be positive");
  const double two_pi = 2.0 * std::numbers::pi;
  const double pitch_rad = two_pi / z;
  std::vector<double> sum(static_cast<std::size_t>(z), 0.0);
  std::vector<int> count(static_cast<std::size_t>(z), 0);
  for (std::size_t j = 0; j < avg.mean.size(); ++j) {
    if (o.in_mesh_threshold && !(avg.mean[j] > *o.in_mesh_threshold)) continue;
    double rel = std::fmod(avg.angle_rad[j] - o.tooth0_start_rad, two_pi);
    if (rel < 0.0) rel += two_pi;
    const int k = std::min(z - 1, static_cast<int>(std::floor(rel / pitch_rad)));
    sum[static_cast<std::size_t>(k)] += avg.mean[j];
    ++count[static_cast<std::size_t>(k)];
  }
  ToothStatistics r;
  r.z_threshold = o.z_threshold;
  r.teeth.resize(static_cast<std::size_t>(z));
  double total = 0.0;
  for (int k = 0; k < z; ++k) {
    const auto i = static_cast<std::size_t>(k);
    if (count[i] == 0)
      throw InputError(std::string(what) + ": tooth " + std::to_string(k) + " has no sample in its window" +
                       (o.in_mesh_threshold ? " above the in-mesh threshold" : "") +
                       "; lower the threshold or raise the samples per revolution");
    r.teeth[i] = {k, count[i], sum[i] / count[i], 0.0, false};
    total += r.teeth[i].mean;
  }
  // Leave-one-out: tooth k against the mean and sample deviation of the other z − 1 teeth.
  for (ToothStatistic& t : r.teeth) {
    const double others_mean = (total - t.mean) / (z - 1);
    double ss = 0.0;
    for (const ToothStatistic& u : r.teeth)
      if (u.tooth != t.tooth) ss += (u.mean - others_mean) * (u.mean - others_mean);
    const double sd = std::sqrt(ss / (z - 2));
    const double d = t.mean - others_mean;
    if (sd > 0.0)
      t.z_score = d / sd;
    else
      t.z_score = d == 0.0 ? 0.0 : std::copysign(std::numeric_limits<double>::infinity(), d);
    t.faulty = std::abs(t.z_score) > o.z_threshold;
    if (t.faulty) r.faulty_teeth.push_back(t.tooth);
  }
  return r;
}

}  // namespace gearsim

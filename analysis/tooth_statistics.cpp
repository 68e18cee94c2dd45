#include "analysis/tooth_statistics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "core/errors.hpp"

namespace gearsim {

std::vector<double> leave_one_out_z_scores(const std::vector<double>& values) {
  const std::size_t z = values.size();
  if (z < 3) throw InputError("leave-one-out z-scores: expected at least 3 values, got " + std::to_string(z));
  double total = 0.0;
  for (double v : values) total += v;
  std::vector<double> out(z);
  // Value k against the mean and sample deviation of the other z − 1 values.
  for (std::size_t k = 0; k < z; ++k) {
    const double others_mean = (total - values[k]) / static_cast<double>(z - 1);
    double ss = 0.0;
    for (std::size_t u = 0; u < z; ++u)
      if (u != k) ss += (values[u] - others_mean) * (values[u] - others_mean);
    const double sd = std::sqrt(ss / static_cast<double>(z - 2));
    const double d = values[k] - others_mean;
    if (sd > 0.0)
      out[k] = d / sd;
    else
      out[k] = d == 0.0 ? 0.0 : std::copysign(std::numeric_limits<double>::infinity(), d);
  }
  return out;
}

std::vector<int> teeth_standing_apart(const std::vector<double>& values, const std::vector<double>& z_scores, double z_threshold,
                                      double min_relative_deviation) {
  double total = 0.0;
  for (double v : values) total += v;
  std::vector<int> out;
  const auto n = static_cast<double>(values.size());
  for (std::size_t k = 0; k < values.size(); ++k) {
    const double others = (total - values[k]) / (n - 1);
    const bool apart = others != 0.0 && std::abs(values[k] - others) > min_relative_deviation * std::abs(others);
    if (std::abs(z_scores[k]) > z_threshold && apart) out.push_back(static_cast<int>(k));
  }
  return out;
}

ToothStatistics tooth_statistics(const AngleAverage& avg, const ToothStatisticsOptions& o) {
  const char* what = "tooth statistics";
  const int z = o.teeth;
  if (z < 3) throw InputError(std::string(what) + ": teeth: expected at least 3, got " + std::to_string(z));
  if (avg.mean.size() < static_cast<std::size_t>(z) || avg.angle_rad.size() != avg.mean.size())
    throw InputError(std::string(what) + ": the average holds " + std::to_string(avg.mean.size()) + " samples, fewer than the " +
                     std::to_string(z) + " teeth");
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
  for (int k = 0; k < z; ++k) {
    const auto i = static_cast<std::size_t>(k);
    if (count[i] == 0)
      throw InputError(std::string(what) + ": tooth " + std::to_string(k) + " has no sample in its window" +
                       (o.in_mesh_threshold ? " above the in-mesh threshold" : "") +
                       "; lower the threshold or raise the samples per revolution");
    r.teeth[i] = {k, count[i], sum[i] / count[i], 0.0, false};
  }
  std::vector<double> means;
  for (const ToothStatistic& t : r.teeth) means.push_back(t.mean);
  const std::vector<double> z_scores = leave_one_out_z_scores(means);
  for (ToothStatistic& t : r.teeth) {
    t.z_score = z_scores[static_cast<std::size_t>(t.tooth)];
    t.faulty = std::abs(t.z_score) > o.z_threshold;
    if (t.faulty) r.faulty_teeth.push_back(t.tooth);
  }
  return r;
}

}  // namespace gearsim

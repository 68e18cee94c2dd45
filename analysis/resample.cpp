#include "analysis/resample.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "analysis/constants.hpp"
#include "core/errors.hpp"

namespace gearsim {
namespace {

void check_increasing(const char* what, const std::vector<double>& x) {
  if (x.size() < 2) throw InputError(std::string(what) + ": expected at least 2 samples, got " + std::to_string(x.size()));
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (!std::isfinite(x[i])) throw InputError(std::string(what) + ": abscissa " + std::to_string(i) + " is not finite");
    if (i > 0 && !(x[i] > x[i - 1]))
      throw InputError(std::string(what) + ": abscissae must increase strictly; sample " + std::to_string(i) + " (" + std::to_string(x[i]) +
                       ") does not exceed sample " + std::to_string(i - 1) + " (" + std::to_string(x[i - 1]) + ")");
  }
}

}  // namespace

std::vector<double> interpolate_linear(const std::vector<double>& x, const std::vector<double>& y, const std::vector<double>& x_query) {
  if (x.size() != y.size())
    throw InputError("interpolation: " + std::to_string(x.size()) + " abscissae but " + std::to_string(y.size()) + " values");
  check_increasing("interpolation", x);
  std::vector<double> out(x_query.size());
  for (std::size_t q = 0; q < x_query.size(); ++q) {
    const double xq = x_query[q];
    if (!(xq >= x.front() && xq <= x.back()))
      throw InputError("interpolation: query " + std::to_string(q) + " (" + std::to_string(xq) + ") lies outside the samples [" +
                       std::to_string(x.front()) + ", " + std::to_string(x.back()) + "]");
    // First sample strictly after xq, kept inside [1, n−1] so the segment [i−1, i] exists.
    auto it = std::upper_bound(x.begin(), x.end(), xq);
    const std::size_t i = std::clamp<std::size_t>(static_cast<std::size_t>(it - x.begin()), 1, x.size() - 1);
    const double t = (xq - x[i - 1]) / (x[i] - x[i - 1]);
    out[q] = y[i - 1] + t * (y[i] - y[i - 1]);
  }
  return out;
}

UniformSignal resample_uniform(const std::vector<double>& times_s, const std::vector<double>& values, double rate_hz) {
  if (!std::isfinite(rate_hz) || rate_hz <= 0.0)
    throw InputError("resampling: rate must be a positive number of Hz, got " + std::to_string(rate_hz));
  check_increasing("resampling", times_s);
  const double t0 = times_s.front();
  const double span_s = times_s.back() - t0;
  // The last grid time within the record; the small slack keeps an end that falls on the grid.
  const auto count = static_cast<std::size_t>(std::floor(span_s * rate_hz * (1.0 + 1e-12))) + 1;
  std::vector<double> t(count);
  for (std::size_t k = 0; k < count; ++k) t[k] = std::min(t0 + static_cast<double>(k) / rate_hz, times_s.back());
  UniformSignal u;
  u.start_time_s = t0;
  u.sample_rate_hz = rate_hz;
  u.values = interpolate_linear(times_s, values, t);
  return u;
}

double uniform_sample_rate_hz(const std::vector<double>& times_s) {
  check_increasing("time base", times_s);
  const double mean_dt = (times_s.back() - times_s.front()) / static_cast<double>(times_s.size() - 1);
  for (std::size_t i = 1; i < times_s.size(); ++i) {
    const double dt = times_s[i] - times_s[i - 1];
    if (std::abs(dt - mean_dt) > analysis_constants::kUniformTimeRelativeTolerance * mean_dt)
      throw InputError("time base: interval " + std::to_string(i) + " is " + std::to_string(dt) + " s but the mean interval is " +
                       std::to_string(mean_dt) + " s; the samples are not uniform (resample them first)");
  }
  return 1.0 / mean_dt;
}

}  // namespace gearsim

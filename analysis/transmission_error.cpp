#include "analysis/transmission_error.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "analysis/resample.hpp"
#include "core/errors.hpp"

namespace gearsim {
namespace {

constexpr double kRadToUrad = 1e6;
constexpr double kRadToDeg = 180.0 / std::numbers::pi;
constexpr double kMToUm = 1e6;

double checked_base_radius(double r_m) {
  if (!std::isfinite(r_m) || r_m <= 0.0)
    throw InputError("transmission error: input base radius must be a positive number of m, got " + std::to_string(r_m));
  return r_m;
}

std::vector<double> scaled(const std::vector<double>& x, double factor) {
  std::vector<double> y(x.size());
  std::transform(x.begin(), x.end(), y.begin(), [factor](double v) { return v * factor; });
  return y;
}

SeriesStats stats_of(const std::vector<double>& x, double factor) {
  SeriesStats s;
  const auto [lo, hi] = std::minmax_element(x.begin(), x.end());
  double sum = 0.0;
  for (const double v : x) sum += v;
  const double mean = sum / static_cast<double>(x.size());
  double ss = 0.0;
  for (const double v : x) ss += (v - mean) * (v - mean);
  s.mean = mean * factor;
  s.min = *lo * factor;
  s.max = *hi * factor;
  s.peak_to_peak = (*hi - *lo) * factor;
  s.rms = std::sqrt(ss / static_cast<double>(x.size())) * factor;
  return s;
}

}  // namespace

TransmissionError transmission_error(const std::vector<double>& time_s, const std::vector<double>& theta_in_rad,
                                     const std::vector<double>& theta_out_rad, double ratio) {
  const char* what = "transmission error";
  if (time_s.size() != theta_in_rad.size() || time_s.size() != theta_out_rad.size())
    throw InputError(std::string(what) + ": " + std::to_string(time_s.size()) + " times, " + std::to_string(theta_in_rad.size()) +
                     " input angles and " + std::to_string(theta_out_rad.size()) + " output angles; expected equal counts");
  if (time_s.size() < 2) throw InputError(std::string(what) + ": expected at least 2 samples");
  if (!std::isfinite(ratio) || ratio == 0.0)
    throw InputError(std::string(what) + ": ratio must be a finite, non-zero number, got " + std::to_string(ratio));
  TransmissionError te;
  te.time_s = time_s;
  te.ratio = ratio;
  te.te_rad.resize(time_s.size());
  for (std::size_t i = 0; i < time_s.size(); ++i) {
    if (!std::isfinite(time_s[i]) || !std::isfinite(theta_in_rad[i]) || !std::isfinite(theta_out_rad[i]))
      throw InputError(std::string(what) + ": sample " + std::to_string(i) + " is not finite");
    te.te_rad[i] = theta_in_rad[i] - ratio * theta_out_rad[i];
  }
  return te;
}

TransmissionError transmission_error_series(const std::vector<double>& time_s, const std::vector<double>& te_rad, double ratio) {
  const char* what = "transmission error series";
  if (time_s.size() != te_rad.size())
    throw InputError(std::string(what) + ": " + std::to_string(time_s.size()) + " times and " + std::to_string(te_rad.size()) +
                     " values; expected equal counts");
  if (time_s.size() < 2) throw InputError(std::string(what) + ": expected at least 2 samples");
  if (!std::isfinite(ratio) || ratio == 0.0)
    throw InputError(std::string(what) + ": ratio must be a finite, non-zero number, got " + std::to_string(ratio));
  for (std::size_t i = 0; i < time_s.size(); ++i)
    if (!std::isfinite(time_s[i]) || !std::isfinite(te_rad[i]))
      throw InputError(std::string(what) + ": sample " + std::to_string(i) + " is not finite");
  return {time_s, te_rad, ratio};
}

std::vector<double> te_urad(const TransmissionError& te) { return scaled(te.te_rad, kRadToUrad); }
std::vector<double> te_deg(const TransmissionError& te) { return scaled(te.te_rad, kRadToDeg); }
std::vector<double> te_um(const TransmissionError& te, double input_base_radius_m) {
  return scaled(te.te_rad, checked_base_radius(input_base_radius_m) * kMToUm);
}

TransmissionErrorStats te_stats(const TransmissionError& te, std::optional<double> input_base_radius_m) {
  GEARSIM_CHECK(!te.te_rad.empty(), "transmission error series is empty");
  TransmissionErrorStats s;
  s.rad = stats_of(te.te_rad, 1.0);
  s.urad = stats_of(te.te_rad, kRadToUrad);
  s.deg = stats_of(te.te_rad, kRadToDeg);
  if (input_base_radius_m) s.um = stats_of(te.te_rad, checked_base_radius(*input_base_radius_m) * kMToUm);
  return s;
}

Spectrum te_spectrum(const TransmissionError& te, const SpectrumOptions& options, double resample_rate_hz) {
  if (resample_rate_hz > 0.0) {
    const UniformSignal u = resample_uniform(te.time_s, te.te_rad, resample_rate_hz);
    return amplitude_spectrum(u.values, u.sample_rate_hz, options);
  }
  double rate_hz = 0.0;
  try {
    rate_hz = uniform_sample_rate_hz(te.time_s);
  } catch (const InputError& e) {
    throw InputError(std::string("transmission error spectrum: ") + e.what() + " (give a resample rate)");
  }
  return amplitude_spectrum(te.te_rad, rate_hz, options);
}

}  // namespace gearsim

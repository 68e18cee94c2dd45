#include "analysis/peaks.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/errors.hpp"

namespace gearsim {
namespace {

// Bin range [first, last] covering lo_hz ≤ f ≤ hi_hz; empty (first > last) when none.
std::pair<std::size_t, std::size_t> bin_range(const Spectrum& s, double lo_hz, double hi_hz) {
  const std::size_t n = s.frequency_hz.size();
  auto first = static_cast<std::size_t>(std::lower_bound(s.frequency_hz.begin(), s.frequency_hz.end(), lo_hz) - s.frequency_hz.begin());
  auto end = static_cast<std::size_t>(std::upper_bound(s.frequency_hz.begin(), s.frequency_hz.end(), hi_hz) - s.frequency_hz.begin());
  if (end == 0 || first >= n || first >= end) return {1, 0};
  return {first, end - 1};
}

}  // namespace

std::vector<SpectralPeak> local_maxima(const Spectrum& s, double lo_hz, double hi_hz, double min_amplitude) {
  std::vector<SpectralPeak> peaks;
  const auto [first, last] = bin_range(s, lo_hz, hi_hz);
  const std::vector<double>& a = s.amplitude;
  for (std::size_t k = std::max<std::size_t>(first, 1); k <= last && k + 1 < a.size(); ++k)
    if (a[k] > a[k - 1] && a[k] >= a[k + 1] && a[k] >= min_amplitude) peaks.push_back({k, s.frequency_hz[k], a[k]});
  return peaks;
}

std::optional<SpectralPeak> nearest_local_maximum(const Spectrum& s, double target_hz, double tolerance_hz) {
  std::optional<SpectralPeak> best;
  double best_distance = std::numeric_limits<double>::infinity();
  for (const SpectralPeak& p : local_maxima(s, target_hz - tolerance_hz, target_hz + tolerance_hz)) {
    const double d = std::abs(p.frequency_hz - target_hz);
    if (d < best_distance || (d == best_distance && p.amplitude > best->amplitude)) {
      best = p;
      best_distance = d;
    }
  }
  return best;
}

double median_noise_floor(const Spectrum& s, double lo_hz, double hi_hz) {
  const auto [first, last] = bin_range(s, lo_hz, hi_hz);
  if (first > last)
    throw InputError("noise floor: the band " + std::to_string(lo_hz) + " … " + std::to_string(hi_hz) + " Hz holds no bin of the spectrum");
  std::vector<double> band(s.amplitude.begin() + static_cast<std::ptrdiff_t>(first),
                           s.amplitude.begin() + static_cast<std::ptrdiff_t>(last) + 1);
  const std::size_t mid = band.size() / 2;
  std::nth_element(band.begin(), band.begin() + static_cast<std::ptrdiff_t>(mid), band.end());
  if (band.size() % 2 == 1) return band[mid];
  const double upper = band[mid];
  const double lower = *std::max_element(band.begin(), band.begin() + static_cast<std::ptrdiff_t>(mid));
  return 0.5 * (lower + upper);
}

double amplitude_ratio_db(double amplitude, double reference) {
  GEARSIM_CHECK(amplitude >= 0.0 && reference >= 0.0, "dB of a negative amplitude or reference");
  if (amplitude == 0.0) return -std::numeric_limits<double>::infinity();
  if (reference == 0.0) return std::numeric_limits<double>::infinity();
  return 20.0 * std::log10(amplitude / reference);
}

}  // namespace gearsim

#include "analysis/spectrum.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <string>

#include "analysis/fft.hpp"
#include "core/errors.hpp"

namespace gearsim {
namespace {

void check_signal(const char* what, const std::vector<double>& x, double sample_rate_hz) {
  if (!std::isfinite(sample_rate_hz) || sample_rate_hz <= 0.0)
    throw InputError(std::string(what) + ": sample rate must be a positive number of Hz, got " + std::to_string(sample_rate_hz));
  if (x.size() < 2) throw InputError(std::string(what) + ": expected at least 2 samples, got " + std::to_string(x.size()));
  for (std::size_t i = 0; i < x.size(); ++i)
    if (!std::isfinite(x[i])) throw InputError(std::string(what) + ": sample " + std::to_string(i) + " is not finite");
}

// Segments of `length` samples starting every `step` samples, each windowed and transformed;
// the result holds the mean PSD and the RMS amplitude over the segments.
Spectrum averaged_spectrum(const std::vector<double>& x, double fs, std::size_t length, std::size_t step, WindowKind kind,
                           std::size_t fft_length, bool remove_mean) {
  const Window w = make_window(kind, length);
  const std::size_t fft_len = fft_length == 0 ? length : fft_length;
  if (fft_len < length)
    throw InputError("spectrum: fft length " + std::to_string(fft_len) + " is shorter than the record (" + std::to_string(length) +
                     " samples); padding can only lengthen it");
  const std::size_t bins = fft_len / 2 + 1;
  const double n = static_cast<double>(length);
  const double s1 = w.coherent_gain * n;  // Σw
  const double s2 = w.enbw_bins * s1 * s1 / n;  // Σw²
  Spectrum s;
  s.window = kind;
  s.sample_rate_hz = fs;
  s.record_length = length;
  s.fft_length = fft_len;
  s.bin_width_hz = fs / static_cast<double>(fft_len);
  s.resolution_hz = fs / n;
  s.mainlobe_halfwidth_hz = w.mainlobe_halfwidth_bins * s.resolution_hz;
  s.enbw_hz = w.enbw_bins * s.resolution_hz;
  s.frequency_hz.resize(bins);
  for (std::size_t k = 0; k < bins; ++k) s.frequency_hz[k] = static_cast<double>(k) * s.bin_width_hz;
  std::vector<double> sum_sq_amplitude(bins, 0.0), sum_psd(bins, 0.0);
  const std::size_t segments = (x.size() - length) / step + 1;
  std::vector<double> seg(length);
  for (std::size_t m = 0; m < segments; ++m) {
    const auto first = x.begin() + static_cast<std::ptrdiff_t>(m * step);
    std::copy(first, first + static_cast<std::ptrdiff_t>(length), seg.begin());
    double mean = 0.0;
    if (remove_mean) {
      for (const double v : seg) mean += v;
      mean /= n;
    }
    for (std::size_t i = 0; i < length; ++i) seg[i] = (seg[i] - mean) * w.values[i];
    const std::vector<std::complex<double>> X = real_dft(seg, fft_len);
    for (std::size_t k = 0; k < bins; ++k) {
      // DC, and Nyquist of an even-length DFT, have no negative-frequency twin to fold in.
      const bool single = k == 0 || (fft_len % 2 == 0 && k == bins - 1);
      const double fold = single ? 1.0 : 2.0;
      const double mag2 = std::norm(X[k]);
      const double a = fold * std::sqrt(mag2) / s1;
      sum_sq_amplitude[k] += a * a;
      sum_psd[k] += fold * mag2 / (fs * s2);
    }
  }
  s.averages = static_cast<int>(segments);
  s.amplitude.resize(bins);
  s.psd_per_hz.resize(bins);
  const double inv = 1.0 / static_cast<double>(segments);
  for (std::size_t k = 0; k < bins; ++k) {
    s.amplitude[k] = std::sqrt(sum_sq_amplitude[k] * inv);
    s.psd_per_hz[k] = sum_psd[k] * inv;
  }
  return s;
}

}  // namespace

Spectrum amplitude_spectrum(const std::vector<double>& x, double sample_rate_hz, const SpectrumOptions& o) {
  check_signal("amplitude spectrum", x, sample_rate_hz);
  return averaged_spectrum(x, sample_rate_hz, x.size(), x.size(), o.window, o.fft_length, o.remove_mean);
}

Spectrum welch_spectrum(const std::vector<double>& x, double sample_rate_hz, const WelchOptions& o) {
  check_signal("welch spectrum", x, sample_rate_hz);
  if (o.segment_length < 2 || o.segment_length > x.size())
    throw InputError("welch spectrum: segment length must be 2 … " + std::to_string(x.size()) + " samples (the record), got " +
                     std::to_string(o.segment_length));
  if (!(o.overlap_fraction >= 0.0 && o.overlap_fraction < 1.0))
    throw InputError("welch spectrum: overlap fraction must be in [0, 1), got " + std::to_string(o.overlap_fraction));
  const auto overlap = static_cast<std::size_t>(std::llround(o.overlap_fraction * static_cast<double>(o.segment_length)));
  const std::size_t step = std::max<std::size_t>(1, o.segment_length - std::min(overlap, o.segment_length - 1));
  return averaged_spectrum(x, sample_rate_hz, o.segment_length, step, o.window, o.fft_length, o.remove_mean);
}

double spectrum_power(const Spectrum& s) {
  double p = 0.0;
  for (const double d : s.psd_per_hz) p += d;
  return p * s.bin_width_hz;
}

std::size_t nearest_bin(const Spectrum& s, double f_hz) {
  GEARSIM_CHECK(!s.frequency_hz.empty() && s.bin_width_hz > 0.0, "spectrum has no bins");
  const double k = std::round(f_hz / s.bin_width_hz);
  if (!(k > 0.0)) return 0;
  return std::min(static_cast<std::size_t>(k), s.frequency_hz.size() - 1);
}

}  // namespace gearsim

#include "analysis/decimation_filter.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <sstream>
#include <string>

#include "analysis/fft.hpp"
#include "core/errors.hpp"

namespace gearsim {
namespace {

namespace ac = analysis_constants;

// A number as a reader would write it (2100, 23.80952381, nan), for messages.
std::string decimation_number(double v) {
  std::ostringstream out;
  out.precision(10);
  out << v;
  return out.str();
}

void check_decimation_rate(const char* what, double rate_hz) {
  if (!std::isfinite(rate_hz) || rate_hz <= 0.0)
    throw InputError(std::string("decimation filter: ") + what + " must be a positive number of Hz, got " + decimation_number(rate_hz));
}

// Kaiser's β for a stopband attenuation a_dB (Kaiser 1974; Oppenheim & Schafer eq. 7.62).
double decimation_kaiser_beta(double a_dB) {
  if (a_dB > 50.0) return 0.1102 * (a_dB - 8.7);
  if (a_dB >= 21.0) return 0.5842 * std::pow(a_dB - 21.0, 0.4) + 0.07886 * (a_dB - 21.0);
  return 0.0;
}

// Kaiser's estimate of the length (odd) for attenuation a_dB over a transition of width Δf, Hz.
std::size_t decimation_kaiser_length(double a_dB, double transition_hz, double input_rate_hz) {
  const double dw = 2.0 * std::numbers::pi * transition_hz / input_rate_hz;  // rad/sample
  const double order = std::ceil((a_dB - 7.95) / (2.285 * dw));
  const double capped = std::min(order, static_cast<double>(ac::kMaxDecimationFilterTaps));
  const auto length = static_cast<std::size_t>(capped) + 1;
  return length % 2 == 1 ? length : length + 1;
}

// Windowed sinc of odd `length`, cut-off at f_out/2 (h_m ∝ sinc(m/R)), normalised to Σh = 1.
// The right half is computed and mirrored, so the taps are exactly symmetric.
std::vector<double> decimation_kaiser_sinc(std::size_t length, int ratio, double beta) {
  const std::size_t m_half = (length - 1) / 2;
  const double r = static_cast<double>(ratio);
  const double i0_beta = std::cyl_bessel_i(0.0, beta);
  std::vector<double> h(length);
  for (std::size_t m = 0; m <= m_half; ++m) {
    const double x = static_cast<double>(m) / r;
    const double sinc = m == 0 ? 1.0 : std::sin(std::numbers::pi * x) / (std::numbers::pi * x);
    const double u = static_cast<double>(m) / static_cast<double>(m_half);  // 0 at the centre, 1 at the ends
    const double w = m_half == 0 ? 1.0 : std::cyl_bessel_i(0.0, beta * std::sqrt(std::max(0.0, 1.0 - u * u))) / i0_beta;
    h[m_half + m] = h[m_half - m] = sinc * w / r;
  }
  // Sum in mirrored pairs so the normalisation does not depend on which half rounds first.
  double sum = h[m_half];
  for (std::size_t m = 1; m <= m_half; ++m) sum += 2.0 * h[m_half + m];
  GEARSIM_CHECK(sum > 0.0, "a low-pass sinc must have a positive DC gain");
  for (double& v : h) v /= sum;
  return h;
}

// Measures passband ripple and stopband attenuation: the zero-padded DFT of the taps on a grid
// kResponseGridOversampling times finer than the response's ripples, plus both band edges.
void measure_decimation_response(DecimationFilter& f) {
  std::size_t fft_length = 1;
  while (fft_length < ac::kResponseGridOversampling * f.length()) fft_length *= 2;
  const std::vector<std::complex<double>> spectrum = real_dft(f.taps, fft_length);
  const double bin_hz = f.input_rate_hz / static_cast<double>(fft_length);
  double ripple = std::max(std::abs(frequency_response(f, f.passband_edge_hz) - 1.0), std::abs(frequency_response(f, 0.0) - 1.0));
  double stop_peak = std::abs(frequency_response(f, f.stopband_edge_hz));
  for (std::size_t k = 0; k < spectrum.size(); ++k) {
    const double fk = static_cast<double>(k) * bin_hz;
    // |DFT| = |H(f)|: the taps' linear phase drops out; H > 0 throughout the passband.
    if (fk <= f.passband_edge_hz) ripple = std::max(ripple, std::abs(std::abs(spectrum[k]) - 1.0));
    if (fk >= f.stopband_edge_hz) stop_peak = std::max(stop_peak, std::abs(spectrum[k]));
  }
  f.passband_ripple = ripple;
  f.stopband_attenuation_dB = -20.0 * std::log10(stop_peak);
}

}  // namespace

DecimationFilter design_decimation_filter(double input_rate_hz, double output_rate_hz, const DecimationFilterOptions& options) {
  check_decimation_rate("input rate", input_rate_hz);
  check_decimation_rate("output rate", output_rate_hz);
  const double exact_ratio = input_rate_hz / output_rate_hz;
  const double ratio = std::round(exact_ratio);
  if (std::abs(exact_ratio - ratio) > ac::kDecimationRatioRelativeTolerance * exact_ratio)
    throw InputError("decimation filter: input rate " + decimation_number(input_rate_hz) + " Hz over output rate " +
                     decimation_number(output_rate_hz) + " Hz is " + decimation_number(exact_ratio) + ", not an integer (within " +
                     decimation_number(ac::kDecimationRatioRelativeTolerance) + "); choose an output rate that divides the input rate");
  if (ratio < 2.0)
    throw InputError("decimation filter: input rate " + decimation_number(input_rate_hz) + " Hz must be at least twice the output rate " +
                     decimation_number(output_rate_hz) + " Hz (ratio " + decimation_number(exact_ratio) +
                     "); at ratio 1 keep every sample");
  const double f_pass = options.passband_edge_hz.value_or(ac::kDefaultPassbandFraction * output_rate_hz);
  if (!std::isfinite(f_pass) || f_pass <= 0.0 || f_pass >= 0.5 * output_rate_hz)
    throw InputError("decimation filter: passband edge " + decimation_number(f_pass) + " Hz must lie in (0, " +
                     decimation_number(0.5 * output_rate_hz) + ") Hz, below half the output rate " + decimation_number(output_rate_hz) +
                     " Hz");
  const double a_dB = options.stopband_attenuation_dB;
  if (!std::isfinite(a_dB) || a_dB < ac::kMinStopbandAttenuation_dB || a_dB > ac::kMaxStopbandAttenuation_dB)
    throw InputError("decimation filter: stopband attenuation " + decimation_number(a_dB) + " dB must lie in [" +
                     decimation_number(ac::kMinStopbandAttenuation_dB) + ", " + decimation_number(ac::kMaxStopbandAttenuation_dB) + "] dB");

  DecimationFilter f;
  f.input_rate_hz = input_rate_hz;
  f.output_rate_hz = output_rate_hz;
  f.ratio = static_cast<int>(ratio);
  f.passband_edge_hz = f_pass;
  f.stopband_edge_hz = output_rate_hz - f_pass;
  f.kaiser_beta = decimation_kaiser_beta(a_dB);
  const double transition_hz = f.stopband_edge_hz - f.passband_edge_hz;
  std::size_t length = decimation_kaiser_length(a_dB, transition_hz, input_rate_hz);
  // Kaiser's estimate is usually within a few taps; lengthen by ~1 % until the measurement agrees.
  for (;;) {
    if (length > ac::kMaxDecimationFilterTaps)
      throw InputError("decimation filter: " + decimation_number(a_dB) + " dB over a transition band of " +
                       decimation_number(transition_hz) + " Hz at " + decimation_number(input_rate_hz) + " Hz needs more than " +
                       std::to_string(ac::kMaxDecimationFilterTaps) +
                       " taps; widen the transition (a lower passband edge) or ask for less attenuation");
    f.taps = decimation_kaiser_sinc(length, f.ratio, f.kaiser_beta);
    f.group_delay_samples = (length - 1) / 2;
    f.group_delay_s = static_cast<double>(f.group_delay_samples) / input_rate_hz;
    measure_decimation_response(f);
    if (f.stopband_attenuation_dB >= a_dB) return f;
    length += 2 * std::max<std::size_t>(1, length / 200);
  }
}

double frequency_response(const DecimationFilter& filter, double frequency_hz) {
  if (!std::isfinite(frequency_hz))
    throw InputError("decimation filter response: frequency must be a finite number of Hz, got " + decimation_number(frequency_hz));
  GEARSIM_CHECK(filter.length() % 2 == 1 && filter.input_rate_hz > 0.0, "a designed decimation filter");
  const std::size_t m_half = filter.group_delay_samples;
  const double w = 2.0 * std::numbers::pi * frequency_hz / filter.input_rate_hz;  // rad/sample
  double h = filter.taps[m_half];
  for (std::size_t m = 1; m <= m_half; ++m) h += 2.0 * filter.taps[m_half + m] * std::cos(w * static_cast<double>(m));
  return h;
}

}  // namespace gearsim

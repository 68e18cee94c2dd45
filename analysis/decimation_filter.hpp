// The anti-aliasing low-pass filter of a decimator: a linear-phase FIR, Kaiser-windowed sinc, that
// lets a signal sampled at f_in be kept at f_out = f_in/R (R an integer ≥ 2). Content below the
// passband edge f_pass passes within the passband ripple; content from the stopband edge
// f_out − f_pass up to f_in/2 is attenuated by at least the stopband attenuation. At f_out such
// content folds only into (f_pass, f_out/2] — above the passband, never into it — so everything
// below f_pass is kept and free of aliases. The figures reported are measured from the taps, not
// only asked for. Not the filtering itself (decimator.hpp), and not a general filter-design
// library (no high-pass, band-pass, IIR or non-integer ratios).
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "analysis/constants.hpp"

namespace gearsim {

struct DecimationFilterOptions {
  // Highest frequency kept (within the passband ripple), Hz; 0 < f_pass < f_out/2. Unset:
  // kDefaultPassbandFraction·f_out (0.48·f_out: 960 Hz at a 2 kHz output).
  std::optional<double> passband_edge_hz;
  // Least attenuation from the stopband edge f_out − f_pass up to f_in/2, dB (100 dB is ×1e-5);
  // within [kMinStopbandAttenuation_dB, kMaxStopbandAttenuation_dB].
  double stopband_attenuation_dB = analysis_constants::kDefaultStopbandAttenuation_dB;
};

// A designed filter: taps plus the figures that describe it. Zero-phase when applied centred
// (decimator.hpp): its response is then the real amplitude H(f) of frequency_response().
struct DecimationFilter {
  double input_rate_hz = 0;  // f_in, Hz
  double output_rate_hz = 0;  // f_out = f_in/R, Hz
  int ratio = 0;  // R, input samples per output sample
  double passband_edge_hz = 0;  // f_pass, Hz
  double stopband_edge_hz = 0;  // f_out − f_pass, Hz
  double kaiser_beta = 0;  // shape parameter of the Kaiser window, dimensionless
  // h_n, n = 0 … L−1: L odd, symmetric (h_n = h_{L−1−n} exactly), Σh = 1 to rounding (DC gain 1).
  std::vector<double> taps;
  std::size_t group_delay_samples = 0;  // (L − 1)/2, input samples: how far the centre tap lags
  double group_delay_s = 0;  // (L − 1)/2 / f_in, s
  double passband_ripple = 0;  // measured max |H(f) − 1| on [0, f_pass], dimensionless
  double stopband_attenuation_dB = 0;  // measured −20·log10 max |H(f)| on [f_stop, f_in/2], dB

  std::size_t length() const { return taps.size(); }  // L, taps
};

// The shortest Kaiser-windowed sinc (cut-off f_out/2) whose measured stopband attenuation reaches
// the one asked for: Kaiser's length estimate L ≈ (A − 7.95)/(2.285·2π·(f_stop − f_pass)/f_in) + 1,
// lengthened if the measurement falls short. Throws InputError, naming the value, on a
// non-finite or non-positive rate, a ratio f_in/f_out that is not an integer ≥ 2 (within
// kDecimationRatioRelativeTolerance), a passband edge outside (0, f_out/2), an attenuation
// outside its range, or a design longer than kMaxDecimationFilterTaps.
DecimationFilter design_decimation_filter(double input_rate_hz, double output_rate_hz, const DecimationFilterOptions& options = {});

// H(f) = h_M + 2·Σ_{m=1…M} h_{M+m}·cos(2π·f·m/f_in), M = (L − 1)/2: the filter's gain at f, Hz,
// when applied centred (zero phase). Real, and negative on alternate stopband lobes; |H| is the
// gain. Periodic in f_in and even in f. Throws InputError when f is not finite.
double frequency_response(const DecimationFilter& filter, double frequency_hz);

}  // namespace gearsim

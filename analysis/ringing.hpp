// The frequency and damping of a lightly damped ringing — one decaying oscillation, such as a
// contact's free vibration after an impact — from a uniformly sampled record, by two-pole linear
// prediction (Prony's method): x_n = c0 + c1·x_{n−1} + c2·x_{n−2} fitted by least squares, whose
// poles r·e^{±iθ} give the damped frequency θ·fs/2π and the decay rate −fs·ln r. Exact for one
// damped sinusoid on a constant offset. A record of several modes, or one with forcing (mesh
// harmonics), is not one ringing: the estimate is then a compromise and the relative residual
// says so. Not a modal analysis (one mode only), and not a spectrum (spectrum.hpp).
#pragma once

#include <vector>

namespace gearsim {

struct RingingEstimate {
  double frequency_hz = 0;  // damped frequency f_d, Hz
  double decay_rate_per_s = 0;  // σ: the envelope goes as exp(−σ·t), 1/s; negative if it grows
  double damping_ratio = 0;  // ζ = σ/ω_n with ω_n = √((2π·f_d)² + σ²), dimensionless
  // RMS of the prediction error over the RMS of x about its mean: ~1e-15 for one ringing on an
  // offset, of order 0.01 or more once anything else is mixed in, dimensionless.
  double relative_residual = 0;
};

// The ringing in x (uniform samples at sample_rate_hz). Throws InputError on fewer than 8 samples,
// a non-positive or non-finite rate, a non-finite sample (named), a constant record, or a record
// whose best two-pole fit does not oscillate (real poles, e.g. a plain exponential decay).
RingingEstimate estimate_ringing(const std::vector<double>& x, double sample_rate_hz);

}  // namespace gearsim

// Resampling by LINEAR INTERPOLATION: non-uniform samples (a variable-step simulator's log) onto a
// uniform time grid, and a sequence y(x) onto any monotone grid (angle_average.hpp uses it for
// angle). Linear interpolation is exact for straight lines, errs by at most h²·max|y''|/8 for a
// spacing h, and damps content near the input's own Nyquist; there is NO anti-alias filter, so
// content above half the new rate folds down. Not a band-limited (sinc) resampler.
#pragma once

#include <vector>

namespace gearsim {

struct UniformSignal {
  double start_time_s = 0;  // time of values[0], s
  double sample_rate_hz = 0;  // samples per second
  std::vector<double> values;  // values[k] at start_time_s + k/sample_rate_hz
};

// y at each x_query by linear interpolation between the samples (x_i, y_i). x must be strictly
// increasing; every query must lie within [x.front(), x.back()]. Throws InputError otherwise
// (naming the offending index), or when x and y differ in length or hold fewer than 2 samples.
std::vector<double> interpolate_linear(const std::vector<double>& x, const std::vector<double>& y, const std::vector<double>& x_query);

// (times_s, values) onto t_k = times_s.front() + k/rate_hz for every t_k ≤ times_s.back().
// Throws InputError as interpolate_linear, or on a non-positive or non-finite rate.
UniformSignal resample_uniform(const std::vector<double>& times_s, const std::vector<double>& values, double rate_hz);

// The sample rate of a uniform time base, Hz: (n − 1)/(t_last − t_first). Throws InputError when
// any interval differs from the mean by more than kUniformTimeRelativeTolerance (then resample),
// or when fewer than 2 times are given.
double uniform_sample_rate_hz(const std::vector<double>& times_s);

}  // namespace gearsim

#include "analysis/band_limited.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "core/errors.hpp"

namespace gearsim {
namespace {

// Kaiser window shape for 90 dB (β = 0.1102·(90 − 8.7)).
constexpr double kKaiserBeta = 0.1102 * (90 - 8.7);

// The zeroth-order modified Bessel function I0 by its series (converges fast for the β here).
double bessel_i0(double x) {
  double sum = 1, term = 1;
  for (int k = 1; k < 60; ++k) {
    term *= (x / (2 * k)) * (x / (2 * k));
    sum += term;
    if (term < 1e-17 * sum) break;
  }
  return sum;
}

// The interpolation kernel at t samples from the point: sinc(t) times the Kaiser window over
// |t| < kBandLimitedHalfTaps.
double kernel(double t) {
  const double half = static_cast<double>(kBandLimitedHalfTaps);
  if (!(std::abs(t) < half)) return 0;
  const double r = t / half;
  const double window = bessel_i0(kKaiserBeta * std::sqrt(1 - r * r)) / bessel_i0(kKaiserBeta);
  const double sinc = t == 0 ? 1 : std::sin(std::numbers::pi * t) / (std::numbers::pi * t);
  return sinc * window;
}

// The extreme of three neighbouring values around b, refined by the parabola through them; b
// itself where they do not bend.
double parabola_peak(double a, double b, double c) {
  const double curvature = a - 2 * b + c;
  if (!(curvature != 0)) return b;
  const double offset = std::clamp(0.5 * (a - c) / curvature, -1.0, 1.0);
  return b - 0.25 * (a - c) * offset;
}

}  // namespace

Extremes band_limited_extremes(const std::vector<double>& x) {
  if (x.empty()) throw InputError("band-limited extremes: the record is empty");
  for (std::size_t k = 0; k < x.size(); ++k)
    if (!std::isfinite(x[k])) throw InputError("band-limited extremes: sample " + std::to_string(k) + " is not finite");
  Extremes e{*std::min_element(x.begin(), x.end()), *std::max_element(x.begin(), x.end())};
  const std::size_t n = x.size(), half = kBandLimitedHalfTaps;
  if (n <= 2 * half) return e;
  // The kernel's weights for each fractional position μ = m/oversample, taps j − half + 1 … j + half
  // around sample j (point j + μ): computed once.
  const int up = kBandLimitedOversample;
  const std::size_t taps = 2 * half;
  std::vector<double> weights(static_cast<std::size_t>(up) * taps);
  for (int m = 0; m < up; ++m)
    for (std::size_t i = 0; i < taps; ++i) {
      const double t = static_cast<double>(m) / up - (static_cast<double>(i) - static_cast<double>(half) + 1);
      weights[static_cast<std::size_t>(m) * taps + i] = kernel(t);
    }
  // The interpolated points from sample half − 1 to n − half − 1 (every tap within the record),
  // in order; each point that is the largest (smallest) so far keeps its two neighbours for the
  // parabola. Nothing stored per point.
  const std::size_t first = half - 1, last = n - half - 1;
  double before = 0, here = 0;  // the two points before the current one
  double top[3] = {0, 0, 0}, bottom[3] = {0, 0, 0};
  bool have_top = false, have_bottom = false;
  std::size_t count = 0;
  for (std::size_t j = first; j <= last; ++j)
    for (int m = 0; m < (j == last ? 1 : up); ++m) {
      double v = x[j];  // at a sample the kernel is 1 there and 0 at the others
      if (m != 0) {
        const double* w = weights.data() + static_cast<std::size_t>(m) * taps;
        const double* s = x.data() + (j + 1 - half);
        v = 0;
        for (std::size_t i = 0; i < taps; ++i) v += w[i] * s[i];
      }
      if (count >= 2) {  // `here` has both neighbours now
        if (!have_top || here > top[1]) top[0] = before, top[1] = here, top[2] = v, have_top = true;
        if (!have_bottom || here < bottom[1]) bottom[0] = before, bottom[1] = here, bottom[2] = v, have_bottom = true;
      }
      before = here, here = v;
      ++count;
    }
  if (have_top) e.max = std::max(e.max, parabola_peak(top[0], top[1], top[2]));
  if (have_bottom) e.min = std::min(e.min, parabola_peak(bottom[0], bottom[1], bottom[2]));
  return e;
}

}  // namespace gearsim

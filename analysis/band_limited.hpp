// The extremes of a band-limited signal between its samples. A record sampled at f_s holds the
// continuous signal it was low-passed to (the anti-aliased te_rad, docs/decimation.md: content up
// to 0.48·f_s), and that signal's peaks fall anywhere between samples: the samples' own
// max − min read low — for a short pulse by much (the faulty paper run's TE dips: 10–18 %) and
// by an amount that changes with where the samples happen to fall. Here the record is
// interpolated between samples by a Kaiser-windowed sinc (kBandLimitedHalfTaps samples on each
// side, 90 dB: flat to 3e-5 up to 0.485·f_s), kBandLimitedOversample points per interval, and each
// extreme refined by the parabola through it and its neighbours. Within kBandLimitedHalfTaps
// samples of either end the kernel runs out of samples: there only the samples count.
#pragma once

#include <cstddef>
#include <vector>

namespace gearsim {

constexpr std::size_t kBandLimitedHalfTaps = 96;
constexpr int kBandLimitedOversample = 16;

struct Extremes {
  double min = 0, max = 0;
};

// Throws InputError on an empty record or a non-finite sample. A record too short for an
// interior (≤ 2·kBandLimitedHalfTaps samples) gives its samples' extremes.
Extremes band_limited_extremes(const std::vector<double>& x);

}  // namespace gearsim

// Peak primitives on an amplitude spectrum: local maxima in a band, the local maximum nearest a
// frequency, a median noise floor, and amplitude ratios in dB. Peaks are taken at their highest
// bin (no interpolation between bins): a peak's frequency is exact to ± half a bin width.
// Not the mesh/sideband logic (sidebands.hpp).
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "analysis/spectrum.hpp"

namespace gearsim {

struct SpectralPeak {
  std::size_t bin = 0;
  double frequency_hz = 0;
  double amplitude = 0;  // the spectrum's amplitude at the bin, signal unit
};

// Local maxima (a[k] > a[k−1] and a[k] ≥ a[k+1]; the first and last bins of the spectrum never
// count) with lo_hz ≤ f ≤ hi_hz and amplitude ≥ min_amplitude, in increasing frequency.
std::vector<SpectralPeak> local_maxima(const Spectrum& s, double lo_hz, double hi_hz, double min_amplitude = 0);

// The local maximum nearest target_hz within ± tolerance_hz, or nothing; equal distances go to
// the higher peak.
std::optional<SpectralPeak> nearest_local_maximum(const Spectrum& s, double target_hz, double tolerance_hz);

// Median amplitude of the bins with lo_hz ≤ f ≤ hi_hz (clamped to the spectrum), signal unit.
// Robust to the few peaks in the band. Throws InputError when the band holds no bin.
double median_noise_floor(const Spectrum& s, double lo_hz, double hi_hz);

// 20·log10(amplitude/reference), dB: −inf for a zero amplitude, else +inf for a zero reference
// (an exactly noiseless synthetic band). Both must be ≥ 0.
double amplitude_ratio_db(double amplitude, double reference);

}  // namespace gearsim

// Envelope analysis (amplitude demodulation): the signal band-passed to [band_lo_hz, band_hi_hz]
// by masking its DFT, its envelope the magnitude of the analytic signal √(x_b² + H(x_b)²) (H the
// Hilbert transform, −i·sgn(f) in the DFT), and the amplitude spectrum of that envelope (its mean
// removed). A carrier c·(1 + m cos 2πf_a t) in the band gives an envelope line of c·m at f_a.
// Periodic extension is assumed (the DFT's): a record that does not hold whole periods leaks at
// its ends, as any DFT does.
#pragma once

#include <vector>

#include "analysis/spectrum.hpp"

namespace gearsim {

struct EnvelopeSpectrum {
  std::vector<double> envelope;  // per sample, the signal's unit
  Spectrum spectrum;  // of the envelope, its mean removed
};

// InputError on fewer than 16 samples, a non-finite sample or rate, or a band that is empty or
// not inside (0, fs/2].
EnvelopeSpectrum envelope_spectrum(const std::vector<double>& x, double sample_rate_hz, double band_lo_hz, double band_hi_hz,
                                   const SpectrumOptions& options = {});

}  // namespace gearsim

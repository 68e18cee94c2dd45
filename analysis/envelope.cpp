#include "analysis/envelope.hpp"

#include <cmath>
#include <complex>
#include <string>

#include "analysis/fft.hpp"
#include "core/errors.hpp"

namespace gearsim {

EnvelopeSpectrum envelope_spectrum(const std::vector<double>& x, double fs, double lo, double hi, const SpectrumOptions& options) {
  if (x.size() < 16) throw InputError("envelope spectrum: expected at least 16 samples, got " + std::to_string(x.size()));
  if (!(fs > 0) || !std::isfinite(fs)) throw InputError("envelope spectrum: the sample rate must be a positive number of Hz");
  if (!(lo >= 0 && lo < hi && hi <= fs / 2))
    throw InputError("envelope spectrum: band " + std::to_string(lo) + "–" + std::to_string(hi) + " Hz is not inside (0, " +
                     std::to_string(fs / 2) + "] Hz");
  const std::size_t n = x.size();
  std::vector<std::complex<double>> X = real_dft(x, n);
  // The band: bins whose frequency k·fs/n lies in [lo, hi]; the mean never.
  X[0] = 0;
  for (std::size_t k = 1; k < X.size(); ++k) {
    const double f = static_cast<double>(k) * fs / static_cast<double>(n);
    if (f < lo || f > hi) X[k] = 0;
  }
  std::vector<std::complex<double>> H(X.size());
  for (std::size_t k = 1; k < X.size(); ++k) H[k] = std::complex<double>(0, -1) * X[k];
  if (n % 2 == 0) H.back() = 0;  // the Nyquist bin has no sign: its Hilbert transform is 0
  const std::vector<double> xb = real_idft(X, n), hb = real_idft(H, n);
  EnvelopeSpectrum e;
  e.envelope.resize(n);
  for (std::size_t i = 0; i < n; ++i) e.envelope[i] = std::hypot(xb[i], hb[i]);
  SpectrumOptions o = options;
  o.remove_mean = true;
  e.spectrum = amplitude_spectrum(e.envelope, fs, o);
  return e;
}

}  // namespace gearsim

// The discrete Fourier transform of a real sequence (FFTW, real-to-complex), the one place the
// library calls FFTW. Plans are made with FFTW_ESTIMATE, never measured, so the same input gives
// the same bits on every run. Not a spectrum: no window, no scaling (spectrum.hpp does that).
#pragma once

#include <complex>
#include <cstddef>
#include <vector>

namespace gearsim {

// X_k = Σ_n x_n·exp(−2πi·k·n/L) for k = 0 … L/2, with L = fft_length ≥ x.size(): x is zero-padded
// to L samples. Unscaled, as FFTW defines it. Throws InputError when x is empty or L < x.size().
std::vector<std::complex<double>> real_dft(const std::vector<double>& x, std::size_t fft_length);

// The inverse: x_n = (1/L) Σ_k X_k·exp(2πi·k·n/L) over the full Hermitian spectrum whose bins
// 0 … L/2 are X (X.size() = L/2 + 1), so real_idft(real_dft(x, L), L) = x. Scaled by 1/L (unlike
// FFTW). Throws InputError when X.size() ≠ L/2 + 1.
std::vector<double> real_idft(const std::vector<std::complex<double>>& X, std::size_t length);

}  // namespace gearsim

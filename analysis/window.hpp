// Spectral windows for the DFT: rectangular, Hann and flat-top, with the numbers that turn a
// windowed DFT into physical units — coherent gain (for the amplitude of a tone) and equivalent
// noise bandwidth (for the density of noise). Periodic (DFT-even) forms: a tone on a bin shows
// exactly the window's few nonzero DFT coefficients. Not a filter design library.
#pragma once

#include <cstddef>
#include <string_view>
#include <vector>

namespace gearsim {

enum class WindowKind {
  Rectangular,  // no taper: best resolution, Parseval exact, heavy leakage (−13 dB sidelobes)
  Hann,  // general purpose: −31 dB first sidelobe, up to −1.42 dB scalloping off-bin
  FlatTop,  // for amplitudes: HFT95 (Heinzel et al. 2002), ±0.0044 dB flatness, −95 dB sidelobes
};

struct Window {
  WindowKind kind = WindowKind::Hann;
  std::vector<double> values;  // w_n, n = 0 … N−1, dimensionless, peak 1 (rect, Hann) or ≈ 1 (flat-top)
  // Σw/N: the DFT of a tone of amplitude A on a bin has magnitude A·N·coherent_gain/2.
  double coherent_gain = 0;
  // N·Σw²/(Σw)²: the bandwidth, in bins of 1/T, of an ideal filter passing the same noise power.
  double enbw_bins = 0;
  // Distance from a tone's bin to the first zero of its main lobe, in bins of 1/T: two tones closer
  // than about this merge into one peak (rect 1, Hann 2, flat-top 5).
  double mainlobe_halfwidth_bins = 0;
};

// The window of `length` samples. Throws InputError for length 0, or 1 for a tapered window.
Window make_window(WindowKind kind, std::size_t length);

// "rectangular", "hann", "flat-top".
std::string_view window_name(WindowKind kind);

}  // namespace gearsim

// Spectra of a uniformly sampled real signal: the single-sided amplitude spectrum of one record
// (windowed, optionally zero-padded) and Welch's averaged spectrum (overlapping windowed
// segments). Amplitudes are in the signal's own unit — a sine of amplitude A shows a peak of A
// after the window's coherent-gain correction — and densities in unit²/Hz (ENBW-corrected).
// Every result carries its frequency resolution. Not for non-uniform samples (resample.hpp first).
#pragma once

#include <cstddef>
#include <vector>

#include "analysis/window.hpp"

namespace gearsim {

// Two frequency scales in every spectrum, kept apart on purpose:
//  - bin_width_hz = fs/fft_length, the spacing of the frequency grid. Zero padding shrinks it.
//  - resolution_hz = 1/T = fs/record_length, the record's resolution. A 1 s record resolves 1 Hz
//    however far it is padded: padding interpolates the spectrum, it never separates two tones
//    closer than the window's main lobe (mainlobe_halfwidth_hz, a small multiple of 1/T).
struct Spectrum {
  std::vector<double> frequency_hz;  // bin k at k·bin_width_hz, k = 0 … fft_length/2
  // Single-sided peak amplitude, in the signal's unit: a tone A·cos(2πft + φ) on a bin reads A.
  std::vector<double> amplitude;
  // Single-sided power spectral density, (signal unit)²/Hz. Σ psd_per_hz·bin_width_hz is the
  // window-weighted mean square Σ(x·w)²/Σw² (Welch: its mean over segments) — for the rectangular
  // window exactly the record's mean square (Parseval), whatever the padding.
  std::vector<double> psd_per_hz;
  WindowKind window = WindowKind::Hann;
  double sample_rate_hz = 0;
  std::size_t record_length = 0;  // samples per DFT before padding (Welch: the segment length)
  std::size_t fft_length = 0;  // DFT length after zero padding, ≥ record_length
  int averages = 1;  // segments averaged (1 for a single record)
  double bin_width_hz = 0;  // fs/fft_length
  double resolution_hz = 0;  // fs/record_length = 1/T
  double mainlobe_halfwidth_hz = 0;  // window main-lobe half width, Hz: tones closer than this merge
  double enbw_hz = 0;  // equivalent noise bandwidth of one bin, Hz
};

struct SpectrumOptions {
  WindowKind window = WindowKind::Hann;
  // DFT length: 0 for the record length; otherwise ≥ the record length (zero padding).
  std::size_t fft_length = 0;
  bool remove_mean = true;  // subtract the record's mean before windowing (DC bin then ≈ 0)
};

// Spectrum of one record x (uniform samples at sample_rate_hz). Throws InputError on an empty or
// too-short record, a non-positive or non-finite rate, a non-finite sample, or fft_length < N.
Spectrum amplitude_spectrum(const std::vector<double>& x, double sample_rate_hz, const SpectrumOptions& options = {});

struct WelchOptions {
  std::size_t segment_length = 0;  // samples per segment, 2 … x.size() (required)
  double overlap_fraction = 0.5;  // overlap of consecutive segments, [0, 1); 0.5 suits Hann
  WindowKind window = WindowKind::Hann;
  std::size_t fft_length = 0;  // 0: the segment length; otherwise ≥ it (zero padding)
  bool remove_mean = true;  // subtract each segment's mean before windowing
};

// Welch's method: the PSD is the mean of the segments' PSDs; the amplitude is the RMS over
// segments of the segments' amplitudes (a steady tone of amplitude A still reads A). Samples after
// the last whole segment are not used. Throws InputError as amplitude_spectrum, or on a segment
// length outside 2 … x.size() or an overlap outside [0, 1).
Spectrum welch_spectrum(const std::vector<double>& x, double sample_rate_hz, const WelchOptions& options);

// Σ psd_per_hz·bin_width_hz: the mean square the spectrum accounts for, (signal unit)².
double spectrum_power(const Spectrum& s);

// Index of the bin nearest to f_hz (clamped to the spectrum's range).
std::size_t nearest_bin(const Spectrum& s, double f_hz);

}  // namespace gearsim

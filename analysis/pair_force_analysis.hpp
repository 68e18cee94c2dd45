// The contact-force spectrum of one gear pair over a run's analysed window, and what it shows: the
// mean force and the share of samples with no contact, the mesh harmonics and how far they stand
// over the 0–1000 Hz median floor, their sidebands matched to characteristic frequencies
// (sidebands.hpp), and for a planetary set the lines of the planet local-fault family. Labels
// lines; it does not decide what is broken.
#pragma once

#include <optional>
#include <vector>

#include "analysis/peaks.hpp"
#include "analysis/run_signals.hpp"
#include "analysis/sidebands.hpp"
#include "analysis/spectrum.hpp"

namespace gearsim {

// A line expected at a multiple of the planet local-fault frequency.
struct FaultLine {
  int multiple = 1;  // k
  double expected_hz = 0;  // k·f_planet_fault, Hz
  std::optional<SpectralPeak> peak;  // the local maximum nearest it within tolerance; nothing: none
  double over_floor_db = 0;  // 20·log10(peak amplitude/floor_N), dB, when found
};

struct PairForceAnalysis {
  PairId pair;
  // Hann, mean removed, zero-padded to the power of two ≥ kRunSpectrumPadding × the record.
  Spectrum spectrum;
  double mean_force_N = 0;
  // The window's peak force, N: of the band-limited force the anti-aliased samples hold (between
  // samples too: band_limited.hpp), or the largest sample of a point-sampled record.
  double peak_force_N = 0;
  // peak_force_N / mean_force_N: how far the meshing dynamics lift the force over its mean
  // within the output band (the band-limited dynamic factor of the window); 0 when the mean is not
  // positive. Below the per-step figure wherever the force carries more than the band holds.
  double dynamic_factor_band_limited = 0;
  // From the per-step log (steps.h5), unset without one: the pair's force in each step of the
  // window (its tooth contacts' impulses / dt), its mean and peak, N, and their ratio — the
  // dynamic factor ISO 6336's K_v stands for (the largest mesh force over the mean one).
  std::optional<double> mean_step_force_N, peak_step_force_N, dynamic_factor_per_step;
  double zero_force_share = 0;  // samples with exactly zero force / samples
  // Steps of the window in which the pair carried no force / steps, from the per-step log
  // (steps.h5); unset without one. A tooth that leaves its mate for less than a sample
  // interval (the paper's faulty tooth: ≈ 0.4 ms per planet turn, samples 0.5 ms apart) is
  // seen here, not always in the samples.
  std::optional<double> steps_without_force_share;
  double floor_N = 0;  // median amplitude over 0 … kRunFloorBandTop_hz, N
  SidebandAnalysis mesh;  // harmonics of f_m and their sidebands (default options)
  // One per mesh.harmonics: its peak over floor_N, dB; nothing where no peak was found.
  std::vector<std::optional<double>> harmonic_over_floor_db;
  // k = 1 … kPlanetFaultMultiples for a planetary set; empty for a gear pair.
  std::vector<FaultLine> planet_fault_family;
};

// force_N: the pair's force over the window, uniform at sample_rate_hz; point_force_N: the same
// force point-sampled, for the share of samples without contact (empty: force_N is). InputError
// as amplitude_spectrum and analyse_sidebands (e.g. a record too short or a harmonic above
// Nyquist), or when a planetary train has no "planet_fault" frequency.
PairForceAnalysis analyse_pair_force(const PairId& pair, const std::vector<double>& force_N, double sample_rate_hz,
                                     const TrainDescription& train, const std::vector<double>& point_force_N = {});

}  // namespace gearsim

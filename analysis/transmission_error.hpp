// Transmission error of a gear train: TE = θ_in − i·θ_out, the input's angular lead over where a
// perfect train of ratio i = ω_in/ω_out would put it, as a time series in rad (and µrad,
// degrees, and µm along the line of action on a given base radius), with its statistics and its
// spectrum. Not a loaded TE model: it measures the angles it is given.
#pragma once

#include <optional>
#include <vector>

#include "analysis/spectrum.hpp"

namespace gearsim {

struct TransmissionError {
  std::vector<double> time_s;  // sample instants, s
  std::vector<double> te_rad;  // θ_in − i·θ_out, rad of the input body
  double ratio = 0;  // i, dimensionless (e.g. 1 + z_r/z_s = 5 for the paper's set)
};

// Throws InputError on different lengths, fewer than 2 samples, a non-finite value, or a
// non-finite or zero ratio.
TransmissionError transmission_error(const std::vector<double>& time_s, const std::vector<double>& theta_in_rad,
                                     const std::vector<double>& theta_out_rad, double ratio);

// A TE series computed elsewhere (a run's logged te_rad = θ_in − ratio·θ_out), with its time base
// and ratio. Throws InputError as transmission_error: different lengths, fewer than 2 samples, a
// non-finite time or value, a non-finite or zero ratio.
TransmissionError transmission_error_series(const std::vector<double>& time_s, const std::vector<double>& te_rad, double ratio);

// The series in other units: µrad; degrees; µm along the line of action, te_rad·base_radius_m
// with the base radius of the INPUT gear (TE is an input angle). Throws InputError on a
// non-positive or non-finite base radius.
std::vector<double> te_urad(const TransmissionError& te);
std::vector<double> te_deg(const TransmissionError& te);
std::vector<double> te_um(const TransmissionError& te, double input_base_radius_m);

// Statistics of a series, in the series' own unit (the member of TransmissionErrorStats names it).
struct SeriesStats {
  double mean = 0;
  double min = 0, max = 0;
  double peak_to_peak = 0;  // max − min
  double rms = 0;  // about the mean: √(mean of (x − mean)²)
};

struct TransmissionErrorStats {
  SeriesStats rad;  // rad
  SeriesStats urad;  // µrad
  SeriesStats deg;  // degrees
  std::optional<SeriesStats> um;  // µm along the line of action, when a base radius was given
};

// Statistics of the samples, each sample weighing the same (resample a variable-step log first).
// Throws InputError on a non-positive or non-finite base radius.
TransmissionErrorStats te_stats(const TransmissionError& te, std::optional<double> input_base_radius_m = {});

// Spectrum of the TE, rad. With resample_rate_hz > 0 the series is first resampled at that rate
// by linear interpolation (for a variable-step log); with 0 the time base must be uniform, else
// InputError.
Spectrum te_spectrum(const TransmissionError& te, const SpectrumOptions& options = {}, double resample_rate_hz = 0);

}  // namespace gearsim

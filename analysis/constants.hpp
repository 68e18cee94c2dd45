// Every tolerance and default of the analysis library, written once with its unit and why.
// Not the window coefficients (window.cpp: they define a window, they are not tolerances).
#pragma once

#include <cstddef>

namespace gearsim::analysis_constants {

// --- Peak search and matching --------------------------------------------------------------------

// Half-width of the search for a mesh harmonic and of a sideband's match to a characteristic
// frequency, in bins of the (padded) spectrum. Normally 1.5: a peak taken at its highest bin lies
// up to 0.5 bin from the true tone, and a neighbour's leakage can skew the highest bin by one more.
inline constexpr double kDefaultMatchToleranceBins = 1.5;

// Relative part of the same tolerances, as a fraction of the expected frequency (or offset).
// Normally 1 %: characteristic frequencies are computed from the nominal input speed, and the
// mean speed of a loaded, compliant run differs from it by up to about that much.
inline constexpr double kDefaultMatchRelativeTolerance = 0.01;

// A sideband must stand this far over the median noise floor of its band, dB. Normally 10 dB
// (×3.16): the amplitude of noise in one bin is Rayleigh distributed with median 1.18·σ, so it
// exceeds 3.16× its median (3.72·σ) with probability exp(−3.72²/2) ≈ 1e-3 per bin.
inline constexpr double kDefaultSidebandMinHeight_dB = 10.0;

// Sidebands are sought within ± this fraction of the mesh frequency around each harmonic, unless a
// span is given. Normally 0.5: halfway to the next harmonic, so no peak belongs to two harmonics.
inline constexpr double kDefaultSidebandSpanFraction = 0.5;

// Highest multiple k of a characteristic frequency f tried when matching a sideband offset to k·f.
// Normally 10: planet-pass modulation puts sidebands at many multiples of the carrier rate.
inline constexpr int kDefaultMaxMultiple = 10;

// Two candidates k·f closer than this are the same frequency (e.g. the planet's spin relative to
// the carrier and the planet local-fault frequency, equal by definition), Hz. Only breaks ties.
inline constexpr double kSameFrequencyTolerance_hz = 1e-9;

// Number of mesh harmonics listed and searched unless told otherwise. Normally 3: the paper's
// figure 5 shows f_m, 2·f_m, 3·f_m (320, 640, 960 Hz).
inline constexpr int kDefaultMeshHarmonics = 3;

// --- Angle-synchronous averaging and tooth statistics --------------------------------------------

// Samples per revolution of the angle-domain average unless told otherwise. Normally 1024: 28 per
// tooth of the paper's 36-tooth planet, enough to resolve a tooth's mesh cycle.
inline constexpr int kDefaultSamplesPerRevolution = 1024;

// A tooth is reported faulty when its leave-one-out z-score exceeds this in magnitude. Normally
// 3.5: with Gaussian tooth-to-tooth scatter a healthy tooth's leave-one-out z (36 teeth) is
// t-distributed (34 degrees of freedom, scaled by √(1 + 1/35)) and passes 3.5 with probability
// 1.5e-3, so a healthy 36-tooth gear raises a false alarm in about 1 run of 19.
inline constexpr double kDefaultToothZThreshold = 3.5;

// A tooth is flagged only when its figure also differs from the mean of the others by more than
// this fraction. Normally 0.05: a 1 µm flank deviation against a loaded mesh's ~1 µm deflection
// moves a tooth's load by tens of percent, while the scatter of healthy teeth in a simulation
// (start transients, the output grid) is a few tenths of a percent; the leave-one-out z alone
// flags such scatter whenever the healthy teeth agree very closely.
inline constexpr double kDefaultToothMinRelativeDeviation = 0.05;

// --- Run analysis (run_analysis.hpp) -------------------------------------------------------------

// Zero padding of a run's contact-force spectra: the DFT length is the smallest power of two at
// least this many times the record. Normally 8: the highest bin of a line then lies within 1/16 of
// the record's resolution of the true frequency (0.06 Hz for a 0.95 s record), so peak
// frequencies are limited by the record, not the grid.
inline constexpr std::size_t kRunSpectrumPadding = 8;

// Top of the band whose median amplitude is a force spectrum's noise floor, Hz (the band starts at
// 0 Hz); app/ also lists the spectra up to it. Normally 1000: the paper's figure 5 axis and the
// issue's floor band (0–1000 Hz).
inline constexpr double kRunFloorBandTop_hz = 1000.0;

// Multiples k of the planet local-fault frequency whose lines are reported. Normally 5: the paper's
// 8.89 Hz family f_m/36·k up to 44 Hz.
inline constexpr int kPlanetFaultMultiples = 5;

// Fewest output samples from the window start on that a run analysis accepts. Normally 64: a
// spectrum of 32 bins; at the paper's 2 kHz, 32 ms or about 10 mesh periods.
inline constexpr std::size_t kMinRunSamples = 64;

// --- Input validation ----------------------------------------------------------------------------

// Largest relative deviation of a sample interval from the mean interval for a time base to count
// as uniform. Normally 1e-6: an interval recovered from logged times t_k ≈ k·dt carries a rounding
// of about k·2.2e-16 of dt (2e-10 after a million steps); a larger spread means variable steps,
// which must be resampled first.
inline constexpr double kUniformTimeRelativeTolerance = 1e-6;

// --- Decimation (anti-aliasing low-pass, decimation_filter.hpp) -----------------------------------

// Default passband edge of a decimation filter, as a fraction of the output rate. Normally 0.48:
// the paper's third mesh harmonic, 960 Hz, is then inside the passband at its 2 kHz output rate,
// and the stopband starts at 0.52·f_out (1040 Hz), leaving an 80 Hz transition band.
inline constexpr double kDefaultPassbandFraction = 0.48;

// Default stopband attenuation of a decimation filter, dB. Normally 100 dB (×1e-5): a mesh
// harmonic as large as the mean contact force folds into the output at 1e-5 of it, below the
// −95 dB sidelobes of the flat-top window, so no aliased line shows in any spectrum we compute.
inline constexpr double kDefaultStopbandAttenuation_dB = 100.0;

// Range of stopband attenuations a decimation filter may be asked for, dB. Below ~21 dB Kaiser's
// window degenerates into the rectangular one, whose −21 dB sidelobe no length improves; 30 dB
// keeps a margin. Above 200 dB (1e-10) the rounding of thousands of taps (~1e-16 each) nears the
// stopband level and the measured attenuation stops meaning anything.
inline constexpr double kMinStopbandAttenuation_dB = 30.0;
inline constexpr double kMaxStopbandAttenuation_dB = 200.0;

// Largest relative distance of f_in/f_out from an integer for the ratio to count as one. Normally
// 1e-9: rates from a time step (1/2e-5 s) round at ~1e-16; an error ε shifts the output grid from
// the inputs it is centred on by ε·T after T seconds, 1 µs after 1000 s, 1/20 of a 20 µs step.
inline constexpr double kDecimationRatioRelativeTolerance = 1e-9;

// Longest decimation filter designed, taps. Normally 2^20 (8 MiB of taps, 16 MiB of ring buffer per
// channel): the paper's 50 kHz → 2 kHz design needs ~4000; a million means a transition band
// below f_in/300000, a design mistake rather than a filter anyone should run.
inline constexpr std::size_t kMaxDecimationFilterTaps = std::size_t{1} << 20;

// The passband ripple and stopband attenuation of a design are measured on a grid this many times
// finer than 1/(L/f_in), the spacing of the response's ripples (plus both band edges). Normally
// 16: a ripple's peak is then sampled within 1/32 of a lobe, its amplitude within 0.5 % (0.04 dB).
inline constexpr std::size_t kResponseGridOversampling = 16;

// --- Ringing (ringing.hpp) -----------------------------------------------------------------------

// A column of the two-pole prediction fit counts as dependent on the others when less than this
// fraction of its norm lies outside their span. Normally 1e-9: rounding leaves ~1e-16·√N, a plain
// exponential decay leaves only that, while an oscillation of θ rad per sample leaves ~θ², so rings
// down to θ ≈ 3e-5 (0.25 Hz at 50 kHz) are still fitted.
inline constexpr double kRingingRankTolerance = 1e-9;

// --- Sensor-alone localisation in in-phase sets (in_phase_localisation.hpp) ----------------------

// A planet's event counts as an event when the RMS of its difference signal over the event window
// (one tooth pitch) stands this many times over its RMS more than one pitch away. Normally 3: for
// a Gaussian background of M ≥ 40 independent samples per window the RMS of a window scatters by
// 1/√(2M) ≤ 11 %, so the largest of a turn's 36 windows stays under about 1.4× the background;
// 3 is twice that, and a healthy run's windows read 0.9–1.4 (docs/condition-monitoring.md).
inline constexpr double kInPhaseEventOverBackground = 3.0;

// A correlation of two event waveforms counts as positive or negative when |ρ| reaches this many
// standard deviations of the correlation of two independent noise records of M samples (1/√M).
// Normally 2 (a 2.3 % one-sided chance per correlation that noise alone passes it).
inline constexpr double kInPhaseCorrelationSigmas = 2.0;

// The event waveforms are compared on a grid whose bins are no wider than one sensor sample (the next power of two at or above the
// sensor's samples per planet turn, at least kDefaultSamplesPerRevolution), and again on twice
// that grid; a planet is named only when both grids name it. Normally 2 (one doubling): a
// housing mode's ringing has a polarity only if its timing is resolved, and a bin as wide as a
// sample can move it by half a period of a mode at a quarter of the sample rate.
inline constexpr int kInPhaseGridRefinement = 2;

}  // namespace gearsim::analysis_constants

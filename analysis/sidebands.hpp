// Mesh harmonics and their sidebands in an amplitude spectrum, for gear condition monitoring: the
// peak nearest each theoretical harmonic k·f_m, the local maxima standing over the noise floor
// within ± a span of it, and each sideband's offset matched to a characteristic frequency or a
// multiple of one (or left unmatched). Every result states the resolution it was found at: a
// match is only as good as the spectrum's bin width and record resolution allow.
// Not a fault classifier: it labels peaks, it does not decide what is broken.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "analysis/characteristic_frequencies.hpp"
#include "analysis/constants.hpp"
#include "analysis/peaks.hpp"
#include "analysis/spectrum.hpp"

namespace gearsim {

struct SidebandOptions {
  int harmonics = analysis_constants::kDefaultMeshHarmonics;  // orders 1 … H searched (≥ 1)
  double span_hz = 0;  // sidebands within ± span of each harmonic; 0: kDefaultSidebandSpanFraction·f_m
  // Tolerance, Hz, of the harmonic search and of a match to k·f:
  //   max(tolerance_bins·bin_width_hz, relative_tolerance·(k·f or the harmonic's frequency)).
  double tolerance_bins = analysis_constants::kDefaultMatchToleranceBins;
  double relative_tolerance = analysis_constants::kDefaultMatchRelativeTolerance;
  double min_height_db = analysis_constants::kDefaultSidebandMinHeight_dB;  // over the median floor
  int max_multiple = analysis_constants::kDefaultMaxMultiple;  // k = 1 … max_multiple (≥ 1)
};

struct SidebandMatch {
  std::string key;  // the characteristic frequency's key, e.g. "planet_fault"
  std::string name;  // and its name
  int multiple = 1;  // k: the offset matched k·f
  double expected_offset_hz = 0;  // k·f
  double error_hz = 0;  // |offset| − k·f
  double tolerance_hz = 0;  // the tolerance the match passed
  // Other candidates also within their tolerance, as "k×key" (e.g. "3×carrier_shaft"): the
  // spectrum cannot tell them apart from the match. Empty when the match is unambiguous.
  std::vector<std::string> alternatives;
};

struct Sideband {
  SpectralPeak peak;
  double offset_hz = 0;  // peak − harmonic peak, signed (negative: lower sideband)
  double level_db_re_harmonic = 0;  // 20·log10(sideband/harmonic amplitude), dB
  double height_over_floor_db = 0;  // 20·log10(sideband/noise floor), dB
  std::optional<SidebandMatch> match;  // nothing: no characteristic frequency explains the offset
  // The peak is itself a mesh line of the candidates (in a train: another stage's mesh harmonic
  // reaching this pair's force), not a modulation: that line (multiple 1, its key and name), or
  // nothing. Sought within the offset's tolerance around the line.
  std::optional<SidebandMatch> mesh_line;
};

struct MeshHarmonic {
  int order = 1;  // k of k·f_m
  double expected_hz = 0;  // k·f_m
  double search_tolerance_hz = 0;  // the peak was sought within ± this of expected_hz
  std::optional<SpectralPeak> peak;  // nothing: no local maximum within the tolerance
  double noise_floor = 0;  // median amplitude within ± span, signal unit
  double height_over_floor_db = 0;  // of the harmonic's peak (0 when not found)
  std::vector<Sideband> sidebands;  // in frequency order; empty when the harmonic was not found
};

struct SidebandAnalysis {
  std::vector<MeshHarmonic> harmonics;
  double bin_width_hz = 0;  // the spectrum's grid spacing
  double resolution_hz = 0;  // the spectrum's 1/T: closer tones are not resolved
  double mainlobe_halfwidth_hz = 0;  // peaks closer than this to a harmonic are its own lobe, skipped
  double span_hz = 0;  // the span used
  double tolerance_floor_hz = 0;  // tolerance_bins·bin_width_hz, the smallest match tolerance
  double relative_tolerance = 0;  // the relative part of the match tolerance
};

// Harmonics of mesh_hz and their sidebands; candidates of kind Mesh (and zero frequencies) are not
// used for matching offsets, only for naming a peak that is a mesh line (Sideband::mesh_line). Throws InputError on a non-positive mesh frequency, harmonics or max_multiple
// < 1, a negative span or tolerance, or a harmonic above the spectrum's highest frequency.
SidebandAnalysis analyse_sidebands(const Spectrum& spectrum, double mesh_hz, const std::vector<CharacteristicFrequency>& candidates,
                                   const SidebandOptions& options = {});

// The candidate multiple k·f nearest |offset_hz| within max(tolerance_floor_hz,
// relative_tolerance·k·f), or nothing. Ties (k·f equal within kSameFrequencyTolerance_hz) go to
// the lower k, then to Fault over Pass over Shaft, then to the earlier candidate.
std::optional<SidebandMatch> match_offset(double offset_hz, const std::vector<CharacteristicFrequency>& candidates,
                                          double tolerance_floor_hz, double relative_tolerance, int max_multiple);

}  // namespace gearsim

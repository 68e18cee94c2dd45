#include "analysis/pair_force_analysis.hpp"

#include <algorithm>

#include "analysis/band_limited.hpp"
#include "analysis/constants.hpp"
#include "core/errors.hpp"

namespace gearsim {
namespace {

using namespace analysis_constants;

// The smallest power of two ≥ kRunSpectrumPadding·n.
std::size_t padded_length(std::size_t n) {
  std::size_t l = 1;
  while (l < kRunSpectrumPadding * n) l <<= 1;
  return l;
}

// Lines at k·f_planet_fault, each sought as a harmonic is: within max(1.5 bins, 1 % of k·f).
std::vector<FaultLine> planet_fault_family(const Spectrum& s, double fault_hz, double floor_N) {
  std::vector<FaultLine> family;
  for (int k = 1; k <= kPlanetFaultMultiples; ++k) {
    const double tol = std::max(kDefaultMatchToleranceBins * s.bin_width_hz, kDefaultMatchRelativeTolerance * k * fault_hz);
    FaultLine line{k, k * fault_hz, nearest_local_maximum(s, k * fault_hz, tol), 0.0};
    if (line.peak) line.over_floor_db = amplitude_ratio_db(line.peak->amplitude, floor_N);
    family.push_back(line);
  }
  return family;
}

}  // namespace

PairForceAnalysis analyse_pair_force(const PairId& pair, const std::vector<double>& f, double sample_rate_hz, const TrainDescription& train,
                                     const std::vector<double>& point_force_N) {
  PairForceAnalysis r;
  r.pair = pair;
  // Mean and peak force, their ratio, and the share of samples without contact.
  const std::vector<double>& point = point_force_N.empty() ? f : point_force_N;
  if (point.size() != f.size())
    throw InputError("run analysis: the point-sampled force of pair " + pair_label(pair) + " holds " + std::to_string(point.size()) +
                     " samples for " + std::to_string(f.size()));
  double mean = 0, zeros = 0;
  for (double v : f) mean += v;
  for (double v : point) zeros += v == 0;
  r.mean_force_N = mean / static_cast<double>(f.size());
  // The band-limited force's peak, between samples too (band_limited.hpp), when the force is the
  // anti-aliased one (a point-sampled record given apart); else the largest sample.
  r.peak_force_N = f.empty() ? 0.0 : point_force_N.empty() ? *std::max_element(f.begin(), f.end()) : band_limited_extremes(f).max;
  r.dynamic_factor_band_limited = r.mean_force_N > 0 ? r.peak_force_N / r.mean_force_N : 0.0;
  r.zero_force_share = zeros / static_cast<double>(f.size());
  // The spectrum, its floor, the mesh harmonics with their sidebands.
  r.spectrum = amplitude_spectrum(f, sample_rate_hz, {WindowKind::Hann, padded_length(f.size()), true});
  r.floor_N = median_noise_floor(r.spectrum, 0, kRunFloorBandTop_hz);
  // The pair's own stage: its mesh frequency and planet fault family (one stage: the train's).
  double mesh_hz = train.frequencies.mesh_hz, planet_fault_hz = 0;
  if (train.planetary && train.pair_stages.empty()) planet_fault_hz = train.frequencies.at("planet_fault").value_hz;
  for (const TrainDescription::PairStage& ps : train.pair_stages)
    if (ps.pair.same_bodies(pair.a, pair.b)) mesh_hz = ps.mesh_hz, planet_fault_hz = ps.planet_fault_hz;
  // The harmonics below the record's Nyquist frequency (a slow stage's three; a fast one's fewer).
  SidebandOptions options;
  const double top_hz = r.spectrum.frequency_hz.empty() ? 0.0 : r.spectrum.frequency_hz.back();
  if (mesh_hz > 0 && top_hz >= mesh_hz) options.harmonics = std::min(options.harmonics, static_cast<int>(top_hz / mesh_hz));
  r.mesh = analyse_sidebands(r.spectrum, mesh_hz, train.frequencies.frequencies, options);
  for (const MeshHarmonic& h : r.mesh.harmonics)
    r.harmonic_over_floor_db.push_back(h.peak ? std::optional(amplitude_ratio_db(h.peak->amplitude, r.floor_N)) : std::nullopt);
  // The planet local-fault family (a planet tooth meets the sun once per relative turn).
  if (planet_fault_hz > 0) r.planet_fault_family = planet_fault_family(r.spectrum, planet_fault_hz, r.floor_N);
  return r;
}

}  // namespace gearsim

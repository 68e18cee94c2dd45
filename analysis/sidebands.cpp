#include "analysis/sidebands.hpp"

#include <cmath>
#include <string>
#include <tuple>

#include "core/errors.hpp"

namespace gearsim {
namespace {

// Lower ranks win ties: a fault explains a sideband more specifically than a shaft rate.
int kind_rank(FrequencyKind k) {
  switch (k) {
    case FrequencyKind::Fault:
      return 0;
    case FrequencyKind::Pass:
      return 1;
    case FrequencyKind::Shaft:
      return 2;
    case FrequencyKind::Mesh:
      return 3;
  }
  return 4;
}

struct Candidate {
  std::size_t index;
  int multiple;
  double value_hz;
  double error_hz;
  double tolerance_hz;
};

// The candidate of kind Mesh nearest frequency_hz within max(tolerance_floor_hz,
// relative_tolerance·f), or nothing.
std::optional<SidebandMatch> mesh_line(double frequency_hz, const std::vector<CharacteristicFrequency>& candidates,
                                       double tolerance_floor_hz, double relative_tolerance) {
  std::optional<SidebandMatch> best;
  for (const CharacteristicFrequency& c : candidates) {
    if (c.kind != FrequencyKind::Mesh || !(c.value_hz > 0.0)) continue;
    const double tol = std::max(tolerance_floor_hz, relative_tolerance * c.value_hz), error = frequency_hz - c.value_hz;
    if (std::abs(error) > tol || (best && std::abs(best->error_hz) <= std::abs(error))) continue;
    best = SidebandMatch{c.key, c.name, 1, c.value_hz, error, tol, {}};
  }
  return best;
}

}  // namespace

std::optional<SidebandMatch> match_offset(double offset_hz, const std::vector<CharacteristicFrequency>& candidates,
                                          double tolerance_floor_hz, double relative_tolerance, int max_multiple) {
  const double target = std::abs(offset_hz);
  std::vector<Candidate> hits;
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    const CharacteristicFrequency& c = candidates[i];
    if (c.kind == FrequencyKind::Mesh || !(c.value_hz > 0.0)) continue;
    for (int k = 1; k <= max_multiple; ++k) {
      const double v = k * c.value_hz;
      const double tol = std::max(tolerance_floor_hz, relative_tolerance * v);
      if (std::abs(target - v) <= tol) hits.push_back({i, k, v, target - v, tol});
    }
  }
  if (hits.empty()) return std::nullopt;
  auto better = [&](const Candidate& a, const Candidate& b) {
    const double da = std::abs(a.error_hz), db = std::abs(b.error_hz);
    if (std::abs(da - db) > analysis_constants::kSameFrequencyTolerance_hz) return da < db;
    return std::make_tuple(a.multiple, kind_rank(candidates[a.index].kind), a.index) <
           std::make_tuple(b.multiple, kind_rank(candidates[b.index].kind), b.index);
  };
  const Candidate* best = &hits.front();
  for (const Candidate& h : hits)
    if (better(h, *best)) best = &h;
  SidebandMatch m;
  m.key = candidates[best->index].key;
  m.name = candidates[best->index].name;
  m.multiple = best->multiple;
  m.expected_offset_hz = best->value_hz;
  m.error_hz = best->error_hz;
  m.tolerance_hz = best->tolerance_hz;
  for (const Candidate& h : hits)
    if (&h != best) m.alternatives.push_back(std::to_string(h.multiple) + "×" + candidates[h.index].key);
  return m;
}

SidebandAnalysis analyse_sidebands(const Spectrum& s, double mesh_hz, const std::vector<CharacteristicFrequency>& candidates,
                                   const SidebandOptions& o) {
  const char* what = "sideband analysis";
  if (!std::isfinite(mesh_hz) || mesh_hz <= 0.0)
    throw InputError(std::string(what) + ": mesh frequency must be a positive number of Hz, got " + std::to_string(mesh_hz));
  if (o.harmonics < 1 || o.max_multiple < 1) throw InputError(std::string(what) + ": harmonics and max_multiple must be at least 1");
  if (!(o.span_hz >= 0.0) || !(o.tolerance_bins >= 0.0) || !(o.relative_tolerance >= 0.0))
    throw InputError(std::string(what) + ": span, tolerance_bins and relative_tolerance must be ≥ 0");
  const double top_hz = s.frequency_hz.empty() ? 0.0 : s.frequency_hz.back();
  if (o.harmonics * mesh_hz > top_hz)
    throw InputError(std::string(what) + ": harmonic " + std::to_string(o.harmonics) + " of " + std::to_string(mesh_hz) +
                     " Hz lies above the spectrum's highest frequency (" + std::to_string(top_hz) + " Hz)");
  SidebandAnalysis r;
  r.bin_width_hz = s.bin_width_hz;
  r.resolution_hz = s.resolution_hz;
  r.mainlobe_halfwidth_hz = s.mainlobe_halfwidth_hz;
  r.span_hz = o.span_hz > 0.0 ? o.span_hz : analysis_constants::kDefaultSidebandSpanFraction * mesh_hz;
  r.tolerance_floor_hz = o.tolerance_bins * s.bin_width_hz;
  r.relative_tolerance = o.relative_tolerance;
  const double min_ratio = std::pow(10.0, o.min_height_db / 20.0);
  for (int k = 1; k <= o.harmonics; ++k) {
    MeshHarmonic h;
    h.order = k;
    h.expected_hz = k * mesh_hz;
    h.search_tolerance_hz = std::max(r.tolerance_floor_hz, o.relative_tolerance * h.expected_hz);
    h.peak = nearest_local_maximum(s, h.expected_hz, h.search_tolerance_hz);
    h.noise_floor = median_noise_floor(s, h.expected_hz - r.span_hz, h.expected_hz + r.span_hz);
    if (h.peak) {
      const SpectralPeak& hp = *h.peak;
      h.height_over_floor_db = amplitude_ratio_db(hp.amplitude, h.noise_floor);
      // Skip the harmonic's own main lobe (less half a bin for the grid's rounding).
      const double lobe_hz = s.mainlobe_halfwidth_hz - 0.5 * s.bin_width_hz;
      for (const SpectralPeak& p : local_maxima(s, hp.frequency_hz - r.span_hz, hp.frequency_hz + r.span_hz, min_ratio * h.noise_floor)) {
        const double offset = p.frequency_hz - hp.frequency_hz;
        if (std::abs(offset) < lobe_hz) continue;
        Sideband sb;
        sb.peak = p;
        sb.offset_hz = offset;
        sb.level_db_re_harmonic = amplitude_ratio_db(p.amplitude, hp.amplitude);
        sb.height_over_floor_db = amplitude_ratio_db(p.amplitude, h.noise_floor);
        sb.match = match_offset(offset, candidates, r.tolerance_floor_hz, o.relative_tolerance, o.max_multiple);
        sb.mesh_line = mesh_line(p.frequency_hz, candidates, r.tolerance_floor_hz, o.relative_tolerance);
        h.sidebands.push_back(std::move(sb));
      }
    }
    r.harmonics.push_back(std::move(h));
  }
  return r;
}

}  // namespace gearsim

#include "analysis/in_phase_localisation.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include "analysis/condition_indicators.hpp"
#include "analysis/constants.hpp"
#include "core/errors.hpp"

namespace gearsim {
namespace {

double rms(const std::vector<double>& v) {
  double s = 0;
  for (double x : v) s += x * x;
  return v.empty() ? 0.0 : std::sqrt(s / static_cast<double>(v.size()));
}

double correlation(const std::vector<double>& a, const std::vector<double>& b) {
  double ab = 0, aa = 0, bb = 0;
  for (std::size_t i = 0; i < a.size(); ++i) ab += a[i] * b[i], aa += a[i] * a[i], bb += b[i] * b[i];
  return aa > 0 && bb > 0 ? ab / std::sqrt(aa * bb) : 0.0;
}

}  // namespace

InPhaseLocalisation localise_in_phase(const std::vector<std::vector<double>>& means, const std::vector<double>& sun_direction_rad,
                                      int teeth, double sensor_samples_per_revolution) {
  constexpr double kTurn = 2 * std::numbers::pi;
  const std::size_t P = means.size();
  if (P < 2 || sun_direction_rad.size() != P)
    throw InputError("in-phase localisation: expected two or more planets, one sun direction each");
  const std::size_t N = means[0].size();
  for (const std::vector<double>& m : means)
    if (m.size() != N) throw InputError("in-phase localisation: every planet's average must lie on one grid");
  if (teeth < 1 || N < 4 * static_cast<std::size_t>(teeth))
    throw InputError("in-phase localisation: the grid needs 4 samples per tooth or more");
  InPhaseLocalisation out;
  out.samples_per_revolution = static_cast<int>(N);
  // Each planet's difference signal, turned so that index 0 is its tooth 0 facing the sun.
  std::vector<std::vector<double>> d(P, std::vector<double>(N));
  const auto Ni = static_cast<long>(N);
  auto wrap = [&](long j) { return static_cast<std::size_t>((j % Ni + Ni) % Ni); };
  for (std::size_t k = 0; k < P; ++k) {
    const std::vector<double> diff = tsa_signals(means[k], teeth).difference;
    const long shift = std::lround(sun_direction_rad[k] / kTurn * static_cast<double>(N));
    for (long j = 0; j < Ni; ++j) d[k][static_cast<std::size_t>(j)] = diff[wrap(j + shift)];
  }
  auto at = [&](std::size_t k, long j) { return d[k][wrap(j)]; };
  // The common event: the one-pitch window holding the most energy summed over the planets.
  const double pitch = static_cast<double>(N) / teeth;
  const long half = std::max(1L, std::lround(pitch / 2));
  std::vector<double> energy(N, 0.0);
  for (std::size_t k = 0; k < P; ++k)
    for (std::size_t j = 0; j < N; ++j) energy[j] += d[k][j] * d[k][j];
  long centre = 0, peak = 0;
  double best = -1;
  for (long j = 0; j < Ni; ++j) {
    double e = 0;
    for (long i = -half; i <= half; ++i) e += energy[wrap(j + i)];
    if (e > best) best = e, centre = j;
  }
  for (long i = -half; i <= half; ++i)
    if (energy[wrap(centre + i)] > energy[wrap(centre + peak)]) peak = i;
  // Tooth t faces the sun at index −t·pitch.
  out.event_tooth = static_cast<int>(((-std::lround(static_cast<double>(centre + peak) / pitch)) % teeth + teeth) % teeth);
  // Event waveforms and backgrounds.
  std::vector<std::vector<double>> v(P);
  for (std::size_t k = 0; k < P; ++k) {
    std::vector<double> background;
    for (long j = 0; j < Ni; ++j) {
      const long from = std::min((j - centre + Ni) % Ni, (centre - j + Ni) % Ni);
      if (from > static_cast<long>(std::lround(pitch))) background.push_back(d[k][static_cast<std::size_t>(j)]);
    }
    for (long i = -half; i <= half; ++i) v[k].push_back(at(k, centre + i));
    out.planets.push_back({rms(v[k]), rms(background)});
    if (out.planets.back().event_rms_m_s2 >= analysis_constants::kInPhaseEventOverBackground * out.planets.back().background_rms_m_s2)
      out.event = true;
  }
  out.correlation.assign(P, std::vector<double>(P, 1.0));
  for (std::size_t a = 0; a < P; ++a)
    for (std::size_t b = a + 1; b < P; ++b) out.correlation[a][b] = out.correlation[b][a] = correlation(v[a], v[b]);
  // M: the sensor's own samples in one pitch (the grid may be finer than the record).
  const double samples = std::max(1.0, std::min(static_cast<double>(2 * half + 1), sensor_samples_per_revolution / teeth));
  out.min_correlation = analysis_constants::kInPhaseCorrelationSigmas / std::sqrt(samples);
  std::ostringstream why;
  why.precision(3);
  if (!out.event) {
    why << "no planet's event at the common tooth stands " << analysis_constants::kInPhaseEventOverBackground << "× over its background";
    out.reason = why.str();
    return out;
  }
  if (P < 3) {
    why << "two planets: load conservation makes their events equal and opposite whichever is flawed";
    out.reason = why.str();
    return out;
  }
  // Planet j: against every other planet, and every other pair agreeing, and the largest event.
  for (std::size_t j = 0; j < P; ++j) {
    bool fits = true;
    for (std::size_t a = 0; a < P; ++a)
      for (std::size_t b = a + 1; b < P; ++b) {
        const double r = out.correlation[a][b];
        fits = fits && ((a == j || b == j) ? r <= -out.min_correlation : r >= out.min_correlation);
      }
    for (std::size_t k = 0; k < P; ++k) fits = fits && (k == j || out.planets[j].event_rms_m_s2 > out.planets[k].event_rms_m_s2);
    if (!fits) continue;
    out.named = static_cast<int>(j);
    out.confidence = 1;
    for (std::size_t a = 0; a < P; ++a)
      for (std::size_t b = a + 1; b < P; ++b) out.confidence = std::min(out.confidence, std::abs(out.correlation[a][b]));
  }
  if (out.named >= 0) {
    why << "its event opposes every other planet's (correlation ≤ −" << out.min_correlation
        << "), the others agree with each other and its event is the largest: the load it sheds or takes, which the others take or shed";
  } else {
    int positive = 0, pairs = 0;
    for (std::size_t a = 0; a < P; ++a)
      for (std::size_t b = a + 1; b < P; ++b) positive += out.correlation[a][b] >= out.min_correlation, ++pairs;
    if (positive == pairs)
      why << "the events at the common tooth have one polarity on every planet (every correlation ≥ " << out.min_correlation
          << "): a shared event (a sun tooth, a torque step, a path common to the windows), not one planet's load handed to the others";
    else
      why << "no planet's event opposes all the others' while they agree (threshold |correlation| " << out.min_correlation
          << ") with the largest event";
  }
  out.reason = why.str();
  return out;
}

}  // namespace gearsim

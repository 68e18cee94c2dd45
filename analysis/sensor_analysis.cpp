#include "analysis/sensor_analysis.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include "analysis/constants.hpp"
#include "analysis/envelope.hpp"
#include "analysis/in_phase_localisation.hpp"
#include "analysis/planet_separation.hpp"
#include "analysis/resample.hpp"
#include "core/errors.hpp"

namespace gearsim {
namespace {

const std::vector<double>& angle_named(const RunSignals& s, const std::string& body) {
  for (const BodyAngle& a : s.angles)
    if (a.body == body) return a.angle_rad;
  throw InputError("sensor analysis: no logged angle of '" + body + "'");
}

// Planets meshing in phase: the localisation of the event at their common tooth, on a grid whose
// bins are no wider than one sensor sample and on kInPhaseGridRefinement times it.
// positions[k], spins[k]: planet k's position angle (world) and spin relative to the carrier,
// sampled with x at times t.
void localise_in_phase_planets(SensorAnalysis& out, const std::vector<double>& t, const std::vector<double>& x,
                               const std::vector<std::vector<double>>& positions, const std::vector<std::vector<double>>& spins,
                               const SensorSignal& sensor, const TrainDescription& train) {
  constexpr double kTurn = 2 * std::numbers::pi;
  // Sensor samples per planet turn relative to the carrier.
  const double turns = std::abs(spins.front().back() - spins.front().front()) / kTurn;
  if (!(turns > 0)) return;
  const double per_turn = out.sample_rate_hz * (t.back() - t.front()) / turns;
  int n = analysis_constants::kDefaultSamplesPerRevolution;
  while (n < per_turn) n *= 2;
  std::vector<double> sun_direction;
  for (const PlanetGear& p : train.planets) sun_direction.push_back(p.sun_direction_rad);
  for (int grid : {n, analysis_constants::kInPhaseGridRefinement * n}) {
    std::vector<std::vector<double>> means;
    for (std::size_t k = 0; k < train.planets.size(); ++k)
      means.push_back(planet_separated_average(x, positions[k], spins[k], sensor.angle_rad, sensor.window_width_rad, grid).mean);
    (grid == n ? out.in_phase : out.in_phase_refined) = localise_in_phase(means, sun_direction, train.planets.front().teeth, per_turn);
  }
  const InPhaseLocalisation& a = *out.in_phase;
  const InPhaseLocalisation& b = *out.in_phase_refined;
  std::ostringstream ev;
  ev.precision(3);
  auto events = [&](std::ostringstream& o) {
    o << "event RMS at the common tooth";
    for (std::size_t k = 0; k < a.planets.size(); ++k)
      o << (k ? ", " : " ") << train.planets[k].body << " " << a.planets[k].event_rms_m_s2 << " m/s² (background "
        << a.planets[k].background_rms_m_s2 << ")";
    o << "; correlations";
    for (std::size_t i = 0; i < a.planets.size(); ++i)
      for (std::size_t j = i + 1; j < a.planets.size(); ++j) o << " " << i << "–" << j << " " << a.correlation[i][j];
    o << " (grid " << a.samples_per_revolution << " per turn)";
  };
  if (a.named < 0 || a.named != b.named) {
    std::ostringstream why;
    why.precision(3);
    why << "the planets mesh in phase (z_s/N whole): every planet's window hears an event at the same tooth; no planet is named: ";
    if (a.named != b.named)
      why << "the grid of " << a.samples_per_revolution << " per turn and that of " << b.samples_per_revolution
          << " disagree (the events' timing is not resolved)";
    else
      why << a.reason;
    why << "; ";
    events(why);
    out.note = why.str();
    return;
  }
  const PlanetGear& p = train.planets[static_cast<std::size_t>(a.named)];
  ToothFault f;
  f.gear = p.body;
  f.tooth = a.event_tooth;
  f.source = "sensor " + sensor.name;
  ev << "the planets mesh in phase; at the tooth they share (tooth " << a.event_tooth << " facing the sun, tooth "
     << (a.event_tooth + p.teeth / 2) % p.teeth << " the ring) " << a.reason << "; ";
  events(ev);
  f.evidence = ev.str();
  f.confidence = std::min(a.confidence, b.confidence);
  out.fault = f;
  for (std::size_t k = 0; k < train.planets.size(); ++k) {
    if (static_cast<int>(k) == a.named) continue;
    std::ostringstream why;
    why.precision(3);
    why << "its event at the same tooth (" << a.planets[k].event_rms_m_s2 << " m/s², against "
        << a.planets[static_cast<std::size_t>(a.named)].event_rms_m_s2 << " on " << p.body << ") has the opposite polarity to " << p.body
        << "'s (correlation " << a.correlation[k][static_cast<std::size_t>(a.named)]
        << ") and agrees with the other responders: it takes up the load " << p.body << " sheds (in-phase load sharing), not a fault";
    out.responses.push_back(
        {train.planets[k].body, a.event_tooth, PairId{}, std::nan(""), std::nan(""), "sensor " + sensor.name, why.str()});
  }
}

}  // namespace

SensorAnalysis analyse_sensor(const SensorSignal& sensor, const RunSignals& s, const TrainDescription& train) {
  SensorAnalysis out;
  out.sensor = sensor.name;
  // The sensor's samples inside the analysed window and the angle record.
  std::vector<double> t, x;
  for (std::size_t i = 0; i < sensor.time_s.size(); ++i)
    if (sensor.time_s[i] >= s.from_s && sensor.time_s[i] <= s.time_s.back())
      t.push_back(sensor.time_s[i]), x.push_back(sensor.acceleration_m_s2[i]);
  if (t.size() < 2) throw InputError("sensor " + sensor.name + ": no samples inside the analysed window");
  out.sample_rate_hz = uniform_sample_rate_hz(t);
  const std::vector<double> carrier = interpolate_linear(s.time_s, angle_named(s, train.carrier), t);
  constexpr int kSamplesPerTurn = analysis_constants::kDefaultSamplesPerRevolution;
  // Each planet's position angle (world) and spin relative to the carrier, with the samples.
  std::vector<std::vector<double>> positions, spins;
  for (const PlanetGear& p : train.planets) {
    spins.push_back(interpolate_linear(s.time_s, angle_named(s, p.body), t));
    const std::vector<double>& spin = spins.back();
    std::vector<double>& position = positions.emplace_back(t.size());
    for (std::size_t i = 0; i < t.size(); ++i) position[i] = p.position0_rad + carrier[i];
    const PlanetSeparatedAverage a =
        planet_separated_average(x, position, spin, sensor.angle_rad, sensor.window_width_rad, kSamplesPerTurn);
    PlanetSensorView v{p.body, a.coverage, a.passes, condition_indicators(a.mean, p.teeth), -1};
    // Where the difference signal peaks, as the tooth then facing the sun (tooth k faces it at
    // the planet's turn sun_direction − k·pitch).
    const TsaSignals sig = tsa_signals(a.mean, p.teeth);
    std::size_t jmax = 0;
    for (std::size_t j = 1; j < sig.difference.size(); ++j)
      if (std::abs(sig.difference[j]) > std::abs(sig.difference[jmax])) jmax = j;
    v.difference_peak_m_s2 = std::abs(sig.difference[jmax]);
    const double turn = 2 * std::numbers::pi * static_cast<double>(jmax) / kSamplesPerTurn;
    const double pitch = 2 * std::numbers::pi / p.teeth;
    v.peak_tooth = static_cast<int>(((std::lround((p.sun_direction_rad - turn) / pitch) % p.teeth) + p.teeth) % p.teeth);
    out.planets.push_back(v);
  }
  // The envelope around the housing mode, read at the train's characteristic frequencies.
  if (sensor.resonance_hz > 0) {
    out.envelope_band_lo_hz = 0.5 * sensor.resonance_hz;
    out.envelope_band_hi_hz = std::min(1.5 * sensor.resonance_hz, out.sample_rate_hz / 2);
    const EnvelopeSpectrum e = envelope_spectrum(x, out.sample_rate_hz, out.envelope_band_lo_hz, out.envelope_band_hi_hz);
    for (const CharacteristicFrequency& f : train.frequencies.frequencies)
      for (int m = 1; m <= 2; ++m) {
        const double at = m * f.value_hz;
        if (!(at > 0) || at >= out.sample_rate_hz / 2) continue;
        out.envelope_lines.push_back({f.key, m, at, e.spectrum.amplitude[nearest_bin(e.spectrum, at)]});
      }
  }
  // The sun's average: every planet's window, each credited to the sun tooth that meets it.
  if (!train.sun.empty() && train.sun_teeth > 0) {
    std::vector<double> offsets;
    for (const PlanetGear& p : train.planets) offsets.push_back(p.position0_rad);
    std::vector<double> sun = interpolate_linear(s.time_s, angle_named(s, train.sun), t);
    for (std::size_t i = 0; i < t.size(); ++i) sun[i] -= carrier[i];
    const PlanetSeparatedAverage a =
        sun_separated_average(x, positions, offsets, sun, sensor.angle_rad, sensor.window_width_rad, kSamplesPerTurn);
    out.sun = PlanetSensorView{train.sun, a.coverage, a.passes, condition_indicators(a.mean, train.sun_teeth), -1};
  }
  // Sequentially phased: one planet standing apart, FM4 over the fault level and over twice every
  // other planet's. Not for planets meshing in phase: they share every event (the paper's 43 µm
  // run names no planet by it; its 5 and 10 µm runs would name planet 2, wrongly); they have
  // their own rule (in_phase_localisation.hpp).
  for (std::size_t i = 0; i < out.planets.size() && !train.planets_in_phase; ++i) {
    const PlanetSensorView& v = out.planets[i];
    double others = 0;
    for (std::size_t j = 0; j < out.planets.size(); ++j)
      if (j != i && std::isfinite(out.planets[j].indicators.fm4)) others = std::max(others, out.planets[j].indicators.fm4);
    if (!(v.indicators.fm4 > kSensorFm4Fault && v.indicators.fm4 > 2 * others)) continue;
    ToothFault f;
    f.gear = v.planet;
    f.tooth = v.peak_tooth;
    f.source = "sensor " + sensor.name;
    std::ostringstream ev;
    ev.precision(3);
    ev << "its separated average (" << v.passes << " passes, " << 100 * v.coverage << " % of its turn seen) has FM4 " << v.indicators.fm4
       << " against at most " << others << " on the other planets; the difference signal peaks when tooth " << v.peak_tooth
       << " faces the sun (tooth " << (v.peak_tooth + train.planets.front().teeth / 2) % std::max(1, train.planets.front().teeth)
       << " then faces the ring: a sensor alone cannot tell the two meshes apart)";
    f.evidence = ev.str();
    f.confidence = 1 - others / v.indicators.fm4;
    out.fault = f;
  }
  if (train.planets_in_phase && out.planets.size() > 1) {
    localise_in_phase_planets(out, t, x, positions, spins, sensor, train);
    return out;
  }
  if (!out.fault && out.planets.size() > 1) {
    std::vector<double> fm4;
    for (const PlanetSensorView& v : out.planets) fm4.push_back(std::isfinite(v.indicators.fm4) ? v.indicators.fm4 : 0.0);
    std::sort(fm4.rbegin(), fm4.rend());
    std::ostringstream n;
    n.precision(3);
    n << "no planet's separated average stands out (largest FM4 " << fm4[0] << ", next " << fm4[1] << ")";
    out.note = n.str();
  }
  return out;
}

}  // namespace gearsim

#include "analysis/run_analysis.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <optional>
#include <utility>
#include <string>
#include <vector>

#include "analysis/angle_average.hpp"
#include "analysis/band_limited.hpp"
#include "analysis/constants.hpp"
#include "analysis/resample.hpp"
#include "core/errors.hpp"

namespace gearsim {
namespace {

// The samples of x at times ≥ from_s.
std::vector<double> window(const std::vector<double>& x, const std::vector<double>& t, double from_s) {
  std::vector<double> out;
  for (std::size_t i = 0; i < x.size(); ++i)
    if (t[i] >= from_s) out.push_back(x[i]);
  return out;
}

void check_length(std::size_t n, std::size_t times, const std::string& what) {
  if (n != times)
    throw InputError("run analysis: " + what + " holds " + std::to_string(n) + " samples for " + std::to_string(times) + " sample times");
}

// Every series as long as the time base; enough samples in the window; at least one pair.
void check_signals(const RunSignals& s) {
  const std::size_t n = samples_from(s.time_s, s.from_s);
  if (n < analysis_constants::kMinRunSamples)
    throw InputError("run analysis: only " + std::to_string(n) + " output samples after t = " + std::to_string(s.from_s) + " s: at least " +
                     std::to_string(analysis_constants::kMinRunSamples) + " are needed to analyse; run longer");
  if (s.pair_forces.empty()) throw InputError("run analysis: no gear pair (a run with no gear pairs has nothing to analyse)");
  for (const PairForce& p : s.pair_forces) {
    check_length(p.force_N.size(), s.time_s.size(), "the force of pair " + pair_label(p.pair));
    if (!p.point_force_N.empty())
      check_length(p.point_force_N.size(), s.time_s.size(), "the point-sampled force of pair " + pair_label(p.pair));
  }
  for (const BodyAngle& a : s.angles) check_length(a.angle_rad.size(), s.time_s.size(), "the angle of " + a.body);
  if (s.te) check_length(s.te->te_rad.size(), s.time_s.size(), "the transmission error");
}

// The angle samples of `body`; InputError naming it and why it was needed when absent.
const std::vector<double>& angle_of(const RunSignals& s, const std::string& body, const char* needed_for) {
  for (const BodyAngle& a : s.angles)
    if (a.body == body) return a.angle_rad;
  throw InputError("run analysis: no angle samples of '" + body + "', needed for " + needed_for);
}

// The TE statistics over the window.
// Its extremes are those of the band-limited signal the samples hold, not of the samples
// (band_limited.hpp): the faulty paper run's TE dips last about a millisecond, and its samples
// caught 82–90 % of their depth depending on where they fell.
TransmissionErrorStats windowed_te_stats(const TransmissionError& te, double from_s, double* samples_peak_to_peak_rad) {
  TransmissionError w;
  w.time_s = window(te.time_s, te.time_s, from_s);
  w.te_rad = window(te.te_rad, te.time_s, from_s);
  w.ratio = te.ratio;
  TransmissionErrorStats s = te_stats(w);
  *samples_peak_to_peak_rad = s.rad.peak_to_peak;
  const Extremes e = band_limited_extremes(w.te_rad);
  const auto set = [&](SeriesStats& st, double scale) {
    st.min = e.min * scale, st.max = e.max * scale, st.peak_to_peak = (e.max - e.min) * scale;
  };
  set(s.rad, 1);
  set(s.urad, 1e6);
  set(s.deg, 180 / std::numbers::pi);
  return s;
}

// The angle-synchronous average of each planet's sun–planet force (planets without a logged
// sun–planet pair are left out).
std::vector<SynchronousTeeth> synchronous_averages(const RunSignals& s, const TrainDescription& train, std::string& note) {
  std::vector<SynchronousTeeth> out;
  for (const PlanetGear& planet : train.planets) {
    const std::string& sun = planet.sun.empty() ? train.sun : planet.sun;
    const auto pf =
        std::find_if(s.pair_forces.begin(), s.pair_forces.end(), [&](const PairForce& p) { return p.pair.same_bodies(sun, planet.body); });
    if (pf == s.pair_forces.end()) continue;
    const std::vector<double>& angle = angle_of(s, planet.body, "the synchronous average of its teeth");
    const std::vector<double> turned = window(angle, s.time_s, s.from_s);
    if (synchronous_revolutions(turned) < 1) {
      // Too short a window for one whole turn of the planet on its carrier: said, not averaged.
      note = "the window (" + std::to_string(s.time_s.back() - s.from_s) + " s) holds less than one whole turn of " + planet.body +
             " on its carrier: no synchronous average";
      continue;
    }
    out.push_back(synchronous_teeth(pf->pair, planet, window(pf->force_N, s.time_s, s.from_s), turned));
  }
  return out;
}

// Per-tooth loads of every counted gear in the log, over its whole revolutions from from_s.
std::vector<ToothLoads> all_tooth_loads(const RunSignals& s, const TrainDescription& train) {
  const ToothContactLog& log = *s.tooth_contacts;
  std::vector<ToothLoads> out;
  for (std::size_t p = 0; p < log.pairs.size(); ++p)
    for (const bool side_a : {true, false}) {
      const std::string& gear = side_a ? log.pairs[p].a : log.pairs[p].b;
      const auto counted =
          std::find_if(train.counted_gears.begin(), train.counted_gears.end(), [&](const CountedGear& g) { return g.body == gear; });
      if (counted == train.counted_gears.end()) continue;
      const WholeRevolutions w = whole_revolutions(s.time_s, angle_of(s, gear, "its per-tooth loads"), s.from_s);
      if (w.turns < 1) continue;
      out.push_back(tooth_loads(log, p, side_a, counted->teeth, s.from_s, w.to_s, w.turns));
    }
  return out;
}

// Per pair, the share of the window's steps (from_s … to_s) in which it carried no force, from
// the per-step log: a step counts as in contact when any of the pair's contacts in it has a
// positive normal impulse. The log's rows come in step order (the reader checks it), so each pair
// keeps only the last step it counted: memory per pair, not per step.
// The window's steps, first and last index (step k ends at k·dt: its time in the log, a sum of
// steps, within rounding of it); nothing without a step or a step in the window.
std::optional<std::pair<std::int64_t, std::int64_t>> window_steps(const ToothContactLog& log, const RunAnalysis& r) {
  const double dt = log.time_step_s;
  if (!(dt > 0)) return std::nullopt;
  const auto first = static_cast<std::int64_t>(std::ceil(r.from_s / dt - 1e-6)),
             last = static_cast<std::int64_t>(std::floor(r.to_s / dt + 1e-6));
  if (last < first) return std::nullopt;
  return std::pair{first, last};
}

void steps_without_force(const ToothContactLog& log, RunAnalysis& r) {
  const auto w = window_steps(log, r);
  if (!w) return;
  const auto [first, last] = *w;
  const double dt = log.time_step_s;
  std::vector<std::int64_t> with_force(log.pairs.size(), 0), last_counted(log.pairs.size(), first - 1);
  for (std::size_t c = 0; c < log.time_s.size(); ++c) {
    const auto k = static_cast<std::int64_t>(std::llround(log.time_s[c] / dt));
    const auto p = static_cast<std::size_t>(log.pair[c]);
    if (k < first || k > last || !(log.normal_impulse_N_s[c] > 0) || k <= last_counted[p]) continue;
    last_counted[p] = k;
    ++with_force[p];
  }
  const double steps = static_cast<double>(last - first + 1);
  for (PairForceAnalysis& pf : r.pairs)
    for (std::size_t q = 0; q < log.pairs.size(); ++q)
      if (log.pairs[q] == pf.pair) pf.steps_without_force_share = 1 - static_cast<double>(with_force[q]) / steps;
}

// Per pair, its force in each step of the window (the sum of its contacts' impulses over dt):
// mean, peak and their ratio, the per-step dynamic factor. Rows in step order: memory per pair.
void per_step_forces(const ToothContactLog& log, RunAnalysis& r) {
  const auto w = window_steps(log, r);
  if (!w) return;
  const auto [first, last] = *w;
  const double dt = log.time_step_s;
  const std::size_t n = log.pairs.size();
  std::vector<std::int64_t> step(n, first - 1);
  std::vector<double> current(n, 0.0), peak(n, 0.0), total(n, 0.0);
  for (std::size_t c = 0; c < log.time_s.size(); ++c) {
    const auto k = static_cast<std::int64_t>(std::llround(log.time_s[c] / dt));
    const auto p = static_cast<std::size_t>(log.pair[c]);
    if (k < first || k > last) continue;
    if (k != step[p]) peak[p] = std::max(peak[p], current[p]), current[p] = 0, step[p] = k;
    const double f = log.normal_impulse_N_s[c] / dt;
    current[p] += f;
    total[p] += f;
  }
  const double steps = static_cast<double>(last - first + 1);
  for (PairForceAnalysis& pf : r.pairs)
    for (std::size_t q = 0; q < n; ++q)
      if (log.pairs[q] == pf.pair) {
        const double mean = total[q] / steps, top = std::max(peak[q], current[q]);
        pf.mean_step_force_N = mean;
        pf.peak_step_force_N = top;
        pf.dynamic_factor_per_step = mean > 0 ? top / mean : 0.0;
      }
}

// A stage's transmission error over the window: θ_in − ratio·θ_out, each the sum of its chain's
// logged angles.
RunAnalysis::StageTe stage_te(const RunSignals& s, const TrainDescription::StageTe& st) {
  const auto absolute = [&](const std::vector<std::string>& chain) {
    std::vector<double> theta(s.time_s.size(), 0.0);
    for (const std::string& body : chain) {
      const std::vector<double>& a = angle_of(s, body, "the transmission error of its stage");
      for (std::size_t i = 0; i < theta.size(); ++i) theta[i] += a[i];
    }
    return theta;
  };
  TransmissionError te = transmission_error(s.time_s, absolute(st.input_chain), absolute(st.output_chain), st.ratio);
  for (double& v : te.te_rad) v -= st.assembly_phase_rad;
  RunAnalysis::StageTe out{st.stage, st.ratio, {}, 0.0};
  out.te = windowed_te_stats(te, s.from_s, &out.samples_peak_to_peak_rad);
  return out;
}

}  // namespace

std::size_t samples_from(const std::vector<double>& time_s, double from_s) {
  return static_cast<std::size_t>(std::count_if(time_s.begin(), time_s.end(), [&](double t) { return t >= from_s; }));
}

RunAnalysis analyze_signals(const RunSignals& s, const TrainDescription& train) {
  check_signals(s);
  // The window and its sample rate.
  const std::vector<double> tw = window(s.time_s, s.time_s, s.from_s);
  RunAnalysis r;
  r.from_s = tw.front();
  r.to_s = tw.back();
  r.sample_rate_hz = uniform_sample_rate_hz(tw);
  // Each pair's force spectrum; the TE; the planets' synchronous averages; the per-tooth loads.
  for (const PairForce& p : s.pair_forces)
    r.pairs.push_back(analyse_pair_force(p.pair, window(p.force_N, s.time_s, s.from_s), r.sample_rate_hz, train,
                                         p.point_force_N.empty() ? std::vector<double>{} : window(p.point_force_N, s.time_s, s.from_s)));
  if (s.te) {
    double samples_p2p = 0;
    r.te = windowed_te_stats(*s.te, s.from_s, &samples_p2p);
    r.te_samples_peak_to_peak_rad = samples_p2p;
  }
  for (const TrainDescription::StageTe& st : train.stage_te) r.stage_te.push_back(stage_te(s, st));
  if (train.planetary) r.synchronous = synchronous_averages(s, train, r.synchronous_note);
  if (train.planetary && !train.carrier.empty()) {
    // The watched set's planets only (a train's other planetary stages mesh elsewhere).
    TrainDescription set = train;
    std::erase_if(set.planets, [&](const PlanetGear& p) { return !p.sun.empty() && p.sun != train.sun; });
    for (const SensorSignal& sensor : s.sensors) r.sensors.push_back(analyse_sensor(sensor, s, set));
  }
  if (s.tooth_contacts) {
    steps_without_force(*s.tooth_contacts, r);
    per_step_forces(*s.tooth_contacts, r);
    r.tooth_loads = all_tooth_loads(s, train);
    r.diagnosis = diagnose_from_contacts(*r.tooth_loads, [&](const PairId& pair, const std::string& gear) -> std::string {
      for (const TrainDescription::LoadedFlank& l : train.loaded_flanks) {
        if (!(l.pair == pair) || l.flank_of_a.empty()) continue;
        if (gear == pair.a || !l.b_internal) return l.flank_of_a;  // two external gears: ccw touches ccw
        return l.flank_of_a == "ccw" ? "cw" : "ccw";
      }
      return "";
    });
  }
  return r;
}

}  // namespace gearsim

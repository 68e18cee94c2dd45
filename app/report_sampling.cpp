// The report's sampling section: why the paper's 2000-sample record misleads (the point-sampled
// force against the anti-aliased one at the mesh harmonics), the filter the run used, and the
// contact ringing above the band — its frequency predicted from the mesh stiffness and reduced
// mass, its damping, and what the per-step log shows there.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

#include "analysis/peaks.hpp"
#include "analysis/spectrum.hpp"
#include "app/html.hpp"
#include "app/report.hpp"
#include "input/csv_table.hpp"
#include "sim/step_log_reader.hpp"

namespace gearsim::app {
namespace {

using json = nlohmann::ordered_json;

// The samples of `column` at window_s[0] ≤ t ≤ window_s[1].
std::vector<double> in_window(const input::CsvTable& t, const std::string& column, const json& window) {
  const double t0 = window[0].get<double>(), t1 = window[1].get<double>();
  const std::vector<double>& time = t.column("time_s");
  const std::vector<double>& v = t.column(column);
  std::vector<double> out;
  for (std::size_t i = 0; i < v.size(); ++i)
    if (time[i] >= t0 - 1e-12 && time[i] <= t1 + 1e-12) out.push_back(v[i]);
  return out;
}

std::size_t padded(std::size_t n) {
  std::size_t l = 1;
  while (l < 8 * n) l <<= 1;
  return l;
}

// Highest amplitude within ± 2/T of f (the Hann main lobe), signal unit.
double amplitude_near(const Spectrum& s, double f_hz) {
  double best = 0;
  for (std::size_t k = 0; k < s.frequency_hz.size(); ++k)
    if (std::abs(s.frequency_hz[k] - f_hz) <= 2 * s.resolution_hz) best = std::max(best, s.amplitude[k]);
  return best;
}

// Per pair, the three mesh harmonics from the anti-aliased force (as analyze reports them) and
// from the point samples of the same window: the paper's method against ours.
std::string aliasing_table(const RunDir& run, const json& a) {
  const input::CsvTable c = input::read_csv(run.dir / "contacts.csv");
  const double rate = a["sample_rate_hz"].get<double>();
  std::vector<std::vector<std::string>> rows;
  for (const auto& [pair, pj] : a["pairs"].items()) {
    if (!c.has(pair + "_force_point_N")) continue;
    const std::vector<double> x = in_window(c, pair + "_force_point_N", a["window_s"]);
    const Spectrum s = amplitude_spectrum(x, rate, {WindowKind::Hann, padded(x.size()), true});
    std::vector<std::string> row{html_escape(pair)};
    for (const json& h : pj["mesh_harmonics"]) {
      if (h["order"].get<int>() > 3 || !h.contains("amplitude_N")) continue;
      const double filtered = h["amplitude_N"].get<double>(), point = amplitude_near(s, h["expected_hz"].get<double>());
      row.push_back(num(filtered, 4) + " / " + num(point, 4) + " (" + num(100 * (point / filtered - 1), 3) + " %)");
    }
    rows.push_back(row);
  }
  if (rows.empty()) return "<p class=\"note\">This run's contacts.csv has no point-sampled force column (an older run).</p>\n";
  return html_table({"pair", "1st harmonic, N: anti-aliased / point samples", "2nd", "3rd"}, rows);
}

// A tooth pair's ringing along the line of action: f = √(n·k/m)/2π with n pairs in contact.
std::string ringing_prediction(const RunDir& run) {
  const json& pairs = run.summary["gear_pairs"];
  std::vector<std::vector<std::string>> rows;
  for (const json& p : pairs) {
    if (!p.contains("reduced_mass_kg")) continue;
    const double k = p["stiffness_N_per_m"].get<double>(), m = p["reduced_mass_kg"].get<double>();
    const double f1 = std::sqrt(k / m) / (2 * std::numbers::pi), f2 = std::sqrt(2 * k / m) / (2 * std::numbers::pi);
    const double zeta = run.scenario.contact.damping_ratio;
    rows.push_back({html_escape(p["a"].get<std::string>() + "–" + p["b"].get<std::string>()), num(k, 4), num(m, 4), num(f1, 4), num(f2, 4),
                    zeta > 0 ? num(1e3 / (zeta * 2 * std::numbers::pi * f1), 3) : "none (undamped)"});
  }
  if (rows.empty()) return "";
  return html_table({"pair", "k per tooth pair, N/m", "reduced mass along the line of action, kg", "ringing, one pair in contact, Hz",
                     "two pairs, Hz", "decay to 1/e, one pair, ms"},
                    rows) +
         "<p>f = √(n·k/m)/2π for n tooth pairs in contact; the damping ratio " + num(run.scenario.contact.damping_ratio, 3) +
         " of critical (scenario <code>contact.damping_ratio</code>) gives the decay time 1/(ζ·2π·f). Every tooth "
         "entering or leaving the mesh changes the stiffness and restarts it.</p>\n";
}

// What the per-step log holds above the stopband edge for the first pair: the strongest lines,
// each with its order of the mesh frequency, and the share of the force's variance up there.
std::string full_rate_lines(const RunDir& run, const json& a, double stop_hz) {
  if (!std::filesystem::exists(run.dir / "steps.h5")) return "<p class=\"note\">No per-step log (steps.h5) in this run.</p>\n";
  const sim::StepLogContacts log = sim::read_step_log_contacts(run.dir / "steps.h5");
  if (log.pairs.empty() || log.step.empty()) return "";
  const double dt = log.time_step_s, t0 = a["window_s"][0].get<double>(), t1 = a["window_s"][1].get<double>();
  const auto first = static_cast<std::size_t>(std::ceil(t0 / dt - 1e-9)), last = static_cast<std::size_t>(t1 / dt + 1e-9);
  std::vector<double> f(last >= first ? last - first + 1 : 0, 0.0);
  for (std::size_t c = 0; c < log.step.size(); ++c) {
    const auto st = static_cast<std::size_t>(log.step[c]);
    if (log.pair[c] == 0 && st >= first && st <= last) f[st - first] += log.normal_impulse_N_s[c] / dt;
  }
  if (f.size() < 64) return "";
  const Spectrum s = amplitude_spectrum(f, 1 / dt, {WindowKind::Hann, 0, true});
  std::vector<SpectralPeak> peaks = local_maxima(s, stop_hz, 0.5 / dt);
  std::sort(peaks.begin(), peaks.end(), [](const SpectralPeak& x, const SpectralPeak& y) { return x.amplitude > y.amplitude; });
  const double fm = pair_mesh_hz(a, log.pairs[0]);
  std::string lines;
  for (std::size_t i = 0; i < peaks.size() && i < 6; ++i)
    lines += (i ? ", " : "") + num(peaks[i].frequency_hz, 5) + " Hz (" + num(peaks[i].frequency_hz / fm, 4) + "·f<sub>m</sub>, " +
             num(peaks[i].amplitude, 3) + " N)";
  double above = 0, total = 0;
  for (std::size_t k = 1; k < s.psd_per_hz.size(); ++k) {
    total += s.psd_per_hz[k] * s.bin_width_hz;
    if (s.frequency_hz[k] >= stop_hz) above += s.psd_per_hz[k] * s.bin_width_hz;
  }
  return "<p>Per-step force of " + html_escape(log.pairs[0]) + " over the same window, above " + num(stop_hz, 4) +
         " Hz: the strongest lines " + lines + "; " + num(total > 0 ? 100 * above / total : 0.0, 3) +
         " % of its variance lies there — what a point-sampled record folds onto 0–" + num(stop_hz, 4) +
         " Hz. Lines at whole orders of f<sub>m</sub> are high mesh harmonics (the stiffness changes as teeth enter and "
         "leave, a step every mesh period); the ringing above shows as a broad rise near its frequency.</p>\n";
}

}  // namespace

std::string report_sampling_section(const RunDir& run) {
  const bool paper = reproduces_paper(run);
  std::string h = paper ? "<h2>Sampling: why the paper's 2000-sample record misleads</h2>\n"
                        : "<h2>Sampling: the anti-aliased force and its point samples</h2>\n";
  const std::filesystem::path analysis = run.dir / "analysis.json";
  if (!run.summary.contains("force_filter") || !std::filesystem::exists(analysis))
    return h + "<p class=\"note\">This run logged point samples only (no force_filter in summary.json).</p>\n";
  const json a = read_json_record(analysis);
  const json& ff = run.summary["force_filter"];
  const double fs = ff["output_rate_hz"].get<double>(), stop = ff["stopband_edge_hz"].get<double>();
  h += std::string(paper ? "<p>The paper kept the contact force every 25th step (2 kHz) of a 50 kHz simulation. Everything the force "
                           "holds above " +
                               num(fs / 2, 4) + " Hz then folds onto 0–" + num(fs / 2, 4) +
                               " Hz: the 24th mesh harmonic (7680 Hz = 4·2000 − 320 Hz) lands exactly on the 320 Hz mesh line, and "
                               "the contact ringing lands wherever its frequency folds. Those point samples change with the time "
                               "step and no spectral figure taken from them converges. "
                         : "<p>Point samples of the contact force at the output rate fold everything it holds above " + num(fs / 2, 4) +
                               " Hz (high mesh harmonics, the contact ringing) onto 0–" + num(fs / 2, 4) + " Hz. ") +
       "This run's <code>contacts.csv</code> force is instead every "
       "step's force through a zero-phase low-pass (" +
       std::to_string(ff["taps"].get<long>()) + " taps, passband to " + num(ff["passband_edge_hz"].get<double>(), 4) + " Hz, " +
       num(ff["stopband_attenuation_dB"].get<double>(), 4) + " dB from " + num(stop, 4) +
       " Hz; docs/decimation.md); the point samples are kept as "
       "<code>_force_point_N</code>. Mesh harmonics over the analysed window:</p>\n";
  h += aliasing_table(run, a);
  h += "<h3>Contact ringing above the band</h3>\n" + ringing_prediction(run) + full_rate_lines(run, a, stop);
  return h;
}

}  // namespace gearsim::app

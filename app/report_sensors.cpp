// Report section: each housing sensor — its signal, its spectrum around the mesh harmonics with
// the planet-pass components McFadden & Smith's rule lets survive marked, the indicators of each
// planet's separated average (beside the --compare run's), and the diagnosis in a sentence.
#include <cmath>
#include <filesystem>
#include <fstream>

#include "analysis/planet_pass.hpp"
#include "analysis/spectrum.hpp"
#include "app/gnuplot.hpp"
#include "app/html.hpp"
#include "app/report.hpp"
#include "input/csv_table.hpp"
#include "app/run_analysis.hpp"
#include "input/gear_train.hpp"

namespace gearsim::app {
namespace {

using json = nlohmann::ordered_json;

json analysis_of(const RunDir& r) {
  return std::filesystem::exists(r.dir / "analysis.json") ? read_json_record(r.dir / "analysis.json") : json();
}

const json* sensor_in(const json& a, const std::string& name) {
  if (!a.contains("sensors")) return nullptr;
  for (const json& s : a["sensors"])
    if (s["sensor"] == name) return &s;
  return nullptr;
}

std::string number_or_dash(const json& v) { return v.is_number() ? num(v.get<double>(), 4) : "–"; }

std::string indicator_table(const json& s, const json* other, const std::string& run_name, const std::string& other_name) {
  std::vector<std::vector<std::string>> rows;
  auto add = [&](const json& sensor, const std::string& who) {
    for (const json& p : sensor["planets"]) {
      const json& c = p["condition_indicators"];
      rows.push_back({html_escape(who), html_escape(p["planet"].get<std::string>()), num(p["passes"].get<double>(), 3),
                      number_or_dash(c["rms_m_s2"]), number_or_dash(c["crest_factor"]), number_or_dash(c["kurtosis"]),
                      number_or_dash(c["fm0"]), number_or_dash(c["fm4"]), number_or_dash(c["m6a"]), number_or_dash(c["na4"]),
                      number_or_dash(c["er"])});
    }
  };
  add(s, run_name);
  if (other) add(*other, other_name);  // the --compare run, after this one's
  return html_table({"run", "planet", "passes", "RMS m/s²", "crest", "kurtosis", "FM0", "FM4", "M6A", "NA4", "ER"}, rows);
}

std::string one_sensor(const RunDir& run, const physics::SensorDef& d, const json& a) {
  std::string h = "<h3>" + html_escape(d.name) + " on " + html_escape(d.body) + " at " + num(d.angle_rad * 180 / M_PI, 4) + "°</h3>\n";
  const input::CsvTable csv = input::read_csv(run.dir / "sensors.csv");
  const std::vector<double>& t = csv.column("time_s");
  const std::vector<double>& x = csv.column(d.name + "_acceleration_m_s2");
  const double from = a.contains("window_s") ? a["window_s"][0].get<double>() : t.front();
  std::vector<double> tw, xw;
  for (std::size_t i = 0; i < t.size(); ++i)
    if (t[i] >= from) tw.push_back(t[i]), xw.push_back(x[i]);
  if (xw.size() < 64) return h + "<p class=\"note\">Too few samples after the ramp for a spectrum.</p>\n";
  std::vector<double> tz, xz;  // 50 ms of the signal
  for (std::size_t i = 0; i < tw.size() && tw[i] < from + 0.05; ++i) tz.push_back(tw[i]), xz.push_back(xw[i]);
  h += gnuplot_svg(data_block("d", {tz, xz}) +
                       "set xlabel 'time, s'; set ylabel 'acceleration, m/s²'; set grid\n"
                       "plot $d using 1:2 with lines lw 1 title '50 ms after the ramp'\n",
                   900, 280);
  const Spectrum sp = amplitude_spectrum(xw, d.sample_rate_hz);
  // The train: which planet-pass components survive at k·f_m + n·f_c.
  const input::GearTrain whole = run_gear_train(run);
  const input::TrainStage* set = whole.first_planetary();
  if (!set || set->fixed != set->ring || set->ring_teeth == 0) return h;
  const input::TrainStage& train = *set;
  const double fm = train.frequencies.mesh_hz, fc = fm / train.ring_teeth;
  const int N = static_cast<int>(train.planets.size());
  for (int k = 1; k <= 3; ++k) {
    const double lo = k * fm - 6.5 * fc, hi = k * fm + 6.5 * fc;
    std::vector<double> f, amp;
    for (std::size_t b = 0; b < sp.frequency_hz.size(); ++b)
      if (sp.frequency_hz[b] >= lo && sp.frequency_hz[b] <= hi) f.push_back(sp.frequency_hz[b]), amp.push_back(sp.amplitude[b]);
    std::string marks;
    for (int n = -6; n <= 6; ++n) {
      const bool keeps = planet_pass_line_survives(N, train.ring_teeth, k, n);
      marks += "set arrow from " + num(k * fm + n * fc, 8) + ", graph 0 to " + num(k * fm + n * fc, 8) + ", graph 1 nohead dt " +
               (keeps ? "2 lc rgb '#228833'" : "3 lc rgb '#cccccc'") + "\n";
    }
    h += "<p>Around " + std::to_string(k) + "·f<sub>m</sub> = " + num(k * fm, 5) +
         " Hz: green dashed, the components k·f<sub>m</sub> + n·f<sub>c</sub> that survive at a fixed sensor (n ≡ −k·z<sub>r</sub> mod N); "
         "grey, those that cancel.</p>\n";
    h += gnuplot_svg(data_block("s", {f, amp}) + marks +
                         "set logscale y; set xlabel 'frequency, Hz'; set ylabel 'amplitude, m/s²'; set grid\n"
                         "plot $s using 1:2 with lines lw 1 title " +
                         gnuplot_string(run.scenario.name) + "\n",
                     900, 280);
  }
  return h;
}

}  // namespace

std::string report_sensors_section(const RunDir& run, const std::optional<RunDir>& compare) {
  if (run.scenario.sensors.empty() || !std::filesystem::exists(run.dir / "sensors.csv")) return "";
  const json a = analysis_of(run);
  const json b = compare ? analysis_of(*compare) : json();
  std::string h = "<h2>Housing sensors</h2>\n<p>McFadden &amp; Smith's planet-pass model (docs/condition-monitoring.md).</p>\n";
  for (const physics::SensorDef& d : run.scenario.sensors) {
    h += one_sensor(run, d, a);
    if (const json* s = sensor_in(a, d.name)) {
      h += "<p>Each planet's separated average (McFadden 1991) and its indicators:</p>\n" +
           indicator_table(*s, compare ? sensor_in(b, d.name) : nullptr, run.scenario.name + " (" + run.dir.filename().string() + ")",
                           compare ? compare->scenario.name + " (" + compare->dir.filename().string() + ")" : "");
      if (s->contains("fault") && !(*s)["fault"].is_null())
        h += "<p><b>From the sensor alone:</b> " + html_escape((*s)["fault"]["gear"].get<std::string>()) + ", tooth " +
             std::to_string((*s)["fault"]["tooth"].get<int>()) + ": " + html_escape((*s)["fault"]["evidence"].get<std::string>()) +
             ".</p>\n";
      else if (s->contains("note"))
        h += "<p><b>From the sensor alone:</b> no planet named: " + html_escape((*s)["note"].get<std::string>()) + ".</p>\n";
    }
  }
  if (a.contains("diagnosis")) {
    std::string sentence;
    for (const json& f : a["diagnosis"]["faults"])
      sentence += (sentence.empty() ? "" : "; ") + html_escape(f["gear"].get<std::string>()) + " tooth " +
                  std::to_string(f["tooth"].get<int>()) +
                  (f["flank"].get<std::string>().empty() ? "" : " (" + html_escape(f["flank"].get<std::string>()) + " flank)") + " from " +
                  html_escape(f["source"].get<std::string>()) + ", confidence " + num(f["confidence"].get<double>(), 2);
    h += "<p><b>Diagnosis:</b> " + (sentence.empty() ? std::string("no fault found") : sentence) + ".</p>\n";
  }
  return h;
}

}  // namespace gearsim::app

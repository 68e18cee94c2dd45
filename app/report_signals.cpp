// Report section: characteristic frequencies and what the record resolves; per stage the contact
// force of its first pair (paper Fig. 4), its spectrum with harmonics (Fig. 5) and zooms with
// sidebands (Fig. 6); the transmission error (Fig. 7), per-tooth loads; healthy/faulty overlays
// with --compare. The paper's figure numbers only for a run that reproduces the paper.
#include <algorithm>
#include <cmath>
#include <fstream>

#include "input/csv_table.hpp"
#include "app/gnuplot.hpp"
#include "app/html.hpp"
#include "app/report.hpp"

namespace gearsim::app {

using json = nlohmann::ordered_json;
namespace {

json read_analysis(const RunDir& r) { return read_json_record(r.dir / "analysis.json"); }

std::string first_force_pair(const json& a) { return a["pairs"].begin().key(); }

std::string frequencies_table(const json& a) {
  std::vector<std::vector<std::string>> rows;
  for (const auto& f : a["gear_train"]["characteristic_frequencies"])
    rows.push_back({html_escape(f["key"].get<std::string>()), html_escape(f["name"].get<std::string>()),
                    num(f["value_hz"].get<double>(), 5), html_escape(f["formula"].get<std::string>())});
  return html_table({"key", "what", "Hz", "formula"}, rows);
}

// " (paper Fig. n)" for a run that reproduces the paper, else "".
std::string paper_figure(const RunDir& run, int n) { return reproduces_paper(run) ? " (paper Fig. " + std::to_string(n) + ")" : ""; }

// Per stage (one for a single-stage train) the first pair analysis.json lists in it.
std::vector<std::string> stage_pairs(const json& a) {
  std::vector<std::string> out;
  if (!a["gear_train"].contains("stages")) return {first_force_pair(a)};
  for (const auto& st : a["gear_train"]["stages"])
    for (const auto& [name, p] : a["pairs"].items())
      if (p.contains("stage") && p["stage"] == st["name"]) {
        out.push_back(name);
        break;
      }
  return out;
}

std::string force_plots(const RunDir& run, const json& a, const std::string& pair) {
  const input::CsvTable c = input::read_csv(run.dir / "contacts.csv");
  const std::vector<double>& t = c.column("time_s");
  const std::vector<double>& f = c.column(pair + "_force_N");
  const double from = a["window_s"][0].get<double>();
  // Eight mesh periods after the ramp (25 ms for the paper's set).
  const double span = 8 / pair_mesh_hz(a, pair);
  std::vector<double> tz, fz;
  for (std::size_t i = 0; i < t.size(); ++i)
    if (t[i] >= from && t[i] < from + span) tz.push_back(t[i]), fz.push_back(f[i]);
  std::string h = "<h3>Contact force, " + html_escape(pair) + paper_figure(run, 4) + "</h3>\n";
  h += gnuplot_svg(data_block("d", {t, f}) +
                   "set xlabel 'time, s'; set ylabel 'force, N'; set grid\n"
                   "plot $d using 1:2 with lines lw 1 title " +
                   gnuplot_string(pair) + "\n");
  h += gnuplot_svg(data_block("d", {tz, fz}) +
                       "set xlabel 'time, s'; set ylabel 'force, N'; set grid\n"
                       "plot $d using 1:2 with linespoints pt 7 ps 0.3 title " +
                       gnuplot_string(num(span * 1e3, 3) + " ms at speed: eight mesh periods (output samples)") + "\n",
                   900, 300);
  return h;
}

std::string spectrum_plots(const RunDir& run, const json& a, const std::string& pair, const std::optional<RunDir>& cmp) {
  const input::CsvTable s = input::read_csv(run.dir / "spectrum.csv");
  const double fm = pair_mesh_hz(a, pair);
  // To 1000 Hz, or past the third harmonic of a faster stage (within the record).
  const double top = std::min(s.column("frequency_hz").back(), std::max(1000.0, 3.3 * fm));
  std::string script = data_block("s", {s.column("frequency_hz"), s.column(pair + "_amplitude_N")});
  std::string plot = "plot $s using 1:2 with lines lw 1 title " + gnuplot_string(run.scenario.name);
  if (cmp) {
    const input::CsvTable s2 = input::read_csv(cmp->dir / "spectrum.csv");
    script += data_block("c", {s2.column("frequency_hz"), s2.column(pair + "_amplitude_N")});
    plot += ", $c using 1:2 with lines lw 1 title " + gnuplot_string(cmp->scenario.name);
  }
  std::string marks;
  for (int k = 1; k <= 3; ++k)
    marks += "set arrow from " + num(k * fm, 6) + ", graph 0 to " + num(k * fm, 6) + ", graph 1 nohead dt 2 lc rgb 'gray'\n";
  std::string h = "<h3>Spectrum of the contact force of " + html_escape(pair) + " to " + num(top, 4) +
                  " Hz, harmonics of f<sub>m</sub> = " + num(fm, 5) + " Hz dashed" + paper_figure(run, 5) + "</h3>\n";
  h += gnuplot_svg(script + marks + "set logscale y; set xrange [0:" + num(top, 6) +
                   "]; set xlabel 'frequency, Hz'; set ylabel 'amplitude, N'; set grid\n" + plot + "\n");
  h += "<h3>Around each harmonic, sidebands labelled by the characteristic frequency they match" + paper_figure(run, 6) + "</h3>\n";
  const json& p = a["pairs"][pair];
  for (const auto& hm : p["mesh_harmonics"]) {
    if (!hm.contains("peak_hz")) continue;
    const double c = hm["peak_hz"].get<double>(), span = std::min(60.0, 0.5 * fm);
    std::vector<json> sb(hm["sidebands"].begin(), hm["sidebands"].end());
    std::sort(sb.begin(), sb.end(),
              [](const json& x, const json& y) { return x["amplitude_N"].get<double>() > y["amplitude_N"].get<double>(); });
    std::string labels;
    int n = 0;
    for (const json& b : sb) {
      if (std::abs(b["offset_hz"].get<double>()) > span || n >= 6) continue;
      ++n;
      const std::string what = b.contains("mesh_line") ? " line " + b["mesh_line"].get<std::string>()
                               : b.contains("match")   ? " " + b["match"].get<std::string>()
                                                       : std::string(" (unmatched)");
      labels += "set label " + gnuplot_string(num(b["offset_hz"].get<double>(), 3) + " Hz" + what) + " at " +
                num(b["frequency_hz"].get<double>(), 6) + "," + num(b["amplitude_N"].get<double>(), 6) +
                " rotate by 60 font ',8' offset 0,0.5\n";
    }
    h += gnuplot_svg(script + labels + "set logscale y; set xrange [" + num(c - span, 6) + ":" + num(c + span, 6) +
                         "]; set xlabel 'frequency, Hz'; set ylabel 'amplitude, N'; set grid\n" + plot + "\n",
                     900, 320);
  }
  return h;
}

std::string te_plot(const RunDir& run) {
  const input::CsvTable st = input::read_csv(run.dir / "state.csv");
  if (!st.has("te_rad")) return "";
  return "<h3>Transmission error θ<sub>in</sub> − i·θ<sub>out</sub>" + paper_figure(run, 7) + "</h3>\n" +
         gnuplot_svg(data_block("d", {st.column("time_s"), st.column("te_rad")}) +
                         "set xlabel 'time, s'; set ylabel 'TE, rad'; set grid\nplot $d using 1:2 with lines title 'te_rad'\n",
                     900, 320);
}

std::string tooth_plot(const json& a, const std::optional<json>& other, const std::string& other_name) {
  if (!a.contains("tooth_loads") || a["tooth_loads"].empty()) return "";
  const json& t = a["tooth_loads"][0];
  std::vector<double> k, f, flag;
  for (const auto& e : t["teeth"]) {
    k.push_back(e["tooth"].get<double>());
    f.push_back(e["mean_force_N"].get<double>());
    bool fl = false;
    for (int g : t["flagged_teeth"]) fl = fl || g == e["tooth"].get<int>();
    flag.push_back(fl ? e["mean_force_N"].get<double>() : NAN);
  }
  std::string script = data_block("t", {k, f, flag});
  std::string plot =
      "plot $t using 1:2 with boxes fs solid 0.5 lc rgb '#4477aa' title 'mean force per tooth', "
      "$t using 1:3 with boxes fs solid 0.9 lc rgb '#cc3311' title 'flagged'";
  if (other && other->contains("tooth_loads") && !(*other)["tooth_loads"].empty()) {
    std::vector<double> k2, f2;
    for (const auto& e : (*other)["tooth_loads"][0]["teeth"])
      k2.push_back(e["tooth"].get<double>()), f2.push_back(e["mean_force_N"].get<double>());
    script += data_block("o", {k2, f2});
    plot += ", $o using 1:2 with linespoints pt 7 ps 0.5 lc rgb 'black' title " + gnuplot_string(other_name);
  }
  return "<h3>Per-tooth load, " + html_escape(t["gear"].get<std::string>()) + " in " + html_escape(t["pair"].get<std::string>()) +
         " (over " + num(t["revolutions"].get<double>()) + " whole revolutions; flagged: |z| &gt; " + num(t["z_threshold"].get<double>()) +
         " and more than " + num(100 * t["min_relative_deviation"].get<double>()) + " % apart)</h3>\n" +
         gnuplot_svg(
             script + "set style fill solid; set boxwidth 0.8; set xlabel 'tooth'; set ylabel 'mean force, N'; set grid\n" + plot + "\n",
             900, 320);
}

}  // namespace

std::string report_signals_section(const RunDir& run, const std::optional<RunDir>& compare) {
  const json a = read_analysis(run);
  std::optional<json> other;
  if (compare) other = read_analysis(*compare);
  const std::string pair = first_force_pair(a);
  const json& p = a["pairs"][pair];
  std::string h = "<h2>Characteristic frequencies</h2>\n" + frequencies_table(a);
  h += "<p>Analysed window " + num(a["window_s"][0].get<double>()) + "–" + num(a["window_s"][1].get<double>()) +
       " s: the record resolves " + num(p["resolution_hz"].get<double>(), 3) +
       " Hz (1/T); with the Hann window, tones closer than about twice that merge into one peak" +
       (reproduces_paper(run) ? ". A 1 s record cannot separate 6.67 Hz (2·f<sub>c</sub>), 8.89 Hz (f<sub>m</sub>/36) and 10 Hz "
                                "(3·f<sub>c</sub>)"
                              : std::string()) +
       ": the spectrum is zero-padded to a " + num(p["bin_width_hz"].get<double>(), 3) +
       " Hz grid, which places peaks, not resolves them.</p>\n";
  h += "<h2>Signals</h2>\n";
  for (const std::string& first : stage_pairs(a)) h += force_plots(run, a, first) + spectrum_plots(run, a, first, compare);
  h += te_plot(run);
  std::vector<std::vector<std::string>> rows;
  for (const auto& [name, q] : a["pairs"].items()) {
    std::vector<std::string> r{
        html_escape(name), q.contains("stage") ? html_escape(q["stage"].get<std::string>()) : "–", num(q["mean_force_N"].get<double>(), 5),
        num(100 * q["zero_force_share"].get<double>(), 3),
        q.contains("steps_without_force_share") ? num(100 * q["steps_without_force_share"].get<double>(), 3) : "no per-step log"};
    for (const auto& hm : q["mesh_harmonics"])
      r.push_back(hm.contains("peak_hz")
                      ? num(hm["peak_hz"].get<double>(), 6) + " Hz, +" + num(hm["over_median_floor_0_1000_hz_db"].get<double>(), 3) + " dB"
                      : "not found");
    while (r.size() < 8) r.push_back("above the record's Nyquist frequency");
    // The dynamic factor both ways: the per-step one is ISO 6336's K_v.
    r.push_back(num(q["dynamic_factor_band_limited"].get<double>(), 4));
    r.push_back(q.contains("dynamic_factor_per_step") ? num(q["dynamic_factor_per_step"].get<double>(), 4) : "no per-step log");
    rows.push_back(r);
  }
  h += "<h3>Every gear pair</h3>\n" +
       html_table({"pair", "stage", "mean force, N", "zero-force samples, %", "steps without force, %", "f<sub>m</sub> over floor",
                   "2·f<sub>m</sub>", "3·f<sub>m</sub>", "dynamic factor, band-limited", "dynamic factor per step (K<sub>v</sub>)"},
                  rows);
  if (a.contains("contact_loss")) {
    std::string pairs;
    for (const auto& q : a["contact_loss"]["pairs"]) pairs += (pairs.empty() ? "" : ", ") + html_escape(q.get<std::string>());
    h += "<p class=\"note\"><b>Contact loss</b> in " + pairs + ": " + html_escape(a["contact_loss"]["note"].get<std::string>()) + ".</p>\n";
  }
  if (p.contains("planet_fault_family")) {
    rows.clear();
    for (std::size_t k = 0; k < p["planet_fault_family"].size(); ++k) {
      const json& e = p["planet_fault_family"][k];
      std::vector<std::string> r{num(e["expected_hz"].get<double>(), 4),
                                 e.contains("amplitude_N") ? num(e["amplitude_N"].get<double>(), 3) : "no line"};
      if (other) {
        const json& o = (*other)["pairs"][pair]["planet_fault_family"][k];
        r.push_back(o.contains("amplitude_N") ? num(o["amplitude_N"].get<double>(), 3) : "no line");
      }
      rows.push_back(r);
    }
    std::vector<std::string> head{"k·f<sub>m</sub>/z<sub>p</sub>, Hz", html_escape(run.scenario.name) + ", N"};
    if (compare) head.push_back(html_escape(compare->scenario.name) + ", N");
    h += "<h3>The planet local-fault family in " + html_escape(pair) + "</h3>\n" + html_table(head, rows);
  }
  h += tooth_plot(a, other, compare ? compare->scenario.name : "");
  return h;
}

}  // namespace gearsim::app

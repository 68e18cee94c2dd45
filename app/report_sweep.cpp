// `gearsim report DIR` on a sweep folder (DIR/sweep.json): the gathered table (from the cases'
// case.json files, as sweep.csv) and one plot per metric against the swept parameter — or
// against mesh_frequency_hz when the sweep collected it, then with the lines f_m = f_n/k
// (k = 1, 2, 3: where the k-th mesh harmonic meets a natural frequency f_n) when DIR holds a
// modes.json (`gearsim modes SCENARIO --json`). Every name and value from the sweep reaches the
// page HTML-escaped and gnuplot as a string literal.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <optional>

#include "app/gnuplot.hpp"
#include "core/input_file.hpp"
#include "input/input_limits.hpp"
#include "app/html.hpp"
#include "app/report.hpp"
#include "core/errors.hpp"
#include "sweep/sweep_dir.hpp"
#include "sweep/table.hpp"

namespace gearsim::app {
namespace {

using json = nlohmann::ordered_json;
namespace fs = std::filesystem;

// The mesh harmonics whose crossings with a natural frequency are marked, unless modes.json's
// Campbell table went further (`gearsim modes --harmonics K`).
constexpr int kMarkedHarmonics = 3;

struct ModeLines {
  std::vector<double> frequencies_hz;  // distinct, > 0
  int harmonics = kMarkedHarmonics;
};

std::optional<double> number_of(const std::string& text) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  return !text.empty() && end == text.c_str() + text.size() && std::isfinite(v) ? std::optional(v) : std::nullopt;
}

// The natural frequencies of DIR/modes.json, Hz: natural_frequencies_hz, else each mode's
// frequency_hz. Nothing when the file is absent; InputError when it is damaged.
ModeLines natural_frequencies(const fs::path& dir) {
  const fs::path p = dir / "modes.json";
  if (!std::filesystem::exists(std::filesystem::symlink_status(p))) return {};
  const std::string text = read_input_file(p, input::limits::kMaxRecordBytes, "a modes record");
  std::vector<double> f;
  ModeLines lines;
  try {
    const json j = json::parse(text);
    if (j.contains("campbell") && j.at("campbell").contains("crossings"))
      for (const json& c : j.at("campbell").at("crossings")) lines.harmonics = std::max(lines.harmonics, c.at("harmonic").get<int>());
    if (j.contains("natural_frequencies_hz"))
      f = j.at("natural_frequencies_hz").get<std::vector<double>>();
    else
      for (const json& m : j.at("modes")) f.push_back(m.at("frequency_hz").get<double>());
  } catch (const json::exception& e) {
    throw InputError(p.string() + ": expected {\"natural_frequencies_hz\": [..]} or {\"modes\": [{\"frequency_hz\": f}]}: " + e.what());
  }
  std::erase_if(f, [](double x) { return !(x > 0) || !std::isfinite(x); });
  std::sort(f.begin(), f.end());
  f.erase(std::unique(f.begin(), f.end()), f.end());  // a repeated frequency is one line
  lines.frequencies_hz = f;
  lines.harmonics = std::min(lines.harmonics, 50);
  return lines;
}

// The x column of the plots: mesh_frequency_hz when collected, else the first parameter whose
// every value is a number.
struct XAxis {
  std::string name;
  std::vector<std::optional<double>> values;  // per row
  bool mesh_frequency = false;
  std::vector<bool> sets_x;  // per parameter: its value alone fixes x (the x parameter, or a speed)
};

// Marks the parameters each of whose values goes with one x only (and x takes several values):
// they are the abscissa, not a series.
void mark_x_parameters(const sweep::SweepTable& t, XAxis& x) {
  x.sets_x.assign(t.parameter_columns.size(), false);
  for (std::size_t k = 0; k < t.parameter_columns.size(); ++k) {
    std::map<std::string, std::optional<double>> x_of;
    bool one_each = true, several = false;
    for (std::size_t i = 0; i < t.rows.size(); ++i) {
      const auto [at, fresh] = x_of.emplace(t.rows[i].parameters[k], x.values[i]);
      one_each = one_each && (fresh || at->second == x.values[i]);
    }
    for (const auto& [v, xv] : x_of) several = several || xv != x_of.begin()->second;
    x.sets_x[k] = one_each && several;
  }
}

std::optional<XAxis> x_axis(const sweep::SweepTable& t) {
  for (std::size_t m = 0; m < t.metric_columns.size(); ++m)
    if (t.metric_columns[m] == "mesh_frequency_hz") {
      XAxis x{"mesh_frequency_hz", {}, true, {}};
      for (const auto& r : t.rows) x.values.push_back(r.metrics[m]);
      mark_x_parameters(t, x);
      return x;
    }
  for (std::size_t k = 0; k < t.parameter_columns.size(); ++k) {
    XAxis x{t.parameter_columns[k], {}, false, {}};
    bool numeric = true;
    for (const auto& r : t.rows) x.values.push_back(number_of(r.parameters[k])), numeric = numeric && x.values.back();
    if (!numeric) continue;
    mark_x_parameters(t, x);
    x.sets_x[k] = true;
    return x;
  }
  return std::nullopt;
}

// The label of a row's series: the parameters other than the x axis ("" when there are none).
std::string series_label(const sweep::SweepTable& t, const sweep::TableRow& r, const XAxis& x) {
  std::string s;
  for (std::size_t k = 0; k < t.parameter_columns.size(); ++k)
    if (!x.sets_x[k]) s += (s.empty() ? "" : ", ") + t.parameter_columns[k] + " = " + r.parameters[k];
  return s;
}

// Vertical lines at f_n/k inside [lo, hi], labelled.
std::string mode_marks(const ModeLines& fn, double lo, double hi) {
  std::string marks;
  for (double f : fn.frequencies_hz)
    for (int k = 1; k <= fn.harmonics; ++k) {
      const double x = f / k;
      if (x < lo || x > hi) continue;
      marks += "set arrow from " + num(x, 8) + ", graph 0 to " + num(x, 8) + ", graph 1 nohead dt 2 lc rgb '#cc3311'\n";
      marks += "set label " + gnuplot_string(num(f, 4) + " Hz / " + std::to_string(k)) + " at " + num(x, 8) +
               ", graph 0.97 rotate by 90 right font ',8' offset -0.6,0 tc rgb '#cc3311'\n";
    }
  return marks;
}

// One metric against the x axis, a line per series, completed cases only.
std::string metric_plot(const sweep::SweepTable& t, std::size_t m, const XAxis& x, const ModeLines& fn) {
  std::map<std::string, std::vector<std::pair<double, double>>> series;
  for (std::size_t i = 0; i < t.rows.size(); ++i)
    if (t.rows[i].status == "completed" && x.values[i] && t.rows[i].metrics[m])
      series[series_label(t, t.rows[i], x)].emplace_back(*x.values[i], *t.rows[i].metrics[m]);
  if (series.empty()) return "<p class=\"note\">No completed case holds " + html_escape(t.metric_columns[m]) + ".</p>\n";
  std::string script = "set termoption noenhanced\nset format y '%.4g'\nset grid\nset key outside right top\nset xlabel " +
                       gnuplot_string(x.name) + "\nset ylabel " + gnuplot_string(t.metric_columns[m]) + "\n";
  std::string plot = "plot ";
  double lo = INFINITY, hi = -INFINITY;
  int n = 0;
  for (auto& [label, points] : series) {
    std::sort(points.begin(), points.end());
    std::vector<double> xs, ys;
    for (const auto& [px, py] : points) xs.push_back(px), ys.push_back(py), lo = std::min(lo, px), hi = std::max(hi, px);
    const std::string name = "s" + std::to_string(n++);
    script += data_block(name, {xs, ys});
    plot += (n > 1 ? ", $" : "$") + name + " using 1:2 with linespoints pt 7 ps 0.6 title " +
            gnuplot_string(label.empty() ? t.metric_columns[m] : label);
  }
  if (x.mesh_frequency) script += mode_marks(fn, lo, hi);
  try {
    return gnuplot_svg(script + plot + "\n", 900, 340);
  } catch (const InputError& e) {
    return "<p class=\"note\">No plot: " + html_escape(e.what()) + "</p>\n";
  }
}

// The gathered table as HTML, with each case's error text where it did not complete.
std::string table_html(const sweep::SweepTable& t) {
  std::vector<std::string> header{"index"};
  for (const std::string& c : t.parameter_columns) header.push_back(html_escape(c));
  header.push_back("status");
  for (const std::string& c : t.metric_columns) header.push_back(html_escape(c));
  header.push_back("error");
  std::vector<std::vector<std::string>> rows;
  for (const sweep::TableRow& r : t.rows) {
    std::vector<std::string> cells{std::to_string(r.index)};
    for (const std::string& p : r.parameters) cells.push_back(html_escape(p));
    cells.push_back(html_escape(r.status));
    for (const auto& v : r.metrics) cells.push_back(v ? num(*v, 6) : "–");
    cells.push_back("<small>" + html_escape(r.error.substr(0, 300)) + "</small>");
    rows.push_back(std::move(cells));
  }
  return html_table(header, rows);
}

}  // namespace

std::string build_sweep_report(const fs::path& dir) {
  const json s = sweep::read_sweep_json(dir);
  const sweep::SweepTable t = sweep::gather_table(dir, s["parameters"].get<std::vector<std::string>>(), s["case_count"].get<std::size_t>());
  const sweep::StatusCounts c = sweep::count_statuses(t);
  const std::string name = s.value("name", std::string("sweep"));
  std::string body = "<h1>Gearsim sweep: " + html_escape(name) + "</h1>\n";
  body += html_table({"", ""}, {{"sweep file", "<code>" + html_escape(s.value("sweep_file", std::string())) + "</code>"},
                                {"base scenario", "<code>" + html_escape(s.value("scenario", std::string())) + "</code>"},
                                {"cases", std::to_string(t.rows.size()) + ": " + std::to_string(c.completed) + " completed, " +
                                              std::to_string(c.diverged) + " diverged, " + std::to_string(c.failed) + " failed, " +
                                              std::to_string(c.interrupted) + " interrupted, " + std::to_string(c.not_run) + " not run"}});
  const std::optional<XAxis> x = x_axis(t);
  const ModeLines fn = natural_frequencies(dir);
  body += "<h2>Metrics</h2>\n";
  if (x && x->mesh_frequency && !fn.frequencies_hz.empty())
    body += "<p>Dashed lines: f<sub>m</sub> = f<sub>n</sub>/k, k = 1–" + std::to_string(fn.harmonics) +
            ", where the k-th mesh harmonic meets a natural frequency of <code>modes.json</code>.</p>\n";
  for (std::size_t m = 0; m < t.metric_columns.size(); ++m) {
    if (x && x->mesh_frequency && t.metric_columns[m] == "mesh_frequency_hz") continue;
    body += "<h3>" + html_escape(t.metric_columns[m]) + "</h3>\n";
    body += x ? metric_plot(t, m, *x, fn) : "<p class=\"note\">No numeric parameter to plot against.</p>\n";
  }
  body += "<h2>The table (sweep.csv)</h2>\n" + table_html(t);
  return html_document("Gearsim sweep: " + name, body);
}

}  // namespace gearsim::app

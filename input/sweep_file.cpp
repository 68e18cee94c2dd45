#include "input/sweep_file.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

#include "core/input_file.hpp"
#include "core/errors.hpp"
#include "input/input_limits.hpp"
#include "input/safe_name.hpp"
#include "input/utf8_text.hpp"
#include "input/yaml_reader.hpp"

namespace gearsim::input {
namespace {

// Longest key path or value text of an override, characters: far beyond any scenario key.
constexpr std::size_t kMaxOverrideText = 200;

// FNV-1a, 64 bit: a content fingerprint (not a security hash: it only tells an edited file).
std::string fnv1a_hex(const std::string& bytes) {
  std::uint64_t h = 14695981039346656037ull;
  for (unsigned char c : bytes) h = (h ^ c) * 1099511628211ull;
  char out[17];
  for (int i = 15; i >= 0; --i, h >>= 4) out[i] = "0123456789abcdef"[h & 15];
  out[16] = '\0';
  return out;
}

// A key path as `--set` and the JSON readers take it: a.b[2].c of A–Z a–z 0–9 _ . - [ ], not
// starting with '-' or '.', so it can never read as an option or leave the tree.
bool is_key_path(const std::string& k) {
  if (k.empty() || k.size() > kMaxOverrideText || k.front() == '-' || k.front() == '.') return false;
  for (char c : k)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.' || c == '-' || c == '[' || c == ']')) return false;
  return true;
}

const char* const kKeyPathRule =
    "expected a key path such as motors[0].target_speed_rad_s (A-Z a-z 0-9 _ . - [ ], "
    "at most 200 characters, not starting with '-' or '.')";

// The text of a scalar value as an override gets it: a number in its shortest round-trip form,
// any other scalar as written (one line, no control characters).
std::string value_text(const YamlMap& m, const std::string& key, const std::string& scalar) {
  double v = 0;
  if (YAML::convert<double>::decode(YAML::Node(scalar), v)) {
    if (!std::isfinite(v)) m.fail(key, "expected a finite number, got '" + shown_name(scalar) + "'");
    return override_number(v);
  }
  bool ok = !scalar.empty() && scalar.size() <= kMaxOverrideText;
  for (char c : scalar) ok = ok && static_cast<unsigned char>(c) >= 0x20 && c != 0x7f;
  if (!ok) m.fail(key, "expected a number or a one-line value of 1 to 200 characters, got '" + shown_name(scalar) + "'");
  return scalar;
}

// A grid axis: {from, to, steps} (evenly spaced, both ends included) or a list of values.
std::vector<std::string> axis_values(const YamlMap& grid, const std::string& key) {
  if (!grid.has_map(key)) {
    std::vector<std::string> values;
    for (const std::string& s : grid.strings(key)) values.push_back(value_text(grid, key, s));
    if (values.empty()) grid.fail(key, "expected at least one value");
    return values;
  }
  const YamlMap r = grid.map(key);
  const double from = r.number("from"), to = r.number("to");
  const int steps = integer_within(r, "steps", limits::kSweepSteps);
  r.reject_unknown_keys();
  std::vector<std::string> values;
  for (int i = 0; i < steps; ++i) values.push_back(override_number(i + 1 == steps ? to : from + (to - from) * i / (steps - 1)));
  return values;
}

// grid: {key: axis, …}; the case count is the product, checked as the axes are read.
void read_grid(const YamlMap& top, SweepFile& f) {
  const YamlMap grid = top.map("grid");
  f.case_count = 1;
  for (const std::string& key : grid.keys()) {
    if (!is_key_path(key)) grid.fail(key, kKeyPathRule);
    SweepParameter p{key, grid.location(key), axis_values(grid, key)};
    if (f.case_count * p.values.size() > limits::kMaxSweepCases)
      grid.fail(key, "the grid has more than " + std::to_string(limits::kMaxSweepCases) + " cases (the product of its axes)");
    f.case_count *= p.values.size();
    f.parameters.push_back(std::move(p));
  }
  if (f.parameters.empty()) top.fail("grid", "expected at least one key: values");
}

// cases: [{key: value, …}, …]; the columns are every key in order of first appearance.
void read_cases(const YamlMap& top, SweepFile& f) {
  const std::vector<YamlMap> cases = top.list_of_maps("cases");
  if (cases.empty()) top.fail("cases", "expected at least one case");
  if (cases.size() > limits::kMaxSweepCases) top.fail("cases", "more than " + std::to_string(limits::kMaxSweepCases) + " cases");
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const YamlMap& c = cases[i];
    const std::vector<std::string> keys = c.keys();
    const std::string first = keys.empty() ? "" : c.location(keys.front());
    SweepListedCase lc{keys.empty() ? top.location("cases") + "[" + std::to_string(i) + "]"
                                    : first.substr(0, first.rfind(": " + c.path())) + ": " + c.path(),
                       {}};
    for (const std::string& key : keys) {
      if (!is_key_path(key)) c.fail(key, kKeyPathRule);
      lc.values.emplace_back(key, value_text(c, key, c.string(key)));
      bool known = false;
      for (const SweepParameter& p : f.parameters) known = known || p.key == key;
      if (!known) f.parameters.push_back({key, c.location(key), {}});
    }
    f.cases.push_back(std::move(lc));
  }
  f.case_count = f.cases.size();
}

// True when the mapping names `key` without a value (`key:`): refused, not taken as absent.
void refuse_empty_value(const YamlMap& m, const std::string& key) {
  for (const std::string& k : m.keys())
    if (k == key && !m.has(key)) m.fail(key, "expected a value (write [] for none)");
}

// A list of key paths (collect.summary, collect.analysis).
std::vector<std::string> key_paths(const YamlMap& m, const std::string& key) {
  refuse_empty_value(m, key);
  if (!m.has(key)) return {};
  const std::vector<std::string> paths = m.strings(key);
  for (const std::string& p : paths)
    if (!is_key_path(p)) m.fail(key, std::string(kKeyPathRule) + ", got '" + shown_name(p) + "'");
  return paths;
}

SweepCollect read_collect(const YamlMap& top) {
  SweepCollect c;
  if (!top.has("collect")) {
    refuse_empty_value(top, "collect");
    return c;
  }
  const YamlMap m = top.map("collect");
  c.summary = key_paths(m, "summary");
  c.analysis = key_paths(m, "analysis");
  refuse_empty_value(m, "metrics");
  if (m.has("metrics"))
    for (const std::string& name : m.strings("metrics")) {
      bool known = false;
      for (const std::string& n : sweep_metric_names()) known = known || n == name;
      if (!known)
        m.fail(
            "metrics", "unknown metric '" + shown_name(name) + "': expected some of {" + [] {
              std::string list;
              for (const std::string& n : sweep_metric_names()) list += (list.empty() ? "" : ", ") + n;
              return list;
            }() + "}" + (name == "dynamic_factor" ? " (the dynamic factor is given two ways, band-limited and per step: name one)" : ""));
      c.metrics.push_back(name);
    }
  m.reject_unknown_keys();
  return c;
}

// set: ["key=value", …]: each one --set argument.
std::vector<std::string> read_set(const YamlMap& top) {
  std::vector<std::string> set;
  refuse_empty_value(top, "set");
  if (!top.has("set")) return set;
  for (const std::string& s : top.strings("set")) {
    const std::size_t eq = s.find('=');
    if (eq == std::string::npos || !is_key_path(s.substr(0, eq)))
      top.fail("set", "expected key.path=value with " + std::string(kKeyPathRule).substr(9) + ", got '" + shown_name(s) + "'");
    set.push_back(s.substr(0, eq) + "=" + value_text(top, "set", s.substr(eq + 1)));
  }
  return set;
}

std::string read_text(const std::filesystem::path& file) { return read_input_file(file, limits::kMaxYamlBytes, "a sweep file"); }

}  // namespace

const std::vector<std::string>& sweep_metric_names() {
  static const std::vector<std::string> names{"dynamic_factor_band_limited", "dynamic_factor_per_step", "mean_force_N", "mesh_frequency_hz",
                                              "rms_dynamic_te_rad"};
  return names;
}

std::string override_number(double value) {
  char buf[64];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, value);
  return std::string(buf, end);
}

SweepFile load_sweep_file(const std::filesystem::path& path) {
  SweepFile f;
  f.file = std::filesystem::absolute(path).lexically_normal();
  const std::string text = read_text(f.file);
  f.content_hash = fnv1a_hex(text);
  const YAML::Node root = parse_yaml_mapping(text, path.string());
  require_utf8_tree(root, path.string());  // names and values reach sweep.json and the case records
  const YamlMap top = YamlMap::from_node(root, path.string());
  f.name = top.string("name");
  require_label(top, "name", f.name);
  const std::filesystem::path scenario = top.string("scenario");
  f.scenario = (scenario.is_absolute() ? scenario : f.file.parent_path() / scenario).lexically_normal();
  std::error_code ec;
  if (!std::filesystem::is_regular_file(f.scenario, ec))
    top.fail("scenario", "no scenario file at " + f.scenario.string() + " (a relative path starts at the sweep file's folder)");
  f.set = read_set(top);
  if (top.has("grid") == top.has("cases")) top.fail_here("expected either grid: (a cartesian product) or cases: (a list), one of them");
  f.grid = top.has("grid");
  if (f.grid)
    read_grid(top, f);
  else
    read_cases(top, f);
  f.collect = read_collect(top);
  top.reject_unknown_keys();
  return f;
}

}  // namespace gearsim::input

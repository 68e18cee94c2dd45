// The rule for names from input files that become file names (a gear's `<gear>.stl` written by
// `gearsim gears --out DIR`) or parts of log names (a body's state.csv columns, the "a__b" gear
// pair columns of contacts.csv and steps.h5): 1 to 64 characters of A–Z a–z 0–9 _ . -, not
// starting with '.' or '-' — no path separator, no "..", no hidden or option-like name, nothing a
// CSV or a shell would read differently. A body name also holds no "__", which joins the two
// bodies of a gear pair. Names that break the rule are refused, never rewritten. Not for labels:
// a scenario's `name:` is free text (UTF-8, printable, no control characters) that reaches other
// programs only escaped (gnuplot_string, html_escape).
#pragma once

#include <string>
#include <string_view>

#include "input/utf8_text.hpp"
#include "input/yaml_reader.hpp"

namespace gearsim::input {

enum class NameUse { File, Body };

// Longest name, characters: far beyond any gear's or body's name, short enough for any file system.
constexpr std::size_t kMaxNameLength = 64;
// Longest label (a scenario's name), characters: one line of a report title.
constexpr std::size_t kMaxLabelLength = 200;

inline bool is_safe_name(std::string_view name, NameUse use) {
  if (name.empty() || name.size() > kMaxNameLength || name.front() == '.' || name.front() == '-') return false;
  for (char c : name)
    if (!((c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '.' || c == '-')) return false;
  return use == NameUse::File || name.find("__") == std::string_view::npos;
}

inline std::string safe_name_rule(NameUse use) {
  return "a name of 1 to 64 characters A-Z a-z 0-9 _ . - not starting with '.' or '-'" +
         std::string(use == NameUse::Body ? " and without '__' (it joins the bodies of a gear pair)" : "");
}

// The name as a message may quote it: control characters as '?', bytes that are not UTF-8 as
// \xHH, at most 80 bytes.
inline std::string shown_name(std::string_view name) {
  std::string out;
  for (char c : name.substr(0, 80)) out += static_cast<unsigned char>(c) < 0x20 || c == 0x7f ? '?' : c;
  return escaped_bytes(out) + (name.size() > 80 ? "…" : "");
}

// m.fail(key, …) naming the rule unless `name` (read from m[key], or m's key itself) follows it.
inline void require_safe_name(const YamlMap& m, const std::string& key, const std::string& name, NameUse use) {
  if (!is_safe_name(name, use)) m.fail(key, "expected " + safe_name_rule(use) + ", got '" + shown_name(name) + "'");
}

// m.fail(key, …) unless `label` is 1 to kMaxLabelLength bytes of UTF-8 without control characters.
inline void require_label(const YamlMap& m, const std::string& key, const std::string& label) {
  bool ok = !label.empty() && label.size() <= kMaxLabelLength && is_utf8(label);
  for (char c : label) ok = ok && static_cast<unsigned char>(c) >= 0x20 && c != 0x7f;
  if (!ok) m.fail(key, "expected a one-line text of 1 to 200 bytes of UTF-8 without control characters, got '" + shown_name(label) + "'");
}

}  // namespace gearsim::input

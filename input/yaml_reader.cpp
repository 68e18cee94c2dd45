#include "input/yaml_reader.hpp"

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "input/input_limits.hpp"
#include "core/errors.hpp"
#include "core/input_file.hpp"

namespace gearsim::input {

YamlMap::YamlMap(YAML::Node node, std::string path, std::shared_ptr<const std::string> source)
    : node_(std::move(node)), path_(std::move(path)), source_(std::move(source)), read_(std::make_shared<std::set<std::string>>()) {}

namespace {

// Every mapping key below `node` is text and appears once in its mapping; at most
// kMaxYamlValues values are visited (an alias counts each time it is met) and no value lies
// deeper than kMaxYamlDepth — checked on yaml-cpp's tree, where an alias is a shared node, so
// nothing is expanded before it is counted and an alias inside its own anchor (`&r [1, *r]`,
// a cycle) ends at the depth limit instead of the stack.
class KeyCheck {
 public:
  explicit KeyCheck(const std::string& source) : source_(source) {}

  void walk(const YAML::Node& node, const std::string& path, std::size_t depth = 0) {
    if (++visited_ > limits::kMaxYamlValues)
      throw InputError(source_ + ": more than " + std::to_string(limits::kMaxYamlValues) +
                       " values (aliases repeating a list?): not a scenario or gear-set file");
    if (depth > limits::kMaxYamlDepth)
      throw InputError(at(node) + ": " + (path.size() > 48 ? path.substr(0, 48) + "…" : path) + ": nested deeper than " +
                       std::to_string(limits::kMaxYamlDepth) +
                       " levels (an alias inside its own anchor?): not a scenario or gear-set file");
    if (node.IsSequence())
      for (std::size_t i = 0; i < node.size(); ++i) walk(node[i], path + "[" + std::to_string(i) + "]", depth + 1);
    if (!node.IsMap()) return;
    std::map<std::string, int> lines;
    for (const auto& kv : node) {
      if (!kv.first.IsScalar())
        throw InputError(at(kv.first) + ": " + (path.empty() ? "" : path + ": ") + "expected a text key, got a " +
                         (kv.first.IsSequence() ? "list"
                          : kv.first.IsMap()    ? "mapping"
                                                : "null value"));
      const std::string key = kv.first.Scalar();
      const std::string key_path = path.empty() ? key : path + "." + key;
      const auto [first, fresh] = lines.emplace(key, kv.first.Mark().line + 1);
      if (!fresh)
        throw InputError(at(kv.first) + ": " + key_path + ": the key appears twice in one mapping (first at line " +
                         std::to_string(first->second) + "): give it once");
      walk(kv.second, key_path, depth + 1);
    }
  }

 private:
  std::string at(const YAML::Node& n) const {
    const YAML::Mark m = n.Mark();
    return m.line < 0 ? source_ : source_ + ":" + std::to_string(m.line + 1) + ":" + std::to_string(m.column + 1);
  }
  const std::string& source_;
  std::size_t visited_ = 0;
};

}  // namespace

void check_yaml_tree(const YAML::Node& node, const std::string& source_name) { KeyCheck(source_name).walk(node, ""); }

YAML::Node parse_yaml_mapping(const std::string& text, const std::string& source_name) {
  if (text.size() > limits::kMaxYamlBytes)
    throw InputError(source_name + ": " + std::to_string(text.size()) + " bytes: larger than the " + std::to_string(limits::kMaxYamlBytes) +
                     " bytes a scenario or gear-set file may have");
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw InputError(source_name + ":" + std::to_string(e.mark.line + 1) + ":" + std::to_string(e.mark.column + 1) +
                     ": YAML syntax error: " + e.msg);
  }
  if (!root.IsMap()) throw InputError(source_name + ": expected a mapping (key: value) at the top level");
  KeyCheck(source_name).walk(root, "");
  return root;
}

YAML::Node load_yaml_mapping(const std::filesystem::path& path) {
  return parse_yaml_mapping(read_input_file(path, limits::kMaxYamlBytes, "a scenario or gear-set file"), path.string());
}

YamlMap YamlMap::load_file(const std::filesystem::path& path) {
  return YamlMap(load_yaml_mapping(path), "", std::make_shared<const std::string>(path.string()));
}

YamlMap YamlMap::from_string(const std::string& text, const std::string& source_name) {
  return YamlMap(parse_yaml_mapping(text, source_name), "", std::make_shared<const std::string>(source_name));
}

YamlMap YamlMap::from_node(const YAML::Node& root, const std::string& source_name) {
  if (!root.IsMap()) throw InputError(source_name + ": expected a mapping (key: value) at the top level");
  KeyCheck(source_name).walk(root, "");
  return YamlMap(root, "", std::make_shared<const std::string>(source_name));
}

std::string YamlMap::where(const YAML::Node& node) const {
  const YAML::Mark m = node.Mark();
  if (m.line < 0) return *source_;
  return *source_ + ":" + std::to_string(m.line + 1) + ":" + std::to_string(m.column + 1);
}

std::string YamlMap::key_path(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }

std::string YamlMap::location(const std::string& key) const {
  const YAML::Node n = node_[key];
  return where(n.IsDefined() ? n : node_) + ": " + key_path(key);
}

void YamlMap::fail(const std::string& key, const std::string& message) const {
  const YAML::Node n = node_[key];
  throw InputError(where(n.IsDefined() ? n : node_) + ": " + key_path(key) + ": " + message);
}

void YamlMap::fail_here(const std::string& message) const {
  throw InputError(where(node_) + ": " + (path_.empty() ? "" : path_ + ": ") + message);
}

bool YamlMap::has(const std::string& key) const { return node_[key].IsDefined() && !node_[key].IsNull(); }
bool YamlMap::has_map(const std::string& key) const { return node_[key].IsDefined() && node_[key].IsMap(); }

YAML::Node YamlMap::get(const std::string& key) const {
  read_->insert(key);
  const YAML::Node n = node_[key];
  if (!n.IsDefined() || n.IsNull()) fail(key, "missing (required)");
  return n;
}

double YamlMap::number(const std::string& key) const {
  const YAML::Node n = get(key);
  double v = 0;
  if (!n.IsScalar() || !YAML::convert<double>::decode(n, v))
    fail(key, "expected a number, got '" + (n.IsScalar() ? n.Scalar() : std::string("a collection")) + "'");
  if (!std::isfinite(v)) fail(key, "expected a finite number");
  return v;
}

double YamlMap::number_or(const std::string& key, double fallback) const {
  read_->insert(key);
  return has(key) ? number(key) : fallback;
}

std::optional<double> YamlMap::optional_number(const std::string& key) const {
  read_->insert(key);
  if (!has(key)) return std::nullopt;
  return number(key);
}

int YamlMap::integer(const std::string& key) const {
  const YAML::Node n = get(key);
  long long v = 0;
  if (!n.IsScalar() || !YAML::convert<long long>::decode(n, v))
    fail(key, "expected an integer, got '" + (n.IsScalar() ? n.Scalar() : std::string("a collection")) + "'");
  if (v < -2147483647LL || v > 2147483647LL) fail(key, "integer out of range");
  return static_cast<int>(v);
}

int YamlMap::integer_or(const std::string& key, int fallback) const {
  read_->insert(key);
  return has(key) ? integer(key) : fallback;
}

std::vector<double> YamlMap::numbers(const std::string& key, std::size_t count) const {
  const YAML::Node n = get(key);
  const std::string expected = count ? "a list of " + std::to_string(count) + " numbers" : "a list of numbers";
  if (!n.IsSequence() || (count && n.size() != count)) fail(key, "expected " + expected);
  std::vector<double> out;
  for (const YAML::Node& item : n) {
    double v = 0;
    if (!item.IsScalar() || !YAML::convert<double>::decode(item, v) || !std::isfinite(v))
      fail(key, "expected " + expected + " (finite), got an item that is not a number");
    out.push_back(v);
  }
  return out;
}

std::vector<std::string> YamlMap::strings(const std::string& key, std::size_t count) const {
  const YAML::Node n = get(key);
  const std::string expected = count ? "a list of " + std::to_string(count) + " names" : "a list of names";
  if (!n.IsSequence() || (count && n.size() != count)) fail(key, "expected " + expected);
  std::vector<std::string> out;
  for (const YAML::Node& item : n) {
    if (!item.IsScalar()) fail(key, "expected " + expected + ", got an item that is not a text value");
    out.push_back(item.Scalar());
  }
  return out;
}

std::string YamlMap::string(const std::string& key) const {
  const YAML::Node n = get(key);
  if (!n.IsScalar()) fail(key, "expected a text value");
  return n.Scalar();
}

std::string YamlMap::string_or(const std::string& key, const std::string& fallback) const {
  read_->insert(key);
  return has(key) ? string(key) : fallback;
}

bool YamlMap::boolean_or(const std::string& key, bool fallback) const {
  read_->insert(key);
  if (!has(key)) return fallback;
  const YAML::Node n = get(key);
  bool v = false;
  if (!n.IsScalar() || !YAML::convert<bool>::decode(n, v)) fail(key, "expected true or false");
  return v;
}

std::string YamlMap::choice(const std::string& key, const std::vector<std::string>& choices) const {
  const std::string v = string(key);
  for (const std::string& c : choices)
    if (c == v) return v;
  std::string list;
  for (const std::string& c : choices) list += (list.empty() ? "" : ", ") + c;
  fail(key, "expected one of {" + list + "}, got '" + v + "'");
}

std::string YamlMap::choice_or(const std::string& key, const std::vector<std::string>& choices, const std::string& fallback) const {
  read_->insert(key);
  return has(key) ? choice(key, choices) : fallback;
}

YamlMap YamlMap::map(const std::string& key) const {
  const YAML::Node n = get(key);
  if (!n.IsMap()) fail(key, "expected a mapping (key: value pairs)");
  return YamlMap(n, key_path(key), source_);
}

std::vector<YamlMap> YamlMap::list_of_maps(const std::string& key) const {
  const YAML::Node n = get(key);
  if (!n.IsSequence()) fail(key, "expected a list");
  std::vector<YamlMap> out;
  for (std::size_t i = 0; i < n.size(); ++i) {
    const std::string p = key_path(key) + "[" + std::to_string(i) + "]";
    if (!n[i].IsMap()) throw InputError(where(n[i]) + ": " + p + ": expected a mapping");
    out.push_back(YamlMap(n[i], p, source_));
  }
  return out;
}

std::vector<std::string> YamlMap::keys() const {
  std::vector<std::string> out;
  for (const auto& kv : node_) out.push_back(kv.first.Scalar());  // text keys: checked when parsed
  return out;
}

std::vector<std::pair<std::string, YamlMap>> YamlMap::entries() const {
  std::vector<std::pair<std::string, YamlMap>> out;
  for (const std::string& k : keys()) out.emplace_back(k, map(k));
  return out;
}

void YamlMap::reject_unknown_keys() const {
  for (const auto& kv : node_) {
    const std::string k = kv.first.Scalar();
    if (!read_->count(k)) throw InputError(where(kv.first) + ": " + key_path(k) + ": unknown key");
  }
}

}  // namespace gearsim::input

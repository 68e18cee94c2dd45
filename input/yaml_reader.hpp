// A strict reader over yaml-cpp: typed getters whose errors name the file, line, column and key
// path, and a check that every key of a mapping was read (unknown keys are errors). Used by every
// file format of the app (gear-set specs, scenarios). Not a schema language.
#pragma once

#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace gearsim::input {

// Parses YAML text whose top level is a mapping, named `source_name` in errors. InputError with
// file:line:column when the text is larger than limits::kMaxYamlBytes, is not valid YAML, or
// holds more than limits::kMaxYamlValues values (aliases included), a mapping key that is not
// text (`[a]: 1`), or a key twice in one mapping (yaml-cpp would keep the first silently).
YAML::Node parse_yaml_mapping(const std::string& text, const std::string& source_name);
// The checks parse_yaml_mapping() makes of a parsed tree, for a value parsed elsewhere (a --set
// value): text keys, each once per mapping, at most limits::kMaxYamlValues values and
// limits::kMaxYamlDepth levels (aliases counted where they are met, never expanded first).
// InputError naming `source_name` and the key path otherwise.
void check_yaml_tree(const YAML::Node& node, const std::string& source_name);
// The same for a file: InputError naming it when it cannot be read or is too large.
YAML::Node load_yaml_mapping(const std::filesystem::path& path);

class YamlMap {
 public:
  // Loads a file whose top level is a mapping. Throws InputError naming the file on I/O or
  // syntax errors (with yaml-cpp's line and column).
  static YamlMap load_file(const std::filesystem::path& path);
  static YamlMap from_string(const std::string& text, const std::string& source_name);
  // Wraps an already parsed tree (e.g. edited by command-line overrides); its nodes keep the
  // marks they were parsed with, nodes built in code have none (errors then name the file only).
  static YamlMap from_node(const YAML::Node& root, const std::string& source_name);

  bool has(const std::string& key) const;
  bool has_map(const std::string& key) const;  // holds a mapping (not a scalar or list)
  double number(const std::string& key) const;
  double number_or(const std::string& key, double fallback) const;
  std::optional<double> optional_number(const std::string& key) const;
  int integer(const std::string& key) const;
  int integer_or(const std::string& key, int fallback) const;
  // A list of numbers, e.g. a vector [x, y, z]; `count` > 0 demands exactly that many.
  std::vector<double> numbers(const std::string& key, std::size_t count = 0) const;
  // A list of text values, e.g. names [sun, planet]; `count` > 0 demands exactly that many.
  std::vector<std::string> strings(const std::string& key, std::size_t count = 0) const;
  std::string string(const std::string& key) const;
  std::string string_or(const std::string& key, const std::string& fallback) const;
  bool boolean_or(const std::string& key, bool fallback) const;
  // A string that must be one of `choices`.
  std::string choice(const std::string& key, const std::vector<std::string>& choices) const;
  std::string choice_or(const std::string& key, const std::vector<std::string>& choices, const std::string& fallback) const;
  YamlMap map(const std::string& key) const;
  std::vector<YamlMap> list_of_maps(const std::string& key) const;
  // Mapping entries in file order, each as (key, map).
  std::vector<std::pair<std::string, YamlMap>> entries() const;
  std::vector<std::string> keys() const;

  // Throws InputError for the first key that no getter asked for.
  void reject_unknown_keys() const;
  // "file:line:col: key.path" of m[key] (of this mapping when the key is absent), for messages
  // about the key raised later, away from the reader.
  std::string location(const std::string& key) const;
  // Throws InputError "file:line:col: key.path: message".
  [[noreturn]] void fail(const std::string& key, const std::string& message) const;
  [[noreturn]] void fail_here(const std::string& message) const;

  const std::string& source() const { return *source_; }
  const std::string& path() const { return path_; }

 private:
  YamlMap(YAML::Node node, std::string path, std::shared_ptr<const std::string> source);
  YAML::Node get(const std::string& key) const;  // marks as read; fails when missing
  std::string where(const YAML::Node& node) const;
  std::string key_path(const std::string& key) const;

  YAML::Node node_;
  std::string path_;  // dotted key path of this mapping ("" at top level)
  std::shared_ptr<const std::string> source_;
  std::shared_ptr<std::set<std::string>> read_;
};

}  // namespace gearsim::input

// record::Node: one JSON object of a run record (scenario.json) with its key path, for the
// record reader's messages ("FILE: key bodies[2].gear.teeth: expected a finite number"): typed
// getters that refuse what the record cannot hold (a missing key, a string for a number, a
// value outside an input limit). Not a schema and not a writer: input/scenario_record.cpp reads
// the record through it.
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "input/input_limits.hpp"

namespace gearsim::input::record {

// A JSON object of the record with its key path, for messages: "FILE: key bodies[2].gear.teeth: …".
class Node {
  using json = nlohmann::json;

 public:
  Node(const json& j, std::string path, const std::filesystem::path& file) : j_(j), path_(std::move(path)), file_(file) {}
  [[noreturn]] void fail(const std::string& key, const std::string& what) const {
    throw InputError(file_.string() + ": key " + where(key) + ": " + what);
  }
  bool has(const std::string& key) const { return j_.is_object() && j_.contains(key) && !j_.at(key).is_null(); }
  const json& at(const std::string& key) const {
    if (!j_.is_object()) throw InputError(file_.string() + ": key " + path_ + ": expected an object");
    if (!j_.contains(key)) fail(key, "missing");
    return j_.at(key);
  }
  double number(const std::string& key) const {
    const json& v = at(key);
    if (!v.is_number() || !std::isfinite(v.get<double>())) fail(key, "expected a finite number");
    return v.get<double>();
  }
  double number_within(const std::string& key, const Limit& limit) const {
    const double v = number(key);
    if (!within(v, limit)) fail(key, limit_message(limit, v));
    return v;
  }
  int integer(const std::string& key, const Limit& limit) const {
    const double v = number_within(key, limit);
    if (v != std::floor(v)) fail(key, "expected a whole number");
    return static_cast<int>(v);
  }
  bool boolean(const std::string& key) const {
    if (!at(key).is_boolean()) fail(key, "expected true or false");
    return at(key).get<bool>();
  }
  std::string string(const std::string& key) const {
    if (!at(key).is_string()) fail(key, "expected a string");
    return at(key).get<std::string>();
  }
  std::vector<double> numbers(const std::string& key, std::size_t n = 0) const {
    const json& v = at(key);
    if (!v.is_array() || (n && v.size() != n)) fail(key, n ? "expected " + std::to_string(n) + " numbers" : "expected a list of numbers");
    std::vector<double> out;
    for (const json& x : v) {
      if (!x.is_number() || !std::isfinite(x.get<double>())) fail(key, "expected finite numbers");
      out.push_back(x.get<double>());
    }
    return out;
  }
  Eigen::Vector3d vec3(const std::string& key) const {
    const std::vector<double> v = numbers(key, 3);
    return {v[0], v[1], v[2]};
  }
  Eigen::Vector3d vec3_within(const std::string& key, const Limit& limit) const {
    const Eigen::Vector3d v = vec3(key);
    for (int i = 0; i < 3; ++i)
      if (!within(v[i], limit)) fail(key, std::string(1, "xyz"[i]) + ": " + limit_message(limit, v[i]));
    return v;
  }
  Node object(const std::string& key) const {
    if (!at(key).is_object()) fail(key, "expected an object");
    return Node(at(key), where(key), file_);
  }
  std::vector<Node> list(const std::string& key) const {
    const json& v = at(key);
    if (!v.is_array()) fail(key, "expected a list");
    std::vector<Node> out;
    for (std::size_t i = 0; i < v.size(); ++i) out.emplace_back(v[i], where(key) + "[" + std::to_string(i) + "]", file_);
    return out;
  }
  const std::filesystem::path& file() const { return file_; }

 private:
  std::string where(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }
  const json& j_;
  std::string path_;
  const std::filesystem::path& file_;
};

}  // namespace gearsim::input::record

#include "input/input_limits.hpp"

#include <cmath>
#include <numbers>
#include <sstream>

#include "core/errors.hpp"

namespace gearsim::input {
namespace {

// "(0, 10000] s"
std::string interval(const Limit& limit) {
  std::ostringstream s;
  s << (limit.min_open ? "(" : "[") << limit.min << ", " << limit.max << (limit.max_open ? ")" : "]") << (*limit.unit ? " " : "")
    << limit.unit;
  return s.str();
}

}  // namespace

bool within(double value, const Limit& limit) {
  if (!std::isfinite(value)) return false;
  return (limit.min_open ? value > limit.min : value >= limit.min) && (limit.max_open ? value < limit.max : value <= limit.max);
}

std::string limit_message(const Limit& limit, double value) {
  std::ostringstream s;
  s << "expected " << limit.what << " in " << interval(limit) << ", got " << value;
  return s.str();
}

void require_within(const std::string& name, double value, const Limit& limit) {
  if (!within(value, limit)) throw InputError(name + ": " + limit_message(limit, value));
}

Limit limit_in_degrees(const Limit& limit_rad) {
  constexpr double kDegPerRad = 180 / std::numbers::pi;
  return {limit_rad.min * kDegPerRad, limit_rad.max * kDegPerRad, limit_rad.min_open, "°", limit_rad.what, limit_rad.max_open};
}

double number_within(const YamlMap& m, const std::string& key, const Limit& limit) {
  const double v = m.number(key);
  if (!within(v, limit)) m.fail(key, limit_message(limit, v));
  return v;
}

double number_within_or(const YamlMap& m, const std::string& key, double fallback, const Limit& limit) {
  return m.has(key) ? number_within(m, key, limit) : m.number_or(key, fallback);
}

int integer_within(const YamlMap& m, const std::string& key, const Limit& limit) {
  const int v = m.integer(key);
  if (!within(v, limit)) m.fail(key, limit_message(limit, v));
  return v;
}

int integer_within_or(const YamlMap& m, const std::string& key, int fallback, const Limit& limit) {
  return m.has(key) ? integer_within(m, key, limit) : m.integer_or(key, fallback);
}

CLI::Validator cli_within(const Limit& limit) {
  return CLI::Validator(
      [limit](std::string& text) -> std::string {
        double v = 0;
        std::size_t used = 0;
        try {
          v = std::stod(text, &used);
        } catch (const std::exception&) {
          return "expected a number, got '" + text + "'";
        }
        if (used != text.size()) return "expected a number, got '" + text + "'";
        return within(v, limit) ? std::string() : limit_message(limit, v);
      },
      interval(limit));
}

}  // namespace gearsim::input

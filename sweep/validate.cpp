#include "sweep/validate.hpp"

#include <algorithm>
#include <cstdlib>
#include <map>
#include <optional>
#include <set>

#include "core/errors.hpp"
#include "input/scenario_file.hpp"

namespace gearsim::sweep {
namespace {

// The value as a number when it reads as one (override texts of numbers are in to_chars form).
std::optional<double> as_number(const std::string& text) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  return !text.empty() && end == text.c_str() + text.size() ? std::optional(v) : std::nullopt;
}

// "k=v, k2=v2" of the case's parameters, for messages.
std::string parameter_list(const Case& c) {
  std::string s;
  for (const auto& [key, value] : c.parameters)
    if (!value.empty()) s += (s.empty() ? "" : ", ") + key + "=" + value;
  return s.empty() ? "the scenario's own values" : s;
}

// Where the error points in the sweep file: the parameter whose override the scenario's message
// blames (load_scenario adds "(set by --set 'key=value')"), else the case itself.
std::string blamed_place(const input::SweepFile& f, const std::string& message, std::size_t index) {
  for (const input::SweepParameter& p : f.parameters)
    if (message.find("--set '" + p.key + "=") != std::string::npos) return p.where;
  if (message.find("--set '") != std::string::npos)
    for (const std::string& s : f.set)
      if (message.find("--set '" + s) != std::string::npos) return f.file.string() + ": set";
  return f.grid ? f.file.string() : f.cases[index].where;
}

}  // namespace

std::vector<std::size_t> cases_to_validate(const input::SweepFile& f, const std::vector<Case>& cases) {
  std::set<std::size_t> chosen;
  if (!cases.empty()) chosen.insert(0);
  for (std::size_t k = 0; k < f.parameters.size(); ++k) {
    // The first case of each value, in case order; and the extremes of the numeric ones.
    std::map<std::string, std::size_t> first_of;
    std::optional<std::pair<double, std::size_t>> low, high;
    std::optional<std::size_t> last;
    for (const Case& c : cases) {
      const std::string& v = c.parameters[k].second;
      if (v.empty()) continue;
      first_of.emplace(v, c.index);
      last = c.index;
      if (const auto x = as_number(v)) {
        if (!low || *x < low->first) low = std::pair(*x, c.index);
        if (!high || *x > high->first) high = std::pair(*x, c.index);
      }
    }
    if (first_of.size() <= kMaxValuesLoaded) {
      for (const auto& [value, index] : first_of) chosen.insert(index);
      continue;
    }
    for (const auto& e : {low, high})
      if (e) chosen.insert(e->second);
    if (last) chosen.insert(*last);
    chosen.insert(
        std::min_element(first_of.begin(), first_of.end(), [](const auto& a, const auto& b) { return a.second < b.second; })->second);
  }
  return {chosen.begin(), chosen.end()};
}

void validate_cases(const input::SweepFile& f, const std::vector<Case>& cases) {
  for (const std::size_t i : cases_to_validate(f, cases)) try {
      input::load_scenario(f.scenario, cases[i].overrides);
    } catch (const InputError& e) {
      const std::string message = e.what();
      throw InputError(blamed_place(f, message, i) + ": case " + std::to_string(i) + " (" + parameter_list(cases[i]) +
                       "): the base scenario refuses it: " + message);
    }
}

}  // namespace gearsim::sweep

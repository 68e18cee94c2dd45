#include "sweep/case_list.hpp"

#include <cstdio>

namespace gearsim::sweep {
namespace {

// Case i of a grid: mixed-radix digits of i, the last key fastest.
Case grid_case(const input::SweepFile& f, std::size_t i) {
  Case c;
  c.index = i;
  c.overrides = f.set;
  c.parameters.resize(f.parameters.size());
  std::size_t rest = i;
  for (std::size_t k = f.parameters.size(); k-- > 0;) {
    const input::SweepParameter& p = f.parameters[k];
    c.parameters[k] = {p.key, p.values[rest % p.values.size()]};
    rest /= p.values.size();
  }
  for (const auto& [key, value] : c.parameters) c.overrides.push_back(key + "=" + value);
  return c;
}

// Case i of a list: its own values, "" for the columns it leaves at the scenario's value.
Case listed_case(const input::SweepFile& f, std::size_t i) {
  Case c;
  c.index = i;
  c.overrides = f.set;
  for (const input::SweepParameter& p : f.parameters) {
    std::string value;
    for (const auto& [key, v] : f.cases[i].values)
      if (key == p.key) value = v;
    c.parameters.emplace_back(p.key, value);
  }
  for (const auto& [key, value] : f.cases[i].values) c.overrides.push_back(key + "=" + value);
  return c;
}

}  // namespace

std::vector<Case> expand_cases(const input::SweepFile& f) {
  std::vector<Case> cases;
  cases.reserve(f.case_count);
  for (std::size_t i = 0; i < f.case_count; ++i) cases.push_back(f.grid ? grid_case(f, i) : listed_case(f, i));
  return cases;
}

std::string case_folder_name(std::size_t index) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%05zu", index);
  return buf;
}

}  // namespace gearsim::sweep

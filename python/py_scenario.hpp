// gearsim.Scenario: a scenario file loaded with its overrides (input::load_scenario, the CLI's
// --set), kept with the path and the override list it came from so that a run records them as the
// CLI does and `set` can load it again with one more. Not a second scenario model: the value is
// the physics::Scenario every other part of gearsim reads.
#pragma once

#include <pybind11/pybind11.h>

#include <filesystem>
#include <string>
#include <vector>

#include "physics/scenario.hpp"

namespace gearsim::python {

namespace py = pybind11;

struct PyScenario {
  std::filesystem::path file;  // the scenario file as given
  std::vector<std::string> overrides;  // key.path=value, in the order applied
  physics::Scenario scenario;  // expanded, validated, SI
};

// Overrides from Python: a dict {"key.path": value, …} (values: numbers, strings, bools, lists)
// or a list of "key.path=value" strings. TypeError otherwise.
std::vector<std::string> override_list(py::handle overrides);

// "key.path=value" with the value as YAML text: a str as it is, anything else as JSON (which
// YAML reads as the same flow value; floats with every digit).
std::string override_text(const std::string& key, py::handle value);

// input::load_scenario(path, overrides); InputError (gearsim.InputError) on bad input.
PyScenario load(const std::filesystem::path& file, const std::vector<std::string>& overrides);

// Binds gearsim.Scenario and gearsim.load_scenario.
void bind_scenario(py::module_& m);

}  // namespace gearsim::python

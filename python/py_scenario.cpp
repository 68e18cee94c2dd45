#include "python/py_scenario.hpp"

#include <yaml-cpp/yaml.h>

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "input/scenario_file.hpp"
#include "input/scenario_record.hpp"
#include "python/py_json.hpp"

namespace gearsim::python {
namespace {

void emit_yaml(YAML::Emitter& out, const nlohmann::json& j) {
  if (j.is_object()) {
    out << YAML::BeginMap;
    for (const auto& [k, v] : j.items()) {
      out << YAML::Key << k << YAML::Value;
      emit_yaml(out, v);
    }
    out << YAML::EndMap;
  } else if (j.is_array()) {
    out << YAML::BeginSeq;
    for (const nlohmann::json& v : j) emit_yaml(out, v);
    out << YAML::EndSeq;
  } else if (j.is_string()) {
    out << YAML::DoubleQuoted << j.get<std::string>();
  } else if (j.is_boolean()) {
    out << j.get<bool>();
  } else if (j.is_number_integer()) {
    out << j.get<std::int64_t>();
  } else if (j.is_number()) {
    out << j.get<double>();
  } else {
    out << YAML::Null;
  }
}

// The scenario record as block YAML, doubles to 17 significant digits (they read back exactly).
std::string yaml_text(const nlohmann::json& j) {
  YAML::Emitter out;
  out.SetDoublePrecision(17);
  emit_yaml(out, j);
  return std::string(out.c_str()) + "\n";
}

}  // namespace

std::string override_text(const std::string& key, py::handle value) {
  if (py::isinstance<py::str>(value)) return key + "=" + value.cast<std::string>();
  return key + "=" + from_python(value).dump();
}

std::vector<std::string> override_list(py::handle overrides) {
  std::vector<std::string> list;
  if (overrides.is_none()) return list;
  if (py::isinstance<py::dict>(overrides)) {
    for (auto item : overrides.cast<py::dict>()) {
      if (!py::isinstance<py::str>(item.first)) throw py::type_error("gearsim: an override's key must be a str (\"key.path\")");
      list.push_back(override_text(item.first.cast<std::string>(), item.second));
    }
    return list;
  }
  if (py::isinstance<py::str>(overrides))
    throw py::type_error("gearsim: overrides must be a dict {\"key.path\": value} or a list of \"key.path=value\"");
  for (py::handle item : overrides) {
    if (!py::isinstance<py::str>(item)) throw py::type_error("gearsim: a list of overrides holds \"key.path=value\" strings");
    list.push_back(item.cast<std::string>());
  }
  return list;
}

PyScenario load(const std::filesystem::path& file, const std::vector<std::string>& overrides) {
  return PyScenario{file, overrides, input::load_scenario(file, overrides)};
}

namespace {

constexpr const char* kLoadDoc = R"(Load a scenario file (YAML) with overrides.

overrides: a dict {"key.path": value} (e.g. {"solver.time_step_s": 1e-5, "duration_s": 0.2})
or a list of "key.path=value" strings, applied in order as the CLI's --set. Raises
gearsim.InputError (a ValueError) naming file:line:col and key for bad input.)";

constexpr const char* kSetDoc = R"(Load the scenario again with one more override key.path=value;
returns the scenario itself. gearsim.InputError when the value is refused (the scenario is then
left as it was).)";

}  // namespace

void bind_scenario(py::module_& m) {
  py::class_<PyScenario>(m, "Scenario",
                         "A loaded, expanded and validated scenario (physics::Scenario) with its "
                         "source file and overrides.")
      .def_property_readonly(
          "path", [](const PyScenario& s) { return s.file.string(); }, "The scenario file as given.")
      .def_property_readonly(
          "overrides", [](const PyScenario& s) { return s.overrides; }, "The key.path=value overrides, in order.")
      .def_property_readonly("name", [](const PyScenario& s) { return s.scenario.name; })
      .def_property_readonly("duration_s", [](const PyScenario& s) { return s.scenario.duration_s; })
      .def_property_readonly("time_step_s", [](const PyScenario& s) { return s.scenario.solver.time_step_s; })
      .def_property_readonly("sample_rate_hz", [](const PyScenario& s) { return s.scenario.output.sample_rate_hz; })
      .def(
          "to_dict", [](const PyScenario& s) { return to_python(input::scenario_json(s.scenario)); },
          "The expanded scenario as a dict (the run folder's scenario.json).")
      .def(
          "__str__", [](const PyScenario& s) { return yaml_text(input::scenario_json(s.scenario)); },
          "The expanded scenario as YAML (the content of scenario.json; numbers to 17 digits).")
      .def("__repr__",
           [](const PyScenario& s) {
             return "<gearsim.Scenario '" + s.scenario.name + "' from " + s.file.string() + ", " + std::to_string(s.overrides.size()) +
                    " overrides>";
           })
      .def(
          "set",
          [](PyScenario& s, const std::string& key, py::object value) -> PyScenario& {
            std::vector<std::string> overrides = s.overrides;
            overrides.push_back(override_text(key, value));
            s = load(s.file, overrides);
            return s;
          },
          py::arg("key"), py::arg("value"), kSetDoc, py::return_value_policy::reference);
  m.def(
      "load_scenario", [](const std::filesystem::path& path, py::object overrides) { return load(path, override_list(overrides)); },
      py::arg("path"), py::arg("overrides") = py::none(), kLoadDoc);
}

}  // namespace gearsim::python

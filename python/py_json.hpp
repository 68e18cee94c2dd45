// nlohmann::json ↔ Python objects for the gearsim module: the analysis, summary and modes
// dictionaries come from the same JSON the CLI writes, converted value by value (objects → dict
// in their order, arrays → list, numbers → int/float, non-finite floats → None as the JSON
// files hold them). The reverse turns an override's Python value into JSON text (a YAML flow value).
#pragma once

#include <pybind11/pybind11.h>

#include <cmath>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>

namespace gearsim::python {

namespace py = pybind11;

// One JSON value (ordered or not) as the Python object json.loads would give for its file.
template <class Json>
py::object to_python(const Json& j) {
  using T = nlohmann::json::value_t;
  switch (j.type()) {
    case T::null:
      return py::none();
    case T::boolean:
      return py::bool_(j.template get<bool>());
    case T::number_integer:
      return py::int_(j.template get<std::int64_t>());
    case T::number_unsigned:
      return py::int_(j.template get<std::uint64_t>());
    case T::number_float: {
      const double v = j.template get<double>();
      return std::isfinite(v) ? py::object(py::float_(v)) : py::object(py::none());
    }
    case T::string:
      return py::str(j.template get_ref<const std::string&>());
    case T::array: {
      py::list list;
      for (const auto& item : j) list.append(to_python(item));
      return list;
    }
    case T::object: {
      py::dict dict;
      for (auto it = j.begin(); it != j.end(); ++it) dict[py::str(it.key())] = to_python(it.value());
      return dict;
    }
    default:
      throw py::type_error("gearsim: a JSON value of a kind Python has no type for (binary or discarded)");
  }
}

// A Python value (None, bool, int, float, str, list/tuple, dict) as JSON; TypeError otherwise.
nlohmann::json from_python(py::handle value);

}  // namespace gearsim::python

#include "python/py_json.hpp"

namespace gearsim::python {

nlohmann::json from_python(py::handle value) {
  if (value.is_none()) return nullptr;
  if (py::isinstance<py::bool_>(value)) return value.cast<bool>();  // before int: bool is an int
  if (py::isinstance<py::int_>(value)) return value.cast<std::int64_t>();
  if (py::isinstance<py::float_>(value)) return value.cast<double>();
  if (py::isinstance<py::str>(value)) return value.cast<std::string>();
  if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
    nlohmann::json list = nlohmann::json::array();
    for (py::handle item : value) list.push_back(from_python(item));
    return list;
  }
  if (py::isinstance<py::dict>(value)) {
    nlohmann::json object = nlohmann::json::object();
    for (auto item : value.cast<py::dict>()) object[py::str(item.first).cast<std::string>()] = from_python(item.second);
    return object;
  }
  // numpy scalars and other numbers: by their float value
  if (py::hasattr(value, "__float__")) return value.attr("__float__")().cast<double>();
  throw py::type_error("gearsim: cannot use a value of type " + py::str(py::type::of(value)).cast<std::string>() +
                       " in a scenario (expected None, bool, int, float, str, list or dict)");
}

}  // namespace gearsim::python

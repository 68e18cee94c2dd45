// A Python exception raised by a signal handler (KeyboardInterrupt for Ctrl-C) while C++ code ran
// with the GIL released, held until that code has stopped cleanly and then raised. Fetch and
// raise with the GIL held.
#pragma once

#include <pybind11/pybind11.h>

namespace gearsim::python {

namespace py = pybind11;

struct PendingError {
  PyObject *type = nullptr, *value = nullptr, *trace = nullptr;
  bool set() const { return type != nullptr; }
  // Runs Python's signal handlers; true when one raised (the exception is then held here).
  bool check_signals() {
    if (PyErr_CheckSignals() == 0) return false;
    PyErr_Fetch(&type, &value, &trace);
    return true;
  }
  [[noreturn]] void raise() {
    PyErr_Restore(type, value, trace);
    type = value = trace = nullptr;
    throw py::error_already_set();
  }
  PendingError() = default;
  PendingError(const PendingError&) = delete;
  PendingError& operator=(const PendingError&) = delete;
  ~PendingError() {
    Py_XDECREF(type);
    Py_XDECREF(value);
    Py_XDECREF(trace);
  }
};

}  // namespace gearsim::python

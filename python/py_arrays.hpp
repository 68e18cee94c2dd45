// numpy arrays from C++ vectors for the gearsim module: copies, owned by Python.
#pragma once

#include <pybind11/numpy.h>

#include <cstring>
#include <vector>

namespace gearsim::python {

namespace py = pybind11;

// A 1-D array holding a copy of v.
template <class T>
py::array_t<T> numpy_copy(const std::vector<T>& v) {
  py::array_t<T> a(static_cast<py::ssize_t>(v.size()));
  if (!v.empty()) std::memcpy(a.mutable_data(), v.data(), v.size() * sizeof(T));
  return a;
}

}  // namespace gearsim::python

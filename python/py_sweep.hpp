// gearsim.sweep: a parameter sweep run by the sweep/ library as `gearsim sweep` runs it (each case
// a `gearsim run` child process of the gearsim binary, on local processes), its table returned as
// numpy arrays. The sweep runs on a C++ thread with the GIL released; the calling thread waits,
// running Python's signal handlers every kSweepPollMs, and a KeyboardInterrupt stops the sweep as
// the CLI's SIGINT does (running cases get SIGINT and are recorded interrupted: a resumable sweep).
#pragma once

#include <pybind11/pybind11.h>

namespace gearsim::python {

namespace py = pybind11;

// How often, ms, the waiting thread runs Python's signal handlers (sweep/process.hpp polls a
// child's stop request every 20 ms).
inline constexpr int kSweepPollMs = 50;

// Binds gearsim.sweep and gearsim.SweepCasesFailed.
void bind_sweep(py::module_& m);

}  // namespace gearsim::python

// gearsim.run: a scenario run through the CLI's own code path (app/run_scenario.hpp: the same
// observers, the same files), its logs read back into numpy arrays at full precision. With
// out=None the files go to a private temporary folder that is removed afterwards. The GIL is
// released while sim::simulate steps; every kPollSteps steps it is taken back briefly to let
// Python run its signal handlers, so that Ctrl-C stops the run between two steps (status
// interrupted, logs flushed) and raises KeyboardInterrupt once the run has stopped.
#pragma once

#include <pybind11/pybind11.h>

#include <optional>

namespace gearsim::python {

namespace py = pybind11;

struct PyScenario;

struct PyRunResult {
  py::dict state;  // state.csv: column name → numpy float64 array
  py::dict contacts;  // contacts.csv
  py::dict sensors;  // sensors.csv (empty without sensors)
  py::dict steps;  // steps.h5's contacts, one entry per tooth-pair contact per step (empty without the log)
  py::dict summary;  // summary.json
  py::object out;  // the run folder (str), or None when the files were temporary
};

// Steps between two checks for Python's signals (SIGINT): ~10 ms of the paper set's stepping.
inline constexpr long kPollSteps = 200;

PyRunResult run(const PyScenario& scenario, py::object out, std::optional<double> duration_s, bool progress);

// A CSV log as {column: numpy float64 array}; the CSV holds %.17g, so every value is the double
// the run computed. Empty when the file does not exist.
py::dict read_csv_columns(const std::filesystem::path& file);

// Binds gearsim.RunResult and gearsim.run.
void bind_run(py::module_& m);

}  // namespace gearsim::python

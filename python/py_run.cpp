#include "python/py_run.hpp"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>

#include "app/run_scenario.hpp"
#include "core/errors.hpp"
#include "input/csv_table.hpp"
#include "input/input_limits.hpp"
#include "python/py_json.hpp"
#include "python/py_pending.hpp"
#include "python/py_scenario.hpp"
#include "sim/step_log_reader.hpp"

namespace gearsim::python {
namespace {

namespace fs = std::filesystem;

// A private folder under the system's temporary directory, removed with everything in it when
// the run is done (or failed).
class TempDir {
 public:
  TempDir() {
    std::string pattern = (fs::temp_directory_path() / "gearsim-py-XXXXXX").string();
    if (!mkdtemp(pattern.data())) throw std::runtime_error("gearsim: cannot create a temporary folder in " + pattern);
    path_ = pattern;
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

}  // namespace

py::dict read_csv_columns(const fs::path& file) {
  py::dict columns;
  if (!fs::exists(file)) return columns;
  const input::CsvTable table = input::read_csv(file);
  for (std::size_t c = 0; c < table.columns.size(); ++c) {
    const std::vector<double>& v = table.data[c];
    py::array_t<double> a(static_cast<py::ssize_t>(v.size()));
    if (!v.empty()) std::memcpy(a.mutable_data(), v.data(), v.size() * sizeof(double));
    columns[py::str(table.columns[c])] = a;
  }
  return columns;
}

namespace {

template <class T>
py::array_t<T> array_of(const std::vector<T>& v) {
  py::array_t<T> a(static_cast<py::ssize_t>(v.size()));
  if (!v.empty()) std::memcpy(a.mutable_data(), v.data(), v.size() * sizeof(T));
  return a;
}

// steps.h5's contact rows as {column: numpy array} (sim/step_log_reader.hpp: the columns the
// analysis reads), with the pair names and the time step. Empty when the run kept no step log.
py::dict read_step_contacts(const fs::path& file) {
  py::dict d;
  if (!fs::exists(file)) return d;
  const sim::StepLogContacts c = sim::read_step_log_contacts(file);
  d["time_step_s"] = c.time_step_s;
  d["pairs"] = c.pairs;
  d["time_s"] = array_of(c.time_s);
  d["step"] = array_of(c.step);
  d["pair"] = array_of(c.pair);
  d["tooth_a"] = array_of(c.tooth_a);
  d["tooth_b"] = array_of(c.tooth_b);
  d["flank_a"] = array_of(c.flank_a);
  d["normal_impulse_N_s"] = array_of(c.normal_impulse_N_s);
  return d;
}

// The options simulate polls: every kPollSteps steps the GIL is taken to run Python's signal
// handlers; an exception they raise stops the run (as SIGINT) and is kept in `pending`.
sim::SimOptions poll_options(PendingError& pending, bool progress, const std::string& name) {
  sim::SimOptions o;
  o.stop_requested = [&pending, calls = 0L]() mutable {
    if (pending.set()) return SIGINT;
    if (++calls % kPollSteps != 0) return 0;
    py::gil_scoped_acquire gil;
    return pending.check_signals() ? SIGINT : 0;
  };
  if (progress)
    o.progress = [name, last = -1](long i, long total, double t) mutable {
      const int percent = static_cast<int>(100 * i / total);
      if (percent == last) return;
      last = percent;
      py::gil_scoped_acquire gil;
      py::print("\r  " + name + ": " + std::to_string(percent) + "% (t = " + std::to_string(t) + " s)",
                py::arg("end") = percent == 100 ? "\n" : "", py::arg("file") = py::module_::import("sys").attr("stderr"),
                py::arg("flush") = true);
    };
  return o;
}

}  // namespace

PyRunResult run(const PyScenario& scenario, py::object out, std::optional<double> duration_s, bool progress) {
  physics::Scenario s = scenario.scenario;
  if (duration_s) {
    input::require_within("duration", *duration_s, input::limits::kDuration_s);  // the CLI's --duration check
    app::set_duration(s, *duration_s);
  }
  std::optional<TempDir> temp;
  const fs::path dir = out.is_none() ? temp.emplace().path() : fs::path(py::module_::import("os").attr("fspath")(out).cast<std::string>());
  // Held as the CLI holds it: locked, the previous run's outputs (its manifest's) removed.
  app::OutputFolder folder(dir, "gearsim.run (Python)", app::OutputFolder::ForNewRun{});
  PendingError pending;
  const sim::SimOptions options = poll_options(pending, progress, s.name);
  app::DirRun r;
  {
    py::gil_scoped_release released;
    r = app::run_into_dir(s, app::RunSource{scenario.file, scenario.overrides}, folder, options);
  }
  if (pending.set()) pending.raise();
  // A log that could not be written (a full disk): gearsim.OutputError, as the CLI's exit code 6.
  if (r.result.status == sim::RunStatus::OutputFailed) {
    std::string what;
    for (const std::string& w : r.result.not_written) what += (what.empty() ? "" : "; ") + w;
    throw OutputError("the run stopped at t = " + std::to_string(r.result.sim_seconds) + " s: " + what);
  }
  PyRunResult result;
  result.state = read_csv_columns(dir / "state.csv");
  result.contacts = read_csv_columns(dir / "contacts.csv");
  result.sensors = read_csv_columns(dir / "sensors.csv");
  result.steps = read_step_contacts(dir / "steps.h5");
  result.summary = to_python(r.summary).cast<py::dict>();
  result.out = out.is_none() ? py::object(py::none()) : py::object(py::str(dir.string()));
  return result;
}

}  // namespace gearsim::python

namespace gearsim::python {
namespace {

constexpr const char* kRunDoc = R"(Run a scenario headless, as `gearsim run` does, and return a RunResult.

The run goes through the CLI's own code (the same observers write the same files): with
out="DIR" the folder gets state.csv, contacts.csv, sensors.csv (with sensors), steps.h5 (with
output.per_step_log), scenario.json, gearset.yaml and summary.json, byte for byte what
`gearsim run SCENARIO --out DIR` writes (a previous run's outputs there are removed first); it is
not analysed (call gearsim.analyze(DIR)). With out=None the files are written to a private
temporary folder, read back and the folder removed. The arrays are read back from the CSV
files, which hold every value with 17 significant digits: they are, bit for bit, the doubles the
run computed and the CLI writes.

duration: simulated seconds in place of the scenario's duration_s (the CLI's --duration).
progress: print a progress line on stderr.

A run that leaves its physical bounds returns normally with summary["status"] == "diverged"
and summary["divergence"]. Ctrl-C (SIGINT) stops the run between two steps, writes every log up
to that step (summary.json: status "interrupted") and raises KeyboardInterrupt. The GIL is
released while the run steps. gearsim.InputError for a scenario the world refuses.)";

}  // namespace

void bind_run(py::module_& m) {
  py::class_<PyRunResult>(m, "RunResult", "The logs of a run as numpy arrays and its summary.")
      .def_readonly("state", &PyRunResult::state, "state.csv: {column: numpy float64 array} (time_s, <body>_angle_rad, te_rad, …).")
      .def_readonly("contacts", &PyRunResult::contacts,
                    "contacts.csv: {column: numpy float64 array} (time_s, <a>__<b>_force_N anti-aliased, _force_point_N, …).")
      .def_readonly("sensors", &PyRunResult::sensors, "sensors.csv as {column: array}; empty without sensors.")
      .def_readonly("steps", &PyRunResult::steps,
                    "steps.h5's tooth contacts, one entry per contact per step: {'time_s', 'step', 'pair', 'tooth_a', 'tooth_b', "
                    "'flank_a' (0 ccw, 1 cw), 'normal_impulse_N_s': arrays; 'pairs': pair names by index; 'time_step_s'} "
                    "(force = impulse / time_step_s); empty without the per-step log.")
      .def_readonly("summary", &PyRunResult::summary, "summary.json as a dict (status, sim_seconds, steps, bodies, gear_pairs, …).")
      .def_readonly("out", &PyRunResult::out, "The run folder, or None when the files were temporary.")
      .def("__repr__", [](const PyRunResult& r) {
        return "<gearsim.RunResult " + py::str(r.summary["status"]).cast<std::string>() + ", " +
               py::str(r.summary["sim_seconds"]).cast<std::string>() + " s, " + std::to_string(py::len(r.state)) + " state and " +
               std::to_string(py::len(r.contacts)) + " contact columns>";
      });
  m.def("run", &run, py::arg("scenario"), py::arg("out") = py::none(), py::arg("duration") = py::none(), py::arg("progress") = false,
        kRunDoc);
}

}  // namespace gearsim::python

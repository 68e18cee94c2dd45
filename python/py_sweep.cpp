#include "python/py_sweep.hpp"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <csignal>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <mutex>
#include <optional>
#include <thread>

#include "app/sweep_metrics.hpp"
#include "core/errors.hpp"
#include "input/input_limits.hpp"
#include "python/py_arrays.hpp"
#include "python/py_pending.hpp"
#include "sweep/process.hpp"
#include "sweep/sweep_runner.hpp"

namespace gearsim::python {
namespace {

namespace fs = std::filesystem;

// gearsim.SweepCasesFailed, created by bind_sweep; a reference kept for the process's life.
PyObject* g_cases_failed = nullptr;

// The gearsim binary the cases run: `executable` when given, else bin/gearsim of the build tree the
// module lives in (build/python/gearsim*.so → build/bin/gearsim), else `gearsim` on PATH.
fs::path gearsim_executable(const std::optional<fs::path>& executable) {
  if (executable) {
    if (!fs::is_regular_file(*executable)) throw InputError("executable: " + executable->string() + ": no such file");
    return fs::absolute(*executable);
  }
  const fs::path module(py::module_::import("gearsim").attr("__file__").cast<std::string>());
  const fs::path built = fs::absolute(module).parent_path().parent_path() / "bin" / "gearsim";
  if (fs::is_regular_file(built)) return built;
  const py::object on_path = py::module_::import("shutil").attr("which")("gearsim");
  if (!on_path.is_none()) return fs::absolute(on_path.cast<std::string>());
  throw InputError("executable: no gearsim binary at " + built.string() + " nor on PATH; pass executable=\"/path/to/gearsim\"");
}

// A parameter column as sweep.h5 holds it: float64 when every value reads as a number, else str.
py::object parameter_column(const sweep::SweepTable& t, std::size_t k) {
  std::vector<double> numbers;
  py::list texts;
  bool numeric = true;
  for (const sweep::TableRow& r : t.rows) {
    const std::string& v = r.parameters[k];
    char* end = nullptr;
    numbers.push_back(std::strtod(v.c_str(), &end));
    numeric = numeric && !v.empty() && end == v.c_str() + v.size();
    texts.append(v);
  }
  return numeric ? py::object(numpy_copy(numbers)) : py::object(texts);
}

// The table by column, in sweep.csv's order: index (int64), the parameters, status (str), the
// metrics (float64, NaN where not collected).
py::dict table_dict(const sweep::SweepTable& t) {
  py::dict d;
  std::vector<std::int64_t> index;
  py::list status;
  for (const sweep::TableRow& r : t.rows) {
    index.push_back(static_cast<std::int64_t>(r.index));
    status.append(r.status);
  }
  d["index"] = numpy_copy(index);
  for (std::size_t k = 0; k < t.parameter_columns.size(); ++k) d[py::str(t.parameter_columns[k])] = parameter_column(t, k);
  d["status"] = status;
  for (std::size_t k = 0; k < t.metric_columns.size(); ++k) {
    std::vector<double> v;
    for (const sweep::TableRow& r : t.rows) v.push_back(r.metrics[k].value_or(std::numeric_limits<double>::quiet_NaN()));
    d[py::str(t.metric_columns[k])] = numpy_copy(v);
  }
  return d;
}

// One line per finished case on sys.stderr, as the CLI's progress.
void print_progress(const sweep::Progress& p) {
  const sweep::CaseRecord& r = *p.last;
  std::string line = "sweep: case " + std::to_string(r.index) + " " + sweep::status_name(r.status);
  if (r.status != sweep::CaseStatus::Completed) line += " (exit " + std::to_string(r.exit_code) + ")";
  line += "; " + std::to_string(p.done) + "/" + std::to_string(p.to_run) + " done, " + std::to_string(p.failed) + " not completed";
  py::gil_scoped_acquire gil;
  py::print(line, py::arg("file") = py::module_::import("sys").attr("stderr"), py::arg("flush") = true);
}

py::dict sweep_cases(const fs::path& sweep_path, const fs::path& out, std::optional<int> jobs, bool fresh,
                     std::optional<fs::path> executable, bool check, bool progress) {
  if (jobs) input::require_within("jobs", *jobs, input::limits::kJobs);  // the CLI's --jobs check
  if (!fs::is_regular_file(sweep_path)) throw InputError(sweep_path.string() + ": sweep file not found");
  const int parallel = jobs.value_or(static_cast<int>(std::max(1u, std::thread::hardware_concurrency())));
  std::atomic<int> stop{0};
  const sweep::CaseContext context{gearsim_executable(executable), app::collect_case_metrics, [&stop] { return stop.load(); }};
  const sweep::ProgressFn report = progress ? sweep::ProgressFn(print_progress) : sweep::ProgressFn();
  const auto schedule = [&](const std::vector<sweep::CaseJob>& list) { return sweep::run_local(list, parallel, context, report); };

  // The sweep on its own thread; this one waits, running Python's signal handlers between waits.
  std::mutex mutex;
  std::condition_variable finished;
  bool done = false;
  std::exception_ptr error;
  sweep::SweepOutcome outcome;
  PendingError pending;
  std::thread worker([&] {
    try {
      outcome = sweep::run_sweep(sweep::SweepOptions{sweep_path, out, fresh}, schedule);
    } catch (...) {
      error = std::current_exception();
    }
    const std::lock_guard<std::mutex> lock(mutex);
    done = true;
    finished.notify_all();
  });
  while (true) {
    {
      py::gil_scoped_release released;
      std::unique_lock<std::mutex> lock(mutex);
      if (finished.wait_for(lock, std::chrono::milliseconds(kSweepPollMs), [&] { return done; })) break;
    }
    if (!pending.set() && pending.check_signals()) stop = SIGINT;  // as the CLI's SIGINT handler
  }
  {
    py::gil_scoped_release released;
    worker.join();
  }
  if (pending.set()) pending.raise();
  if (error) std::rethrow_exception(error);
  py::dict table = table_dict(outcome.table);
  const sweep::StatusCounts& c = outcome.statuses;
  if (check && c.completed != outcome.cases) {
    py::object e = py::handle(g_cases_failed)(std::to_string(outcome.cases - c.completed) + " of " + std::to_string(outcome.cases) +
                                              " cases did not complete; see their case.json (status, error) and " + outcome.csv.string());
    e.attr("table") = table;
    PyErr_SetObject(g_cases_failed, e.ptr());
    throw py::error_already_set();
  }
  return table;
}

constexpr const char* kSweepDoc = R"(Run a parameter sweep as `gearsim sweep SWEEP --out OUT [--jobs N] [--fresh]` does.

Each case is a `gearsim run` child process of the gearsim binary in OUT/cases/<index>/, jobs at
once (default: the number of cores); the table goes to OUT/sweep.csv and OUT/sweep.h5 as the CLI
writes them. Run again into OUT to resume (finished cases are kept); fresh=True removes OUT's
sweep outputs first. executable: the gearsim binary (default: build/bin/gearsim next to this
module's build/python, else `gearsim` on PATH).

Returns the table as a dict by column, in sweep.csv's order: index (int64 array), each swept
parameter (float64 array when every value is a number, else a list of str), status (list of
str: completed, diverged, failed, interrupted, not run), each collected metric (float64 array
with its unit in the name, NaN where a case has none). The CLI ends with exit code 5 when some
cases did not complete; here, with check=True (the default), gearsim.SweepCasesFailed is raised
with that message and the table as its `table` attribute; with check=False the table is returned
and its status column tells. progress: one line per finished case on stderr.

The GIL is released while the sweep runs. Ctrl-C (KeyboardInterrupt) stops it as the CLI's
SIGINT does: running cases are stopped and recorded interrupted, the table is written, and
KeyboardInterrupt is raised; calling sweep again with the same OUT resumes it. gearsim.InputError
naming the file, case and key when the sweep file or a case is refused (before anything runs).)";

}  // namespace

void bind_sweep(py::module_& m) {
  g_cases_failed = PyErr_NewExceptionWithDoc("gearsim.SweepCasesFailed",
                                             "Some cases of a sweep did not complete (the CLI's exit 5); `table` holds the sweep table.",
                                             PyExc_RuntimeError, nullptr);
  if (!g_cases_failed) throw py::error_already_set();
  m.attr("SweepCasesFailed") = py::handle(g_cases_failed);
  m.def("sweep", &sweep_cases, py::arg("sweep_path"), py::arg("out"), py::arg("jobs") = py::none(), py::arg("fresh") = false,
        py::arg("executable") = py::none(), py::arg("check") = true, py::arg("progress") = false, kSweepDoc);
}

}  // namespace gearsim::python

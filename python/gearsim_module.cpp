// The gearsim Python module (pybind11): load_scenario, run, analyze, modes, gear, inspect,
// tolerance, render_frame and sweep over the same libraries and the same app/ and sweep/ code
// paths as the CLI — no second implementation. Bad input raises
// gearsim.InputError (a ValueError) with the CLI's message (file:line:col: key: what was expected).
// docs/python.md is the reference.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <optional>

#include "app/modes_analysis.hpp"
#include <hdf5.h>

#include "app/output_folder.hpp"
#include "core/folder_lock.hpp"
#include "app/modes_outputs.hpp"
#include "app/run_analysis.hpp"
#include "app/run_dir.hpp"
#include "core/errors.hpp"
#include "input/input_limits.hpp"
#include "python/py_geometry.hpp"
#include "python/py_json.hpp"
#include "python/py_render.hpp"
#include "python/py_run.hpp"
#include "python/py_scenario.hpp"
#include "python/py_sweep.hpp"

namespace py = pybind11;

namespace gearsim::python {
namespace {

constexpr const char* kAnalyzeDoc = R"(Analyse a run folder as `gearsim analyze DIR` does and return analysis.json as a dict,
with the force spectra as arrays under "spectrum" (spectrum.csv by column: frequency_hz and
<pair>_amplitude_N, numpy float64).

Writes DIR/analysis.json, spectrum.csv, sidebands.csv, teeth.csv and the analysis keys of
summary.json, as the CLI does. from_s: start of the analysed window, s, in [0, 1e4] (default
None: the end of the motors' ramps). gearsim.InputError when DIR is not a run folder, the run is
too short or from_s is out of range; gearsim.FolderBusy when another gearsim command writes into
DIR; gearsim.OutputError (an OSError) when an output cannot be written.)";

constexpr const char* kModesDoc = R"(The scenario's model linearised about its start, as `gearsim modes --json`.

Returns the modes.json dict: natural_frequencies_hz, modes[] (frequency_hz, multiplicity, type,
energy shares, shapes), meshes, Campbell crossings. drive: "BODY=ccw" or "BODY=cw" (default: the
motor's body); harmonics: mesh harmonics in the Campbell table (1 to 50); phases: mesh positions
per pitch for the mean mesh stiffness (4 to 4096); max_speed_rad_s: leave out crossings above it
(default None: none left out). gearsim.InputError, as the CLI's, for a value out of range.)";

py::object analyze(const std::filesystem::path& run_dir, std::optional<double> from_s) {
  app::AnalyzeOptions o;
  if (from_s) {
    input::require_within("from_s", *from_s, input::limits::kRunTime_s);  // the CLI's --from check
    o.from_s = *from_s;
  }
  const app::OutputFolder folder(run_dir, "gearsim.analyze (Python)");
  py::dict analysis = to_python(app::write_run_analysis(app::open_run_dir(run_dir), o)).cast<py::dict>();
  analysis["spectrum"] = read_csv_columns(run_dir / "spectrum.csv");
  return analysis;
}

py::object modes(const PyScenario& s, const std::string& drive, int harmonics, int phases, std::optional<double> max_speed_rad_s) {
  // The CLI's option checks (cmd_modes.cpp), with the argument's name.
  input::require_within("harmonics", harmonics, input::limits::kModeHarmonics);
  input::require_within("phases", phases, input::limits::kModePhases);
  app::ModesSettings settings{drive, harmonics, phases};
  if (max_speed_rad_s) {
    input::require_within("max_speed_rad_s", *max_speed_rad_s, input::limits::kDriveSpeed_rad_s);
    settings.max_speed_rad_s = *max_speed_rad_s;
  }
  const app::ModesResult r = app::analyse_modes(s.scenario, settings);
  return to_python(app::modes_json(s.scenario.name, r.model, r.modes, r.campbell));
}

}  // namespace
}  // namespace gearsim::python

PYBIND11_MODULE(gearsim, m) {
  using namespace gearsim::python;
  m.doc() = "Gearsim: planetary gearbox dynamics (the C++ libraries of the gearsim CLI). SI units in every name.";
  H5dont_atexit();  // as the CLI (app/main.cpp): files are closed by the code that writes them
  py::register_exception<gearsim::InputError>(m, "InputError", PyExc_ValueError);
  // The CLI's exit codes 6 and 7: an output not written (disk full, permission), a folder in use.
  py::register_exception<gearsim::OutputError>(m, "OutputError", PyExc_OSError);
  py::register_exception<gearsim::FolderBusy>(m, "FolderBusy", PyExc_OSError);
  bind_scenario(m);
  bind_run(m);
  m.def("analyze", &analyze, py::arg("run_dir"), py::arg("from_s") = py::none(), kAnalyzeDoc);
  m.def("modes", &modes, py::arg("scenario"), py::arg("drive") = "", py::arg("harmonics") = 3, py::arg("phases") = 64,
        py::arg("max_speed_rad_s") = py::none(), kModesDoc);
  bind_geometry(m);
  bind_render(m);
  bind_sweep(m);
}

// The gearsim Python module (pybind11): load_scenario, run, analyze, modes, gear, inspect,
// tolerance, render_frame and sweep over the same libraries and the same app/ and sweep/ code
// paths as the CLI — no second implementation. Bad input raises
// gearsim.InputError (a ValueError) with the CLI's message (file:line:col: key: what was expected).
// docs/python.md is the reference.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "app/modes_analysis.hpp"
#include "app/modes_outputs.hpp"
#include "app/run_analysis.hpp"
#include "app/run_dir.hpp"
#include "core/errors.hpp"
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
summary.json, as the CLI does. from_s: start of the analysed window, s (default: the end of the
motors' ramps). gearsim.InputError when DIR is not a run folder or the run is too short.)";

constexpr const char* kModesDoc = R"(The scenario's model linearised about its start, as `gearsim modes --json`.

Returns the modes.json dict: natural_frequencies_hz, modes[] (frequency_hz, multiplicity, type,
energy shares, shapes), meshes, Campbell crossings. drive: "BODY=ccw" or "BODY=cw" (default: the
motor's body); harmonics: mesh harmonics in the Campbell table; phases: mesh positions per
pitch for the mean mesh stiffness; max_speed_rad_s: leave out crossings above it.)";

py::object analyze(const std::filesystem::path& run_dir, double from_s) {
  app::AnalyzeOptions o;
  o.from_s = from_s;
  py::dict analysis = to_python(app::analyze_run(app::open_run_dir(run_dir), o)).cast<py::dict>();
  analysis["spectrum"] = read_csv_columns(run_dir / "spectrum.csv");
  return analysis;
}

py::object modes(const PyScenario& s, const std::string& drive, int harmonics, int phases, double max_speed_rad_s) {
  const app::ModesResult r = app::analyse_modes(s.scenario, app::ModesSettings{drive, harmonics, phases, max_speed_rad_s});
  return to_python(app::modes_json(s.scenario.name, r.model, r.modes, r.campbell));
}

}  // namespace
}  // namespace gearsim::python

PYBIND11_MODULE(gearsim, m) {
  using namespace gearsim::python;
  m.doc() = "Gearsim: planetary gearbox dynamics (the C++ libraries of the gearsim CLI). SI units in every name.";
  py::register_exception<gearsim::InputError>(m, "InputError", PyExc_ValueError);
  bind_scenario(m);
  bind_run(m);
  m.def("analyze", &analyze, py::arg("run_dir"), py::arg("from_s") = -1.0, kAnalyzeDoc);
  m.def("modes", &modes, py::arg("scenario"), py::arg("drive") = "", py::arg("harmonics") = 3, py::arg("phases") = 64,
        py::arg("max_speed_rad_s") = std::numeric_limits<double>::infinity(), kModesDoc);
  bind_geometry(m);
  bind_render(m);
  bind_sweep(m);
}

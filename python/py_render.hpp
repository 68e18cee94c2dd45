// gearsim.render_frame: one off-screen (OSMesa) frame of a run folder at a simulated time, drawn
// by app::render_run_frame — the code `gearsim render` draws its frames with — as an H×W×3 uint8
// numpy array.
#pragma once

#include <pybind11/pybind11.h>

namespace gearsim::python {

namespace py = pybind11;

// Binds gearsim.render_frame.
void bind_render(py::module_& m);

}  // namespace gearsim::python

// gearsim.gear, gearsim.inspect and gearsim.tolerance: the gear table of a gear-set spec file
// (app::analyse_gearset, what `gearsim gears` prints and writes) with each gear's outline and
// flank table as numpy arrays; a CAD mesh inspected (app::inspect_mesh, `gearsim inspect --json`);
// the accuracy tolerances of one gear (app::tolerance_json, `gearsim tolerance --json`). The same
// app/ functions as the CLI; nothing computed twice.
#pragma once

#include <pybind11/pybind11.h>

namespace gearsim::python {

namespace py = pybind11;

// A gear's flank table is built at the radii the physics builds it at (physics/world_bodies.cpp):
// 4096 samples from root to tip.
inline constexpr int kGearFlankSamples = 4096;

// Binds gearsim.gear, gearsim.inspect and gearsim.tolerance.
void bind_geometry(py::module_& m);

}  // namespace gearsim::python

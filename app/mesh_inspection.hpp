// What `gearsim inspect MESH` reports about a CAD mesh, as one JSON document: topology checks,
// exact mass properties, the convex decomposition the physics would use (exact for prisms, else
// Bullet's HACD) with its deviation measured against the mesh, and the gear recognised from the
// outline with the departure of the contact's flank table from it. Units as the CLI prints them
// (mm, µm, kg, kg·m²; the key says which). Built by the `inspect` subcommand and the Python
// module's gearsim.inspect. Prints nothing.
#pragma once

#include <string>

#include "app/tolerance_report.hpp"
#include "geometry/constants.hpp"
#include "geometry/mesh_gear.hpp"

namespace gearsim::app {

struct InspectOptions {
  std::string mesh;  // the mesh file
  std::string unit = "mm";  // its length unit: m, cm, mm, um, in, ft
  double density_kg_m3 = constants::kPaperSteelDensity_kg_m3;  // for the mass properties, kg/m³
  int teeth = 0;  // > 0: cut the decomposition into tooth sectors
  double tooth0_deg = 0;  // tooth 0's centre line, deg
  double prism_tolerance_um = kCadPrismTolerance_m * 1e6;  // vertices off the cap planes, µm
  double spacing_mm = 0.5;  // deviation sample spacing, mm
};

// InputError naming the unit, or the file and its first offending face or edge when the mesh is
// not a valid solid. The document holds one timing, decompose_seconds (prisms only).
json inspect_mesh(const InspectOptions& options);

}  // namespace gearsim::app

// The analysis of a gear-set spec file as one JSON document (gear table, meshes, decomposition,
// train, tolerances, comparison with published values) and its text rendering. Built by the
// `gears` subcommand; read back by reports. Lengths in m, angles in deg where the key says so.
#pragma once

#include <filesystem>
#include <map>
#include <ostream>

#include "input/gearset_file.hpp"
#include "app/tolerance_report.hpp"
#include "geometry/gear_body.hpp"

namespace gearsim::app {

struct GearSetAnalysis {
  const input::GearSetFile* file = nullptr;
  std::map<std::string, GearBody> bodies;
  json doc;
};

// Builds every gear body and the JSON document. `hausdorff_spacing_m` is the sample spacing of
// the decomposition deviation measurement. Deterministic: no timings inside.
GearSetAnalysis analyse_gearset(const input::GearSetFile& file, double hausdorff_spacing_m);

// The tables a gear engineer reads, from the JSON document.
void print_gearset(std::ostream& out, const json& doc);

}  // namespace gearsim::app

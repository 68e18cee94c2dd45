// Gear-set spec files (YAML): the gears of a train, their errors, the train that joins them and
// optional reference values to compare against (e.g. the paper's Table 1). Parsed into plain
// structs; all numbers SI with the unit in the key (angles: `_deg` or `_rad`).
// Not the scenario format of a simulation run: that one embeds gear specs through parse_gear().
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "input/input_limits.hpp"
#include "input/yaml_reader.hpp"
#include "geometry/gear_spec.hpp"
#include "geometry/planetary.hpp"

namespace gearsim::input {

// Published values of one gear to compare with ours, m.
struct ReferenceGear {
  std::map<std::string, double> diameters_m;  // key: reference/tip/root/base_diameter_m
};

struct GearSetFile {
  std::filesystem::path path;
  std::string name;
  double density_kg_m3 = 0;
  std::vector<GearSpec> gears;  // file order
  std::optional<PlanetarySpec> planetary;
  std::optional<std::pair<std::string, std::string>> pair;  // external pair: driver, driven
  std::optional<int> tolerance_quality;  // DIN/ISO class for the table
  std::string reference_source;
  std::map<std::string, ReferenceGear> reference;

  const GearSpec& gear(const std::string& name) const;
};

GearSetFile load_gearset(const std::filesystem::path& path);

// One gear from its mapping; `defaults` (may be null) supplies keys the gear leaves out.
GearSpec parse_gear(const YamlMap& gear, const std::string& name, const YamlMap* defaults);

// Reads `<base>_deg` or `<base>_rad` (not both) as radians, checked against `limit_rad` in the
// key's own unit; fallback when neither is present.
double angle_rad_or(const YamlMap& m, const std::string& base, double fallback_rad, const Limit& limit_rad = limits::kAngle_rad);

// A gear's `errors:` mapping (flank_offsets, pitch_errors, profile_slopes, eccentricity), unknown
// keys refused; the tooth indices are checked with the gear (validate_gear_spec).
GearErrors parse_gear_errors(const YamlMap& e);

}  // namespace gearsim::input

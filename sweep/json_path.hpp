// A value inside a JSON document by its key path, as a sweep file names what to collect:
// `bodies.wheel.mean_absolute_speed_rad_s`, `gear_pairs[0].mean_normal_force_N.ccw_flanks_of_a`. Keys may
// themselves hold dots (body names such as "gear.a"): at each level the longest key that matches
// wins. Not JSON Pointer: the sweep's column names are these paths.
#pragma once

#include <nlohmann/json.hpp>

#include <string>

namespace gearsim::sweep {

// The value at `path`, or nullptr when the path leads nowhere.
const nlohmann::ordered_json* find_json_path(const nlohmann::ordered_json& doc, const std::string& path);

// The number at `path` (null stays null); InputError naming `file` and the path when the path
// leads nowhere or to something else.
nlohmann::ordered_json number_at_path(const nlohmann::ordered_json& doc, const std::string& path, const std::string& file);

}  // namespace gearsim::sweep

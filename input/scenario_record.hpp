// The expanded scenario of a run, kept in its folder: `gearsim run` writes DIR/scenario.json (every
// field of the physics::Scenario it ran, macros expanded, overrides applied) and a copy of the
// gear-set spec its gears came from (DIR/gearset.yaml); `analyze`, `report` and `render` read these
// copies, so that editing or moving the original scenario never changes an old run's results.
// CAD meshes are not copied (they can be large): the record keeps each one's path, size and hash
// and reading it refuses a mesh that changed since the run.
#pragma once

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>

#include "physics/scenario.hpp"

namespace gearsim::input {

// The expanded scenario as JSON (SI keys; every field, so scenario_from_json gives it back).
nlohmann::ordered_json scenario_json(const physics::Scenario& scenario);

// The scenario back from scenario_json's output. `file` names the record in messages. InputError
// naming file and key (e.g. bodies[2].gear.teeth) for a missing or mistyped key, a value out of
// its limits, an invalid gear, or a mesh whose size or hash differs from the recorded ones.
physics::Scenario scenario_from_json(const nlohmann::json& j, const std::filesystem::path& file);

// Writes DIR/scenario.json, and DIR/gearset.yaml when the scenario has a gear-set spec.
void write_scenario_record(const physics::Scenario& scenario, const std::filesystem::path& dir);

// Reads DIR/scenario.json (its gearset_spec pointing at DIR/gearset.yaml). InputError as
// scenario_from_json, or naming the file when it is missing or not JSON.
physics::Scenario read_scenario_record(const std::filesystem::path& dir);

// The FNV-1a 64-bit hash of a file's bytes as 16 hex digits ("" for no file): how a record
// recognises a mesh that changed. It detects edits, not deliberate collisions.
std::string file_fnv1a64(const std::filesystem::path& file);

}  // namespace gearsim::input

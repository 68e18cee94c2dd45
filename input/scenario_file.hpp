// Scenario files (YAML) → a validated physics::Scenario. SI units with the unit in every key
// (angles `_deg` or `_rad`); relative paths resolve against the scenario file's folder.
// Macros (`planetary`, `pair`) expand into plain bodies and joints: the expansion is what physics
// sees and what a run records in its folder (scenario_record.hpp). Not the world: physics/ builds that from the Scenario.
// The format is described, key by key, in the files of assets/scenarios/.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "physics/scenario.hpp"

namespace gearsim::input {

// Loads, expands and validates a scenario. Each override is "key.path=value" (the CLI's --set):
// a dotted path into mappings, `name[i]` for item i of a list, and a YAML value (a scalar, or a
// flow list/map such as [0, 0, 1]), applied to the tree before validation. A path that does not
// exist yet is created, so the strict reader rejects it unless it names a known optional key.
// Throws InputError naming the file, line, key path and what was expected; an error caused by an
// override names the override too.
physics::Scenario load_scenario(const std::filesystem::path& file, const std::vector<std::string>& overrides = {});

}  // namespace gearsim::input

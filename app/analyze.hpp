// The analysis summary printer shared by `gearsim analyze` and the end of `gearsim run`.
#pragma once

#include <nlohmann/json.hpp>

#include <ostream>

namespace gearsim::app {

void print_analysis(const nlohmann::ordered_json& analysis, std::ostream& out);

}  // namespace gearsim::app

// The modal analysis of a scenario as one call: the world built from it, linearised about its
// start (linear/lumped_model.hpp), its natural frequencies and shapes (linear/modes.hpp) and the
// Campbell crossings (linear/campbell.hpp). `gearsim modes` (cmd_modes.cpp) and the Python
// module's gearsim.modes call it; modes_outputs.hpp writes what it returns. Prints nothing.
#pragma once

#include <limits>
#include <optional>
#include <string>
#include <utility>

#include "linear/campbell.hpp"
#include "linear/lumped_model.hpp"
#include "linear/modes.hpp"
#include "physics/scenario.hpp"

namespace gearsim::app {

struct ModesSettings {
  std::string drive;  // BODY=ccw|cw, or empty: the motor's body, else the transmission input's load
  int harmonics = 3;  // mesh harmonics in the Campbell table
  int phases = 64;  // mesh positions per pitch the mean mesh stiffness is taken over
  double max_speed_rad_s = std::numeric_limits<double>::infinity();  // crossings above it left out
};

struct ModesResult {
  linear::LumpedModel model;
  linear::ModalAnalysis modes;
  linear::Campbell campbell;
};

// "BODY=ccw" → (BODY, +1), "BODY=cw" → (BODY, −1), "" → none; InputError for anything else.
std::optional<std::pair<std::string, int>> parse_drive(const std::string& text);

// InputError when the world or the model cannot be built (physics::World, build_lumped_model).
ModesResult analyse_modes(const physics::Scenario& s, const ModesSettings& settings);

}  // namespace gearsim::app

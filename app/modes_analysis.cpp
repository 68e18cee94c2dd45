#include "app/modes_analysis.hpp"

#include "core/errors.hpp"
#include "physics/world.hpp"

namespace gearsim::app {

std::optional<std::pair<std::string, int>> parse_drive(const std::string& text) {
  if (text.empty()) return std::nullopt;
  const auto eq = text.rfind('=');
  const std::string sense = eq == std::string::npos ? "" : text.substr(eq + 1);
  if (eq == std::string::npos || eq == 0 || (sense != "ccw" && sense != "cw"))
    throw InputError("--drive: expected BODY=ccw or BODY=cw (the gear whose torque drives the train, and its sense about +z), got '" +
                     text + "'");
  return std::make_pair(text.substr(0, eq), sense == "ccw" ? 1 : -1);
}

ModesResult analyse_modes(const physics::Scenario& s, const ModesSettings& settings) {
  const physics::World world(s);
  linear::ModelOptions mo;
  mo.drive = parse_drive(settings.drive);
  mo.phases_per_pitch = settings.phases;
  ModesResult r{linear::build_lumped_model(world, s, mo), {}, {}};
  r.modes = linear::solve_modes(r.model);
  r.campbell = linear::campbell(r.model, world.structure(), r.modes, settings.harmonics, settings.max_speed_rad_s);
  return r;
}

}  // namespace gearsim::app

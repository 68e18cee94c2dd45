// RunBounds: the physical limits a running World must stay within, checked after every step. A
// run that leaves them has diverged: its numbers can no longer be trusted, so the caller stops it
// at that step and reports the Divergence (status "diverged", a distinct exit code). What is
// merely suspicious (a 10 µm penetration, a 2 % power imbalance) stays a warning of the run
// summary, not a divergence. Not a logger and not a step loop: it only looks at the world.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "physics/scenario.hpp"
#include "physics/world.hpp"

namespace gearsim::sim {

// Where and why a run left its physical bounds.
struct Divergence {
  std::string what;  // "tooth penetration", "dropped contacts", "speed", "motor speed", "energy", "non-finite", "solver"
  std::string where;  // the gear pair "a/b", body or joint name
  std::string message;  // one sentence with the figures and the likely cause
  double time_s = 0;
  long step = 0;
  double value = 0;  // the offending figure, in the unit `what` implies (m, rad/s, J, count)
  double limit = 0;  // the bound it crossed, same unit
};

// The bounds, each with its unit and why it is where it is.
struct RunBoundsDef {
  // A contact deeper than this share of the pair's smaller tooth height is no elastic
  // deflection (≈ 1 µm in a loaded steel mesh, 0.05 % of a module-1 tooth) but gears passing
  // through each other: 5 % is 112 µm at module 1.
  double max_depth_share_of_tooth_height = 0.05;
  // No gear drive turns faster than this, rad/s (≈ 190 000 rpm; turbo gears reach ~30 000).
  double max_speed_rad_s = 2e4;
  // A motor whose joint speed, after its ramp, leaves its target by more than this share of it
  // is overpowered (the load exceeds max_torque_N_m) or the train jammed: the run no longer has
  // the operating point it was set up for.
  double max_motor_speed_error_share = 0.5;
  // Energy the bodies gained beyond the work of motors and loads (contacts and joints can only
  // dissipate, apart from the elastic energy they hold), as a share of the external work and
  // kinetic energy moved so far, plus a floor, J: an unstable integration creates energy.
  double max_created_energy_share = 0.1;
  double created_energy_floor_J = 1e-3;
};

class RunBounds {
 public:
  RunBounds(const physics::Scenario& scenario, const physics::World& world, RunBoundsDef def = {});
  // The first bound the world's last step crossed, if any.
  std::optional<Divergence> check(const physics::World& world);
  // Energy created so far beyond the external work, J (≤ 0 for a sound run: dissipation).
  double created_energy_J() const { return created_J_; }

 private:
  std::optional<Divergence> check_contacts(const physics::World& world) const;
  std::optional<Divergence> check_speeds(const physics::World& world) const;
  std::optional<Divergence> check_energy(const physics::World& world);
  Divergence at(const physics::World& world, std::string what, std::string where, std::string message, double value, double limit) const;

  const physics::Scenario& scenario_;
  RunBoundsDef def_;
  std::vector<int> motor_body_;  // per motor: its joint's body index in physics::World::bodies()
  long dropped_seen_ = 0;
  double kinetic0_J_ = 0, external_J_ = 0, moved_J_ = 0, created_J_ = 0;
};

}  // namespace gearsim::sim

#include "sim/run_bounds.hpp"

#include <cmath>
#include <sstream>

namespace gearsim::sim {
namespace {

std::string fmt(double v) {
  std::ostringstream o;
  o.precision(4);
  o << v;
  return o.str();
}

}  // namespace

RunBounds::RunBounds(const physics::Scenario& scenario, const physics::World& world, RunBoundsDef def)
    : scenario_(scenario), def_(def), kinetic0_J_(world.power().kinetic_J) {
  for (const physics::MotorDef& m : scenario.motors) {
    int body = -1;
    for (const physics::JointDef& j : scenario.joints)
      if (j.name == m.joint)
        for (std::size_t b = 0; b < world.bodies().size(); ++b)
          if (world.bodies()[b].name == j.body) body = static_cast<int>(b);
    motor_body_.push_back(body);
  }
}

Divergence RunBounds::at(const physics::World& world, std::string what, std::string where, std::string message, double value,
                         double limit) const {
  return {std::move(what), std::move(where), std::move(message), world.time_s(), world.steps(), value, limit};
}

std::optional<Divergence> RunBounds::check(const physics::World& world) {
  if (world.failed_solves() > 0)
    return at(world, "solver", "",
              "the direct solve of the contact, bearing and motor rows found no solution (solver.engine multibody): the rows are "
              "contradictory or singular",
              static_cast<double>(world.failed_solves()), 0);
  if (auto d = check_contacts(world)) return d;
  if (auto d = check_speeds(world)) return d;
  return check_energy(world);
}

std::optional<Divergence> RunBounds::check_contacts(const physics::World& world) const {
  const std::vector<physics::GearPairInfo>& pairs = world.gear_pairs();
  for (const physics::ContactSample& c : world.contacts()) {
    const physics::GearPairInfo& p = pairs[static_cast<std::size_t>(c.pair)];
    const std::string where = p.body_a + "/" + p.body_b;
    if (!std::isfinite(c.normal_force_N) || !std::isfinite(c.geometry.depth_m))
      return at(world, "non-finite", where, "a contact force of gears " + where + " is not finite", c.normal_force_N, 0);
    const double limit = def_.max_depth_share_of_tooth_height * p.tooth_height_m;
    if (c.geometry.depth_m > limit)
      return at(world, "tooth penetration", where,
                "gears " + where + " interpenetrate " + fmt(c.geometry.depth_m * 1e6) + " um at tooth " +
                    std::to_string(c.geometry.tooth_a) + "/" + std::to_string(c.geometry.tooth_b) + " (force " + fmt(c.normal_force_N) +
                    " N), beyond " + fmt(limit * 1e6) + " um = " + fmt(100 * def_.max_depth_share_of_tooth_height) +
                    " % of the tooth height: the gears pass through each other (flank table not matching the mesh, "
                    "a load far beyond the contact's strength, or a time step too large for the contact stiffness)",
                c.geometry.depth_m, limit);
  }
  if (world.dropped_contacts() > 0)
    return at(world, "dropped contacts", "",
              std::to_string(world.dropped_contacts()) +
                  " tooth contacts dropped: a gear pair touched on more than 4 tooth pairs at once, which sound "
                  "gears never do (interpenetrating teeth)",
              static_cast<double>(world.dropped_contacts()), 0);
  return std::nullopt;
}

std::optional<Divergence> RunBounds::check_speeds(const physics::World& world) const {
  for (const physics::BodyState& b : world.bodies()) {
    if (!std::isfinite(b.speed_rad_s) || !std::isfinite(b.angle_rad))
      return at(world, "non-finite", b.name, "body '" + b.name + "': speed or angle is not finite (NaN/infinite)", b.speed_rad_s, 0);
    if (std::abs(b.speed_rad_s) > def_.max_speed_rad_s)
      return at(world, "speed", b.name,
                "body '" + b.name + "' turns at " + fmt(b.speed_rad_s) + " rad/s, beyond " + fmt(def_.max_speed_rad_s) +
                    " rad/s, faster than any gear drive",
                b.speed_rad_s, def_.max_speed_rad_s);
  }
  for (std::size_t k = 0; k < scenario_.motors.size(); ++k) {
    const physics::MotorDef& m = scenario_.motors[k];
    const int body = motor_body_[k];
    if (body < 0 || world.time_s() <= m.ramp_time_s || m.target_speed_rad_s == 0) continue;
    const double speed = world.bodies()[static_cast<std::size_t>(body)].speed_rad_s;
    const double error = std::abs(speed - m.target_speed_rad_s), limit = def_.max_motor_speed_error_share * std::abs(m.target_speed_rad_s);
    if (error > limit)
      return at(world, "motor speed", m.joint,
                "motor of joint '" + m.joint + "' turns at " + fmt(speed) + " rad/s against its target " + fmt(m.target_speed_rad_s) +
                    " rad/s after its ramp: the load exceeds its max_torque_N_m (" + fmt(m.max_torque_N_m) + " N·m) or the train jammed",
                speed, m.target_speed_rad_s);
  }
  return std::nullopt;
}

std::optional<Divergence> RunBounds::check_energy(const physics::World& world) {
  const physics::PowerFlows& p = world.power();
  const double dt = scenario_.solver.time_step_s;
  external_J_ += (p.motor_W + p.load_W + p.impulse_W) * dt;
  moved_J_ += (std::abs(p.motor_W) + std::abs(p.load_W) + std::abs(p.impulse_W)) * dt;
  created_J_ = (p.kinetic_J - kinetic0_J_) - external_J_;
  const double limit = def_.max_created_energy_share * (moved_J_ + p.kinetic_J) + def_.created_energy_floor_J;
  if (!std::isfinite(created_J_))
    return at(world, "non-finite", "", "the kinetic energy or the power flows are not finite", created_J_, limit);
  if (created_J_ > limit)
    return at(world, "energy", "",
              "the bodies gained " + fmt(created_J_) + " J beyond the work of motors and loads (" + fmt(external_J_) + " J), more than " +
                  fmt(limit) +
                  " J: contacts or joints create energy, the integration is unstable (time step too large for the "
                  "contact stiffness, or gears interpenetrating)",
              created_J_, limit);
  return std::nullopt;
}

}  // namespace gearsim::sim

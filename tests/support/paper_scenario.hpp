// Test helper: the paper's planetary gearbox as a physics::Scenario built in code (sun driven,
// ring fixed, carrier out), so physics tests need no scenario parser.
#pragma once

#include <cmath>

#include "geometry/planetary.hpp"
#include "physics/scenario.hpp"
#include "tests/support/gear_specs.hpp"

namespace gearsim::test {

inline physics::Scenario paper_planetary(double sun_speed_rad_s, double carrier_load_N_m, double duration_s,
                                         bool floating_sun = true, double flank_error_m = 0.0) {
  using namespace physics;
  GearSpec sun = external_gear(24), planet = external_gear(36, 0.010), ring = internal_gear(96);
  sun.name = "sun";
  planet.name = "planet";
  ring.name = "ring";
  const PlanetaryGeometry g = analyse_planetary({sun, planet, ring, 3});
  Scenario s;
  s.name = "paper_planetary_test";
  s.duration_s = duration_s;
  auto body = [](const std::string& name, const GearSpec& spec, double x, double y, double angle, bool fixed) {
    BodyDef b;
    b.name = name;
    b.gear = spec;
    b.gear->name = name;
    b.density_kg_m3 = 7580;
    b.pose.position_m = {x, y, 0};
    b.pose.orientation = Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitZ());
    b.fixed = fixed;
    return b;
  };
  s.bodies.push_back(body("sun", sun, 0, 0, 0, false));
  for (int k = 0; k < 3; ++k) {
    const PlanetPlacement& p = g.placements[k];
    GearSpec pk = planet;
    if (k == 0 && flank_error_m != 0) pk.errors.flank_offsets.push_back({0, Flank::Ccw, flank_error_m});
    s.bodies.push_back(body("planet_" + std::to_string(k), pk, g.centre_distance_m * std::cos(p.carrier_angle_rad),
                            g.centre_distance_m * std::sin(p.carrier_angle_rad), p.spin_angle_rad, false));
  }
  s.bodies.push_back(body("ring", ring, 0, 0, g.ring_angle_rad, true));
  BodyDef carrier;
  carrier.name = "carrier";
  carrier.mass_kg = 0.3;
  carrier.principal_inertia_kg_m2 = Eigen::Vector3d(1e-4, 1e-4, 2e-4);
  s.bodies.push_back(carrier);
  JointDef js{"sun", "sun", "ground", {0, 0, 0}, Eigen::Vector3d::UnitZ(), std::nullopt};
  if (floating_sun) js.bearing = BearingDef{1e7, 50};
  s.joints.push_back(js);
  s.joints.push_back({"carrier", "carrier", "ground", {0, 0, 0}, Eigen::Vector3d::UnitZ(), std::nullopt});
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector3d c = s.bodies[1 + k].pose.position_m;
    s.joints.push_back({"planet_" + std::to_string(k), "planet_" + std::to_string(k), "carrier", c, Eigen::Vector3d::UnitZ(), std::nullopt});
  }
  s.motors.push_back({"sun", sun_speed_rad_s, 0.02, 50.0});
  if (carrier_load_N_m != 0) s.loads.push_back({"carrier", -carrier_load_N_m, 0});
  s.contact.friction = 0.0;
  s.transmission = TransmissionDef{"sun", "carrier", 5.0};
  return s;
}

}  // namespace gearsim::test

#include "render/planetary_pose.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "core/errors.hpp"
#include "geometry/constants.hpp"

namespace gearsim::render {
namespace {

using gearsim::constants::kPi;

Eigen::Isometry3d about_z(double angle_rad, const Eigen::Vector3d& centre_m = Eigen::Vector3d::Zero()) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.translate(centre_m);
  t.rotate(Eigen::AngleAxisd(angle_rad, Eigen::Vector3d::UnitZ()));
  return t;
}

void check_planet(const PlanetaryGeometry& g, int planet, const char* who) {
  if (planet < 0 || planet >= static_cast<int>(g.placements.size()))
    throw InputError(std::string(who) + ": planet " + std::to_string(planet) + " out of range [0, " + std::to_string(g.placements.size()) +
                     ")");
}

double ratio(const PlanetarySpec& s) { return 1.0 + double(s.ring.teeth) / s.sun.teeth; }

// World position of a planet's centre at its current carrier angle.
Eigen::Vector2d planet_centre(const PlanetaryGeometry& g, const PlanetaryPose& pose, int planet) {
  const double beta = g.placements[planet].carrier_angle_rad + pose.carrier_angle_rad;
  return g.centre_distance_m * Eigen::Vector2d(std::cos(beta), std::sin(beta));
}

}  // namespace

PlanetaryPose kinematic_planetary_pose(const PlanetarySpec& s, const PlanetaryGeometry& g, double carrier_angle_rad) {
  if (!std::isfinite(carrier_angle_rad)) throw InputError("planetary pose: carrier angle must be finite");
  if (g.placements.empty()) throw InputError("planetary pose: the geometry has no planet placements");
  PlanetaryPose p;
  p.carrier_angle_rad = carrier_angle_rad;
  p.sun_angle_rad = ratio(s) * carrier_angle_rad;
  p.sun = about_z(p.sun_angle_rad);
  p.ring = about_z(g.ring_angle_rad);
  // Relative to the carrier the ring turns by −θ_c, an internal mesh turns the planet the same
  // way by z_r/z_p: absolute spin θ_c·(1 − z_r/z_p).
  const double spin = carrier_angle_rad * (1.0 - double(s.ring.teeth) / s.planet.teeth);
  for (const PlanetPlacement& pl : g.placements) {
    const double beta = pl.carrier_angle_rad + carrier_angle_rad;
    const Eigen::Vector3d centre(g.centre_distance_m * std::cos(beta), g.centre_distance_m * std::sin(beta), 0);
    p.planets.push_back(about_z(pl.spin_angle_rad + spin, centre));
  }
  return p;
}

PlanetaryPose kinematic_planetary_pose_from_sun(const PlanetarySpec& s, const PlanetaryGeometry& g, double sun_angle_rad) {
  PlanetaryPose p = kinematic_planetary_pose(s, g, sun_angle_rad / ratio(s));
  p.sun_angle_rad = sun_angle_rad;  // exact, not divided and multiplied back
  p.sun = about_z(sun_angle_rad);
  return p;
}

double carrier_angle_tooth_at_sun(const PlanetarySpec& s, const PlanetaryGeometry& g, int planet, int tooth) {
  check_planet(g, planet, "carrier_angle_tooth_at_sun");
  if (tooth < 0 || tooth >= s.planet.teeth)
    throw InputError("carrier_angle_tooth_at_sun: tooth " + std::to_string(tooth) + " out of range [0, " + std::to_string(s.planet.teeth) +
                     ")");
  // Tooth direction relative to the carrier-fixed direction toward the sun (β + θ_c + π):
  // spin0 + tooth0 + k·2π/z_p − β − π − θ_c·z_r/z_p, which must vanish modulo 2π.
  const PlanetPlacement& pl = g.placements[planet];
  const double offset = pl.spin_angle_rad + s.planet.tooth0_angle_rad + tooth * 2 * kPi / s.planet.teeth - pl.carrier_angle_rad - kPi;
  const double rate = double(s.ring.teeth) / s.planet.teeth;  // tooth angle lost per carrier radian
  const double period = 2 * kPi / rate;
  const double theta = std::fmod(offset / rate, period);
  return theta < 0 ? theta + period : theta;
}

Eigen::Vector3d sun_mesh_point(const PlanetarySpec& s, const PlanetaryGeometry& g, const PlanetaryPose& pose, int planet, double z_m) {
  check_planet(g, planet, "sun_mesh_point");
  // The pitch point divides the centre distance as z_s : z_p.
  const Eigen::Vector2d c = planet_centre(g, pose, planet) * (double(s.sun.teeth) / (s.sun.teeth + s.planet.teeth));
  return {c.x(), c.y(), z_m};
}

Eigen::Vector3d ring_mesh_point(const PlanetarySpec& s, const PlanetaryGeometry& g, const PlanetaryPose& pose, int planet, double z_m) {
  check_planet(g, planet, "ring_mesh_point");
  // Internal mesh: the pitch point lies beyond the planet centre, at radius a·z_r/(z_r − z_p).
  const Eigen::Vector2d c = planet_centre(g, pose, planet) * (double(s.ring.teeth) / (s.ring.teeth - s.planet.teeth));
  return {c.x(), c.y(), z_m};
}

}  // namespace gearsim::render

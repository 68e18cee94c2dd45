// Kinematic poses of a planetary set (ring fixed, sun in, carrier out) from analyse_planetary's
// assembly placement, so frames can be made before any dynamics run: the carrier turned by θ_c,
// the sun by (1 + z_r/z_s)·θ_c, each planet by (1 − z_r/z_p)·θ_c about its own axis. Plus where
// the meshes are and when a given planet tooth meets the sun. Not dynamics: no backlash, no
// deflection; run logs will supply real poses later.
#pragma once

#include <Eigen/Geometry>
#include <vector>

#include "geometry/planetary.hpp"

namespace gearsim::render {

struct PlanetaryPose {
  double carrier_angle_rad = 0;
  double sun_angle_rad = 0;
  Eigen::Isometry3d sun = Eigen::Isometry3d::Identity();  // body → world, m
  Eigen::Isometry3d ring = Eigen::Isometry3d::Identity();
  std::vector<Eigen::Isometry3d> planets;  // one per planet, in placement order
};

// The set turned by carrier_angle_rad from its assembly placement (carrier angle 0 = planet 0 on
// +x). Throws InputError for a non-finite angle or a geometry without placements.
PlanetaryPose kinematic_planetary_pose(const PlanetarySpec& spec, const PlanetaryGeometry& geometry, double carrier_angle_rad);

// The same for a sun angle: carrier angle = sun angle / (1 + z_r/z_s).
PlanetaryPose kinematic_planetary_pose_from_sun(const PlanetarySpec& spec, const PlanetaryGeometry& geometry, double sun_angle_rad);

// Smallest carrier angle ≥ 0 at which the centre line of tooth `tooth` of planet `planet` points
// at the sun centre (that tooth in the middle of the sun mesh). Throws InputError for an index
// out of range.
double carrier_angle_tooth_at_sun(const PlanetarySpec& spec, const PlanetaryGeometry& geometry, int planet, int tooth);

// The sun–planet and planet–ring pitch points of a planet in a pose, on the face at z_m, world.
Eigen::Vector3d sun_mesh_point(const PlanetarySpec& spec, const PlanetaryGeometry& geometry, const PlanetaryPose& pose, int planet,
                               double z_m = 0.0);
Eigen::Vector3d ring_mesh_point(const PlanetarySpec& spec, const PlanetaryGeometry& geometry, const PlanetaryPose& pose, int planet,
                                double z_m = 0.0);

}  // namespace gearsim::render

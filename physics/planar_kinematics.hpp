// solver.mass_matrix planar (docs/solver.md, "The planar kinematics"): on a tree whose joints all
// turn about z, the positions, the links' poses and velocities and the bodies' states from the
// joint coordinates in closed form — every link's turn is the sum of the angles on its chain —
// in place of Bullet's position step, forward kinematics and link velocities. The multibody
// engine's working data for it. Internal to physics/.
#pragma once

#include <btBulletDynamicsCommon.h>

#include <Eigen/Dense>

#include <vector>

#include "contact/tooth_contact.hpp"

namespace gearsim::physics {

struct PlanarKinematics {
  // Per link its parent, its joint's turn about world z (σ = ±1) and vectors at q = 0 (world),
  // its basis at q = 0.
  struct Link {
    int parent = -1;
    bool planar_joint = false;
    double sigma = 1, axis_length2 = 1;
    btMatrix3x3 basis0 = btMatrix3x3::getIdentity();
    btVector3 e0{0, 0, 0}, d0{0, 0, 0}, b1{0, 0, 0}, b2{0, 0, 0};
  };
  std::vector<Link> links;
  // Per link this pose's turn φ, cos φ, sin φ; link_jac_current: the link Jacobians are this
  // pose's (the pose has not moved since forward_kinematics()).
  std::vector<double> link_phi, link_cos, link_sin;
  bool link_jac_current = false;
  // Per joint its angle at q = 0; per gear body its frame's in-plane x axis (unit) and angle at
  // q = 0; the fixed gears' poses.
  std::vector<double> angle_at_zero;
  std::vector<Eigen::Vector2d> gear_x0;
  std::vector<double> gear_angle0;
  std::vector<contact::PlanarPose> fixed_pose;
  // World::set_mass_matrix_check: the step's start coordinates, the velocities its positions
  // moved with and its length (check() steps Bullet from them).
  std::vector<double> check_q_start, check_v_positions;
  double check_h = 0;
};

}  // namespace gearsim::physics

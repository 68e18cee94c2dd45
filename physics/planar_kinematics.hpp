// verify.mass_matrix planar (docs/solver.md, "The planar kinematics"): on a tree whose joints all
// turn about z, the positions, the links' poses, Jacobians and velocities and the bodies' states
// from the joint coordinates in closed form — every link's turn is the sum of the angles on its
// chain — in place of Bullet's position step, forward kinematics, link velocities and Jacobian
// tree walks. Bullet's btMultiBody still holds the coordinates and the tree (the multibody
// engine owns it); this writes its link caches and the bodies' transforms. Not the mass matrix
// (planar_mass.hpp). Internal to physics/.
#pragma once

#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <btBulletDynamicsCommon.h>

#include <Eigen/Dense>

#include <cstddef>
#include <vector>

#include "contact/tooth_contact.hpp"
#include "physics/bullet_scratch.hpp"
#include "physics/model.hpp"
#include "physics/state.hpp"
#include "physics/world.hpp"

namespace gearsim::physics {

class PlanarKinematics {
 public:
  // On the tree as built (q = 0, at rest): each link's chain and joint vectors, the gears' frames
  // at q = 0; checks that the closed form starts at Bullet's pose. link_of_body: each body's link
  // (−1: the ground or fixed).
  void build(const Model& model, btMultiBody& tree, const std::vector<int>& link_of_body);

  // Joint positions q⁺ = q + h·v as Bullet's position step takes them, then the poses.
  void step_positions(double h, const double* v);
  // The links' turns and transforms from the joint positions (into Bullet's link cache and the
  // bodies' transforms), then their Jacobians at this pose (the next step's free motion and rows
  // take them as they are: the pose does not move in between).
  void forward_kinematics();
  // link_jac() at this step's pose: from the joints' axes (no tree walks).
  void link_jacobians();
  // Each link's spin rate and centre velocity (world) from the coordinates' velocities u.
  void link_velocities(const double* u);
  // The end of a step: the links' velocities at the new pose onto the bodies, then with a
  // check, Bullet's own passes from the same coordinates compared into it.
  void finish_step(BulletScratch& scratch, World::MassMatrixCheck* check);
  // World::set_mass_matrix_check: the step's start coordinates and length, and the velocities
  // its positions moved with (check() steps Bullet from them).
  void keep_step_start(double h);
  void keep_position_velocities(const double* v);

  // Joint angles and speeds (state.bodies) from the links' turns and spin rates.
  void measure_joints(State& state) const;
  // A gear body's planar pose from its link's turn.
  contact::PlanarPose gear_pose(std::size_t body) const;

  // Per link: rows ω_z, v_x, v_y of its centre over the coordinates (links × 3 × dofs).
  const std::vector<double>& link_jac() const { return link_jac_; }
  // Per link: the coordinates that move it.
  const std::vector<int>& link_dofs(std::size_t link) const { return link_dofs_[link]; }
  std::size_t links() const { return links_.size(); }
  // Per link this step's spin rate (rad/s) and centre velocity (m/s, world).
  const std::vector<double>& link_w() const { return link_w_; }
  const std::vector<double>& link_vx() const { return link_vx_; }
  const std::vector<double>& link_vy() const { return link_vy_; }
  // Per coordinate: the z component of its joint's angular axis s_d, its linear axis b_d (world)
  // and the link it belongs to.
  const std::vector<double>& dof_s() const { return dof_s_; }
  const std::vector<double>& dof_bx() const { return dof_bx_; }
  const std::vector<double>& dof_by() const { return dof_by_; }
  const std::vector<int>& dof_link() const { return dof_link_; }

 private:
  void build_links();
  void build_gears();
  void check(BulletScratch& scratch, World::MassMatrixCheck& check);

  // Per link its parent, its joint's turn about world z (σ = ±1) and vectors at q = 0 (world),
  // its basis at q = 0.
  struct Link {
    int parent = -1;
    bool planar_joint = false;
    double sigma = 1, axis_length2 = 1;
    btMatrix3x3 basis0 = btMatrix3x3::getIdentity();
    btVector3 e0{0, 0, 0}, d0{0, 0, 0}, b1{0, 0, 0}, b2{0, 0, 0};
  };
  const Model* model_ = nullptr;
  btMultiBody* tree_ = nullptr;  // the engine's
  std::vector<int> link_of_body_;
  std::size_t dofs_ = 0;
  std::vector<Link> links_;
  std::vector<std::vector<int>> link_chain_;  // per link: it and its ancestors
  std::vector<std::vector<int>> link_dofs_;
  std::vector<double> dof_s_, dof_bx_, dof_by_;
  std::vector<int> dof_link_;
  std::vector<double> link_jac_;
  // Per link this pose's turn φ, cos φ, sin φ, spin rate and centre velocity.
  std::vector<double> link_phi_, link_cos_, link_sin_;
  std::vector<double> link_w_, link_vx_, link_vy_;
  // Per joint its angle at q = 0; per gear body its frame's in-plane x axis (unit) and angle at
  // q = 0; the fixed gears' poses.
  std::vector<double> angle_at_zero_;
  std::vector<Eigen::Vector2d> gear_x0_;
  std::vector<double> gear_angle0_;
  std::vector<contact::PlanarPose> fixed_pose_;
  // World::set_mass_matrix_check: see keep_step_start().
  std::vector<double> check_q_start_, check_v_positions_;
  double check_h_ = 0;
};

}  // namespace gearsim::physics

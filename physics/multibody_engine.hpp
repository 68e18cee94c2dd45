// The `multibody` engine (solver.engine multibody, the default): the joint tree as one
// btMultiBody on a fixed base (reduced coordinates, Featherstone), and per step one direct solve
// of every row that is not a joint — tooth contacts (normal, friction), bearing springs,
// torsional springs, motors (multibody_rows.hpp) — by the row solvers (row_solvers.hpp), with the
// planar mass matrix and kinematics on a tree turning about z (planar_mass.hpp,
// planar_kinematics.hpp), sliding friction (slip_friction.hpp) and the step split at a contact's
// onset (onset_split.hpp), integrated as solver.integrator says (multibody_integrator.hpp). Its
// own sources: multibody_engine.cpp (building, stepping), multibody_rows.cpp (the rows, what they
// did), multibody_solve.cpp (the rows' problem, the solvers in turn). Not the rigid_bodies
// engine (rigid_body_engine.hpp). Internal to physics/.
#pragma once

#include <btBulletDynamicsCommon.h>
#include <BulletDynamics/Featherstone/btMultiBody.h>

#include <Eigen/Dense>

#include <memory>
#include <vector>

#include "physics/bullet_scratch.hpp"
#include "physics/engine.hpp"
#include "physics/folded_solve.hpp"
#include "physics/multibody_integrator.hpp"
#include "physics/multibody_rows.hpp"
#include "physics/onset_split.hpp"
#include "physics/planar_kinematics.hpp"
#include "physics/planar_mass.hpp"
#include "physics/primal_solve.hpp"
#include "physics/row_solvers.hpp"
#include "physics/slip_friction.hpp"

namespace gearsim::physics {

class MultibodyEngine final : public Engine {
 public:
  // Throws InputError where the joints do not form a tree of hinges and bearings.
  MultibodyEngine(const Model& model, State& state);
  MultibodyEngine(const MultibodyEngine&) = delete;
  MultibodyEngine& operator=(const MultibodyEngine&) = delete;

  void step() override;
  double motor_torque_N_m(std::size_t joint) const override { return motor_torque_[joint]; }
  long failed_solves() const override { return failed_solves_; }
  void set_mass_matrix_check(bool on) override { check_mass_ = on; }
  const World::MassMatrixCheck& mass_matrix_check() const override { return mass_check_; }

 private:
  // Building and stepping (multibody_engine.cpp).
  void build_tree();
  void set_options();
  void advance(double h);  // one (sub)step from the contacts generate_contacts() found
  void apply_loads_and_impulses();
  void bullet_step_positions(double h, bool mid);
  void generate_contacts();
  void measure_joints();
  double kinetic_energy_J() const;
  // The rows and what they did (multibody_rows.cpp).
  void build_rows();
  void bullet_link_jacobians();
  void results();
  // The solve (multibody_solve.cpp): the rows' problem, then the row solvers in turn.
  void solve_rows();
  bool solve_rows_active_set();
  int solve_rows_planar();  // the dof-space solve, the folded one where it does not settle
  bool locate_slip_reversals(bool solved);
  // dv = M⁻¹·Jᵀ·λ over this step's rows (λ: one impulse per row; dv: dofs entries).
  void velocity_change(const double* lambda, double* dv);
  void velocity_change_of_x(double* dv);  // of x: the dof-space solve's where it found x, else velocity_change()

  const Model& model_;
  State& state_;
  // The tree: per body its link (−1 for the ground and fixed bodies), per joint its spin
  // coordinate among the dofs and its bearing centre in the body's and the parent's frame
  // (world for the ground); Bullet's scratch.
  std::unique_ptr<btMultiBody> tree_;
  int dofs_ = 0;  // joint coordinates, without the fixed base's six
  std::vector<int> link_of_body_;
  std::vector<int> dof_of_joint_;
  std::vector<btVector3> pivot_in_body_, pivot_in_parent_;
  std::vector<double> buf_, out_;  // 6 + dofs
  BulletScratch scratch_;
  bool planar_ = false;  // every joint axis along z: rows from the links' Jacobians
  bool planar_mass_ = false;  // verify.mass_matrix planar on a planar tree: mass_ and kin_
  std::vector<double> link_jac_;  // planar tree, articulated path: per link rows ω_z, v_x, v_y over the dofs
  Integrator integ_;
  RowSystem rows_;
  PlanarKinematics kin_;
  PlanarMass mass_;
  ActiveSetSolve active_;
  PrimalSolve primal_;
  FoldedSolve folded_;
  DantzigSolve dantzig_;
  // World::set_mass_matrix_check: the dof-space solve's bound states before it, its impulses and
  // states after it (the folded solve is compared from the same states).
  struct {
    std::vector<RowBound> states_before, states;
    std::vector<double> x;
  } planar_check_;
  SlipFriction slip_;
  OnsetSplit onset_;
  std::vector<double> motor_torque_;  // per joint, last step, N·m
  long failed_solves_ = 0;
  bool check_mass_ = false;  // World::set_mass_matrix_check
  World::MassMatrixCheck mass_check_;
};

}  // namespace gearsim::physics

// The `rigid_bodies` engine (solver.engine rigid_bodies): Bullet's btDiscreteDynamicsWorld with
// the model's rigid bodies, a hinge or a bearing's 6-dof spring constraint per joint, velocity
// motors on them, load torques, and one manifold per gear pair whose points are the touching
// tooth pairs (compliant, damped, warm-started per tooth pair), solved by sequential impulses.
// Not the multibody engine (multibody_engine.hpp). Internal to physics/.
#pragma once

#include <btBulletDynamicsCommon.h>
#include <BulletDynamics/ConstraintSolver/btGeneric6DofSpring2Constraint.h>

#include <tuple>
#include <utility>
#include <vector>

#include "physics/engine.hpp"

namespace gearsim::physics {

class RigidBodyEngine final : public Engine {
 public:
  RigidBodyEngine(const Model& model, State& state);
  // Takes constraints, manifolds and bodies out of Bullet's world before it goes.
  ~RigidBodyEngine() override;
  RigidBodyEngine(const RigidBodyEngine&) = delete;
  RigidBodyEngine& operator=(const RigidBodyEngine&) = delete;

  void step() override;
  double motor_torque_N_m(std::size_t joint) const override;

  // This step's tooth contacts into the pairs' manifolds: Bullet calls it before each solve.
  void generate_contacts();

 private:
  // A joint's Bullet constraint: a hinge, or a bearing's spring constraint.
  struct Joint {
    btTypedConstraint* constraint = nullptr;  // owned
    btJointFeedback feedback;
    btHingeConstraint* hinge = nullptr;
    btGeneric6DofSpring2Constraint* spring = nullptr;
  };
  // A gear pair's manifold, its points' tooth contacts and stiffnesses (in point order) and the
  // last step's impulse per tooth pair (tooth_a, tooth_b, flank_a), the warm start.
  struct Pair {
    btPersistentManifold* manifold = nullptr;
    std::vector<std::pair<std::tuple<int, int, int>, double>> last_impulse;
    std::vector<contact::ToothContact> current;
    std::vector<double> current_stiffness_N_per_m;
  };

  void add_bodies();
  void add_joints();
  void add_manifold_points(std::size_t pair, double z);
  void apply_motors_and_loads();
  void apply_impulses();
  void measure();  // joints, then contacts
  void measure_contacts();
  void measure_power();

  const Model& model_;
  State& state_;
  btDefaultCollisionConfiguration config_;
  btCollisionDispatcher dispatcher_{&config_};
  btDbvtBroadphase broadphase_;
  btSequentialImpulseConstraintSolver solver_;
  btDiscreteDynamicsWorld world_{&dispatcher_, &broadphase_, &solver_, &config_};
  std::vector<Joint> joints_;  // per model joint
  std::vector<Pair> pairs_;  // per model pair
};

}  // namespace gearsim::physics

// The constant part of a World (in MuJoCo's terms its model): what is built once from a Scenario
// and then only read — the scenario itself, the bodies (mass properties, collision shapes, flank
// tables), the joints (body and parent, axis, motor and load) and the meshing gear pairs (their
// contact data and stiffness rule) — with the checks a scenario is refused by. Not the state
// that changes from step to step (state.hpp) and not how a step is taken (engine.hpp).
// One exception, owned here because Bullet ties it to the shapes: each body's btRigidBody
// carries the body's pose and velocity, which the engines move every step (a const Model still
// hands out the non-const btRigidBody). Internal to physics/.
#pragma once

#include <Eigen/Dense>

#include <algorithm>
#include <map>
#include <string>
#include <vector>

#include "physics/scenario.hpp"
#include "physics/tooth_pair_stiffness.hpp"
#include "physics/world.hpp"
#include "physics/world_bodies.hpp"

namespace gearsim::physics {

struct ModelJoint {
  JointDef def;
  int body = -1, parent = -1;  // parent −1: the ground
  Eigen::Vector3d axis_world = Eigen::Vector3d::UnitZ();  // unit
  const MotorDef* motor = nullptr;  // into Model::scenario
  const LoadDef* load = nullptr;
};

struct ModelPair {
  int a = -1, b = -1;  // a external (tooth_a is always its tooth); b may be internal
  GearPairInfo info;
  MeshStiffnessModel stiffness;  // how each touching tooth pair's stiffness is set
};

class Model {
 public:
  // Throws InputError when the scenario cannot be built (World's constructor documents which).
  explicit Model(const Scenario& scenario);
  Model(const Model&) = delete;  // the joints point into the scenario held here
  Model& operator=(const Model&) = delete;

  Scenario scenario;
  std::vector<BuiltBody> bodies;
  std::map<std::string, int> body_index;
  std::vector<ModelJoint> joints;
  std::vector<ModelPair> pairs;
  std::vector<GearPairInfo> pair_infos;  // pairs[p].info, as World::gear_pairs() hands them out
  // The gears' planar poses at the start (checked clear of each other), per body (gears only).
  std::vector<contact::PlanarPose> start_poses;

  double time_step_s() const { return scenario.solver.time_step_s; }

 private:
  void add_bodies();
  void add_joints();
  void attach_drives();
  void find_pairs();
  void add_pair_stiffness(ModelPair& pr) const;
  void check_start();
};

// A motor's target speed at time t: the ramp from rest reaches the target at ramp_time_s. A step
// from t to t + h constrains the speed at its end, so it asks for the target at t + h.
inline double motor_target_rad_s(const MotorDef& m, double t) {
  return m.target_speed_rad_s * (m.ramp_time_s > 0 ? std::min(1.0, t / m.ramp_time_s) : 1.0);
}

// Damping of a tooth-pair contact of stiffness k (N/m) in pair pr, N·s/m.
double contact_damping(const Model& model, const ModelPair& pr, double k);

}  // namespace gearsim::physics

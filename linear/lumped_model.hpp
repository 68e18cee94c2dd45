// The scenario's world linearised about its start: every body that is not welded to the ground
// gets three planar coordinates (x, y of its centre of mass in m, its turn θ about z in rad);
// bearings are radial springs between a body and its parent at the joint's pivot, torsional
// supports springs on their relative turn, each gear mesh the mean of its tooth pairs' springs
// over a mesh period (mesh_average.hpp); rigid hinges and velocity motors are constraints
// (a velocity motor holds its joint's speed, so its relative turn does not vary). The classic
// lumped planetary model (Lin & Parker 1999) is this model of a planetary scenario with supports.
// Planar only: every joint axis and gear axis along z.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "physics/scenario.hpp"
#include "physics/world.hpp"

namespace gearsim::linear {

// One spring of the model, as its stiffness matrix over all coordinates (N/m, N, N·m/rad).
struct Element {
  enum class Kind { Mesh, Bearing, Torsion };
  Kind kind = Kind::Mesh;
  std::string name;  // "sun–planet_0", the bearing's or torsional support's body
  Eigen::MatrixXd stiffness;
  double value = 0;  // mesh: mean stiffness N/m; bearing: radial N/m; torsion: N·m/rad
};

// A gear mesh as the model saw it.
struct MeshInfo {
  int a = -1, b = -1;  // bodies (a external)
  int driven = -1;  // the body driven through this mesh
  int driven_sense = 0;  // +1: its loaded flanks turn it counter-clockwise
  double mean_N_per_m = 0, min_N_per_m = 0, max_N_per_m = 0;
  double mean_pairs = 0;  // loaded tooth pairs in contact, mean over the period
  double line_of_action_deg = 0;  // direction of the mean contact normal (from b toward a)
  int element = -1;  // index in LumpedModel::elements
};

struct BodyInfo {
  std::string name;
  int first_dof = -1;  // x, y, θ at first_dof .. first_dof + 2; −1: welded to the ground
  double mass_kg = 0, inertia_z_kg_m2 = 0;
  Eigen::Vector2d centre_of_mass_m = Eigen::Vector2d::Zero();
  int parent = -1;  // the body its joint hangs on (−1: ground or none)
  // The parent, when the joint is a pin off the parent's axis (a planet on its carrier: the body
  // that carries its meshes); −1 for a joint on the parent's axis (a shaft, a coupling) or none.
  int pin_parent = -1;
  bool gear = false;
  int teeth = 0;
  double radius_m = 0;  // a gear's tip (ring: its root), a carrier's reach to its planets; for pictures
};

struct LumpedModel {
  std::vector<BodyInfo> bodies;
  Eigen::MatrixXd mass;  // diag(m, m, I) per body
  Eigen::MatrixXd stiffness;  // Σ elements
  Eigen::MatrixXd constraints;  // one row per rigid hinge direction and velocity motor
  std::vector<std::string> constraint_names;
  std::vector<Element> elements;
  std::vector<MeshInfo> meshes;
  int driver = -1;  // the body whose torque drives the train
  std::string drive;  // "<body> counter-clockwise" and where that came from
  int dofs() const { return static_cast<int>(mass.rows()); }
};

struct ModelOptions {
  // The gear whose torque drives the train and its sense (+1 ccw, −1 cw), which decides the
  // loaded flanks; default: the body of the first motor in its speed's sense, else the
  // transmission's input joint's load in its torque's sense.
  std::optional<std::pair<std::string, int>> drive;
  int phases_per_pitch = 64;  // mesh positions averaged
  double mesh_deflection_m = 1e-6;  // how deep the loaded flanks are pressed at each
};

// Throws InputError when the model cannot be formed (a joint axis not along z, no drive to say
// which flanks carry the load, a gear no mesh drives).
LumpedModel build_lumped_model(const physics::World& world, const physics::Scenario& scenario, const ModelOptions& options);

// The train's rigid kinematics: every body's absolute speed about +z per rad/s of `driver`, each
// mesh (pair of `structure`) rolling without slip, z_a (ω_a − ω_c) = ∓ z_b (ω_b − ω_c), about the
// body c that carries it (a planet's movable parent), welded bodies still, and joints with a
// torsional spring (supports, shafts) turning with their parent. `why_not` says why there are no
// speeds: the drive does not fix them all, or they contradict each other (a locked train).
struct RigidSpeeds {
  Eigen::VectorXd omega;  // per body of model.bodies, rad/s per rad/s of the driver
  std::string why_not;
};
RigidSpeeds rigid_speeds(const LumpedModel& model, const physics::WorldStructure& structure, int driver);

}  // namespace gearsim::linear

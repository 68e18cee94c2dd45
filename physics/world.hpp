// World: a running Bullet simulation built from a Scenario. Rigid bodies (gears as compounds of
// their exact convex pieces, mass properties from the mesh), hinges or compliant bearings,
// velocity motors, loads, and tooth contact between meshing gears: one compliant, damped contact
// point per touching tooth pair (tooth_contact.hpp), handed to Bullet's solver as a manifold
// point with stiffness and damping. SI units throughout; Bullet runs in SI double precision.
// Not a logger and not a file writer: see run_log.hpp.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "physics/scenario.hpp"
#include "contact/coherent_contact.hpp"
#include "contact/tooth_contact.hpp"
#include "physics/tooth_pair_stiffness.hpp"

namespace gearsim::physics {

struct BodyState {
  std::string name;
  double angle_rad = 0;  // unwrapped rotation about its joint axis relative to the parent
  double speed_rad_s = 0;  // relative to the parent
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();  // gear-frame origin, world
};

// One tooth-pair contact as the solver left it after a step.
struct ContactSample {
  int pair = -1;  // index into World::gear_pairs()
  contact::ToothContact geometry;
  double normal_force_N = 0;  // applied impulse / dt
  double friction_force_N = 0;  // magnitude of the lateral impulses / dt
  double stiffness_N_per_m = 0;  // the contact stiffness it was solved with (pair constant or table)
};

// Power flows of the last step, W (forces from the solver's impulses / dt, velocities after the
// step). Over a steady window: motor = −load + dissipation + d(kinetic energy)/dt, which is the
// power balance a run reports.
struct PowerFlows {
  double motor_W = 0;  // delivered by the velocity motors (torque × joint speed)
  double load_W = 0;  // delivered by the load torques (< 0 for a brake)
  double contact_W = 0;  // delivered by tooth contacts (< 0: friction and contact damping dissipate)
  double joint_W = 0;  // delivered by joints apart from their motors (< 0: bearing damping)
  double impulse_W = 0;  // delivered by the scenario's force and torque pulses (impulses:)
  double kinetic_J = 0;  // kinetic energy of all bodies, J
};

struct GearPairInfo {
  std::string body_a, body_b;
  double stiffness_N_per_m = 0;  // per tooth pair (the constant; a table's pair varies per contact)
  double damping_N_s_per_m = 0;
  double face_width_m = 0;  // common face width the stiffness per width is multiplied by
  double reduced_mass_kg = 0;  // along the line of action, for the damping c = 2ζ√(k·m)
  double tooth_height_m = 0;  // radial extent of the smaller of the two gears' teeth
  std::string stiffness_table;  // the table's source when the pair has one, else empty
  double mesh_stiffness_N_per_m = 0;  // a constant mesh stiffness shared by its tooth pairs (0: none)
};

// The world as built, before its first step, for a linearised model (linear/): pointers into the
// World, valid while it lives.
struct StructureBody {
  std::string name;
  double mass_kg = 0;
  double inertia_z_kg_m2 = 0;  // about its axis (z) through the centre of mass
  Eigen::Vector2d centre_of_mass_m = Eigen::Vector2d::Zero();
  bool fixed = false;  // welded to the ground
  const contact::FlankTable* flanks = nullptr;  // gears only
  contact::PlanarPose gear_pose;  // gears only
};
struct StructureJoint {
  const JointDef* def = nullptr;
  int body = -1, parent = -1;  // parent −1: the ground
  const MotorDef* motor = nullptr;
  const LoadDef* load = nullptr;
};
struct StructurePair {
  int a = -1, b = -1;  // a external; b may be internal
  const GearPairInfo* info = nullptr;
  MeshStiffnessModel stiffness;
};
struct WorldStructure {
  std::vector<StructureBody> bodies;
  std::vector<StructureJoint> joints;
  std::vector<StructurePair> pairs;
};

class World {
 public:
  // Throws InputError when the scenario cannot be built, also when two gears overlap by more
  // than kStartOverlapLimit_m at t = 0 or anywhere over a mesh period turned at the ideal ratio
  // (mesh_cycle_overlap: interference; the message names the pair, teeth, radii and depth).
  explicit World(const Scenario& scenario);
  // Overlap of two gears' teeth that is the meshes' resolution rather than a placement error or
  // interference, m: a flank table may depart this far from its mesh (a zero-backlash pair touches).
  static constexpr double kStartOverlapLimit_m = 2e-6;
  ~World();
  World(const World&) = delete;
  World& operator=(const World&) = delete;

  // Advances one fixed time step.
  void step();

  double time_s() const;
  long steps() const;
  const std::vector<BodyState>& bodies() const;
  const std::vector<ContactSample>& contacts() const;  // of the last step
  const std::vector<GearPairInfo>& gear_pairs() const;
  // Torque the motor of a joint applied in the last step, N·m (impulse / dt).
  double motor_torque_N_m(const std::string& joint) const;
  // Deepest tooth penetration in the last step, m.
  double max_penetration_m() const;

  // Where the wall time of step() went since construction, s: finding tooth contacts, and
  // everything else Bullet does (constraint solve, integration) plus measuring.
  struct Profile {
    double tooth_contact_s = 0;
    double row_solve_s = 0;  // multibody: rows, M⁻¹ and the direct solve (part of the rest)
    double step_total_s = 0;
    long active_set_solves = 0, dantzig_solves = 0;  // multibody: steps whose rows each solved
    long onset_splits =
        0;  // multibody, verify.locate_contact_onset: splits of a step at a contact's onset (each adds a search and a solve)
    long friction_rounds = 0;  // multibody, verify.friction_model sliding: solves again to locate slip reversals
    // The coherent tooth search's flank visits, summed over the gear pairs (both passes; all 0
    // with verify.coherent_search false): contact::CoherentToothSearch::Counts, each a count
    // of flanks — searched in full, tracked, skipped by their records, continued (of them
    // `crossings` at a tip circle), renewed, shared between the passes, parked near pairs.
    contact::CoherentToothSearch::Counts flank_visits;
  };
  const Profile& profile() const;
  const PowerFlows& power() const;
  // Tooth contacts dropped since construction because a pair had more touching tooth pairs than
  // a Bullet manifold holds (4): numerical trouble a run reports, never seen in a sound mesh.
  long dropped_contacts() const;
  // Contacts since construction whose radius lay outside their pair's stiffness table: they took
  // the nearest end row's value. Counted, reported in the run summary, never silent.
  long stiffness_table_misses() const;
  // Steps since construction whose direct row solve (solver.engine multibody) found no solution;
  // always 0 for rigid_bodies. A run stops at the first (sim/run_bounds.hpp).
  long failed_solves() const;

  // verify.mass_matrix planar (multibody, a tree turning about z): with the check on, every
  // step also takes Bullet's articulated-body solves for M⁻¹ and its Jacobian tree walks for the
  // links, and records the largest |M·M⁻¹ − I| (M the planar mass matrix) and the largest
  // difference of a link Jacobian's entries (1 or m) seen: that both paths state the same
  // equations, to rounding (docs/solver.md, "The planar mass matrix"); likewise the free motion
  // against Bullet's articulated-body pass, every dof-space row solve against the folded
  // row-space solve from the same bound states ("The row solve in the coordinates' space"), and
  // the velocity change a step applies from that solve against M⁻¹·Jᵀ·λ.
  // Costs the articulated path's time; off by default. steps stays 0 where the planar path is
  // not used.
  struct MassMatrixCheck {
    long steps = 0;
    double identity_residual = 0, jacobian_difference = 0;
    // |v* − v*_Bullet| / max(|v*_Bullet − v|, ε): the velocities after the applied forces alone
    // (PlanarMass::free_velocities) against Bullet's articulated-body pass, relative to the change.
    double free_velocity_difference = 0;
    // The rows' impulses of the dof-space solve (PrimalSolve) against the folded row-space
    // solve's from the same bound states: max |Δλ| / max |λ| over the solves compared.
    // Fallbacks: the dof-space solve did not settle; of them, settled by the row-space solve.
    long row_solves_compared = 0, row_solve_fallbacks = 0, row_solve_fallbacks_settled = 0;
    double row_solve_difference = 0;
    // The velocity change the dof-space solve found with its impulses (what the step applies
    // where that solve settled) against M⁻¹·Jᵀ·λ from the same impulses: max |Δdv| / max |dv|.
    long velocity_changes_compared = 0;
    double velocity_change_difference = 0;
    // The planar kinematics (planar_kinematics.hpp) against Bullet's position step, forward
    // kinematics and link velocities from the same coordinates: the largest coordinate
    // difference, link centre distance (m), basis row difference and link velocity difference
    // (rad/s, m/s), over kinematics_steps steps.
    long kinematics_steps = 0;
    double coordinate_difference = 0, centre_difference_m = 0, basis_difference = 0, link_velocity_difference = 0;
  };
  void set_mass_matrix_check(bool on);
  const MassMatrixCheck& mass_matrix_check() const;

  // Bodies, joints and meshing pairs as built (call before the first step for t = 0).
  WorldStructure structure() const;

  struct Impl;

 private:
  std::unique_ptr<Impl> impl_;
};

}  // namespace gearsim::physics

// Inside physics::World (world.hpp), shared by its two sources: world.cpp builds the Bullet world
// from a scenario, world_step.cpp advances and measures it. Not for use outside physics/.
#pragma once

#include <algorithm>
#include <btBulletDynamicsCommon.h>
#include <BulletDynamics/ConstraintSolver/btGeneric6DofSpring2Constraint.h>
#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/MLCPSolvers/btDantzigLCP.h>

#include <array>

#include "physics/row_lcp.hpp"

#include <Eigen/Dense>

#include <chrono>
#include <cstdint>
#include <mutex>
#include <map>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "physics/world.hpp"
#include "contact/coherent_contact.hpp"
#include "physics/tooth_pair_stiffness.hpp"
#include "physics/world_bodies.hpp"

namespace gearsim::physics {

// Collision groups: gears reach each other only through tooth contact, never through Bullet's
// own narrowphase (whose point counts and GJK chatter are what tooth contact replaces).
// Shapeless bodies (a carrier arm) collide with nothing.
constexpr int kGearGroup = 1 << 6;
constexpr int kOtherGroup = 1 << 7;
constexpr int kShapelessGroup = 1 << 8;

// A Bullet manifold holds at most 4 points: enough for one point per tooth pair at contact
// ratios below 4. Extra pairs (never seen in a healthy mesh) are dropped and counted.
constexpr int kMaxPointsPerPair = 4;

// contact.friction_model sliding (world_friction.cpp): the step is solved again while a friction
// share differs from the one its end slip asks for by more than kSlipShareTolerance (an impulse
// error of that fraction of μ·λ_n·h), at most kSlipRounds times.
constexpr int kSlipRounds = 30;
constexpr double kSlipShareTolerance = 1e-6;
// solver.locate_contact_onset (world_onset.cpp): at most this many splits of one step (a
// step with more onsets takes the rest late, as without the option), and no piece shorter than
// this fraction of the step (a pair that close starts with the piece: its onset is late by less).
constexpr int kMaxOnsetSplits = 4;
constexpr double kMinOnsetFraction = 0.01;

// Bullet's Dantzig solver's global failure flag: held around every call (world_multibody.cpp).
std::mutex& dantzig_flag();

// The step profile's clock (World::Profile): on x86-64 where the processor's time-stamp counter
// runs at a constant rate (CPUID's invariant-TSC bit), that counter, read in a few cycles
// instead of the kernel's clock (six reads a step cost ≈ 1 % of the paper step); its ticks
// become seconds at the ratio steady_clock shows over the same span, taken when the profile is
// read. Elsewhere steady_clock's own ticks.
class ProfileClock {
 public:
  ProfileClock();
  std::uint64_t now() const;
  // Seconds per tick: over the span since construction, against steady_clock.
  double seconds_per_tick() const;

 private:
  bool tsc_ = false;
  std::uint64_t tick0_ = 0;
  std::chrono::steady_clock::time_point t0_;
};

// A motor's target speed at time t: the ramp from rest reaches the target at ramp_time_s. A step
// from t to t + h constrains the speed at its end, so it asks for the target at t + h (until
// 2026-11-26 it asked for the one at t: every driven body ran one step behind its command, the
// sun 2.1e-3 rad at dt 2e-5 s on the paper set).
inline double motor_target_rad_s(const MotorDef& m, double t) {
  return m.target_speed_rad_s * (m.ramp_time_s > 0 ? std::min(1.0, t / m.ramp_time_s) : 1.0);
}
inline btVector3 bt(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }
inline Eigen::Vector3d eig(const btVector3& v) { return {v.x(), v.y(), v.z()}; }

struct JointRec {
  JointDef def;
  int body = -1, parent = -1;  // parent -1 = ground
  btTypedConstraint* constraint = nullptr;
  btJointFeedback feedback;
  btHingeConstraint* hinge = nullptr;
  btGeneric6DofSpring2Constraint* spring = nullptr;
  Eigen::Vector3d axis_world = Eigen::Vector3d::UnitZ();
  double last_raw = 0, unwrapped = 0;
  double angle_at_zero = 0;  // the multibody tree's joint angle at q = 0 (planar kinematics)
  const MotorDef* motor = nullptr;
  const LoadDef* load = nullptr;
};

// A tooth contact's identity from step to step: (pair, tooth_a, tooth_b, flank_a).
using ContactKey = std::tuple<int, int, int, int>;
inline ContactKey contact_key(int pair, const contact::ToothContact& c) { return {pair, c.tooth_a, c.tooth_b, static_cast<int>(c.flank_a)}; }
inline ContactKey contact_key(const ContactSample& c) { return contact_key(c.pair, c.geometry); }

struct PairRec {
  int a = -1, b = -1;
  btPersistentManifold* manifold = nullptr;
  GearPairInfo info;
  // Warm start per tooth pair: last step's impulse of each (tooth_a, tooth_b, flank_a), at most
  // kMaxPointsPerPair of them, searched in place (no allocation per step).
  std::vector<std::pair<std::tuple<int, int, int>, double>> last_impulse;
  std::vector<contact::ToothContact> found;                            // this step's, kept for its storage
  std::vector<contact::ToothContact> near;   // this step's near pairs (a gap of a few µm; solver.locate_contact_onset)
  std::vector<double> pair_stiffness;                         // per found contact, N/m (storage kept)
  std::vector<char> active;                                   // per found contact: passed to the solver
  std::vector<contact::ToothContact> current;                          // in manifold point order
  std::vector<double> current_stiffness_N_per_m;              // the stiffness each was given
  MeshStiffnessModel stiffness;  // how each touching tooth pair's stiffness is set
  contact::CoherentToothSearch search;  // the pair's flank records (contact.coherent_search)
};

// The `multibody` engine (world_multibody.cpp): the joint tree as one btMultiBody on a fixed base
// (reduced coordinates, Featherstone), and per step one direct solve of every row that is not a
// joint: tooth contacts (normal, friction), bearing springs, torsional springs, motors.
struct MultibodyRow {
  enum Kind { contact_normal, contact_friction, bearing, torsion, motor } kind = contact_normal;
  int owner = -1;       // contact_*: index into World::Impl::contacts; the others: joint index
  double cfm = 0;       // compliance of the implicit spring–damper, (N·s)⁻¹·… per unit impulse
  double target = 0;    // right-hand side before the predicted velocity is taken off
  double lo = 0, hi = 0;
  int friction_of = -1;  // contact_friction: the row of its normal (bounds ±μ times its impulse)
  double start_rate_weight = 0;  // trapezoidal spring rows: 1 (the start-of-step rate enters)
  double move_rate_weight = 0;   // BDF2 spring rows: k·h/(3σ) (the spring at the extrapolated position)
};

struct MultibodyEngine {
  std::unique_ptr<btMultiBody> tree;
  int dofs = 0;                       // joint coordinates, without the fixed base's six
  std::vector<int> link_of_body;      // per body: its link, −1 for the ground and fixed bodies
  std::vector<int> dof_of_joint;      // per joint: index of its spin coordinate among the dofs
  std::vector<btVector3> pivot_in_body, pivot_in_parent;  // per joint: bearing centre in the body's and the parent's frame (world for the ground)
  std::vector<double> motor_torque_N_m;                   // per joint, last step
  std::vector<MultibodyRow> rows;
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> jac;  // rows × dofs: jrows, on the articulated path
  Eigen::MatrixXd inverse_mass;                                                // dofs × dofs
  Eigen::MatrixXd minv_jt;                                                     // dofs × rows
  Eigen::VectorXd row_rate, row_rate_start, v_theta;  // per step, kept for their storage
  std::vector<double> a, b, x, w, lo, hi;
  std::vector<int> findex;
  btDantzigScratchMemory dantzig;
  std::vector<double> buf, out;  // 6 + dofs
  std::vector<double> v_start, v_end, v_mid;  // joint velocities at the step's start, end, mean
  bool sliding_friction = false;  // contact.friction_model sliding
  // sliding: per row, its slip's change over the step by the contact's travel (slip_drift()), m/s;
  // each friction row's tooth pair and slip at the step's end, this step's and the last's.
  std::vector<double> slip_drift;
  double slip_end_h = 0;
  // sliding: per row, the bracket of its friction share's root (world_friction.cpp): the shares
  // below and above it tried so far and the g they gave (g_lo > 0 > g_hi once both are known).
  struct SlipBracket {
    double lo = -1, g_lo = 0, hi = 1, g_hi = 0;
    int last = 0;  // which end the last round moved: +1 lo, −1 hi
  };
  std::vector<SlipBracket> slip_brackets;
  bool dv_of_x = false;  // buf[6…] holds M⁻¹·Jᵀ·x of this step's x (locate_slip_reversals left it)
  bool primal_dv_of_x = false;  // primal_dv is the velocity change of x: the dof-space solve settled x (solve_rows_planar)
  // Row i is friction held at a fixed multiple of its normal's impulse (lo = hi): no unknown of the solve.
  bool held_friction(std::size_t i) const { return findex[i] >= 0 && !(hi[i] > lo[i]); }
  std::vector<std::pair<ContactKey, double>> slip_end, slip_end_before;
  bool planar = false;            // every joint axis along z: rows from link_jac (world_multibody.cpp)
  std::vector<double> link_jac;   // per link: rows ω_z, v_x, v_y of its centre over the dofs
  // solver.mass_matrix planar on a planar tree (docs/solver.md, "The planar mass matrix"): the
  // links' Jacobians from their joints' axes (no tree walks); M = Σ m·(J_xᵀ·J_x + J_yᵀ·J_y) +
  // I_zz·J_ωᵀ·J_ω over the links, factored M = L·Lᵀ (Cholesky); per row g_i = L⁻¹·J_iᵀ, so that
  // A = Gᵀ·G and M⁻¹·Jᵀ·λ = L⁻ᵀ·(G·λ), without M⁻¹. Otherwise (articulated) M⁻¹ by articulated-
  // body solves, one per coordinate, and M⁻¹·Jᵀ (minv_jt).
  bool planar_mass = false;
  std::vector<double> link_mass_kg, link_izz_kg_m2;  // per link: mass, moment about z
  std::vector<std::vector<int>> link_chain;          // per link: it and its ancestors
  std::vector<std::vector<int>> link_dofs;           // per link: the coordinates that move it
  // Per coordinate: the z component of its joint's angular axis s_d, its linear axis b_d (world)
  // and the link it belongs to; per link, this step's spin rate and centre velocity (world).
  std::vector<double> dof_s, dof_bx, dof_by;
  std::vector<int> dof_link;
  std::vector<double> link_w, link_vx, link_vy;
  std::vector<double> gen_force;                     // dofs: Q − c of planar_free_velocities()
  // The planar kinematics (world_planar_kinematics.cpp): per link its parent, its joint's turn
  // about world z (σ = ±1) and vectors at q = 0 (world), its basis at q = 0; per link this
  // pose's turn φ, cos φ, sin φ; link_jac_current: link_jac is this pose's (the pose has not
  // moved since planar_forward_kinematics()). Per gear body its frame's in-plane x axis (unit)
  // and angle at q = 0; the fixed gears' poses.
  struct PlanarLink {
    int parent = -1;
    bool planar_joint = false;
    double sigma = 1, axis_length2 = 1;
    btMatrix3x3 basis0 = btMatrix3x3::getIdentity();
    btVector3 e0{0, 0, 0}, d0{0, 0, 0}, b1{0, 0, 0}, b2{0, 0, 0};
  };
  std::vector<PlanarLink> plinks;
  std::vector<double> link_phi, link_cos, link_sin;
  bool link_jac_current = false;
  std::vector<Eigen::Vector2d> gear_x0;
  std::vector<double> gear_angle0;
  std::vector<contact::PlanarPose> fixed_pose;
  // World::set_mass_matrix_check: the step's start coordinates, the velocities its positions
  // moved with and its length (check_planar_kinematics() steps Bullet from them).
  std::vector<double> check_q_start, check_v_positions;
  double check_h = 0;
  std::vector<double> bullet_qdd;                    // dofs: Bullet's q̈ at the same state (check_mass)
  std::vector<double> chol;                          // dofs × dofs, row-major: L (lower triangle)
  std::vector<double> chol_inv_diag;                 // dofs: 1 / L's diagonal
  std::vector<double> mass;                          // dofs × dofs, row-major: M (lower triangle)
  std::vector<double> g;                             // dofs × rows: G = L⁻¹·Jᵀ (planar_g(), when needed)
  bool g_formed = false;                             // e.g holds this step's G
  std::vector<double> g_lambda;                      // dofs: scratch (Jᵀ·λ and its substitutions; a row's L⁻¹·Jᵀ)
  std::vector<double> compliance;                    // per row: the compliance added to A's diagonal
  bool a_formed = false;                             // e.a holds this step's dense A (planar_full_a)
  // solve_rows_folded(): the rows kept (not friction held at a multiple of its normal), each row's
  // index among them (−1: held), their g and column vectors h, and the folded problem.
  std::vector<int> fold_kept, fold_index, fold_findex;
  std::vector<double> fold_g, fold_h, fold_a, fold_b, fold_lo, fold_hi, fold_x;
  std::vector<RowBound> fold_states;
  // solve_rows_primal() (world_primal_solve.cpp): per row its unknown's index (−1: a constant or
  // a folded friction row), the unknowns' rows, whether each is stiff (no spring: solved by its
  // Schur complement), their folded columns by unknown (unknowns × dofs), the constant rows'
  // impulses on the coordinates, K and its LU pivots, and the solutions.
  std::vector<int> primal_unknown, primal_rows, primal_pivots, primal_stiff, primal_stiff_pivots;
  std::vector<double> primal_cols, primal_const, primal_k, primal_rhs, primal_y, primal_s, primal_t, primal_dv, primal_w;
  std::vector<char> primal_soft;  // per row: a spring soft enough for K (else stiff)
  std::vector<RowBound> primal_states_before;
  std::vector<double> primal_x_check;
  std::vector<RowBound> primal_states_check;
  bool check_mass = false;                           // World::set_mass_matrix_check
  World::MassMatrixCheck mass_check;
  std::vector<double> jrows;      // this step's row Jacobians, row-major (e.jac: the same, articulated path only)
  // Row i of this step's Jacobian times v (one entry per coordinate), summed in coordinate order.
  double row_dot(std::size_t i, const double* v) const {
    const std::size_t ud = static_cast<std::size_t>(dofs);
    const double* j = jrows.data() + i * ud;
    double s = 0;
    for (std::size_t k = 0; k < ud; ++k) s += j[k] * v[k];
    return s;
  }
  // rates = J·v over this step's rows.
  void rows_times(const double* v, Eigen::VectorXd& rates) const {
    rates.resize(static_cast<Eigen::Index>(rows.size()));
    for (std::size_t i = 0; i < rows.size(); ++i) rates[static_cast<Eigen::Index>(i)] = row_dot(i, v);
  }
  double theta = 1;  // spring rows at s + θ·h·ṡ_θ, positions with (1 − θ)·v + θ·v⁺; 1: implicit Euler
  // BDF2 (solver.integrator bdf2): v⁺ = v̂ + h_eff·M⁻¹·F(x⁺, v⁺), x⁺ = x + h·v_move with
  // v̂ = (4v − v_prev)/3, h_eff = 2h/3, v_move = (v_move_prev + 2v⁺)/3 (so x⁺ = (4x − x_prev)/3 +
  // h_eff·v⁺); implicit Euler (h_eff = h, v_move = v⁺) until there is a step behind.
  bool bdf2 = false, has_history = false;
  bool trapezoid_closed = false;  // θ per step: ½ while every contact stays closed, else 1
  std::vector<ContactKey> touching, touching_before;  // (pair, tooth_a, tooth_b, flank_a) this step, the last
  double h_eff = 0;                    // this step's h_eff (h for the θ-method)
  double h_step = 0;                   // this (sub)step's length, s
  // solver.locate_contact_onset: a step in which a near tooth pair closes is split at the
  // instant it touches (at most kMaxOnsetSplits times); the sub-steps' impulses summed per
  // contact (the step's forces: their sum over h), its power flows and motor torques averaged.
  bool locate_onset = false;
  struct Accumulated {
    std::vector<ContactSample> contacts;  // impulse-weighted: normal_force_N · h_sub summed
    PowerFlows power;
    std::vector<double> motor_torque;
  } accumulated;
  std::vector<double> v_prev, v_move;  // BDF2: v at the last step's start; the last step's v_move
  Eigen::VectorXd row_rate_move;       // BDF2: J·v_move of the last step (the spring's extrapolation)
  btAlignedObjectArray<btScalar> scratch_r;
  btAlignedObjectArray<btVector3> scratch_v;
  btAlignedObjectArray<btMatrix3x3> scratch_m;
  btAlignedObjectArray<btQuaternion> world_to_local;
  btAlignedObjectArray<btVector3> local_origin;
  std::vector<btVector3> omega, vel;
  long failed_solves = 0;
  // solver.row_solver active_set: each row's identity (kind and contact or joint) and bound state,
  // this step's and the last's (the warm start).
  bool active_set = false;
  std::vector<std::array<int, 5>> row_keys, row_keys_before;
  std::vector<RowBound> row_states, row_states_before;
  RowLcpScratch lcp;
};

struct World::Impl {
  Scenario scenario;
  btDefaultCollisionConfiguration config;
  btCollisionDispatcher dispatcher{&config};
  btDbvtBroadphase broadphase;
  btSequentialImpulseConstraintSolver solver;
  btDiscreteDynamicsWorld world{&dispatcher, &broadphase, &solver, &config};
  std::vector<BuiltBody> bodies;
  std::vector<JointRec> joints;
  std::vector<PairRec> pairs;
  std::vector<BodyState> states;
  std::vector<ContactSample> contacts;
  std::vector<contact::PlanarPose> gear_poses;  // this step's, per body (gears only)
  std::vector<contact::CoherentToothSearch::PlanarTwist> gear_twists;  // the same, their velocities (parking near pairs only)
  std::vector<GearPairInfo> pair_infos;
  std::map<std::string, int> body_index;
  double time = 0;
  long steps = 0;
  double max_penetration = 0;
  long dropped_points = 0;
  long table_misses = 0;
  // The profile: its counts here, its times as ProfileClock ticks (World::profile() turns them
  // into seconds).
  World::Profile profile;
  ProfileClock clock;
  std::uint64_t tooth_contact_ticks = 0, row_solve_ticks = 0, step_total_ticks = 0;
  PowerFlows power;
  std::unique_ptr<MultibodyEngine> mb;  // solver.engine multibody

  // Takes constraints, manifolds and bodies out of Bullet's world before its members go: also
  // when World's constructor throws half way (then ~World never runs, but ~Impl does).
  ~Impl();

  // Building (world.cpp), in this order.
  void add_bodies();
  void add_joints();
  void attach_drives();
  void find_pairs();
  void check_start();
  // Stepping (world_step.cpp).
  void build_multibody();
  void generate_contacts();
  void pair_stiffnesses(PairRec& pr);
  void add_manifold_points(PairRec& pr, double z);
  double contact_damping(const PairRec& pr, double k) const;
  void apply_motors_and_loads();
  void apply_impulses();
  void measure();  // joints (from the bodies' transforms), then contacts of the rigid-body engine
  void measure_joints();
  double joint_raw_angle(const JointRec& j) const;
  void measure_contacts();
  void measure_power();
  double kinetic_energy_J() const;
  double impulse_power_W(double h) const;  // of the pulses in the (sub)step of length h just taken
  void step_multibody();
  void advance_multibody(double h);  // one (sub)step from the contacts generate_contacts() found
  contact::CoherentToothSearch::PlanarTwist gear_twist(std::size_t body) const;
  double contact_onset_s(double within_s) const;  // when the first near pair touches (≥ within_s: none)
  void accumulate_substep(double h, bool first);
  void finish_split_step(double h);
  void multibody_rows();
  MultibodyRow spring_row(double k, double c, double force0) const;
  double trapezoid_closed_theta();
  void solve_multibody_rows();
  void build_planar_mass();
  void planar_link_jacobians();
  void planar_mass_factor();
  void planar_free_velocities(double h);
  double planar_diag_a(std::size_t row);
  void planar_full_a();
  int solve_rows_folded();
  void planar_soft_rows();  // per row: soft spring (into K) or stiff, for solve_rows_primal()
  template <int N>
  void planar_soft_rows_n();  // N coordinates (0: e.dofs), physics/dof_dispatch.hpp
  int solve_rows_primal();
  int solve_rows_planar();  // solve_rows_primal(), solve_rows_folded() where it does not settle
  void planar_g();
  void check_planar_mass(const double* m_lower);
  void build_planar_kinematics();
  void planar_step_positions(double h, const double* v);
  void planar_forward_kinematics();
  void planar_link_velocities(const double* u);
  void planar_finish_step();
  void planar_measure_joints();
  contact::PlanarPose planar_gear_pose(std::size_t body) const;
  void check_planar_kinematics();
  bool solve_rows_dantzig_fixed_friction();
  // dv = M⁻¹·Jᵀ·λ over this step's rows (λ: one impulse per row; dv: dofs entries).
  void velocity_change(const double* lambda, double* dv);
  void velocity_change_of_x(double* dv);  // of e.x: the dof-space solve's where it found x, else velocity_change()
  bool locate_slip_reversals(bool solved);
  double slip_drift(int row, double slip_start_m_s, std::size_t& hint) const;
  bool solve_rows_active_set();
  void multibody_results();
};

// Gear-frame pose projected on the common plane (the gear axes must be parallel to world z): its
// angle from the gear frame's x axis, and that axis normalised in the plane as the angle's cosine
// and sine (the same rotation to rounding, without libm's sincos of an angle that grows with
// every turn).
inline contact::PlanarPose planar_pose(const BuiltBody& b) {
  const btTransform t = b.rigid->getWorldTransform() * b.com_from_gear;
  const btVector3 x = t.getBasis().getColumn(0);
  contact::PlanarPose p{{t.getOrigin().x(), t.getOrigin().y()}, std::atan2(x.y(), x.x())};
  const double length = std::sqrt(x.x() * x.x() + x.y() * x.y());
  p.cos_angle = x.x() / length;
  p.sin_angle = x.y() / length;
  p.rotation_of_rad = p.angle_rad;
  return p;
}

}  // namespace gearsim::physics

// Scenario: the validated description of one simulation run, as plain structs with defaults, in
// SI units. app/ parses scenario files into it; physics/ builds a world from it. Nothing here
// reads files or knows YAML. Not the running world: see world.hpp.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "geometry/convex_decomposition.hpp"
#include "geometry/gear_recognition.hpp"
#include "geometry/gear_spec.hpp"
#include "geometry/involute_pair.hpp"
#include "geometry/mesh_io.hpp"
#include "geometry/planetary.hpp"
#include "contact/stiffness_table.hpp"

namespace gearsim::physics {

// Where a body is at t = 0: origin of its body frame in the world, and its orientation.
struct Pose {
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
};

// A body's shape from a CAD mesh file. A gear mesh names its tooth layout so that contacts know
// which tooth touched (tooth k centred at tooth0_angle_rad + k·2π/teeth about the body's z axis).
struct MeshSource {
  std::filesystem::path path;
  LengthUnit unit = LengthUnit::Millimetre;
  // The tooth layout the contact uses (none: a toothless body). Given in the scenario and
  // checked against the mesh, or recognised from it (teeth_recognised).
  std::optional<ToothLayout> teeth;
  bool teeth_recognised = false;
  std::optional<RecognisedGear> recognised;  // the mesh as a gear (set when the scenario was read)
};

struct BodyDef {
  std::string name;
  std::optional<GearSpec> gear;  // a generated gear (its errors included) ...
  std::optional<MeshSource> mesh;  // ... or a mesh file; neither: a carrier-like body without shape
  // Mass from density and the shape's volume, or given directly with its inertia about the
  // centre of mass (for shapeless bodies such as a carrier arm).
  std::optional<double> density_kg_m3;
  std::optional<double> mass_kg;
  // With mass_kg: the moments about the centre of mass in the body's own axes (z the gear axis).
  // Required for a shapeless body; for a gear or mesh it replaces the shape's own inertia (a
  // lumped model's member whose hub, shaft or rim the shape does not hold).
  std::optional<Eigen::Vector3d> principal_inertia_kg_m2;
  Pose pose;
  bool fixed = false;  // welded to the ground (a fixed ring gear)
};

// A compliant support: the joint's pivot may move perpendicular to its axis against an isotropic
// radial spring and damper, and (torsional_stiffness > 0) the body's turn relative to its parent
// is held by a torsional spring and damper (a ring gear held against rotation, a flexible
// coupling). Torsional 0: free to turn, as a hinge.
// radially_rigid: a shaft or coupling between coaxial members instead: the pivot held as by a
// hinge (no radial spring), only the turn relative to the parent elastic.
struct BearingDef {
  double radial_stiffness_N_per_m = 0;
  double radial_damping_N_s_per_m = 0;
  double torsional_stiffness_N_m_per_rad = 0;
  double torsional_damping_N_m_s_per_rad = 0;
  bool radially_rigid = false;
};

// A revolute joint of `body` about `axis` through `pivot_m` (world, at t = 0), to `parent`
// ("ground" or another body's name).
struct JointDef {
  std::string name;
  std::string body;
  std::string parent = "ground";
  Eigen::Vector3d pivot_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();
  std::optional<BearingDef> bearing;  // none: a rigid hinge
};

// Drives a joint at a target speed, reached by a linear ramp, with a torque limit.
struct MotorDef {
  std::string joint;
  double target_speed_rad_s = 0;
  double ramp_time_s = 0;
  double max_torque_N_m = 0;
};

// Torque on a joint's body about the joint axis, opposing nothing in particular: a constant
// part (sign as given, positive about +axis), reached by a linear ramp like a motor's so that a
// light gear is not flung into its mate before contact forms, and a viscous part −c·ω
// (relative to the parent).
struct LoadDef {
  std::string joint;
  double constant_torque_N_m = 0;
  double viscous_N_m_s_per_rad = 0;
  double ramp_time_s = 0;  // s; 0: the whole constant torque from t = 0
};

// The load's torque at time t on a joint turning at `speed_rad_s`, N·m.
inline double load_torque_N_m(const LoadDef& l, double time_s, double speed_rad_s) {
  const double ramp = l.ramp_time_s > 0 && time_s < l.ramp_time_s ? time_s / l.ramp_time_s : 1.0;
  return ramp * l.constant_torque_N_m - l.viscous_N_m_s_per_rad * speed_rad_s;
}

// A force and torque pulse on a body, to excite its model's modes (an impact hammer): a half
// sine from at_s over duration_s, peaking at force_N (world axes, at the centre of mass) and
// torque_N_m (world axes). Its impulse is (2/π)·peak·duration; its spectrum is flat to within
// 3 dB up to ≈ 0.6/duration_s.
struct ImpulseDef {
  std::string body;
  double at_s = 0;
  double duration_s = 0;
  Eigen::Vector3d force_N = Eigen::Vector3d::Zero();
  Eigen::Vector3d torque_N_m = Eigen::Vector3d::Zero();
};

// The pulse's share of its peak at time t (0 outside it).
inline double impulse_shape(const ImpulseDef& i, double time_s) {
  if (time_s < i.at_s || time_s >= i.at_s + i.duration_s) return 0.0;
  return std::sin(3.14159265358979323846 * (time_s - i.at_s) / i.duration_s);
}

// A virtual accelerometer on a housing body (a ring gear, or any body the meshes are fixed to):
// the McFadden & Smith (1985) model. Each tooth contact's normal force reaches it through a
// path whose gain depends on where the contact is: for the meshes on `body`, a Hann window
// w(Δ) = ½(1 + cos(2πΔ/width)) of the angle Δ between the contact point and the sensor about the
// body's centre (1 under the sensor, 0 beyond ±width/2: planet-pass modulation), for every other
// mesh a constant `other_meshes_weight` (the path through shafts and bearings). The summed
// force e(t) (N) drives the housing's structural mode: acceleration A(s) = s²/(s² + 2ζω_r s +
// ω_r²) · E(s)/m_eff (the acceleration of a mass m_eff on that mode's spring, the static part
// gone), integrated with the bilinear transform at the simulation step; then measurement noise
// (seeded, rms noise_rms_m_s2) and an anti-aliasing filter before sampling at sample_rate_hz.
struct SensorDef {
  std::string name;
  std::string body;  // the housing body the sensor sits on (its centre at t = 0)
  double angle_rad = 0;  // sensor position about the body's centre, from world +x
  double window_width_rad = 0;  // full width of the planet-pass window, (0, 2π]
  double other_meshes_weight = 0;  // path gain of meshes not on `body`, (dimensionless)
  double resonance_hz = 0;  // the structural mode the sensor sees
  double damping_ratio = 0.05;  // of that mode
  double effective_mass_kg = 0;  // its modal mass: 1/m_eff is the high-frequency gain, m/s² per N
  double noise_rms_m_s2 = 0;  // white measurement noise added at the sensor rate
  double sample_rate_hz = 0;  // the acquisition rate (a whole number of steps)
};

// The stiffness table of the meshes between two gear bodies (by body name): the contact radius
// is measured on body_a, whichever of the two the world puts first.
// body_stiffness_N_per_m (0: none) is the compliance of the two gear bodies between their bores
// and the teeth, in series with all tooth pairs of the mesh at once, along the line of action:
// with n pairs in contact the mesh stiffness is 1/(1/(n k) + 1/k_body) (the FE series fit,
// docs/fe-reference.md), so each pair is given k / (1 + n k / k_body). Exact for the mesh's total force.
struct PairStiffnessDef {
  std::string body_a, body_b;
  contact::StiffnessTable table;
  double body_stiffness_N_per_m = 0;
};

// A constant mesh stiffness for the meshes between two gear bodies (by name), N/m along the line
// of action: the tooth pairs in contact share it equally (n pairs: k/n each), so the mesh's
// stiffness does not vary as pairs come and go — the time-invariant mesh of lumped models (Lin &
// Parker 1999). Neither this nor a stiffness table: each pair has the constant per face width.
struct PairMeshStiffnessDef {
  std::string body_a, body_b;
  double stiffness_N_per_m = 0;
};

// Tooth contact: a compliant, damped, unilateral contact with one point per tooth pair.
struct ContactDef {
  // Single-pair tooth stiffness per face width, N/m per m (ISO 6336 c' ≈ 14 N/(mm·µm) = 1.4e10).
  double stiffness_N_per_m_per_m = 1.4e10;
  // Pairs listed here take the stiffness of each contact from their table at the contact's
  // radius on body_a instead (the damping follows from it); the others keep the constant.
  std::vector<PairStiffnessDef> stiffness_tables;
  std::vector<PairMeshStiffnessDef> mesh_stiffnesses;  // pairs with a constant mesh stiffness
  double damping_ratio = 0.05;  // of the pair's critical damping along the line of action
  double friction = 0.0;  // Coulomb coefficient on the flanks
  // How the multibody engine applies it (docs/solver.md, "Friction at the pitch point").
  // `sliding`: μ·λ_n against the sliding velocity, whose sign over the step is taken from the
  // contact's slip at the step's start and its change over the last step; in the step where the
  // slip reverses (the pitch point) the impulse is μ·λ_n times the share of the step on each side
  // of the reversal. No sticking: gear flanks slide by their kinematics everywhere but at the
  // pitch point. `stick_slip`: one friction row per contact with the bounds ±μ·λ_n, which sticks
  // where the step's impulse can stop the slip (a band of steps around the pitch point, the same
  // number of steps whatever their length) and reverses at the first step that ends sliding the
  // other way: the reversal's timing is quantised to the step, and the paper's faulty set
  // converges slowly in the step with it (the default until 2026-11-27). Both tend to the same
  // answer as the step shrinks. rigid_bodies: Bullet's friction, stick_slip (the parser sets it).
  enum class FrictionModel { sliding, stick_slip } friction_model = FrictionModel::sliding;
  // Chordal deviation of the outline the flank tables are built from. The tables interpolate
  // the outline's vertices (which lie on the true flanks) with cubics, so the default outline
  // already resolves depths to ~2 nm (tests/physics/test_tooth_contact.cpp).
  double chordal_deviation_m = 0.5e-6;
  // A gear whose flank table strays further than this from the outline it was built from
  // (FlankTable::departure) is refused, m: beyond it the contact no longer acts on the mesh's
  // teeth. 2 µm: the static deflection of a loaded mesh, ten times a CAD export's resolution.
  double max_flank_departure_m = 2e-6;
  // Tooth contact with temporal coherence (contact/coherent_contact.hpp): a flank whose last
  // search left it clear is skipped until the pair's relative motion could have closed the gap.
  // The same contacts as the stateless search (false), found faster.
  bool coherent_search = true;
  // Continuation on top of it (CoherentToothSearch::set_continuation): a flank whose contact was
  // solved by Newton's method last step is solved again from there without probing, where the
  // solution stays smooth and shallow. The stateless search's contacts to ~0.1 nm, not bit for
  // bit (docs/tooth-contact.md, "Continuation"). Part of coherent_search: off without it. With a
  // CAD mesh in the pair, the deeper of the continued and the searched contact.
  bool continued_search = true;
  // Near pairs parked on top of the continuation (CoherentToothSearch::set_park_near_pairs): a
  // continued pair with a gap is not solved again while a bound proves it still apart and (with
  // verify.locate_contact_onset) unable to close within two steps (docs/tooth-contact.md, "Near
  // pairs: the osculating-circle bound"). Part of continued_search: off without it.
  bool park_near_pairs = true;
};

// How Bullet advances the bodies. `rigid_bodies`: each body a btRigidBody, joints, bearings,
// motors and tooth contacts rows of the sequential-impulse solver (`iterations` sweeps).
// `multibody`: the joint tree in reduced coordinates (btMultiBody, Featherstone), joints exact by
// construction; tooth contacts (with friction), bearing springs and motors rows of one direct
// (Dantzig) solve per step, exact whatever `iterations` says (physics/multibody_engine.hpp).
enum class SolverEngine { rigid_bodies, multibody };

struct SolverDef {
  double time_step_s = 2e-5;
  int iterations = 50;
  SolverEngine engine = SolverEngine::multibody;
  // multibody, integrator `theta`: the θ-method for the spring–damper rows (contacts, bearings):
  // forces at s + θ·h·ṡ_θ, positions advanced with (1 − θ)·v + θ·v⁺. θ = 1 is implicit Euler, as
  // Bullet's own contact ERP/CFM: first order, damps every mode of period ≲ 2π·h heavily. θ < 1 is
  // closer to second order (½: the trapezoidal rule) but gains energy where contacts open and
  // close (docs/solver.md, "θ"). Giving `theta` without `integrator` chooses this integrator.
  double theta = 1.0;
  // multibody: `trapezoid_closed` (the default): θ chosen per step — ½ (the trapezoidal rule:
  // second order, no numerical damping) unless a tooth contact is new; then ½ plus just the
  // damping that takes out the energy its late detection added (docs/solver.md, "θ that follows
  // the contacts").
  // `theta`: the θ-method above. `bdf2`: the two-step backward differentiation formula, second
  // order and, like implicit Euler, damping the modes the step does not resolve (docs/solver.md,
  // "BDF2"); its first step is implicit Euler.
  enum class Integrator { theta, bdf2, trapezoid_closed } integrator = Integrator::trapezoid_closed;
  // multibody: how the step's rows are solved. `active_set` (the default): an active-set
  // iteration warm-started from the last step's row states, exact in the friction coupling,
  // falling back to Dantzig when it does not settle; `dantzig`: Bullet's Dantzig LCP solver
  // alone (docs/solver.md, "The row solve").
  enum class RowSolver { active_set, dantzig } row_solver = RowSolver::active_set;
  // multibody: how the rows' Jacobians and the inverse mass they need are found. `planar` (the
  // default; used where every joint turns about z, otherwise `articulated`): each link's
  // Jacobian from its joints' axes, the mass matrix from them and its Cholesky factor;
  // `articulated`: Bullet's Jacobian tree walks and one articulated-body solve per coordinate
  // for M⁻¹ (docs/solver.md, "The planar mass matrix"). The same equations; results differ by
  // rounding.
  enum class MassMatrix { planar, articulated } mass_matrix = MassMatrix::planar;
  // multibody with the θ-method or trapezoid_closed: a step in which a tooth pair a few µm apart
  // (the search's near pairs) closes at its present rate of approach is split at the instant it
  // touches (plus 1 % of the step, at most 4 splits), so the contact starts with its spring at
  // rest, not up to a step late with a depth no work put in (docs/solver.md, "Contact onset").
  // false (and always for rigid_bodies and bdf2, which the parser records): contacts start at the
  // first step that begins with the teeth overlapping.
  bool locate_contact_onset = true;
};

inline const char* engine_name(SolverEngine e) { return e == SolverEngine::multibody ? "multibody" : "rigid_bodies"; }
inline const char* row_solver_name(SolverDef::RowSolver r) { return r == SolverDef::RowSolver::dantzig ? "dantzig" : "active_set"; }
inline const char* mass_matrix_name(SolverDef::MassMatrix m) { return m == SolverDef::MassMatrix::articulated ? "articulated" : "planar"; }
inline const char* friction_model_name(ContactDef::FrictionModel f) {
  return f == ContactDef::FrictionModel::stick_slip ? "stick_slip" : "sliding";
}
inline const char* integrator_name(SolverDef::Integrator i) {
  return i == SolverDef::Integrator::bdf2 ? "bdf2" : i == SolverDef::Integrator::trapezoid_closed ? "trapezoid_closed" : "theta";
}

struct OutputDef {
  double sample_rate_hz = 2000;  // state.csv and contacts.csv rate
  bool per_step_log = true;  // the binary per-step contact log
};

// How transmission error is formed: te = θ_input − ratio·θ_output.
struct TransmissionDef {
  std::string input_joint;
  std::string output_joint;
  double ratio = 0;  // θ_input/θ_output of the ideal train
};

// Frames and a video rendered from the run when it ends (`gearsim render` takes the same
// settings from its command line). Read by app/, not by the simulation.
struct RenderDef {
  std::string camera = "overview";  // overview, tilted, sun_mesh, ring_mesh
  int fps = 30;  // video frames per second
  double slowmo = 1;  // the video plays this many times slower than simulated time
  std::optional<double> from_s, to_s;  // simulated span, s (default: all that was logged)
  int width_px = 1280, height_px = 720;
  int msaa = 0;  // multisampling samples (2 to 16); 0: edge anti-aliasing instead
  int png_every = 10;  // every Nth frame also as PNG under DIR/frames/ (0: none)
};

// The gears the `planetary:` macro built the train from (for tools that need the train itself,
// such as the finite-element loaded TE). Read by app/, not by the simulation.
struct PlanetaryTrainDef {
  PlanetarySpec spec;  // sun, healthy planet, ring, planet count
  std::vector<GearSpec> planet_gears;  // one per planet, faulty ones included
  bool ring_fixed = true;
};

// `fe:` — the quasi-static loaded transmission error by finite elements (`gearsim fe-te`),
// CalculiX + Gmsh. Read by app/, not by the simulation; the reader fills every field (defaults in
// fe/constants.hpp).
struct FeTeDef {
  double flank_size_m = 0;  // element size along flanks and fillets, m
  double core_size_m = 0;  // element size in the gear bodies, m
  double transition_m = 0;  // distance over which the size grows, m
  double max_sagitta_m = 0;  // largest distance of a boundary edge from the outline, m
  double thinning_per_flank_m = 0;  // added to every gear's own thinning (backlash), m
  double sun_torque_N_m = 0;  // input torque on the sun, N·m
  std::string torque_source;  // where sun_torque_N_m came from (for the summary)
  double friction = 0;  // flank Coulomb coefficient
  std::string element_type;  // CPS4R (paper) or CPS4
  int positions_per_mesh = 0;  // solves per mesh period
  double mesh_periods = 0;  // mesh periods swept (centred on planet 0's tooth 0)
  int jobs = 0;  // ccx processes at once
};

// A pair macro's gear-table figures at the centre distance it used (involute_pair.hpp): what the
// run summary reports of the mesh before any dynamics.
struct PairTableDef {
  std::string driver, driven;
  bool centre_distance_derived = false;  // placed from the teeth (place_pair), not given
  InvolutePair figures;
  std::string placement_note;  // why a derived distance is not the fits' zero-backlash one
};

struct Scenario {
  std::string name;
  std::filesystem::path source;  // the file it came from
  double duration_s = 0;
  std::uint64_t seed = 0;
  std::vector<BodyDef> bodies;
  std::vector<JointDef> joints;
  std::vector<MotorDef> motors;
  std::vector<LoadDef> loads;
  std::vector<ImpulseDef> impulses;
  std::vector<SensorDef> sensors;  // all at one sample rate (sensors.csv)
  ContactDef contact;
  SolverDef solver;
  OutputDef output;
  std::optional<TransmissionDef> transmission;
  // The gear-set spec file a macro (planetary, pair) generated its gears from; empty otherwise.
  // For reports that show the gear table; the simulation does not read it.
  std::filesystem::path gearset_spec;
  // What the scenario reproduces: "paper" — the reference paper's gearbox (the report then sets
  // the paper's figures beside the run's); "" — the user's own gearbox. Read by app/ only.
  std::string reference;
  std::optional<RenderDef> render;
  std::optional<PlanetaryTrainDef> planetary;  // set by the planetary macro
  std::optional<FeTeDef> fe;  // the `fe:` section, when given
  std::vector<PairTableDef> pair_tables;  // set by the pair macro
};

// When every motor and load has reached its target (the end of the longest ramp), s: steady
// figures (mean speeds, power balance, spectra) are taken after it.
inline double ramps_end_s(const Scenario& s) {
  double t = 0;
  for (const MotorDef& m : s.motors) t = t > m.ramp_time_s ? t : m.ramp_time_s;
  for (const LoadDef& l : s.loads) t = t > l.ramp_time_s ? t : l.ramp_time_s;
  return t;
}

}  // namespace gearsim::physics

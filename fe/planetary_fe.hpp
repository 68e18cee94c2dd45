// Loaded transmission error of a simple planetary set by finite elements: one CalculiX solve per
// quasi-static position (planetary_positions.hpp places and closes the set in the carrier frame;
// the carrier is held, the ring rim fixed, the input torque on the sun), plane stress, contact
// pairs on every sun–planet and planet–ring mesh. Not a dynamics model and not a report.
#pragma once

#include <filesystem>
#include <functional>
#include <utility>
#include <vector>

#include "geometry/planetary.hpp"
#include "fe/gear_mesher.hpp"

namespace gearsim::fe {

struct PlanetaryFeDef {
  PlanetarySpec spec;  // sun, healthy planet, ring, planet count
  std::vector<GearSpec> planet_gears;  // one per planet (errors included); empty: all spec.planet
  MeshSizingDef sizing;  // element sizes (paper: 0.4 mm at the flanks)
  double sun_torque_N_m = 4.0;  // input torque on the sun about +z, N·m
  double friction = 0.03;  // flank Coulomb coefficient (paper: 0.03)
  std::string element_type = "CPS4R";  // paper: CPS4R
  std::string ccx = "ccx";  // solver executable
};

// The tooth a sweep follows: the first planet tooth with a manufacturing error (flank offset,
// profile slope on one tooth, pitch error; in planet order), else planet 0's tooth 0. Its
// sun-side contact force and root stresses are reported at every position.
struct TrackedTooth {
  int planet = 0;
  int tooth = 0;
  bool faulty = false;  // whether it carries an error
};
TrackedTooth tracked_tooth(const PlanetaryFeDef& def);

// Stresses in the root of one side of a tooth (the quads along its fillet and root land, their
// integration points: CPS4R has one, at the element centre, so a fillet value lies half an
// element inside the surface), Pa. Plane stress: σ1 ≥ σ2 the in-plane principal stresses.
struct RootStress {
  int tooth = 0;  // tooth of the tracked planet
  Flank side = Flank::Ccw;  // side of the tooth's centre line
  double sigma1_max_Pa = 0;  // largest tensile principal stress
  double sigma2_min_Pa = 0;  // most compressive principal stress
  double von_mises_max_Pa = 0;
  double sigma1_max_low_Pa = 0;  // largest σ1 at the low load stage
  int elements = 0;  // quads in the set
};

// One solved position. TE = θ_sun − i·θ_carrier with the carrier held: the sun's rotation from
// its kinematic angle, rad.
//
// The FE boundary is straight edges between nodes on the exact outline; on the flanks those
// chords sit up to MeshSizingDef::max_sagitta_m inside the true curve, so the FE model's own
// geometric TE (its rigid clearance) is off by a few µm on the base circles and varies with the
// position. The loaded TE therefore takes its geometric part from the exact outlines (flank
// tables) and its load-dependent part from the FE, as the secant between the two load stages per
// N·m that the teeth take off the sun (ccx's CPS4R hubs keep a little of the torque: see
// sun_mesh_torque_N_m):
//   te_elastic = (te_fe_full − te_fe_low) / (M_full − M_low) · T  (linear contact and material)
//   te_loaded  = te_geometric + te_elastic.
// The raw FE values are kept beside it.
struct PlanetaryFePosition {
  double sun_turn_rad = 0;  // kinematic sun turn relative to the carrier
  double te_geometric_rad = 0;  // rigid teeth, exact outlines: the clearance the sun closed
  double te_fe_low_rad = 0;  // FE at kLowLoadFraction of the torque (raw, FE boundary)
  double te_fe_full_rad = 0;  // FE at the full torque (raw)
  double te_elastic_rad = 0;  // load-dependent part at the full torque (see above)
  double te_loaded_rad = 0;  // te_geometric_rad + te_elastic_rad
  // Torque the teeth take off the sun (moment of the contact forces about its centre), N·m, at
  // the full and the low stage. Below the applied torque by ccx's spurious hub stiffness of
  // CPS4R bodies times the sun's turn (measured 0.3–0.5 kN·m/rad for the paper's sun).
  double sun_mesh_torque_N_m = 0, sun_mesh_torque_low_N_m = 0;
  // Per planet, at the full torque: contact force magnitudes (N) and the planet's rotation (rad).
  std::vector<double> sun_planet_force_N, planet_ring_force_N, planet_rotation_rad;
  // Per planet, at the low stage.
  std::vector<double> sun_planet_force_low_N, planet_ring_force_low_N, planet_rotation_low_rad;
  // Per planet, secant mesh stiffness between the stages, N/m along the line of action: force
  // change over the change of the pair's approach (sun–planet: r_b,s Δθ_s + r_b,p Δθ_p;
  // planet–ring: −r_b,p Δθ_p, ring fixed). Includes the gear bodies between the rigid bores and
  // the teeth. NaN when the pair's approach did not change (open pair).
  std::vector<double> sun_planet_stiffness_N_per_m, planet_ring_stiffness_N_per_m;
  // Per planet: the sun's contact force on each planet tooth near the sun mesh at the full torque
  // (tooth index, N; every tooth within reach, loaded or not).
  std::vector<std::vector<std::pair<int, double>>> sun_mesh_tooth_force_N;
  TrackedTooth tracked;
  // Root stresses at the full torque of the tracked tooth's neighbour before it, the tracked
  // tooth and the neighbour after it (teeth t−1, t, t+1 of the tracked planet), Ccw then Cw side.
  std::vector<RootStress> tracked_root_stress;
  double wall_time_s = 0;  // ccx wall time
};

// The meshes of the set (made once; positions only move them).
struct PlanetaryFeMeshes {
  GearMesh sun, ring;
  std::vector<GearMesh> planets;
};
PlanetaryFeMeshes mesh_planetary(const PlanetaryFeDef& def);

// Solves one position in `work_dir` (deck, ccx log and results stay there). A folder that already
// holds a finished solve of the identical deck (position.inp, position.dat and position.done with
// the solve's wall time) is read instead of solved again: an interrupted sweep resumes where it
// stopped. Throws InputError for
// a bad definition and std::runtime_error quoting ccx when the solve fails.
PlanetaryFePosition solve_position(const PlanetaryFeDef& def, const PlanetaryFeMeshes& meshes, double sun_turn_rad,
                                   const std::filesystem::path& work_dir);

// Sun turns of a loaded-TE sweep over `mesh_periods` mesh periods (2π/z_s of sun turn relative
// to the carrier each), `positions_per_mesh` per period, centred on the turn at which the flank of
// the tracked tooth (tracked_tooth) that the sun loads passes the pitch point (so a faulty tooth
// passes through the middle of the sweep; on a healthy set every window is alike). Kinematic
// angles, rad.
std::vector<double> sweep_turns(const PlanetaryFeDef& def, int positions_per_mesh, double mesh_periods);

// Solves the positions, `jobs` ccx processes at a time, each in work_dir/pos_NNN. on_done(i, p)
// runs (one call at a time) as position i finishes. When a solve fails the running ones finish,
// then the first failure is rethrown; positions finished before stay reported through on_done.
std::vector<PlanetaryFePosition> solve_positions(const PlanetaryFeDef& def, const PlanetaryFeMeshes& meshes,
                                                 const std::vector<double>& turns_rad, const std::filesystem::path& work_dir, int jobs,
                                                 const std::function<void(std::size_t, const PlanetaryFePosition&)>& on_done = {});

}  // namespace gearsim::fe

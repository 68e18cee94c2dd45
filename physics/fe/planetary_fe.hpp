// Loaded transmission error of a simple planetary set by finite elements: one CalculiX solve per
// quasi-static position (planetary_positions.hpp places and closes the set in the carrier frame;
// the carrier is held, the ring rim fixed, the input torque on the sun), plane stress, contact
// pairs on every sun–planet and planet–ring mesh. Not a dynamics model and not a report.
#pragma once

#include <filesystem>
#include <vector>

#include "geometry/planetary.hpp"
#include "physics/fe/gear_mesher.hpp"

namespace gearsim::fe {

struct PlanetaryFeDef {
  PlanetarySpec spec;                  // sun, healthy planet, ring, planet count
  std::vector<GearSpec> planet_gears;  // one per planet (errors included); empty: all spec.planet
  MeshSizingDef sizing;                // element sizes (paper: 0.4 mm at the flanks)
  double sun_torque_N_m = 4.0;         // input torque on the sun about +z, N·m
  double friction = 0.03;              // flank Coulomb coefficient (paper: 0.03)
  std::string element_type = "CPS4R";  // paper: CPS4R
  std::string ccx = "ccx";             // solver executable
};

// One solved position.
struct PlanetaryFePosition {
  double sun_turn_rad = 0;        // kinematic sun turn relative to the carrier
  double te_unloaded_rad = 0;     // geometric TE: the clearance the sun closed (rigid teeth)
  double te_low_rad = 0;          // TE at the low load stage (kLowLoadFraction of the torque)
  double te_loaded_rad = 0;       // TE at the full torque: θ_sun − i·θ_carrier
  std::vector<double> sun_planet_force_N;   // per planet, contact force magnitude on the sun mesh
  std::vector<double> planet_ring_force_N;  // per planet, on the ring mesh
  std::vector<double> planet_rotation_rad;  // per planet, elastic rotation at full load
  double wall_time_s = 0;
};

// The meshes of the set (made once; positions only move them).
struct PlanetaryFeMeshes {
  GearMesh sun, ring;
  std::vector<GearMesh> planets;
};
PlanetaryFeMeshes mesh_planetary(const PlanetaryFeDef& def);

// Solves one position in `work_dir` (deck, ccx log and results stay there). Throws InputError for
// a bad definition and std::runtime_error quoting ccx when the solve fails.
PlanetaryFePosition solve_position(const PlanetaryFeDef& def, const PlanetaryFeMeshes& meshes,
                                   double sun_turn_rad, const std::filesystem::path& work_dir);

}  // namespace gearsim::fe

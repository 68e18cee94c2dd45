// Quasi-static finite-element mesh stiffness of one external spur pair (CalculiX, plane stress):
// the pinion drives (rigid hub at its bore, torque about +z), the wheel is held at its bore; at
// each pinion roll position the pinion turns at two load levels and the secant between them is the
// mesh stiffness along the line of action, k = ΔT / (r_b1² Δθ). Also the gear bodies' own torsion
// (a separate solve of each gear without contact), and the ISO 6336 and potential-energy references
// for the same pair. Not a dynamics model and not a report: numbers in SI.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "fe/gear_mesher.hpp"
#include "fe/potential_energy.hpp"
#include "fe/spur_pair_placement.hpp"

namespace gearsim::fe {

// The solve settings on top of the pair (spur_pair_placement.hpp).
struct SpurPairFeDef {
  SpurPairDef pair;
  MeshSizingDef sizing;  // element sizes (paper: 0.4 mm on the flanks)
  double friction = 0.03;  // flank Coulomb coefficient (paper: 0.03)
  std::string element_type = "CPS4R";  // CPS4R (paper) or CPS4
  // Pinion torque at the full load stage, N·m. Normally 10 N·m: F/b ≈ 100 N/mm on a 10 mm wide
  // z = 20, m = 1 mm pinion, the line load ISO 6336-1 takes its stiffness values at.
  double pinion_torque_N_m = 10.0;
  double low_load_fraction = kLowLoadFraction;  // the first load stage, fraction of the torque
  std::string ccx = "ccx";  // solver executable
};

// One tooth pair's share at one position.
struct SpurPairFePairLoad {
  int pinion_tooth = 0;
  double roll_m = 0;  // roll length of this pair's contact point on the pinion flank, m
  bool on_path = false;  // within the path of contact
  double fe_gap_m = 0;  // clearance of the mesh boundaries at the closed position, as the
      // wheel's further turn to touch times r_b2, m: 0 for the pair that
      // touches first, +inf when it would not touch within kMaxClosingTurn_rad
  double force_low_N = 0;  // contact force magnitude at the low load stage, N
  double force_full_N = 0;  // at the full load, N
};

// One solved position.
struct SpurPairFePosition {
  double roll_m = 0;  // the reference pair's roll length, m
  double wheel_closing_exact_rad = 0;  // wheel turn closing the backlash on the exact outlines
  double wheel_closing_fe_rad = 0;  // the same on the mesh boundaries (chords)
  double pinion_rotation_low_rad = 0;  // pinion turn from the closed position, low load stage
  double pinion_rotation_full_rad = 0;  // at the full torque
  // Torque the mesh carries: the applied torque less the pinion spring's
  // (kSpurPinionSpring_N_m_per_rad · rotation), N·m.
  double torque_low_N_m = 0, torque_full_N_m = 0;
  double contact_force_low_N = 0;  // magnitude of the total force of the wheel on the pinion
  double contact_force_full_N = 0;
  std::vector<SpurPairFePairLoad> pairs;
  int loaded_pairs = 0;  // pairs carrying > kLoadedPairShare of the full-load force
  double stiffness_N_per_m = 0;  // secant mesh stiffness along the line of action, bodies included
  double stiffness_per_width_N_per_m2 = 0;  // the same per face width (1e9 N/m² = 1 N/(mm·µm))
  double pe_stiffness_N_per_m = 0;  // potential-energy mesh stiffness at this position
  int pe_pairs = 0;  // pairs on the path of contact (PE counts these)
  double wall_time_s = 0;  // ccx wall time, s
};

// Torsion of one gear body without contact: the hub turned by a torque with every node of the
// toothed loop held. Its compliance in series with the mesh, as seen along the line of action,
// is r_b² · rotation_per_torque.
struct GearBodyTorsion {
  double rotation_per_torque_rad_per_N_m = 0;
  double line_of_action_compliance_m_per_N = 0;  // r_b² · rotation_per_torque
  double annulus_closed_form_rad_per_N_m = 0;  // T/(4πGb)(1/r_bore² − 1/r_root²) per unit T
  double wall_time_s = 0;
};

struct SpurPairMeshes {
  GearMesh pinion, wheel;
};
SpurPairMeshes mesh_spur_pair(const SpurPairFeDef& def);

// Throws InputError naming the field for a bad definition (checks the pair too).
void validate_spur_pair_fe(const SpurPairFeDef& def);

// Solves the position with the reference pair's contact at roll_m (on the path of contact) in
// work_dir (deck, ccx log and results stay there). Throws InputError for bad input and
// std::runtime_error quoting ccx when the solve fails.
SpurPairFePosition solve_spur_pair_position(const SpurPairFeDef& def, const SpurPairMeshes& meshes, double roll_m,
                                            const std::filesystem::path& work_dir);

// Torsion of the pinion (pinion = true) or wheel body, solved in work_dir.
GearBodyTorsion solve_gear_body_torsion(const SpurPairFeDef& def, const SpurPairMeshes& meshes, bool pinion,
                                        const std::filesystem::path& work_dir);

// Mesh stiffness with both bodies' torsion taken out (in series): 1/k − c_pinion − c_wheel, N/m.
double stiffness_without_body_torsion(double stiffness_N_per_m, const GearBodyTorsion& pinion, const GearBodyTorsion& wheel);

// The closed-form references for the pair, per face width in N/m² (1e9 N/m² = 1 N/(mm·µm)).
struct SpurPairReferences {
  double contact_ratio = 0;  // ε_α
  double iso_single_N_per_m2 = 0;  // c' (C_M = 0.8)
  double iso_single_theory_N_per_m2 = 0;  // c'_th
  double iso_mesh_N_per_m2 = 0;  // c_γα
  double iso_mesh_theory_N_per_m2 = 0;  // c'_th (0.75 ε_α + 0.25)
  double pe_mean_N_per_m2 = 0;  // potential-energy mean over a mesh period
  double pe_pitch_point_N_per_m2 = 0;  // one pair at the pitch point (PE)
};
// The potential-energy model takes Sainsot's h_f = r_f / r_bore of the actual bores.
PotentialEnergyPairDef potential_energy_def(const SpurPairDef& pair);
SpurPairReferences spur_pair_references(const SpurPairDef& pair);

}  // namespace gearsim::fe

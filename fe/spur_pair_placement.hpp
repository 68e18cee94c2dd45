// Quasi-static positions of one external spur pair for the FE mesh stiffness: the pinion at the
// origin turned so that a chosen tooth's driving (Ccw) flank meets the line of action at a given
// roll length, the wheel on +x at the standard centre distance, turned back (counter-clockwise)
// from the kinematic position until its flanks touch the pinion's, on the exact outlines and on the
// FE mesh boundaries (whose chords lie inside the curved flanks). Pure geometry (rigid flank-table
// probes), no FE. Not a dynamics model.
//
// Frame: pinion turns counter-clockwise when driving (+z torque), the wheel clockwise. The line of
// action runs from the pinion's base tangent point T1 = r_b1 (cos α, −sin α) in the direction
// n = (sin α, cos α); a contact point's roll length ℓ is its distance from T1 (the pinion flank's
// radius of curvature there): the path of contact runs from the wheel tip (ℓ_start) to the pinion
// tip (ℓ_end), and pinion tooth k meets the line one base pitch further per tooth.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "geometry/gear_dimensions.hpp"
#include "geometry/gear_spec.hpp"
#include "fe/constants.hpp"
#include "fe/quad_mesh.hpp"
#include "contact/tooth_contact.hpp"

namespace gearsim::fe {

// A standard (x = 0) external spur pair, both gears of the same steel.
struct SpurPairDef {
  int pinion_teeth = 20;  // z1, the driving gear
  int wheel_teeth = 31;  // z2, held at its bore
  double module_m = 1e-3;  // m, in m
  double pressure_angle_rad = 0.3490658503988659;  // α, normally 20°
  double face_width_m = 10e-3;  // b (plane-stress thickness), in m
  // Backlash allowance: every flank of both gears moved inward along its normal, m. Must be > 0:
  // without backlash each tooth wedges in its mate's space and the contact forces are preload.
  double thinning_per_flank_m = 20e-6;
  // Bore diameter over root diameter, both gears, dimensionless. Normally kSpurBoreOverRoot.
  double bore_over_root = kSpurBoreOverRoot;
};

// Throws InputError naming the field.
void validate_spur_pair(const SpurPairDef& def);

// The gear specs of the pair (pinion tooth 0 and the frame as described above).
GearSpec pinion_spec(const SpurPairDef& def);
GearSpec wheel_spec(const SpurPairDef& def);

// The path of contact along the line of action, in roll lengths ℓ, m.
struct SpurPairPath {
  double start_roll_m = 0;  // the wheel's tip circle
  double end_roll_m = 0;  // the pinion's tip circle
  double pitch_roll_m = 0;  // the pitch point, r_b1 tan α
  double base_pitch_m = 0;  // p_b
  double contact_ratio = 0;  // ε_α
  double pinion_base_radius_m = 0, wheel_base_radius_m = 0, centre_distance_m = 0;
};
SpurPairPath spur_pair_path(const SpurPairDef& def);

// n roll lengths spread over one base pitch from the start of the path, at the middles of n equal
// intervals (none on the wheel's tip corner), m.
std::vector<double> rolls_over_base_pitch(const SpurPairPath& path, int n);

// One pinion tooth near the mesh, the wheel space it sits in, and their mesh edges (the FE
// contact surfaces: the whole pinion tooth up to the centres of the spaces beside it; the wheel
// space up to the centre lines of the two wheel teeth around it).
struct SpurToothSlot {
  int pinion_tooth = 0;  // 0..z1−1
  int offset = 0;  // k: teeth ahead of the reference tooth (roll + k·p_b)
  int wheel_space = 0;  // the space between wheel teeth s (its Ccw flank) and s+1 (Cw flank)
  double roll_m = 0;  // roll length of this tooth's Ccw flank on the line of action, m
  bool on_path = false;
  // Clearance of this pair's mesh boundaries when the pair is closed, as the wheel's further turn
  // to touch times r_b2, m (0 for the pair that touches first, +inf when it would not touch
  // within kMaxClosingTurn_rad).
  double fe_gap_m = 0;
  std::vector<QuadEdge> pinion_edges, wheel_edges;
};

struct SpurPairPlacement {
  double roll_m = 0;  // the reference tooth's roll length, m
  contact::PlanarPose pinion, wheel;  // wheel closed on the mesh boundaries
  double wheel_closing_exact_rad = 0;  // wheel turn from kinematic to touching, exact outlines
  double wheel_closing_fe_rad = 0;  // the same on the mesh boundaries (chords between nodes)
  std::vector<SpurToothSlot> slots;  // pinion teeth within kSpurSlotMargin_basePitches of the path
};

// The pair placed with the reference tooth (pinion tooth 0) at roll_m, which must lie on the path
// of contact, and the wheel closed onto the pinion's Ccw flanks: on the exact outlines by the
// flank tables, on the meshes' boundary polygons exactly (the first turn at which a node of one
// mesh enters an edge of the other). Throws InputError for a roll off the path, or flanks that do
// not close within kMaxClosingTurn_rad.
SpurPairPlacement place_spur_pair(const SpurPairDef& def, const QuadMesh2& pinion_mesh, const QuadMesh2& wheel_mesh, double roll_m);

}  // namespace gearsim::fe

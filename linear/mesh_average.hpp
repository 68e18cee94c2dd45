// A gear mesh's stiffness averaged over its hunting period (every tooth of a against every tooth
// of b: lcm(z_a, z_b) pitches, `phases` positions per pitch, at most 65 536 positions), from the
// contact model itself: the two gears turned at their ideal ratio, the driven gear turned back
// against its load until its loaded flanks are pressed `deflection_m` deep, and every loaded
// tooth pair's stiffness (physics::tooth_pair_stiffnesses: the constant, a table, a shared mesh
// stiffness, bodies in series) taken along its own contact normal. Any spur gears: generated,
// CAD, with errors — the mean includes them.
#pragma once

#include <Eigen/Core>

#include "contact/flank_table.hpp"
#include "contact/tooth_contact.hpp"
#include "physics/tooth_pair_stiffness.hpp"

namespace gearsim::linear {

struct MeshGear {
  const contact::FlankTable* flanks = nullptr;
  contact::PlanarPose pose;  // gear frame at t = 0
  Eigen::Vector2d centre_of_mass_m = Eigen::Vector2d::Zero();
};

struct MeshAverage {
  // k̄ ḡ ḡᵀ: k̄ the mean of Σ_i k_i, ḡ the k-weighted mean of the contacts' g_i, the approach
  // of the flanks per unit motion of (x_a, y_a, θ_a, x_b, y_b, θ_b) (centre of mass translations
  // in m, turns in rad), its direction part a unit vector: one spring on the mean line of action.
  Eigen::Matrix<double, 6, 6> stiffness = Eigen::Matrix<double, 6, 6>::Zero();
  double mean_N_per_m = 0, min_N_per_m = 0, max_N_per_m = 0;  // Σ k_i over the period
  double mean_pairs = 0;  // loaded tooth pairs, mean
  Eigen::Vector2d mean_normal_on_b = Eigen::Vector2d::Zero();  // unit, from b toward a
  long samples = 0;  // mesh positions averaged
};

// `driven_is_b`: gear b is the one driven through this mesh (else a), and `driven_sense` (+1
// counter-clockwise, −1 clockwise) the sense of the torque its loaded flanks receive. Throws
// InputError when the loaded flanks never touch within a quarter pitch.
MeshAverage average_mesh(const MeshGear& a, const MeshGear& b, const physics::MeshStiffnessModel& model, bool driven_is_b, int driven_sense,
                         int phases, double deflection_m);

}  // namespace gearsim::linear

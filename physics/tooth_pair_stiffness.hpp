// The stiffness each touching tooth pair of a gear mesh is given: the constant per face width, a
// stiffness table's value at the contact radius, a constant mesh stiffness shared by the pairs,
// and gear bodies in series with them. One rule for the dynamics (World) and for the linearised
// model (linear/), so that both see the same mesh.
#pragma once

#include <vector>

#include "contact/stiffness_table.hpp"
#include "contact/tooth_contact.hpp"

namespace gearsim::physics {

struct MeshStiffnessModel {
  double pair_stiffness_N_per_m = 0;  // the constant per tooth pair
  const contact::StiffnessTable* table = nullptr;  // else this table's, radius on gear a (table_on_a) or b
  bool table_on_a = true;
  double face_width_m = 0;  // a table's stiffness is per face width
  double body_stiffness_N_per_m = 0;  // gear bodies in series with all pairs (0: rigid)
  double mesh_stiffness_N_per_m = 0;  // a constant mesh stiffness, shared (0: none)
};

// k[i] (N/m) and active[i] for each contact in `found`; `table_gear` is the pose of the table's
// gear. Returns how many contacts lay outside the table's radii (they took the nearest end row).
// Inactive contacts (unloaded once the bodies' compliance is in series) get no solver point.
long tooth_pair_stiffnesses(const MeshStiffnessModel& model, const std::vector<contact::ToothContact>& found,
                            const contact::PlanarPose& table_gear, std::vector<double>& k, std::vector<char>& active);

}  // namespace gearsim::physics

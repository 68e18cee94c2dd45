#include "physics/tooth_pair_stiffness.hpp"

namespace gearsim::physics {

long tooth_pair_stiffnesses(const MeshStiffnessModel& model, const std::vector<contact::ToothContact>& found,
                            const contact::PlanarPose& table_gear, std::vector<double>& k_pair, std::vector<char>& active) {
  long misses = 0;
  // Each pair's own stiffness: the constant, or its table's at the contact radius on the table's
  // gear (the point on that gear's own surface, half the depth from the overlap's mid-point).
  k_pair.assign(found.size(), model.pair_stiffness_N_per_m);
  if (model.table)
    for (std::size_t i = 0; i < found.size(); ++i) {
      const contact::ToothContact& c = found[i];
      const Eigen::Vector2d on = c.point_m + (model.table_on_a ? -0.5 : 0.5) * c.depth_m * c.normal_on_b;
      const contact::StiffnessLookup k = contact::stiffness_at(*model.table, (on - table_gear.centre_m).norm());
      k_pair[i] = k.stiffness_N_per_m_per_m * model.face_width_m;
      if (k.outside) ++misses;
    }
  // A constant mesh stiffness: shared equally by the pairs in contact on the same flanks. A pair
  // without backlash also touches on its back flanks now and then: they are the mesh in the other
  // sense, with the same stiffness of its own; counted together, each touch of a back flank would
  // halve the loaded flanks' stiffness for a step (and pump energy into the mesh).
  if (model.mesh_stiffness_N_per_m > 0 && !found.empty()) {
    std::size_t ccw = 0;
    for (const contact::ToothContact& c : found) ccw += c.flank_a == Flank::Ccw;
    const std::size_t cw = found.size() - ccw;
    for (std::size_t i = 0; i < found.size(); ++i)
      k_pair[i] = model.mesh_stiffness_N_per_m / static_cast<double>(found[i].flank_a == Flank::Ccw ? ccw : cw);
  }
  // Gear bodies in series with all pairs (compliance c): F_i = k_i (δ_i − c F),
  // F = Σ k_i δ_i / (1 + c Σ k_i) over the pairs with δ_i > c F (found by dropping the others
  // until none is left to drop). Each active pair then gets the secant stiffness
  // F_i/δ_i = k_i (1 − c F/δ_i), continuous as a pair comes into load.
  active.assign(found.size(), 1);
  if (model.body_stiffness_N_per_m > 0) {
    const double c_body = 1.0 / model.body_stiffness_N_per_m;
    double F = 0;
    for (bool dropped = true; dropped;) {
      double num = 0, den = 1;
      for (std::size_t i = 0; i < found.size(); ++i)
        if (active[i]) num += k_pair[i] * found[i].depth_m, den += c_body * k_pair[i];
      F = num / den;
      dropped = false;
      for (std::size_t i = 0; i < found.size(); ++i)
        if (active[i] && found[i].depth_m <= c_body * F) active[i] = 0, dropped = true;
    }
    for (std::size_t i = 0; i < found.size(); ++i)
      if (active[i]) k_pair[i] *= 1.0 - c_body * F / found[i].depth_m;
  }
  return misses;
}

}  // namespace gearsim::physics

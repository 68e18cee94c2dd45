// mesh_cycle_overlap(): two placed gears turned together at their tooth ratio over one mesh
// cycle, the deepest tooth contact found on the way (the start check of physics::World and the
// pair macros: a pair that overlaps there interferes). Declared in tooth_contact.hpp.
#include <vector>

#include "contact/tooth_contact.hpp"

namespace gearsim::contact {

MeshCycleOverlap mesh_cycle_overlap(const FlankTable& a, const PlanarPose& pa, const FlankTable& b, const PlanarPose& pb, int steps) {
  // θ_b = ∓(z_a/z_b)·θ_a about fixed centres: opposite senses unless one of them is a ring.
  const double sense = (a.internal() || b.internal()) ? 1.0 : -1.0;
  const double ratio = sense * a.teeth() / static_cast<double>(b.teeth());
  MeshCycleOverlap worst;
  std::vector<ToothContact> found;
  for (int i = 0; i < steps; ++i) {
    const double turn = a.pitch_angle_rad() * i / steps;
    PlanarPose qa = pa, qb = pb;
    qa.angle_rad += turn;
    qb.angle_rad += ratio * turn;
    find_tooth_contacts(a, qa, b, qb, found);
    for (const ToothContact& c : found)
      if (c.depth_m > worst.deepest.depth_m) {
        worst.deepest = c;
        worst.turn_a_rad = turn;
        worst.radius_a_m = (c.point_m - qa.centre_m).norm();
        worst.radius_b_m = (c.point_m - qb.centre_m).norm();
      }
  }
  return worst;
}

}  // namespace gearsim::contact

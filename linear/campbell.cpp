#include "linear/campbell.hpp"

#include <cmath>

#include "geometry/constants.hpp"

namespace gearsim::linear {
namespace {

// The body that carries a mesh (a planet's carrier): the pin's parent, with coordinates, of either gear.
int carrier_of(const LumpedModel& m, const MeshInfo& mi) {
  for (int g : {mi.a, mi.b}) {
    const int p = m.bodies[g].pin_parent;
    if (p >= 0 && m.bodies[p].first_dof >= 0) return p;
  }
  return -1;
}

}  // namespace

Campbell campbell(const LumpedModel& m, const physics::WorldStructure& w, const ModalAnalysis& modes, int harmonics,
                  double max_speed_rad_s) {
  Campbell c;
  c.drive = m.bodies[m.driver].name;
  const RigidSpeeds rigid = rigid_speeds(m, w, m.driver);
  if (!rigid.why_not.empty()) {
    c.why_not = rigid.why_not;
    return c;
  }
  const Eigen::VectorXd& omega = rigid.omega;
  for (std::size_t k = 0; k < m.meshes.size(); ++k) {
    const MeshInfo& mi = m.meshes[k];
    const int carrier = carrier_of(m, mi);
    const double rel = omega(mi.a) - (carrier >= 0 ? omega(carrier) : 0.0);
    c.rates.push_back({static_cast<int>(k), m.bodies[mi.a].teeth * std::abs(rel) / (2 * constants::kPi)});
  }
  for (const physics::StructureJoint& j : w.joints)
    if (j.motor && j.body == m.driver) c.operating_speed_rad_s = std::abs(j.motor->target_speed_rad_s);
  // One row per distinct mesh frequency (a planetary set's meshes share one).
  std::vector<MeshRate> distinct;
  for (const MeshRate& r : c.rates) {
    bool seen = false;
    for (const MeshRate& s : distinct) seen = seen || std::abs(s.hz_per_rad_s - r.hz_per_rad_s) <= 1e-9 * s.hz_per_rad_s;
    if (!seen && r.hz_per_rad_s > 0) distinct.push_back(r);
  }
  for (std::size_t g = 0; g < modes.groups.size(); ++g) {
    const ModeGroup& grp = modes.groups[g];
    if (grp.frequency_hz <= 0) continue;
    for (int h = 1; h <= harmonics; ++h)
      for (const MeshRate& r : distinct) {
        const double speed = grp.frequency_hz / (h * r.hz_per_rad_s);
        if (speed <= max_speed_rad_s) c.crossings.push_back({static_cast<int>(g), r.mesh, h, grp.frequency_hz, speed});
      }
  }
  return c;
}

}  // namespace gearsim::linear

#include "linear/campbell.hpp"

#include <Eigen/QR>
#include <cmath>

#include "geometry/constants.hpp"

namespace gearsim::linear {
namespace {

// The body that carries a mesh (a planet's carrier): the parent, with coordinates, of either gear.
int carrier_of(const LumpedModel& m, const MeshInfo& mi) {
  for (int g : {mi.a, mi.b}) {
    const int p = m.bodies[g].parent;
    if (p >= 0 && m.bodies[p].first_dof >= 0) return p;
  }
  return -1;
}

}  // namespace

Campbell campbell(const LumpedModel& m, const physics::WorldStructure& w, const ModalAnalysis& modes, int harmonics,
                  double max_speed_rad_s) {
  Campbell c;
  c.drive = m.bodies[m.driver].name;
  // Unknowns: every body's absolute speed (welded bodies' rows pin theirs to 0).
  const int n = static_cast<int>(m.bodies.size());
  std::vector<Eigen::RowVectorXd> rows;
  std::vector<double> rhs;
  auto row = [&]() {
    rows.push_back(Eigen::RowVectorXd::Zero(n));
    rhs.push_back(0);
    return rows.size() - 1;
  };
  for (int b = 0; b < n; ++b)
    if (m.bodies[b].first_dof < 0) rows[row()](b) = 1;
  const std::size_t d = row();
  rows[d](m.driver) = 1, rhs[d] = 1;
  for (const physics::StructureJoint& j : w.joints)
    if (j.def->bearing && j.def->bearing->torsional_stiffness_N_m_per_rad > 0) {
      const std::size_t r = row();
      rows[r](j.body) = 1;
      if (j.parent >= 0) rows[r](j.parent) -= 1;
    }
  for (const MeshInfo& mi : m.meshes) {
    const bool internal = w.bodies[mi.a].flanks->internal() || w.bodies[mi.b].flanks->internal();
    const int carrier = carrier_of(m, mi);
    const double za = m.bodies[mi.a].teeth, zb = (internal ? -1.0 : 1.0) * m.bodies[mi.b].teeth;
    const std::size_t r = row();
    rows[r](mi.a) += za, rows[r](mi.b) += zb;
    if (carrier >= 0) rows[r](carrier) -= za + zb;
  }
  Eigen::MatrixXd A(static_cast<Eigen::Index>(rows.size()), n);
  Eigen::VectorXd y(static_cast<Eigen::Index>(rows.size()));
  for (std::size_t r = 0; r < rows.size(); ++r) A.row(static_cast<Eigen::Index>(r)) = rows[r], y(static_cast<Eigen::Index>(r)) = rhs[r];
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(A);
  if (qr.rank() < n) {
    c.why_not = "the drive's speed does not fix every body's speed (a body free to turn without a mesh, torsional support or weld)";
    return c;
  }
  const Eigen::VectorXd omega = qr.solve(y);
  if ((A * omega - y).norm() > 1e-9 * (1 + y.norm())) {
    c.why_not = "the gear train's kinematics contradict each other (a locked train)";
    return c;
  }
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

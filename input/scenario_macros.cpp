// Scenario macros: `planetary` (scenario_planetary.cpp) and `pair` (scenario_pair.cpp) expand
// into plain bodies and hinges placed so that every mesh engages (tooth centred in the mating
// gap), plus the ideal transmission. This file holds what both use: a turn about z, a hinge, a
// gear body's involutes and a mesh's checked gear-table figures.
#include <cmath>
#include <sstream>

#include "core/errors.hpp"
#include "geometry/involute_pair.hpp"
#include "input/scenario_macros_detail.hpp"
#include "physics/world.hpp"

namespace gearsim::input::scenario_detail {

Eigen::Quaterniond about_z(double angle_rad) { return Eigen::Quaterniond(Eigen::AngleAxisd(angle_rad, Eigen::Vector3d::UnitZ())); }

physics::JointDef hinge(const std::string& name, const std::string& parent, const Eigen::Vector3d& pivot_m) {
  physics::JointDef j;
  j.name = name;
  j.body = name;
  j.parent = parent;
  j.pivot_m = pivot_m;
  return j;  // axis +z
}

physics::BearingDef parse_bearing(const YamlMap& m) {
  using namespace limits;
  physics::BearingDef b;
  b.radial_stiffness_N_per_m = number_within(m, "radial_stiffness_N_per_m", kStiffness_N_per_m);
  b.radial_damping_N_s_per_m = number_within_or(m, "radial_damping_N_s_per_m", 0.0, kDamping_N_s_per_m);
  // 0: free to turn.
  b.torsional_stiffness_N_m_per_rad = number_within_or(m, "torsional_stiffness_N_m_per_rad", 0.0, kTorsionalStiffness_N_m_per_rad);
  b.torsional_damping_N_m_s_per_rad = number_within_or(m, "torsional_damping_N_m_s_per_rad", 0.0, kTorsionalDamping_N_m_s_per_rad);
  m.reject_unknown_keys();
  return b;
}

std::optional<InvoluteTeeth> involutes_of(const physics::BodyDef& b, std::string& why) {
  if (b.gear) return involute_teeth(*b.gear);
  const physics::MeshSource& mesh = *b.mesh;
  if (mesh.recognised && mesh.recognised->involute) return involute_teeth(*mesh.recognised);
  std::ostringstream msg;
  msg << mesh.path.string();
  if (!mesh.recognised)
    msg << ": not recognised as a gear";
  else if (mesh.recognised->asymmetric)
    msg << ": its teeth are asymmetric (the two flank sides fit involutes of base radii " << mesh.recognised->ccw.base_radius_m * 1e3
        << " and " << mesh.recognised->cw.base_radius_m * 1e3 << " mm)";
  else
    msg << ": its flanks are not recognised involutes";
  why = msg.str();
  return std::nullopt;
}

physics::PairTableDef checked_pair_table(const YamlMap& m, const std::string& a, const std::string& b, const InvoluteTeeth& ta,
                                         const InvoluteTeeth& tb, double centre_distance_m, bool derived, const std::string& key) {
  physics::PairTableDef table{a, b, derived, {}, {}};
  try {
    table.figures = involute_pair(ta, tb, centre_distance_m, "pair '" + a + "'–'" + b + "'");
  } catch (const InputError& e) {
    m.fail(derived ? key : "centre_distance_m", e.what());
  }
  const double c = table.figures.centre_distance_m;
  if (table.figures.normal_backlash_m < -physics::World::kStartOverlapLimit_m) {
    std::ostringstream msg;
    msg << "'" << a << "'–'" << b << "': at " << c * 1e3 << " mm the teeth overlap by " << -table.figures.normal_backlash_m * 1e6
        << " um along the line of action (zero backlash at " << table.figures.zero_backlash_centre_distance_m * 1e3 << " mm)";
    m.fail(derived ? key : "centre_distance_m", msg.str());
  }
  if (!(table.figures.contact_ratio > 0)) {
    std::ostringstream msg;
    msg << "'" << a << "'–'" << b << "': at " << c * 1e3 << " mm the tips do not reach the line of action (contact ratio "
        << table.figures.contact_ratio << ")";
    m.fail(derived ? key : "centre_distance_m", msg.str());
  }
  return table;
}

}  // namespace gearsim::input::scenario_detail

#include "linear/lumped_model.hpp"

#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

#include "core/errors.hpp"
#include "geometry/constants.hpp"
#include "linear/mesh_average.hpp"

namespace gearsim::linear {
namespace {

// Rows over all coordinates: the motion of a point of a body, and its turn.
class Rows {
 public:
  Rows(const LumpedModel& m) : m_(m) {}
  // Displacement of `point` on body b along `dir` per coordinate (zero for a welded body).
  Eigen::RowVectorXd point(int b, const Eigen::Vector2d& point, const Eigen::Vector2d& dir) const {
    Eigen::RowVectorXd r = Eigen::RowVectorXd::Zero(m_.dofs());
    if (b < 0 || m_.bodies[b].first_dof < 0) return r;
    const int d = m_.bodies[b].first_dof;
    const Eigen::Vector2d arm = point - m_.bodies[b].centre_of_mass_m;
    r(d) = dir.x(), r(d + 1) = dir.y(), r(d + 2) = arm.x() * dir.y() - arm.y() * dir.x();
    return r;
  }
  Eigen::RowVectorXd turn(int b) const {
    Eigen::RowVectorXd r = Eigen::RowVectorXd::Zero(m_.dofs());
    if (b >= 0 && m_.bodies[b].first_dof >= 0) r(m_.bodies[b].first_dof + 2) = 1;
    return r;
  }

 private:
  const LumpedModel& m_;
};

void add_constraint(LumpedModel& m, const Eigen::RowVectorXd& row, const std::string& name) {
  if (row.isZero(0)) return;  // between two welded bodies: nothing moves
  m.constraints.conservativeResize(m.constraints.rows() + 1, m.dofs());
  m.constraints.row(m.constraints.rows() - 1) = row;
  m.constraint_names.push_back(name);
}

void add_joints(LumpedModel& m, const physics::WorldStructure& w) {
  const Rows rows(m);
  for (const physics::StructureJoint& j : w.joints) {
    const physics::JointDef& jd = *j.def;
    if ((jd.axis.normalized() - Eigen::Vector3d::UnitZ()).norm() > 1e-9 && (jd.axis.normalized() + Eigen::Vector3d::UnitZ()).norm() > 1e-9)
      throw InputError("modes: joint '" + jd.name + "': axis not along z (the linear model is planar)");
    const Eigen::Vector2d pivot = jd.pivot_m.head<2>();
    const Eigen::Vector2d ex = Eigen::Vector2d::UnitX(), ey = Eigen::Vector2d::UnitY();
    const Eigen::RowVectorXd rx = rows.point(j.body, pivot, ex) - rows.point(j.parent, pivot, ex);
    const Eigen::RowVectorXd ry = rows.point(j.body, pivot, ey) - rows.point(j.parent, pivot, ey);
    const Eigen::RowVectorXd rt = rows.turn(j.body) - rows.turn(j.parent);
    if (!jd.bearing || jd.bearing->radially_rigid) {
      add_constraint(m, rx, "hinge " + jd.name + " x");
      add_constraint(m, ry, "hinge " + jd.name + " y");
    } else {
      Element e{Element::Kind::Bearing, jd.body, jd.bearing->radial_stiffness_N_per_m * (rx.transpose() * rx + ry.transpose() * ry),
                jd.bearing->radial_stiffness_N_per_m};
      m.elements.push_back(std::move(e));
    }
    if (jd.bearing && jd.bearing->torsional_stiffness_N_m_per_rad > 0)  // a torsional support, or a shaft
      m.elements.push_back({Element::Kind::Torsion, jd.bearing->radially_rigid ? "shaft " + jd.parent + "–" + jd.body : jd.body,
                            jd.bearing->torsional_stiffness_N_m_per_rad * (rt.transpose() * rt),
                            jd.bearing->torsional_stiffness_N_m_per_rad});
    if (j.motor) add_constraint(m, rt, "motor " + jd.name);
  }
}

// The drive: which gear's torque drives the train, and its sense.
std::pair<int, int> find_drive(const LumpedModel& m, const physics::WorldStructure& w, const physics::Scenario& s, const ModelOptions& o,
                               std::string& said) {
  auto sign_z = [](const physics::JointDef& jd, double v) { return (v * jd.axis.z() > 0) ? 1 : -1; };
  if (o.drive) {
    for (std::size_t b = 0; b < m.bodies.size(); ++b)
      if (m.bodies[b].name == o.drive->first) {
        said = "given";
        return {static_cast<int>(b), o.drive->second};
      }
    throw InputError("modes: --drive: no body named '" + o.drive->first + "'");
  }
  for (const physics::StructureJoint& j : w.joints)
    if (j.motor && j.motor->target_speed_rad_s != 0) {
      said = "the motor of joint '" + j.def->name + "'";
      return {j.body, sign_z(*j.def, j.motor->target_speed_rad_s)};
    }
  for (const physics::StructureJoint& j : w.joints)
    if (j.load && j.load->constant_torque_N_m != 0 && s.transmission && s.transmission->input_joint == j.def->name) {
      said = "the load torque on the input joint '" + j.def->name + "'";
      return {j.body, sign_z(*j.def, j.load->constant_torque_N_m)};
    }
  throw InputError(
      "modes: no motor, and no load torque on a transmission input, says which flanks carry the load: "
      "give --drive BODY=ccw|cw");
}

}  // namespace

LumpedModel build_lumped_model(const physics::World& world, const physics::Scenario& s, const ModelOptions& o) {
  const physics::WorldStructure w = world.structure();
  LumpedModel m;
  int n = 0;
  for (const physics::StructureBody& b : w.bodies) {
    BodyInfo bi;
    bi.name = b.name;
    bi.first_dof = b.fixed ? -1 : 3 * n++;
    bi.mass_kg = b.mass_kg;
    bi.inertia_z_kg_m2 = b.inertia_z_kg_m2;
    bi.centre_of_mass_m = b.centre_of_mass_m;
    bi.gear = b.flanks != nullptr;
    bi.teeth = b.flanks ? b.flanks->teeth() : 0;
    bi.radius_m = b.flanks ? (b.flanks->internal() ? b.flanks->r_min_m() : b.flanks->r_max_m()) : 0;
    m.bodies.push_back(bi);
  }
  for (const physics::StructureJoint& j : w.joints) m.bodies[j.body].parent = j.parent;
  // Pins off the parent's axis (its own joint's pivot, else its centre of mass), by 1 µm or more.
  for (const physics::StructureJoint& j : w.joints) {
    if (j.parent < 0) continue;
    Eigen::Vector3d axis(m.bodies[j.parent].centre_of_mass_m.x(), m.bodies[j.parent].centre_of_mass_m.y(), 0);
    for (const physics::StructureJoint& pj : w.joints)
      if (pj.body == j.parent) axis = pj.def->pivot_m;
    if ((j.def->pivot_m - axis).head<2>().norm() > 1e-6) m.bodies[j.body].pin_parent = j.parent;
  }
  // A shapeless body that carries others (a carrier) is drawn out to the bodies it carries.
  for (const BodyInfo& b : m.bodies)
    if (b.parent >= 0 && !m.bodies[b.parent].gear) {
      BodyInfo& p = m.bodies[b.parent];
      p.radius_m = std::max(p.radius_m, (b.centre_of_mass_m - p.centre_of_mass_m).norm());
    }
  m.mass = Eigen::MatrixXd::Zero(3 * n, 3 * n);
  for (const BodyInfo& b : m.bodies)
    if (b.first_dof >= 0) m.mass.diagonal().segment<3>(b.first_dof) << b.mass_kg, b.mass_kg, b.inertia_z_kg_m2;
  m.constraints.resize(0, 3 * n);
  add_joints(m, w);

  // Loaded flanks: senses spread from the drive over the meshes.
  std::string said;
  const auto [driver, sense] = find_drive(m, w, s, o, said);
  m.driver = driver;
  m.drive = m.bodies[driver].name + (sense > 0 ? " counter-clockwise" : " clockwise") + " (" + said + ")";
  std::vector<int> senses(m.bodies.size(), 0), depth(m.bodies.size(), -1);
  senses[driver] = sense;
  depth[driver] = 0;
  auto internal = [&](const physics::StructurePair& pr) { return w.bodies[pr.a].flanks->internal() || w.bodies[pr.b].flanks->internal(); };
  std::vector<int> driven_of(w.pairs.size(), -1);
  // A shaft passes the drive on to the next stage: its far end, reached from the drive's side,
  // takes power in, its driving torque in the sense it turns (from the train's rigid speeds; the
  // near end may be a carrier, which no mesh gives a sense).
  const RigidSpeeds rigid = rigid_speeds(m, w, driver);
  const Eigen::VectorXd omega = rigid.why_not.empty() ? Eigen::VectorXd(sense * rigid.omega) : Eigen::VectorXd::Zero(m.bodies.size());
  auto reached = [&](int b) { return senses[b] != 0 || (!m.bodies[b].gear && std::abs(omega[b]) > 0 && depth[b] >= 0); };
  for (bool grew = true; grew;) {
    grew = false;
    for (const physics::StructureJoint& j : w.joints) {
      if (!j.def->bearing || !j.def->bearing->radially_rigid || j.parent < 0) continue;
      for (auto [near, far] : {std::pair{j.parent, j.body}, std::pair{j.body, j.parent}}) {
        if (!reached(near) || senses[far] != 0 || !(std::abs(omega[far]) > 1e-12)) continue;
        senses[far] = omega[far] > 0 ? 1 : -1;
        depth[far] = *std::max_element(depth.begin(), depth.end()) + 1;
        grew = true;
      }
    }
    // A carrier is reached once a gear it carries is.
    for (const physics::StructureJoint& j : w.joints)
      if (j.parent >= 0 && !m.bodies[j.parent].gear && senses[j.body] != 0 && depth[j.parent] < 0)
        depth[j.parent] = depth[j.body], grew = true;
    // A carrier that drives (the drive itself, or a shaft's far end) pushes its planets on their
    // pins: each planet pushes both its mates — sun and ring — on in the carrier's sense (equal
    // tangential forces, one direction), so each of those meshes is driven at its mate.
    for (std::size_t p = 0; p < w.pairs.size(); ++p) {
      const physics::StructurePair& pr = w.pairs[p];
      if (driven_of[p] >= 0) continue;
      for (auto [planet, mate] : {std::pair{pr.a, pr.b}, std::pair{pr.b, pr.a}}) {
        const int c = m.bodies[planet].pin_parent;
        if (c < 0 || m.bodies[c].gear || senses[c] == 0 || senses[planet] != 0 || m.bodies[mate].pin_parent == c) continue;
        if (senses[mate] != 0 && senses[mate] != senses[c])
          throw InputError("modes: gear '" + m.bodies[mate].name +
                           "' would carry load on opposite flanks from two paths of the drive (a locked train): give --drive");
        senses[mate] = senses[c];
        if (depth[mate] < 0) depth[mate] = depth[c] + 1;
        if (depth[planet] < 0) depth[planet] = depth[c] + 1;
        driven_of[p] = mate;
        grew = true;
        break;
      }
    }
    for (std::size_t p = 0; p < w.pairs.size(); ++p) {
      const physics::StructurePair& pr = w.pairs[p];
      if (driven_of[p] >= 0 || (senses[pr.a] == 0 && senses[pr.b] == 0)) continue;
      // Driven: the gear the drive reaches later (a ring two meshes from the sun, not its planet).
      const int from = senses[pr.b] == 0 || (senses[pr.a] != 0 && depth[pr.a] <= depth[pr.b]) ? pr.a : pr.b;
      const int to = from == pr.a ? pr.b : pr.a;
      const int expected = internal(pr) ? senses[from] : -senses[from];
      if (senses[to] != 0 && senses[to] != expected)
        throw InputError("modes: gears '" + m.bodies[from].name + "' and '" + m.bodies[to].name +
                         "' would carry load on opposite flanks from two paths of the drive (a locked train): give --drive");
      if (senses[to] == 0) senses[to] = expected, depth[to] = depth[from] + 1;
      driven_of[p] = to;
      grew = true;
    }
  }
  // Pairs of the same two gears at the same distance, driven alike, differ only by a turn of
  // their centre line about the train (the planets of a set): one mean, turned for each, so that
  // a symmetric set stays exactly symmetric (sampling each at its own phase would not).
  struct Done {
    MeshAverage avg;
    double centre_line_rad;
  };
  std::map<std::tuple<const void*, const void*, long long, int, bool, const void*, double, double, double>, Done> done;
  for (std::size_t p = 0; p < w.pairs.size(); ++p) {
    const physics::StructurePair& pr = w.pairs[p];
    const physics::StructureBody &A = w.bodies[pr.a], &B = w.bodies[pr.b];
    if (driven_of[p] < 0)
      throw InputError("modes: gears '" + A.name + "' and '" + B.name + "' are driven by no mesh from the drive " + m.drive);
    const bool driven_is_b = driven_of[p] == pr.b;
    const Eigen::Vector2d line = B.gear_pose.centre_m - A.gear_pose.centre_m;
    const double line_rad = std::atan2(line.y(), line.x());
    // Only gears whose centre of mass is their centre turn with the line exactly.
    const bool centred =
        (A.centre_of_mass_m - A.gear_pose.centre_m).norm() < 1e-9 && (B.centre_of_mass_m - B.gear_pose.centre_m).norm() < 1e-9;
    const auto key =
        std::make_tuple(static_cast<const void*>(A.flanks), static_cast<const void*>(B.flanks), std::llround(line.norm() * 1e9),
                        senses[driven_of[p]], driven_is_b, static_cast<const void*>(pr.stiffness.table),
                        pr.stiffness.pair_stiffness_N_per_m, pr.stiffness.mesh_stiffness_N_per_m, pr.stiffness.body_stiffness_N_per_m);
    const MeshGear ga{A.flanks, A.gear_pose, A.centre_of_mass_m}, gb{B.flanks, B.gear_pose, B.centre_of_mass_m};
    MeshAverage avg;
    if (const auto it = done.find(key); centred && it != done.end()) {
      avg = it->second.avg;
      const Eigen::Matrix2d R = Eigen::Rotation2Dd(line_rad - it->second.centre_line_rad).toRotationMatrix();
      Eigen::Matrix<double, 6, 6> T = Eigen::Matrix<double, 6, 6>::Identity();
      T.block<2, 2>(0, 0) = R;
      T.block<2, 2>(3, 3) = R;
      avg.stiffness = T * avg.stiffness * T.transpose();
      avg.mean_normal_on_b = R * avg.mean_normal_on_b;
    } else {
      avg = average_mesh(ga, gb, pr.stiffness, driven_is_b, senses[driven_of[p]], o.phases_per_pitch, o.mesh_deflection_m);
      if (centred) done[key] = {avg, line_rad};
    }
    Element e{Element::Kind::Mesh, A.name + "–" + B.name, Eigen::MatrixXd::Zero(3 * n, 3 * n), avg.mean_N_per_m};
    const int da = m.bodies[pr.a].first_dof, db = m.bodies[pr.b].first_dof;
    for (int r = 0; r < 6; ++r)
      for (int c = 0; c < 6; ++c) {
        const int gr = r < 3 ? (da >= 0 ? da + r : -1) : (db >= 0 ? db + r - 3 : -1);
        const int gc = c < 3 ? (da >= 0 ? da + c : -1) : (db >= 0 ? db + c - 3 : -1);
        if (gr >= 0 && gc >= 0) e.stiffness(gr, gc) += avg.stiffness(r, c);
      }
    MeshInfo mi{pr.a,
                pr.b,
                driven_of[p],
                senses[driven_of[p]],
                avg.mean_N_per_m,
                avg.min_N_per_m,
                avg.max_N_per_m,
                avg.mean_pairs,
                std::atan2(avg.mean_normal_on_b.y(), avg.mean_normal_on_b.x()) * 180 / constants::kPi,
                static_cast<int>(m.elements.size())};
    m.elements.push_back(std::move(e));
    m.meshes.push_back(mi);
  }
  m.stiffness = Eigen::MatrixXd::Zero(3 * n, 3 * n);
  for (const Element& e : m.elements) m.stiffness += e.stiffness;
  return m;
}

RigidSpeeds rigid_speeds(const LumpedModel& m, const physics::WorldStructure& w, int driver) {
  // The body that carries a mesh (a planet's carrier): the pin's parent, with coordinates, of either gear.
  auto carrier_of = [&](int a, int b) {
    for (int g : {a, b}) {
      const int p = m.bodies[g].pin_parent;
      if (p >= 0 && m.bodies[p].first_dof >= 0) return p;
    }
    return -1;
  };
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
  rows[d](driver) = 1, rhs[d] = 1;
  for (const physics::StructureJoint& j : w.joints)
    if (j.def->bearing && j.def->bearing->torsional_stiffness_N_m_per_rad > 0) {
      const std::size_t r = row();
      rows[r](j.body) = 1;
      if (j.parent >= 0) rows[r](j.parent) -= 1;
    }
  for (const physics::StructurePair& pr : w.pairs) {
    const bool internal = w.bodies[pr.a].flanks->internal() || w.bodies[pr.b].flanks->internal();
    const int carrier = carrier_of(pr.a, pr.b);
    const double za = m.bodies[pr.a].teeth, zb = (internal ? -1.0 : 1.0) * m.bodies[pr.b].teeth;
    const std::size_t r = row();
    rows[r](pr.a) += za, rows[r](pr.b) += zb;
    if (carrier >= 0) rows[r](carrier) -= za + zb;
  }
  Eigen::MatrixXd A(static_cast<Eigen::Index>(rows.size()), n);
  Eigen::VectorXd y(static_cast<Eigen::Index>(rows.size()));
  for (std::size_t r = 0; r < rows.size(); ++r) A.row(static_cast<Eigen::Index>(r)) = rows[r], y(static_cast<Eigen::Index>(r)) = rhs[r];
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(A);
  RigidSpeeds out;
  if (qr.rank() < n) {
    out.why_not = "the drive's speed does not fix every body's speed (a body free to turn without a mesh, torsional support or weld)";
    return out;
  }
  out.omega = qr.solve(y);
  if ((A * out.omega - y).norm() > 1e-9 * (1 + y.norm()))
    out.why_not = "the gear train's kinematics contradict each other (a locked train)";
  return out;
}

}  // namespace gearsim::linear

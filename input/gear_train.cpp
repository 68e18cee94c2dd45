#include "input/gear_train.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <deque>
#include <set>

#include "core/errors.hpp"

namespace gearsim::input {

int teeth_of(const physics::BodyDef& b) {
  if (b.gear) return b.gear->teeth;
  if (b.mesh && b.mesh->teeth) return b.mesh->teeth->teeth;
  return 0;
}

bool is_internal(const physics::BodyDef& b) {
  if (b.gear) return b.gear->kind == GearKind::Internal;
  return b.mesh && b.mesh->recognised && b.mesh->recognised->internal;  // a mesh as recognised
}

const TrainStage* GearTrain::stage_of(const std::string& gear) const {
  for (const TrainStage& st : stages) {
    const bool in_set = gear == st.sun || gear == st.ring || std::find(st.planets.begin(), st.planets.end(), gear) != st.planets.end();
    if ((st.planetary && in_set) || (!st.planetary && (gear == st.driver || gear == st.driven))) return &st;
  }
  return nullptr;
}

const TrainStage* GearTrain::first_planetary() const {
  for (const TrainStage& st : stages)
    if (st.planetary) return &st;
  return nullptr;
}

namespace {

struct Topology {
  const physics::Scenario& s;
  std::string where;
  const physics::JointDef* joint_of(const std::string& body) const {
    for (const physics::JointDef& j : s.joints)
      if (j.body == body) return &j;
    return nullptr;  // welded or free
  }
  const physics::BodyDef* body(const std::string& name) const {
    for (const physics::BodyDef& b : s.bodies)
      if (b.name == name) return &b;
    return nullptr;
  }
  // Turns on a pin off its parent body's axis (a planet on its carrier), not about the ground or
  // coaxially on another member (a shaft, a coupling). The parent's axis: its own joint's pivot,
  // else (a welded carrier) its position.
  bool carried(const std::string& gear) const {
    const physics::JointDef* j = joint_of(gear);
    if (!j || j->parent == "ground") return false;
    const physics::JointDef* pj = joint_of(j->parent);
    const physics::BodyDef* p = body(j->parent);
    const Eigen::Vector3d axis = pj ? pj->pivot_m : p ? p->pose.position_m : Eigen::Vector3d::Zero();
    return (j->pivot_m - axis).head<2>().norm() > kCoaxial_m;
  }
  // Pivots closer than this (in the plane) share an axis, m.
  static constexpr double kCoaxial_m = 1e-6;
};

// Every body's absolute speed, rad/s, from the train's rigid kinematics: the motor's joint at its
// target speed relative to its parent, a joint held by a torsional spring (a support, a shaft)
// turning with its parent on average, welded bodies still, and each mesh rolling without slip
// about the body c that carries it, z_a(ω_a − ω_c) = ∓z_b(ω_b − ω_c) (− external, + internal).
// `needed`: the bodies whose speeds the analysis uses; InputError when one of them is not fixed.
std::map<std::string, double> rigid_speeds(const Topology& t, const std::vector<Mesh>& meshes, const physics::MotorDef& motor,
                                           const std::set<std::string>& needed) {
  std::map<std::string, int> index;
  std::vector<std::string> names;
  for (const physics::BodyDef& b : t.s.bodies)
    if (!b.fixed) index[b.name] = static_cast<int>(names.size()), names.push_back(b.name);
  const int n = static_cast<int>(names.size());
  std::vector<Eigen::RowVectorXd> rows;
  std::vector<double> rhs;
  auto add = [&](const std::vector<std::pair<std::string, double>>& terms, double value) {
    Eigen::RowVectorXd r = Eigen::RowVectorXd::Zero(n);
    for (const auto& [body, c] : terms)
      if (index.count(body)) r(index.at(body)) += c;  // the ground and welded bodies: ω = 0
    rows.push_back(r);
    rhs.push_back(value);
  };
  for (const physics::JointDef& j : t.s.joints) {
    if (j.name == motor.joint)
      add({{j.body, 1.0}, {j.parent, -1.0}}, motor.target_speed_rad_s);
    else if (j.bearing && j.bearing->torsional_stiffness_N_m_per_rad > 0)
      add({{j.body, 1.0}, {j.parent, -1.0}}, 0.0);
  }
  for (const auto& [a, b] : meshes) {
    const physics::BodyDef *ba = t.body(a), *bb = t.body(b);
    const double za = teeth_of(*ba), zb = teeth_of(*bb);
    const double sign = is_internal(*ba) || is_internal(*bb) ? 1.0 : -1.0;  // internal: same sense
    std::string c = "ground";
    if (t.carried(a)) c = t.joint_of(a)->parent;
    if (t.carried(b)) c = t.joint_of(b)->parent;
    // za(ωa − ωc) − sign·zb(ωb − ωc) = 0
    add({{a, za}, {c, -za}, {b, -sign * zb}, {c, sign * zb}}, 0.0);
  }
  Eigen::MatrixXd A(static_cast<Eigen::Index>(rows.size()), n);
  Eigen::VectorXd y(static_cast<Eigen::Index>(rows.size()));
  for (std::size_t r = 0; r < rows.size(); ++r) A.row(static_cast<Eigen::Index>(r)) = rows[r], y(static_cast<Eigen::Index>(r)) = rhs[r];
  const Eigen::FullPivLU<Eigen::MatrixXd> lu(A);
  const Eigen::VectorXd w = lu.solve(y);
  const double scale = std::max(1.0, std::abs(motor.target_speed_rad_s));
  if (!((A * w - y).norm() <= 1e-9 * scale * std::max(1.0, A.norm())))
    throw InputError(t.where + "the meshes and the motor ask for speeds that contradict each other (a locked train): not analysed");
  const Eigen::MatrixXd kernel = lu.rank() < n ? Eigen::MatrixXd(lu.kernel()) : Eigen::MatrixXd::Zero(n, 0);
  std::map<std::string, double> speed;
  for (const physics::BodyDef& b : t.s.bodies) speed[b.name] = 0.0;
  for (int i = 0; i < n; ++i) {
    if (kernel.cols() > 0 && kernel.row(i).norm() > 1e-9 && needed.count(names[static_cast<std::size_t>(i)]))
      throw InputError(t.where + "the motor does not fix the speed of '" + names[static_cast<std::size_t>(i)] +
                       "' (a differential, or a gear nothing holds): the analysis needs every stage's speeds");
    speed[names[static_cast<std::size_t>(i)]] = w(i);
  }
  return speed;
}

// The shared "<prefix>_" of every member's name, without its "_"; "" when there is none.
std::string common_prefix(const std::vector<std::string>& members) {
  std::string p = members.front();
  for (const std::string& m : members)
    p = p.substr(0, static_cast<std::size_t>(std::mismatch(p.begin(), p.end(), m.begin(), m.end()).first - p.begin()));
  const std::size_t cut = p.rfind('_');
  return cut == std::string::npos || cut == 0 ? "" : p.substr(0, cut);
}

// The stage of the meshing gears `gears` (one connected set).
TrainStage classify(const Topology& t, const std::vector<std::string>& gears) {
  TrainStage st;
  std::string listed;
  for (const std::string& g : gears) listed += (listed.empty() ? "'" : ", '") + g + "'";
  std::vector<std::string> internal, carried, free;
  for (const std::string& g : gears) (is_internal(*t.body(g)) ? internal : t.carried(g) ? carried : free).push_back(g);
  if (!internal.empty() && !carried.empty()) {
    if (internal.size() > 1)
      throw InputError(t.where + "gears " + listed + " mesh as one set with two internal gears: not a planetary set");
    st.planetary = true;
    st.ring = internal.front();
    st.ring_teeth = teeth_of(*t.body(st.ring));
    for (const std::string& g : carried) {
      const std::string& parent = t.joint_of(g)->parent;
      if (!st.carrier.empty() && parent != st.carrier)
        throw InputError(t.where + "planets on two carriers ('" + st.carrier + "', '" + parent + "'): not a planetary set");
      st.carrier = parent;
      if (st.planet_teeth && teeth_of(*t.body(g)) != st.planet_teeth)
        throw InputError(t.where + "planets with different tooth counts (" + listed + "): not analysed");
      st.planet_teeth = teeth_of(*t.body(g));
      st.planets.push_back(g);
    }
    if (free.size() != 1)
      throw InputError(t.where + "gears " + listed + " mesh as one set with " + std::to_string(free.size()) +
                       " gears turning about a fixed axis besides the ring: a planetary set has one sun");
    st.sun = free.front();
    st.sun_teeth = teeth_of(*t.body(st.sun));
    return st;
  }
  if (gears.size() != 2 || !carried.empty())
    throw InputError(t.where + "gears " + listed +
                     " mesh as one set that is neither a planetary set (an internal ring, planets on one carrier, a sun) nor one "
                     "gear pair: not analysed");
  st.internal_pair = !internal.empty();
  st.driver = gears[0];
  st.driven = gears[1];
  return st;
}

PlanetaryMember member(const TrainStage& st, const std::string& body) {
  return body == st.sun ? PlanetaryMember::Sun : body == st.carrier ? PlanetaryMember::Carrier : PlanetaryMember::Ring;
}

// The stage's fixed member, input and output, ratio and frequencies from the speeds; `order`:
// each body's distance from the motor's body (joints and meshes as steps).
void set_kinematics(const Topology& t, TrainStage& st, const std::map<std::string, double>& w, const std::map<std::string, int>& order,
                    double scale) {
  const auto dist = [&](const std::string& b) { return order.count(b) ? order.at(b) : 1 << 30; };
  const double still = 1e-9 * scale;
  if (st.planetary) {
    std::vector<std::string> turning;
    for (const std::string& m : {st.sun, st.carrier, st.ring}) (std::abs(w.at(m)) <= still ? st.fixed : turning.emplace_back()) = m;
    if (turning.size() != 2)
      throw InputError(t.where + "no member of the planetary set of '" + st.sun + "', '" + st.carrier + "' and '" + st.ring +
                       "' stands still: the analysis takes sets with a fixed sun, carrier or ring");
    if (dist(turning[1]) < dist(turning[0])) std::swap(turning[0], turning[1]);
    st.input = turning[0];
    st.output = turning[1];
    PlanetaryTrainSpec spec{st.sun_teeth,         st.planet_teeth,      st.ring_teeth,  static_cast<int>(st.planets.size()),
                            member(st, st.fixed), member(st, st.input), w.at(st.input), 3};
    st.frequencies = planetary_frequencies(spec);
  } else {
    if (dist(st.driven) < dist(st.driver)) std::swap(st.driver, st.driven);
    st.driver_teeth = teeth_of(*t.body(st.driver));
    st.driven_teeth = teeth_of(*t.body(st.driven));
    st.input = st.driver;
    st.output = st.driven;
    st.frequencies = gear_pair_frequencies({st.driver_teeth, st.driven_teeth, w.at(st.driver), 3});
  }
  st.input_speed_rad_s = w.at(st.input);
  st.output_speed_rad_s = w.at(st.output);
  st.ratio = st.output_speed_rad_s != 0 ? st.input_speed_rad_s / st.output_speed_rad_s : 0.0;
}

}  // namespace

GearTrain gear_train_of(const physics::Scenario& s, const std::vector<Mesh>& meshes) {
  const Topology t{s, s.source.string() + ": "};
  GearTrain train;
  if (s.motors.empty()) throw InputError(t.where + "no motor: the analysis needs to know which member is the input");
  const physics::MotorDef& motor = s.motors.front();
  for (const physics::JointDef& j : s.joints)
    if (j.name == motor.joint) train.input_body = j.body;
  train.input_speed_rad_s = motor.target_speed_rad_s;
  for (const auto& [a, b] : meshes)
    for (const std::string& g : {a, b})
      if (!t.body(g) || teeth_of(*t.body(g)) == 0)
        throw InputError(t.where + "the gear pair " + a + "–" + b + " names '" + g + "', which is not a gear of the scenario");
  if (meshes.empty()) throw InputError(t.where + "no gear pair meshes: nothing to analyse");
  // Connected sets of meshing gears, each a stage.
  std::map<std::string, std::string> root;
  const auto find = [&](std::string g) {
    while (root.count(g) && root.at(g) != g) g = root.at(g);
    return g;
  };
  for (const auto& [a, b] : meshes) {
    root.try_emplace(a, a), root.try_emplace(b, b);
    root[find(a)] = find(b);
  }
  std::vector<std::vector<std::string>> sets;
  std::map<std::string, std::size_t> set_of;
  for (const physics::BodyDef& b : s.bodies) {  // scenario order within a set
    if (!root.count(b.name)) continue;
    const std::string r = find(b.name);
    if (!set_of.count(r)) set_of[r] = sets.size(), sets.emplace_back();
    sets[set_of.at(r)].push_back(b.name);
  }
  for (const std::vector<std::string>& g : sets) train.stages.push_back(classify(t, g));
  // Distances from the motor's body over joints and meshes: the stages' order and direction.
  std::map<std::string, std::vector<std::string>> next;
  for (const physics::JointDef& j : s.joints)
    if (j.parent != "ground") next[j.body].push_back(j.parent), next[j.parent].push_back(j.body);
  for (const auto& [a, b] : meshes) next[a].push_back(b), next[b].push_back(a);
  std::map<std::string, int> order{{train.input_body, 0}};
  for (std::deque<std::string> q{train.input_body}; !q.empty(); q.pop_front())
    for (const std::string& m : next[q.front()])
      if (!order.count(m)) order[m] = order.at(q.front()) + 1, q.push_back(m);
  std::set<std::string> needed;
  for (const TrainStage& st : train.stages)
    for (const std::string& m : {st.sun, st.ring, st.carrier, st.driver, st.driven})
      if (!m.empty()) needed.insert(m);
  train.speed_rad_s = rigid_speeds(t, meshes, motor, needed);
  const double scale = std::max(1e-300, std::abs(motor.target_speed_rad_s));
  for (TrainStage& st : train.stages) set_kinematics(t, st, train.speed_rad_s, order, scale);
  const auto nearest = [&](const TrainStage& st) {
    int d = 1 << 30;
    for (const std::string& m : {st.input, st.sun, st.driver})
      if (order.count(m)) d = std::min(d, order.at(m));
    return d;
  };
  std::stable_sort(train.stages.begin(), train.stages.end(),
                   [&](const TrainStage& x, const TrainStage& y) { return nearest(x) < nearest(y); });
  // Names: the members' shared prefix, unless two stages would share one.
  if (train.stages.size() > 1) {
    std::set<std::string> names;
    for (TrainStage& st : train.stages) {
      std::vector<std::string> members = st.planets;
      for (const std::string& m : {st.sun, st.ring, st.carrier, st.driver, st.driven})
        if (!m.empty()) members.push_back(m);
      st.name = common_prefix(members);
      names.insert(st.name);
    }
    if (names.size() != train.stages.size() || names.count(""))
      for (std::size_t k = 0; k < train.stages.size(); ++k) train.stages[k].name = "stage_" + std::to_string(k + 1);
  }
  // The train's frequencies: one stage's own; several stages' labelled by stage.
  if (train.stages.size() == 1) {
    train.frequencies = train.stages.front().frequencies;
  } else {
    train.frequencies.mesh_hz = train.stages.front().frequencies.mesh_hz;
    for (const TrainStage& st : train.stages)
      for (CharacteristicFrequency f : st.frequencies.frequencies) {
        f.key = st.name + "." + f.key;
        f.name = "stage " + st.name + ": " + f.name;
        train.frequencies.frequencies.push_back(f);
      }
  }
  // Each body's chain of logged relative angles up to the ground.
  for (const physics::BodyDef& b : s.bodies) {
    std::vector<std::string>& chain = train.angle_chain[b.name];
    std::set<std::string> seen;
    for (std::string x = b.name; !x.empty() && x != "ground" && seen.insert(x).second;) {
      const physics::JointDef* j = t.joint_of(x);
      if (!j) {
        if (!t.body(x) || !t.body(x)->fixed) chain.push_back(x);  // a free body logs its own angle
        break;
      }
      chain.push_back(x);
      x = j->parent;
    }
  }
  return train;
}

}  // namespace gearsim::input

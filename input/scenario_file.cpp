// Scenario files: parse the top level, bodies, joints, motors, loads and the transmission;
// expand macros (scenario_macros.cpp); check every cross-reference. See scenario_file.hpp.
#include "input/scenario_file.hpp"

#include <fstream>
#include <map>
#include <numbers>
#include <set>
#include <sstream>

#include "input/gearset_file.hpp"
#include "input/input_limits.hpp"
#include "input/safe_name.hpp"
#include "input/scenario_events.hpp"
#include "input/scenario_parts.hpp"
#include "input/utf8_text.hpp"
#include "core/errors.hpp"

namespace gearsim::input {
namespace {

using namespace scenario_detail;
namespace fs = std::filesystem;
constexpr const char* kGround = "ground";

physics::Pose parse_pose(const YamlMap& m) {
  physics::Pose pose;
  pose.position_m = vec3_within_or(m, "position_m", Eigen::Vector3d::Zero(), limits::kPosition_m);
  const bool full = m.has("orientation_deg") || m.has("orientation_rad");
  const bool about_z = m.has("angle_deg") || m.has("angle_rad");
  if (full && about_z)
    m.fail(m.has("angle_deg") ? "angle_deg" : "angle_rad", "give orientation_deg/_rad [rx, ry, rz] or angle_deg/_rad about z, not both");
  if (m.has("orientation_deg") && m.has("orientation_rad"))
    m.fail("orientation_deg", "give the orientation once: orientation_deg or orientation_rad");
  Eigen::Vector3d r = vec3_within_or(m, "orientation_rad", Eigen::Vector3d::Zero(), limits::kAngle_rad);
  r += vec3_within_or(m, "orientation_deg", Eigen::Vector3d::Zero(), limit_in_degrees(limits::kAngle_rad)) * (std::numbers::pi / 180.0);
  r.z() += angle_rad_or(m, "angle", 0.0);
  // Rotations about the fixed world axes x, then y, then z: R = Rz·Ry·Rx.
  pose.orientation = Eigen::AngleAxisd(r.z(), Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(r.y(), Eigen::Vector3d::UnitY()) *
                     Eigen::AngleAxisd(r.x(), Eigen::Vector3d::UnitX());
  return pose;
}

physics::BodyDef parse_body(const YamlMap& m, const fs::path& dir) {
  physics::BodyDef b;
  b.name = m.string("name");
  require_safe_name(m, "name", b.name, NameUse::Body);
  b.fixed = m.boolean_or("fixed", false);
  parse_shape_and_mass(m, b, dir);
  b.pose = parse_pose(m);
  m.reject_unknown_keys();
  return b;
}

// Every name the scenario defines so far, for duplicate and reference checks.
struct Names {
  std::map<std::string, const physics::BodyDef*> bodies;
  std::map<std::string, std::string> joint_of_body;  // body → its hinge
  std::set<std::string> joints;
  std::set<std::string> shaft_joints;  // joints of members that turn on a shaft
};

physics::JointDef parse_joint(const YamlMap& m, const Names& names) {
  physics::JointDef j;
  j.name = m.string("name");
  j.body = m.string("body");
  const auto body = names.bodies.find(j.body);
  if (body == names.bodies.end()) m.fail("body", "no body named '" + j.body + "'");
  if (body->second->fixed) m.fail("body", "body '" + j.body + "' is fixed (welded to the ground): it cannot turn in a joint");
  j.parent = m.string_or("parent", kGround);
  if (j.parent != kGround && !names.bodies.count(j.parent)) m.fail("parent", "no body named '" + j.parent + "' (or 'ground')");
  if (j.parent == j.body) m.fail("parent", "a body cannot be hinged to itself");
  // The pivot defaults to the body's origin (a gear's centre).
  j.pivot_m = vec3_within_or(m, "pivot_m", body->second->pose.position_m, limits::kPosition_m);
  const Eigen::Vector3d axis = vec3_or(m, "axis", Eigen::Vector3d::UnitZ());
  if (!(axis.norm() > 1e-12)) m.fail("axis", "the hinge axis has zero length");
  if (!std::isfinite(axis.norm())) m.fail("axis", "expected a direction of finite length (its components overflow)");
  j.axis = axis.normalized();  // a direction: only its sense matters
  if (given(m, "bearing")) j.bearing = parse_bearing(m.map("bearing"));
  m.reject_unknown_keys();
  return j;
}

void add_body(Names& names, const physics::BodyDef& b, const YamlMap& at, const std::string& key) {
  if (b.name == kGround) at.fail(key, "'ground' is reserved for the world");
  if (!names.bodies.emplace(b.name, &b).second) at.fail(key, "a second body named '" + b.name + "'");
}

void add_joint(Names& names, const physics::JointDef& j, const YamlMap& at, const std::string& key) {
  if (!names.joints.insert(j.name).second) at.fail(key, "a second joint named '" + j.name + "'");
  const auto [it, fresh] = names.joint_of_body.emplace(j.body, j.name);
  if (!fresh) at.fail(key, "body '" + j.body + "' already turns in joint '" + it->second + "' (one hinge per body)");
}

std::string joint_ref(const YamlMap& m, const std::string& key, const Names& names) {
  const std::string j = m.string(key);
  if (!names.joints.count(j)) m.fail(key, "no joint named '" + j + "'");
  if (names.shaft_joints.count(j))
    m.fail(key, "joint '" + j +
                    "' is a shaft's downstream end (it turns relative to the shaft's upstream member): a motor, a load or a "
                    "transmission acts on a member that turns on the ground, e.g. the shaft's upstream member");
  return j;
}

// An impulse on a movable body, within the run (event_outside_run) and no shorter than a step.
physics::ImpulseDef parse_impulse(const YamlMap& m, const Names& names, const physics::Scenario& s) {
  physics::ImpulseDef i;
  i.body = m.string("body");
  const auto body = names.bodies.find(i.body);
  if (body == names.bodies.end()) m.fail("body", "no body named '" + i.body + "'");
  if (body->second->fixed) m.fail("body", "body '" + i.body + "' is fixed (welded to the ground): a pulse cannot move it");
  i.at_s = number_within_or(m, "at_s", 0.0, limits::kRunTime_s);
  i.duration_s = number_within(m, "duration_s", limits::kDuration_s);
  if (const std::string why = event_outside_run(i.at_s, i.duration_s, s.duration_s); !why.empty())
    m.fail(m.has("at_s") ? "at_s" : "duration_s", why);
  if (i.duration_s < s.solver.time_step_s)
    m.fail("duration_s",
           "a pulse shorter than one time step (" + std::to_string(s.solver.time_step_s) + " s) would be missed or taken whole");
  i.force_N = vec3_or(m, "force_N", Eigen::Vector3d::Zero());
  i.torque_N_m = vec3_or(m, "torque_N_m", Eigen::Vector3d::Zero());
  for (int k = 0; k < 3; ++k) {
    if (!within(i.force_N[k], limits::kImpulseForce_N))
      m.fail("force_N", std::string(1, "xyz"[k]) + ": " + limit_message(limits::kImpulseForce_N, i.force_N[k]));
    if (!within(i.torque_N_m[k], limits::kTorque_N_m))
      m.fail("torque_N_m", std::string(1, "xyz"[k]) + ": " + limit_message(limits::kTorque_N_m, i.torque_N_m[k]));
  }
  if (i.force_N.isZero(0) && i.torque_N_m.isZero(0)) m.fail_here("a pulse needs force_N or torque_N_m");
  m.reject_unknown_keys();
  return i;
}

// motors, loads and impulses, on the joints and bodies the scenario names.
void parse_drives(const YamlMap& top, const Names& names, physics::Scenario& s) {
  if (given(top, "motors")) {
    std::set<std::string> driven;
    for (const YamlMap& m : top.list_of_maps("motors")) {
      physics::MotorDef d;
      d.joint = joint_ref(m, "joint", names);
      if (!driven.insert(d.joint).second) m.fail("joint", "joint '" + d.joint + "' already has a motor");
      d.target_speed_rad_s = number_within(m, "target_speed_rad_s", limits::kMotorSpeed_rad_s);
      d.ramp_time_s = number_within_or(m, "ramp_time_s", 0.0, limits::kRampTime_s);
      d.max_torque_N_m = number_within(m, "max_torque_N_m", limits::kMaxTorque_N_m);
      m.reject_unknown_keys();
      s.motors.push_back(d);
    }
  }
  if (given(top, "loads"))
    for (const YamlMap& m : top.list_of_maps("loads")) {
      physics::LoadDef l;
      l.joint = joint_ref(m, "joint", names);
      l.constant_torque_N_m = number_within_or(m, "constant_torque_N_m", 0.0, limits::kTorque_N_m);
      l.viscous_N_m_s_per_rad = number_within_or(m, "viscous_N_m_s_per_rad", 0.0, limits::kViscous_N_m_s_per_rad);
      l.ramp_time_s = number_within_or(m, "ramp_time_s", 0.0, limits::kRampTime_s);
      m.reject_unknown_keys();
      s.loads.push_back(l);
    }
  if (given(top, "impulses"))
    for (const YamlMap& m : top.list_of_maps("impulses")) s.impulses.push_back(parse_impulse(m, names, s));
}

// The transmission: the explicit block, each key defaulting to the macros' proposal.
std::optional<physics::TransmissionDef> parse_transmission(const YamlMap& top, const std::vector<std::pair<Expansion, std::string>>& macros,
                                                           const Names& names) {
  std::optional<physics::TransmissionDef> proposed;
  for (const auto& [e, key] : macros)
    if (e.transmission) {
      if (proposed && !top.has("transmission"))
        top.fail(key, "two macros each define a transmission: give transmission {input_joint, output_joint, ratio}");
      proposed = e.transmission;
    }
  if (given(top, "transmission")) {
    const YamlMap m = top.map("transmission");
    physics::TransmissionDef t = proposed.value_or(physics::TransmissionDef{});
    if (!proposed || m.has("input_joint")) t.input_joint = joint_ref(m, "input_joint", names);
    if (!proposed || m.has("output_joint")) t.output_joint = joint_ref(m, "output_joint", names);
    if (t.input_joint == t.output_joint) m.fail("output_joint", "input and output are the same joint");
    t.ratio = proposed ? m.number_or("ratio", t.ratio) : m.number("ratio");
    if (!within(std::abs(t.ratio), limits::kRatioMagnitude))
      m.fail("ratio", "a ratio θ_input/θ_output of either sign: " + limit_message(limits::kRatioMagnitude, std::abs(t.ratio)));
    m.reject_unknown_keys();
    proposed = t;
  }
  return proposed;
}

// solver.engine multibody holds the joints as one tree on the ground and the welded bodies:
// every body that is not welded turns in a joint (a free body is rigid_bodies' alone), no chain
// of joints closes on itself, and bodies touch only through teeth (a mesh body without teeth is a
// shape that only rigid_bodies collides). where[i]: the map and key body i was given at.
void require_multibody_tree(const physics::Scenario& s, const Names& names,
                            const std::vector<std::pair<const YamlMap*, std::string>>& where) {
  if (s.solver.engine != physics::SolverEngine::multibody) return;
  std::map<std::string, std::string> parent_of;  // body → the body its joint turns it on, or ground
  for (const physics::JointDef& j : s.joints) parent_of[j.body] = j.parent;
  for (std::size_t i = 0; i < s.bodies.size(); ++i) {
    const physics::BodyDef& b = s.bodies[i];
    const YamlMap& map = *where[i].first;
    const std::string& key = where[i].second;
    if (!b.fixed && !names.joint_of_body.count(b.name))
      map.fail(key,
               "body '" + b.name + "' has no joint; a free body needs solver.engine: rigid_bodies (multibody turns every body in a joint)");
    if (b.mesh && !b.mesh->teeth)
      map.fail(key, "body '" + b.name +
                        "' has a shape but no teeth; bodies touch only through tooth contact in solver.engine multibody (rigid_bodies "
                        "collides shapes)");
    std::string up = b.name;
    for (std::size_t n = 0; !b.fixed; ++n) {
      const auto p = parent_of.find(up);
      if (p == parent_of.end() || p->second == kGround) break;
      up = p->second;
      if (up == b.name || n == s.bodies.size())
        map.fail(key, "body '" + b.name + "' turns on a loop of joints (the joints must form a tree)");
    }
  }
}

physics::Scenario parse(const YamlMap& top, const fs::path& file) {
  const fs::path dir = file.parent_path();
  physics::Scenario s;
  s.source = file;
  s.name = top.string_or("name", file.stem().string());
  require_label(top, "name", s.name);
  s.duration_s = number_within(top, "duration_s", limits::kDuration_s);
  const int seed = top.integer_or("seed", 0);
  if (seed < 0) top.fail("seed", "expected a seed ≥ 0");
  s.seed = static_cast<std::uint64_t>(seed);
  s.reference = top.string_or("reference", "");
  if (given(top, "reference") && s.reference != "paper")
    top.fail("reference", "expected `paper` (the scenario reproduces the reference paper's gearbox), or no key for your own gearbox");
  parse_settings(top, s);
  if (s.solver.time_step_s >= s.duration_s) top.fail("duration_s", "expected a duration longer than one time step");

  // Bodies: explicit ones, then the macros' (their names must not collide).
  std::vector<YamlMap> body_maps;
  if (given(top, "bodies")) body_maps = top.list_of_maps("bodies");
  for (const YamlMap& m : body_maps) s.bodies.push_back(parse_body(m, dir));
  std::vector<std::pair<Expansion, std::string>> macros;
  if (given(top, "stages"))
    for (const char* single : {"planetary", "pair"})
      if (given(top, single))
        top.fail(single, "give it as one of `stages` (a train of stages), or give no `stages`: a scenario is one or the other");
  if (given(top, "planetary")) macros.emplace_back(expand_planetary(top.map("planetary"), dir), "planetary");
  if (given(top, "pair")) macros.emplace_back(expand_pair(top.map("pair"), dir), "pair");
  std::vector<Stage> stages;
  if (given(top, "stages")) {
    stages = expand_stages(top, dir);
    for (const Stage& st : stages) {
      Expansion e = st.expansion;
      e.transmission.reset();  // the train's, chained through the shafts below, instead
      e.planetary.reset();  // the single-stage planetary train's tools (FE TE, its analysis) do not apply
      e.gearset_spec.clear();
      macros.emplace_back(std::move(e), "stages");
    }
  } else if (given(top, "shafts")) {
    top.fail("shafts", "shafts join the members of `stages`: give the train as stages");
  }
  for (const auto& [e, key] : macros) {
    s.bodies.insert(s.bodies.end(), e.bodies.begin(), e.bodies.end());
    if (!e.gearset_spec.empty()) s.gearset_spec = e.gearset_spec;
    if (e.planetary) s.planetary = e.planetary;
    for (const physics::PairTableDef& t : e.pair_tables) s.pair_tables.push_back(t);
  }
  Names names;
  std::vector<std::pair<const YamlMap*, std::string>> where;  // per body: where it was given
  std::size_t bi = 0;
  for (const YamlMap& m : body_maps) {
    add_body(names, s.bodies[bi++], m, "name");
    where.emplace_back(&m, "name");
  }
  for (const auto& [e, key] : macros)
    for (std::size_t k = 0; k < e.bodies.size(); ++k) {
      add_body(names, s.bodies[bi++], top, key);
      where.emplace_back(&top, key);
    }

  // Joints: the macros' first, then explicit ones (which may hinge to macro bodies).
  for (const auto& [e, key] : macros)
    for (const physics::JointDef& j : e.joints) {
      add_joint(names, j, top, key);
      s.joints.push_back(j);
    }
  if (given(top, "joints"))
    for (const YamlMap& m : top.list_of_maps("joints")) {
      s.joints.push_back(parse_joint(m, names));
      add_joint(names, s.joints.back(), m, "name");
    }

  if (!stages.empty()) {
    if (given(top, "shafts")) names.shaft_joints = apply_shafts(top, s, stages);
    if (std::optional<physics::TransmissionDef> t = chained_transmission(stages, s.joints)) {
      Expansion train;
      train.transmission = t;
      macros.emplace_back(std::move(train), "stages");
    }
  }
  require_multibody_tree(s, names, where);
  parse_drives(top, names, s);
  s.transmission = parse_transmission(top, macros, names);
  if (given(top, "contact")) {
    const YamlMap c = top.map("contact");
    if (given(c, "stiffness_tables")) parse_stiffness_tables(c.list_of_maps("stiffness_tables"), s, dir);
    if (given(c, "mesh_stiffnesses")) parse_mesh_stiffnesses(c.list_of_maps("mesh_stiffnesses"), s);
  }
  if (given(top, "sensors")) parse_sensors(top.list_of_maps("sensors"), s);
  if (given(top, "fe")) s.fe = parse_fe(top.map("fe"), s);
  top.reject_unknown_keys();
  return s;
}

}  // namespace

physics::Scenario load_scenario(const fs::path& file, const std::vector<std::string>& overrides) {
  YAML::Node root = load_yaml_mapping(file);  // size, syntax, text keys, no key twice
  // The overrides' text is recorded whole in summary.json (a YAML comment in it included).
  for (const std::string& o : overrides)
    if (!is_utf8(o)) throw InputError(file.string() + ": --set '" + escaped_bytes(o) + "': expected UTF-8 text");
  apply_overrides(root, overrides, file.string());
  try {
    const YamlMap top = YamlMap::from_node(root, file.string());
    require_utf8_tree(root, file.string());  // names, paths and --set values reach the JSON records
    return parse(top, file);
  } catch (const InputError& e) {
    throw InputError(blame_override(e.what(), overrides));
  }
}

}  // namespace gearsim::input

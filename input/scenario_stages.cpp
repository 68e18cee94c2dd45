// `stages:` and `shafts:` — a gear train of several stages. Each stage is the `planetary:` or the
// `pair:` macro, placed by its own origin_m (its plane: gears mesh only with gears whose faces
// overlap theirs along the axis), its members and joints named "<stage>_<member>". A shaft joins
// two coaxial members of different stages: the downstream member turns on the upstream one about
// their common axis, held by the shaft's torsional spring and damper (radially rigid). The train's
// transmission chains the stages' own when shafts join each stage's output to the next one's input.
#include <cmath>
#include <map>
#include <numbers>
#include <set>

#include "core/errors.hpp"
#include "input/input_limits.hpp"
#include "input/safe_name.hpp"
#include "input/scenario_macros_detail.hpp"

namespace gearsim::input::scenario_detail {
namespace {

namespace fs = std::filesystem;

// The shear modulus a shaft given by its size is taken with when none is given, Pa: steel
// (E = 206 GPa, ν = 0.3: G = E/(2(1 + ν)) = 79.2 GPa; 79.3 GPa in DIN EN 10025 tables).
constexpr double kSteelShearModulus_Pa = 79.3e9;

std::string prefixed(const std::string& stage, const std::string& name) { return name == "ground" ? name : stage + "_" + name; }

// The expansion with every body, joint and gear-table name prefixed by the stage's.
void prefix_names(Expansion& e, const std::string& stage) {
  for (physics::BodyDef& b : e.bodies) b.name = prefixed(stage, b.name);
  for (physics::JointDef& j : e.joints) {
    j.name = prefixed(stage, j.name);
    j.body = prefixed(stage, j.body);
    j.parent = prefixed(stage, j.parent);
  }
  if (e.transmission) {
    e.transmission->input_joint = prefixed(stage, e.transmission->input_joint);
    e.transmission->output_joint = prefixed(stage, e.transmission->output_joint);
  }
  for (physics::PairTableDef& t : e.pair_tables) {
    t.driver = prefixed(stage, t.driver);
    t.driven = prefixed(stage, t.driven);
    if (!t.placement_note.empty()) t.placement_note = "stage '" + stage + "': " + t.placement_note;
  }
}

const physics::JointDef* joint_of_body(const std::vector<physics::JointDef>& joints, const std::string& body) {
  for (const physics::JointDef& j : joints)
    if (j.body == body) return &j;
  return nullptr;
}

// The shaft's torsional stiffness: given, or from a solid (or hollow) round shaft's size,
// k = G·J_p/L with J_p = π(d⁴ − d_i⁴)/32.
double shaft_stiffness(const YamlMap& m) {
  const bool given_k = m.has("torsional_stiffness_N_m_per_rad");
  const bool sized = m.has("length_m") || m.has("diameter_m");
  if (given_k && sized) m.fail("torsional_stiffness_N_m_per_rad", "give the stiffness or the shaft's length_m and diameter_m, not both");
  if (given_k) {
    const double k = number_within(m, "torsional_stiffness_N_m_per_rad", limits::kTorsionalStiffness_N_m_per_rad);
    if (!(k > 0)) m.fail("torsional_stiffness_N_m_per_rad", "expected a stiffness > 0 in N·m/rad");
    return k;
  }
  if (!sized)
    m.fail_here("a shaft needs torsional_stiffness_N_m_per_rad, or length_m and diameter_m (shear_modulus_Pa, steel's by default)");
  const double length = number_within(m, "length_m", limits::kShaftLength_m);
  const double d = number_within(m, "diameter_m", limits::kGearDiameter_m);
  const double di = number_within_or(m, "inner_diameter_m", 0.0, limits::kGearDiameter_m);
  const double g = number_within_or(m, "shear_modulus_Pa", kSteelShearModulus_Pa, limits::kShearModulus_Pa);
  if (!(length > 0)) m.fail("length_m", "expected a length > 0 in m");
  if (!(d > 0)) m.fail("diameter_m", "expected a diameter > 0 in m");
  if (!(di < d)) m.fail("inner_diameter_m", "expected a bore smaller than the shaft's diameter");
  const double k = g * std::numbers::pi * (std::pow(d, 4) - std::pow(di, 4)) / (32 * length);
  if (!within(k, limits::kTorsionalStiffness_N_m_per_rad))
    m.fail_here("the shaft's torsional stiffness G·π(d⁴ − d_i⁴)/(32·L) = " + std::to_string(k) +
                " N·m/rad: " + limit_message(limits::kTorsionalStiffness_N_m_per_rad, k));
  return k;
}

}  // namespace

std::vector<Stage> expand_stages(const YamlMap& top, const fs::path& dir) {
  std::vector<Stage> stages;
  std::set<std::string> names;
  for (const YamlMap& m : top.list_of_maps("stages")) {
    Stage st;
    st.name = m.string("name");
    require_safe_name(m, "name", st.name, NameUse::Body);
    if (!names.insert(st.name).second) m.fail("name", "a second stage named '" + st.name + "'");
    const bool planetary = given(m, "planetary"), pair = given(m, "pair");
    if (planetary == pair) m.fail_here("a stage is one of planetary: or pair: (the macros' keys; origin_m places the stage)");
    st.expansion = planetary ? expand_planetary(m.map("planetary"), dir) : expand_pair(m.map("pair"), dir);
    st.key = planetary ? "planetary" : "pair";
    m.reject_unknown_keys();
    prefix_names(st.expansion, st.name);
    for (const physics::BodyDef& b : st.expansion.bodies) require_safe_name(m, "name", b.name, NameUse::Body);
    stages.push_back(std::move(st));
  }
  if (stages.empty()) top.fail("stages", "expected at least one stage");
  return stages;
}

std::set<std::string> apply_shafts(const YamlMap& top, physics::Scenario& s, const std::vector<Stage>& stages) {
  std::map<std::string, std::string> stage_of;  // body → its stage
  for (const Stage& st : stages)
    for (const physics::BodyDef& b : st.expansion.bodies) stage_of[b.name] = st.name;
  std::set<std::string> shaft_joints, names;
  for (const YamlMap& m : top.list_of_maps("shafts")) {
    const std::string from = m.string("from"), to = m.string("to");
    const std::string name = m.string_or("name", from + "__" + to);
    require_label(m, "name", name);
    if (!names.insert(name).second) m.fail("name", "a second shaft named '" + name + "'");
    auto body = [&](const std::string& key, const std::string& n) -> const physics::BodyDef& {
      for (const physics::BodyDef& b : s.bodies)
        if (b.name == n) {
          if (b.fixed) m.fail(key, "body '" + n + "' is fixed (welded to the ground): a shaft joins two turning members");
          return b;
        }
      m.fail(key, "no body named '" + n + "'");
    };
    body("from", from);
    body("to", to);
    if (from == to) m.fail("to", "a shaft joins two different members");
    if (stage_of.count(from) && stage_of.count(to) && stage_of[from] == stage_of[to])
      m.fail("to", "'" + from + "' and '" + to + "' are members of one stage ('" + stage_of[from] +
                       "'): a shaft joins members of different stages (within a stage the gears mesh)");
    physics::JointDef* j = nullptr;
    for (physics::JointDef& jd : s.joints)
      if (jd.body == to) j = &jd;
    if (!j) m.fail("to", "body '" + to + "' turns in no joint");
    if (shaft_joints.count(j->name)) m.fail("to", "body '" + to + "' already turns on a shaft");
    if (j->parent != "ground")
      m.fail("to", "body '" + to + "' turns on '" + j->parent +
                       "', not on the ground: a shaft's downstream member is one that turns on the ground");
    if (j->bearing) m.fail("to", "body '" + to + "' sits on a bearing: a shaft's downstream member turns on a plain hinge");
    const physics::JointDef* up = joint_of_body(s.joints, from);
    if (!up) m.fail("from", "body '" + from + "' turns in no joint");
    // Coaxial: parallel axes through both pivots.
    const Eigen::Vector3d axis = up->axis.normalized();
    if (std::abs(std::abs(axis.dot(j->axis.normalized())) - 1) > 1e-9)
      m.fail("to", "'" + from + "' and '" + to + "' turn about axes that are not parallel: a shaft joins coaxial members");
    const Eigen::Vector3d off = j->pivot_m - up->pivot_m;
    const double across = (off - off.dot(axis) * axis).norm();
    if (across > 1e-9)
      m.fail("to", "'" + to + "' turns " + std::to_string(across * 1e3) + " mm off the axis of '" + from +
                       "': a shaft joins members on one axis line (place the stages' origin_m on it)");
    physics::BearingDef shaft;
    shaft.radially_rigid = true;
    shaft.torsional_stiffness_N_m_per_rad = shaft_stiffness(m);
    shaft.torsional_damping_N_m_s_per_rad =
        number_within_or(m, "torsional_damping_N_m_s_per_rad", 0.0, limits::kTorsionalDamping_N_m_s_per_rad);
    m.reject_unknown_keys();
    j->parent = from;
    j->bearing = shaft;
    shaft_joints.insert(j->name);
  }
  return shaft_joints;
}

std::optional<physics::TransmissionDef> chained_transmission(const std::vector<Stage>& stages,
                                                             const std::vector<physics::JointDef>& joints) {
  // Each stage's output member must drive the next stage's input member through a shaft (either
  // end upstream): then θ_in/θ_out of the train is the product of the stages' ratios.
  auto body_of = [&](const std::string& joint) {
    for (const physics::JointDef& j : joints)
      if (j.name == joint) return j.body;
    return std::string();
  };
  auto joined = [&](const std::string& a, const std::string& b) {
    for (const physics::JointDef& j : joints)
      if (j.bearing && j.bearing->radially_rigid && ((j.body == a && j.parent == b) || (j.body == b && j.parent == a))) return true;
    return false;
  };
  double ratio = 1;
  for (std::size_t k = 0; k < stages.size(); ++k) {
    const std::optional<physics::TransmissionDef>& t = stages[k].expansion.transmission;
    if (!t) return std::nullopt;
    ratio *= t->ratio;
    if (k > 0 && !joined(body_of(stages[k - 1].expansion.transmission->output_joint), body_of(t->input_joint))) return std::nullopt;
  }
  return physics::TransmissionDef{stages.front().expansion.transmission->input_joint, stages.back().expansion.transmission->output_joint,
                                  ratio};
}

}  // namespace gearsim::input::scenario_detail

#include "physics/model.hpp"

#include <string>

#include "core/errors.hpp"

// The model's construction from a scenario — bodies, joints, motors and loads, the meshing gear
// pairs — and the checks it refuses a scenario by. The engines add what they simulate with
// (Bullet's constraints and manifolds, or the multibody tree) on top (engine.hpp).
namespace gearsim::physics {

Model::Model(const Scenario& s) : scenario(s) {
  for (const PairStiffnessDef& t : s.contact.stiffness_tables)
    if (const Check c = contact::check_stiffness_table(t.table); !c)
      throw InputError("scenario: stiffness table " + t.table.source + " of gears '" + t.body_a + "' and '" + t.body_b +
                       "': " + (c.refusal().index >= 0 ? "row " + std::to_string(c.refusal().index + 1) + ": " : "") + c.reason());
  add_bodies();
  add_joints();
  attach_drives();
  find_pairs();
  check_start();
}

void Model::add_bodies() {
  for (const BodyDef& def : scenario.bodies) {
    GEARSIM_CHECK(!body_index.count(def.name), "a second body named '" + def.name + "' (input/ refuses a scenario's)");
    body_index[def.name] = static_cast<int>(bodies.size());
    bodies.push_back(build_body(def, scenario.contact));
    BuiltBody& b = bodies.back();
    // Bodies of the same gear (the planets of a set) share one flank table: less memory, and
    // the tables probing reads stay in the cache.
    for (std::size_t e = 0; b.flanks && e + 1 < bodies.size(); ++e)
      if (bodies[e].flanks && bodies[e].flanks->same_as(*b.flanks)) {
        b.flanks = bodies[e].flanks;
        break;
      }
  }
}

void Model::add_joints() {
  auto body_of = [&](const std::string& name, const std::string& who) {
    auto it = body_index.find(name);
    GEARSIM_CHECK(it != body_index.end(), who + ": no body named '" + name + "' (input/ refuses a scenario's)");
    return it->second;
  };
  joints.reserve(scenario.joints.size());
  for (const JointDef& jd : scenario.joints) {
    ModelJoint j;
    j.def = jd;
    j.body = body_of(jd.body, "joint '" + jd.name + "'");
    j.parent = jd.parent == "ground" ? -1 : body_of(jd.parent, "joint '" + jd.name + "'");
    GEARSIM_CHECK(jd.axis.norm() >= 1e-12, "joint '" + jd.name + "': an axis of zero length (input/ refuses a scenario's)");
    j.axis_world = jd.axis.normalized();
    joints.push_back(j);
  }
}

void Model::attach_drives() {
  auto joint_of = [&](const std::string& name, const std::string& who) -> ModelJoint& {
    for (ModelJoint& j : joints)
      if (j.def.name == name) return j;
    GEARSIM_CHECK(false, who + ": no joint named '" + name + "' (input/ refuses a scenario's)");
    return joints.front();
  };
  for (const MotorDef& md : scenario.motors) joint_of(md.joint, "motor").motor = &md;
  for (const LoadDef& ld : scenario.loads) joint_of(ld.joint, "load").load = &ld;
}

// Meshing gear pairs: every two gears whose toothed zones can reach each other, with their
// stiffness table if the scenario gives one.
void Model::find_pairs() {
  for (std::size_t a = 0; a < bodies.size(); ++a)
    for (std::size_t b = a + 1; b < bodies.size(); ++b) {
      const BuiltBody &ga = bodies[a], &gb = bodies[b];
      if (!ga.flanks || !gb.flanks || (ga.flanks->internal() && gb.flanks->internal())) continue;
      if (!gears_can_mesh(ga, gb)) continue;
      ModelPair pr;
      // The external gear first, so that tooth_a is always the external one's.
      pr.a = static_cast<int>(ga.flanks->internal() ? b : a);
      pr.b = static_cast<int>(ga.flanks->internal() ? a : b);
      pr.info = pair_contact(bodies[pr.a], bodies[pr.b], scenario.contact);
      add_pair_stiffness(pr);
      pairs.push_back(std::move(pr));
      pair_infos.push_back(pairs.back().info);
    }
}

// A pair's stiffness rule: the constant, or the scenario's table or mesh stiffness for it.
void Model::add_pair_stiffness(ModelPair& pr) const {
  pr.stiffness.pair_stiffness_N_per_m = pr.info.stiffness_N_per_m;
  pr.stiffness.face_width_m = pr.info.face_width_m;
  const std::string &na = bodies[pr.a].name, &nb = bodies[pr.b].name;
  for (const PairStiffnessDef& t : scenario.contact.stiffness_tables) {
    if (!((t.body_a == na && t.body_b == nb) || (t.body_a == nb && t.body_b == na))) continue;
    if (pr.stiffness.table) throw InputError("scenario: contact.stiffness_tables: two tables for gears '" + na + "' and '" + nb + "'");
    pr.stiffness.table = &t.table;
    pr.stiffness.table_on_a = t.body_a == na;
    pr.stiffness.body_stiffness_N_per_m = t.body_stiffness_N_per_m;
    pr.info.stiffness_table = t.table.source;
  }
  for (const PairMeshStiffnessDef& k : scenario.contact.mesh_stiffnesses) {
    if (!((k.body_a == na && k.body_b == nb) || (k.body_a == nb && k.body_b == na))) continue;
    if (pr.stiffness.table || pr.stiffness.mesh_stiffness_N_per_m > 0)
      throw InputError("scenario: contact.mesh_stiffnesses: gears '" + na + "' and '" + nb +
                       "' have a stiffness table or mesh stiffness already");
    pr.stiffness.mesh_stiffness_N_per_m = pr.info.mesh_stiffness_N_per_m = k.stiffness_N_per_m;
  }
}

// Gears overlapping at the start would be flung apart by a force of k·depth in the first step;
// every stiffness table must belong to a meshing pair.
void Model::check_start() {
  for (std::size_t i = 0; i < bodies.size(); ++i)
    if (bodies[i].flanks) start_poses.resize(bodies.size()), start_poses[i] = planar_pose(bodies[i]);
  for (ModelPair& pr : pairs) {
    const BuiltBody &a = bodies[pr.a], &b = bodies[pr.b];
    pr.info.tooth_height_m = std::min(a.flanks->r_max_m() - a.flanks->r_min_m(), b.flanks->r_max_m() - b.flanks->r_min_m());
    pair_infos[static_cast<std::size_t>(&pr - pairs.data())].tooth_height_m = pr.info.tooth_height_m;
    require_clear_mesh(a, start_poses[pr.a], b, start_poses[pr.b], centre_distance_derived(scenario.pair_tables, a.name, b.name));
  }
  for (const PairStiffnessDef& t : scenario.contact.stiffness_tables) {
    bool used = false;
    for (const ModelPair& pr : pairs) used = used || pr.stiffness.table == &t.table;
    if (!used)
      throw InputError("scenario: stiffness table " + t.table.source + ": gears '" + t.body_a + "' and '" + t.body_b +
                       "' do not mesh (no tooth contact between them)");
  }
  for (const PairMeshStiffnessDef& k : scenario.contact.mesh_stiffnesses) {
    bool used = false;
    for (const ModelPair& pr : pairs)
      used = used || (pr.stiffness.mesh_stiffness_N_per_m > 0 && ((bodies[pr.a].name == k.body_a && bodies[pr.b].name == k.body_b) ||
                                                                  (bodies[pr.a].name == k.body_b && bodies[pr.b].name == k.body_a)));
    if (!used)
      throw InputError("scenario: contact.mesh_stiffnesses: gears '" + k.body_a + "' and '" + k.body_b +
                       "' do not mesh (no tooth contact between them)");
  }
}

double contact_damping(const Model& model, const ModelPair& pr, double k) {
  // A constant mesh stiffness has a constant mesh damping too (ζ of the whole mesh), shared alike.
  const double zeta = model.scenario.contact.damping_ratio;
  return pr.stiffness.mesh_stiffness_N_per_m > 0
             ? contact_damping_N_s_per_m(pr.stiffness.mesh_stiffness_N_per_m, pr.info.reduced_mass_kg, zeta) *
                   (k / pr.stiffness.mesh_stiffness_N_per_m)
         : pr.stiffness.table || pr.stiffness.body_stiffness_N_per_m > 0 ? contact_damping_N_s_per_m(k, pr.info.reduced_mass_kg, zeta)
                                                                         : pr.info.damping_N_s_per_m;
}

}  // namespace gearsim::physics

// scenario_json(): the expanded, validated scenario as JSON — every field of physics::Scenario,
// SI keys, angles in rad, orientations as a quaternion (w, x, y, z) beside a rotation vector for
// reading. scenario_record.cpp reads it back.
#include <Eigen/Geometry>

#include <cstdio>
#include <fstream>

#include "input/scenario_record.hpp"

namespace gearsim::input {
namespace {

// Not `json`: a unity batch may hold scenario_record.cpp, whose `json` is nlohmann::json.
using ojson = nlohmann::ordered_json;

ojson vec(const Eigen::Vector3d& v) { return ojson::array({v.x(), v.y(), v.z()}); }

const char* flank_name(Flank f) { return f == Flank::Ccw ? "ccw" : "cw"; }

ojson gear_json(const GearSpec& g) {
  ojson errors = {{"flank_offsets", ojson::array()}, {"pitch_errors", ojson::array()}, {"profile_slopes", ojson::array()}};
  for (const FlankOffset& f : g.errors.flank_offsets)
    errors["flank_offsets"].push_back({{"tooth", f.tooth}, {"flank", flank_name(f.flank)}, {"normal_offset_m", f.normal_offset_m}});
  for (const PitchError& p : g.errors.pitch_errors) errors["pitch_errors"].push_back({{"tooth", p.tooth}, {"error_m", p.error_m}});
  for (const ProfileSlopeError& p : g.errors.profile_slopes)
    errors["profile_slopes"].push_back({{"tooth", p.tooth}, {"flank", flank_name(p.flank)}, {"slope_m", p.slope_m}});
  errors["eccentricity"] = {{"eccentricity_m", g.errors.eccentricity.eccentricity_m}, {"phase_rad", g.errors.eccentricity.phase_rad}};
  ojson j = {{"name", g.name},
             {"kind", g.kind == GearKind::Internal ? "internal" : "external"},
             {"teeth", g.teeth},
             {"module_m", g.module_m},
             {"pressure_angle_rad", g.pressure_angle_rad},
             {"face_width_m", g.face_width_m},
             {"profile_shift", g.profile_shift},
             {"addendum_coeff", g.addendum_coeff},
             {"dedendum_coeff", g.dedendum_coeff},
             {"root_fillet_coeff", g.root_fillet_coeff},
             {"thinning_per_flank_m", g.thinning_per_flank_m},
             {"bore_diameter_m", g.bore_diameter_m},
             {"rim_diameter_m", g.rim_diameter_m},
             {"tooth0_angle_rad", g.tooth0_angle_rad},
             {"chordal_deviation_m", g.chordal_deviation_m},
             {"errors", errors}};
  if (g.helix_angle_rad != 0) j["helix_angle_rad"] = g.helix_angle_rad;  // the values above transverse
  return j;
}

ojson body_json(const physics::BodyDef& b) {
  ojson j = {{"name", b.name}};
  if (b.gear) j["gear"] = gear_json(*b.gear);
  if (b.mesh) {
    std::error_code ec;
    const auto bytes = std::filesystem::file_size(b.mesh->path, ec);
    j["mesh"] = {{"file", b.mesh->path.string()},
                 {"unit", std::string(symbol(b.mesh->unit))},
                 {"bytes", ec ? 0 : bytes},
                 {"fnv1a64", file_fnv1a64(b.mesh->path)}};
    if (b.mesh->teeth) {
      j["mesh"]["teeth"] = b.mesh->teeth->teeth;
      j["mesh"]["tooth0_angle_rad"] = b.mesh->teeth->tooth0_angle_rad;
      j["mesh"]["teeth_recognised"] = b.mesh->teeth_recognised;
    } else {
      j["mesh"]["teeth"] = "none";
    }
  }
  if (b.density_kg_m3) j["density_kg_m3"] = *b.density_kg_m3;
  if (b.mass_kg) j["mass_kg"] = *b.mass_kg;
  if (b.principal_inertia_kg_m2) j["principal_inertia_kg_m2"] = vec(*b.principal_inertia_kg_m2);
  const Eigen::AngleAxisd aa(b.pose.orientation);
  const Eigen::Quaterniond& q = b.pose.orientation;
  j["position_m"] = vec(b.pose.position_m);
  j["orientation_wxyz"] = ojson::array({q.w(), q.x(), q.y(), q.z()});
  j["rotation_vector_rad"] = vec(aa.axis() * aa.angle());  // the same orientation, for reading
  j["fixed"] = b.fixed;
  return j;
}

ojson joint_json(const physics::JointDef& jd) {
  ojson j = {{"name", jd.name}, {"body", jd.body}, {"parent", jd.parent}, {"pivot_m", vec(jd.pivot_m)}, {"axis", vec(jd.axis)}};
  if (jd.bearing)
    j["bearing"] = {{"radial_stiffness_N_per_m", jd.bearing->radial_stiffness_N_per_m},
                    {"radial_damping_N_s_per_m", jd.bearing->radial_damping_N_s_per_m},
                    {"torsional_stiffness_N_m_per_rad", jd.bearing->torsional_stiffness_N_m_per_rad},
                    {"torsional_damping_N_m_s_per_rad", jd.bearing->torsional_damping_N_m_s_per_rad},
                    {"radially_rigid", jd.bearing->radially_rigid}};
  return j;
}

ojson fe_json(const physics::FeTeDef& f) {
  return {{"flank_size_m", f.flank_size_m},
          {"core_size_m", f.core_size_m},
          {"transition_m", f.transition_m},
          {"max_sagitta_m", f.max_sagitta_m},
          {"thinning_per_flank_m", f.thinning_per_flank_m},
          {"sun_torque_N_m", f.sun_torque_N_m},
          {"torque_source", f.torque_source},
          {"friction", f.friction},
          {"element_type", f.element_type},
          {"positions_per_mesh", f.positions_per_mesh},
          {"mesh_periods", f.mesh_periods},
          {"jobs", f.jobs}};
}

ojson planetary_json(const physics::PlanetaryTrainDef& p) {
  ojson planets = ojson::array();
  for (const GearSpec& g : p.planet_gears) planets.push_back(gear_json(g));
  return {{"sun", gear_json(p.spec.sun)},   {"planet", gear_json(p.spec.planet)},
          {"ring", gear_json(p.spec.ring)}, {"planets", p.spec.planets},
          {"planet_gears", planets},        {"ring_fixed", p.ring_fixed}};
}

ojson pair_table_json(const physics::PairTableDef& t) {
  return {{"driver", t.driver},
          {"driven", t.driven},
          {"centre_distance_derived", t.centre_distance_derived},
          {"centre_distance_m", t.figures.centre_distance_m},
          {"zero_backlash_centre_distance_m", t.figures.zero_backlash_centre_distance_m},
          {"operating_pressure_angle_rad", t.figures.operating_pressure_angle_rad},
          {"normal_backlash_m", t.figures.normal_backlash_m},
          {"contact_ratio", t.figures.contact_ratio},
          {"base_pitch_mismatch_m", t.figures.base_pitch_mismatch_m}};
}

// The run settings: solver, output, contact and the verification switches.
void settings_json(const physics::Scenario& s, ojson& j) {
  j["solver"] = {{"time_step_s", s.solver.time_step_s},
                 {"iterations", s.solver.iterations},
                 {"engine", physics::engine_name(s.solver.engine)},
                 {"theta", s.solver.theta},
                 {"integrator", physics::integrator_name(s.solver.integrator)}};
  j["output"] = {{"sample_rate_hz", s.output.sample_rate_hz}, {"per_step_log", s.output.per_step_log}};
  j["contact"] = {{"stiffness_N_per_m_per_m", s.contact.stiffness_N_per_m_per_m},
                  {"damping_ratio", s.contact.damping_ratio},
                  {"friction", s.contact.friction},
                  {"chordal_deviation_m", s.contact.chordal_deviation_m},
                  {"max_flank_departure_m", s.contact.max_flank_departure_m}};
  if (!s.contact.stiffness_tables.empty()) {
    ojson tables = ojson::array();
    for (const physics::PairStiffnessDef& t : s.contact.stiffness_tables)
      tables.push_back({{"body_a", t.body_a},
                        {"body_b", t.body_b},
                        {"file", t.table.source},
                        {"radius_a_m", t.table.radius_m},
                        {"stiffness_N_per_m_per_m", t.table.stiffness_N_per_m_per_m},
                        {"body_stiffness_N_per_m", t.body_stiffness_N_per_m}});
    j["contact"]["stiffness_tables"] = tables;
  }
  if (!s.contact.mesh_stiffnesses.empty()) {
    ojson meshes = ojson::array();
    for (const physics::PairMeshStiffnessDef& m : s.contact.mesh_stiffnesses)
      meshes.push_back({{"body_a", m.body_a}, {"body_b", m.body_b}, {"stiffness_N_per_m", m.stiffness_N_per_m}});
    j["contact"]["mesh_stiffnesses"] = meshes;
  }

  j["verify"] = {{"row_solver", physics::row_solver_name(s.solver.row_solver)},
                 {"mass_matrix", physics::mass_matrix_name(s.solver.mass_matrix)},
                 {"locate_contact_onset", s.solver.locate_contact_onset},
                 {"friction_model", physics::friction_model_name(s.contact.friction_model)},
                 {"coherent_search", s.contact.coherent_search},
                 {"continued_search", s.contact.continued_search},
                 {"park_near_pairs", s.contact.park_near_pairs}};
}

}  // namespace

ojson scenario_json(const physics::Scenario& s) {
  ojson j = {{"name", s.name}, {"source", s.source.string()}, {"duration_s", s.duration_s}, {"seed", s.seed}};
  if (!s.reference.empty()) j["reference"] = s.reference;
  settings_json(s, j);
  j["bodies"] = ojson::array();
  for (const physics::BodyDef& b : s.bodies) j["bodies"].push_back(body_json(b));
  j["joints"] = ojson::array();
  for (const physics::JointDef& jd : s.joints) j["joints"].push_back(joint_json(jd));
  j["motors"] = ojson::array();
  for (const physics::MotorDef& m : s.motors)
    j["motors"].push_back({{"joint", m.joint},
                           {"target_speed_rad_s", m.target_speed_rad_s},
                           {"ramp_time_s", m.ramp_time_s},
                           {"max_torque_N_m", m.max_torque_N_m}});
  j["loads"] = ojson::array();
  for (const physics::LoadDef& l : s.loads)
    j["loads"].push_back({{"joint", l.joint},
                          {"constant_torque_N_m", l.constant_torque_N_m},
                          {"viscous_N_m_s_per_rad", l.viscous_N_m_s_per_rad},
                          {"ramp_time_s", l.ramp_time_s}});
  if (!s.sensors.empty()) {
    j["sensors"] = ojson::array();
    for (const physics::SensorDef& d : s.sensors)
      j["sensors"].push_back({{"name", d.name},
                              {"body", d.body},
                              {"angle_rad", d.angle_rad},
                              {"window_width_rad", d.window_width_rad},
                              {"other_meshes_weight", d.other_meshes_weight},
                              {"resonance_hz", d.resonance_hz},
                              {"damping_ratio", d.damping_ratio},
                              {"effective_mass_kg", d.effective_mass_kg},
                              {"noise_rms_m_s2", d.noise_rms_m_s2},
                              {"sample_rate_hz", d.sample_rate_hz}});
  }
  if (!s.impulses.empty()) {
    j["impulses"] = ojson::array();
    for (const physics::ImpulseDef& i : s.impulses)
      j["impulses"].push_back({{"body", i.body},
                               {"at_s", i.at_s},
                               {"duration_s", i.duration_s},
                               {"force_N", vec(i.force_N)},
                               {"torque_N_m", vec(i.torque_N_m)}});
  }
  if (s.render) {
    const physics::RenderDef& r = *s.render;
    j["render"] = {{"camera", r.camera},       {"fps", r.fps},   {"slowmo", r.slowmo},      {"width_px", r.width_px},
                   {"height_px", r.height_px}, {"msaa", r.msaa}, {"png_every", r.png_every}};
    if (r.from_s) j["render"]["from_s"] = *r.from_s;
    if (r.to_s) j["render"]["to_s"] = *r.to_s;
  }
  if (s.transmission)
    j["transmission"] = {{"input_joint", s.transmission->input_joint},
                         {"output_joint", s.transmission->output_joint},
                         {"ratio", s.transmission->ratio},
                         {"te_formula", "te_rad = θ_input − ratio·θ_output"}};
  if (!s.gearset_spec.empty()) j["gearset_spec"] = s.gearset_spec.string();
  if (s.planetary) j["planetary"] = planetary_json(*s.planetary);
  if (s.fe) j["fe"] = fe_json(*s.fe);
  if (!s.pair_tables.empty()) {
    j["pair_tables"] = ojson::array();
    for (const physics::PairTableDef& t : s.pair_tables) j["pair_tables"].push_back(pair_table_json(t));
  }
  return j;
}

}  // namespace gearsim::input

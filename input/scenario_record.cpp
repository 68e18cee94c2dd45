#include "input/scenario_record.hpp"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "geometry/mesh_gear.hpp"
#include "input/input_limits.hpp"
#include "input/record_node.hpp"
#include "core/input_file.hpp"
#include "core/output_file.hpp"
#include "geometry/mesh_io.hpp"

namespace gearsim::input {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;
using record::Node;

constexpr Limit kAny{-1e30, 1e30, true, "", "a value"};
constexpr Limit kCount{0, 1e6, false, "", "a count"};
// A stiffness table's gear-body stiffness, N/m: 0 records rigid gear bodies (the key left out).
constexpr Limit kBodyStiffness_N_per_m{0, limits::kStiffness_N_per_m.max, false, "N/m", "a body stiffness"};

Flank flank_of(const Node& n, const std::string& key) {
  const std::string f = n.string(key);
  if (f != "ccw" && f != "cw") n.fail(key, "expected ccw or cw");
  return f == "ccw" ? Flank::Ccw : Flank::Cw;
}

GearSpec gear_of(const Node& n) {
  GearSpec g;
  g.name = n.string("name");
  const std::string kind = n.string("kind");
  if (kind != "internal" && kind != "external") n.fail("kind", "expected internal or external");
  g.kind = kind == "internal" ? GearKind::Internal : GearKind::External;
  g.teeth = n.integer("teeth", limits::kTeeth);
  // The limits of the gear-set reader (gearset_file.cpp): a record is input too.
  for (auto [key, field, limit] : {std::tuple{"module_m", &g.module_m, limits::kModule_m},
                                   {"pressure_angle_rad", &g.pressure_angle_rad, limits::kPressureAngle_rad},
                                   {"face_width_m", &g.face_width_m, limits::kFaceWidth_m},
                                   {"profile_shift", &g.profile_shift, limits::kProfileShift},
                                   {"addendum_coeff", &g.addendum_coeff, limits::kToothDepthFactor},
                                   {"dedendum_coeff", &g.dedendum_coeff, limits::kToothDepthFactor},
                                   {"root_fillet_coeff", &g.root_fillet_coeff, limits::kRootFilletFactor},
                                   {"thinning_per_flank_m", &g.thinning_per_flank_m, limits::kThinning_m},
                                   {"bore_diameter_m", &g.bore_diameter_m, limits::kGearDiameter_m},
                                   {"rim_diameter_m", &g.rim_diameter_m, limits::kGearDiameter_m},
                                   {"tooth0_angle_rad", &g.tooth0_angle_rad, limits::kAngle_rad},
                                   {"chordal_deviation_m", &g.chordal_deviation_m, limits::kChordalDeviation_m}})
    *field = n.number_within(key, limit);
  if (n.has("helix_angle_rad")) {
    g.helix_angle_rad = n.number("helix_angle_rad");
    if (!(std::abs(g.helix_angle_rad) <= limits::kHelixAngle_rad.max))
      n.fail("helix_angle_rad", "expected a helix angle within ±45° (+ right hand), in rad");
  }
  const Node e = n.object("errors");
  using limits::kToothError_m;
  for (const Node& f : e.list("flank_offsets"))
    g.errors.flank_offsets.push_back({f.integer("tooth", kCount), flank_of(f, "flank"), f.number_within("normal_offset_m", kToothError_m)});
  for (const Node& p : e.list("pitch_errors"))
    g.errors.pitch_errors.push_back({p.integer("tooth", kCount), p.number_within("error_m", kToothError_m)});
  for (const Node& p : e.list("profile_slopes"))
    g.errors.profile_slopes.push_back({p.integer("tooth", kAny), flank_of(p, "flank"), p.number_within("slope_m", kToothError_m)});
  const Node ecc = e.object("eccentricity");
  g.errors.eccentricity = {ecc.number_within("eccentricity_m", limits::kEccentricity_m),
                           ecc.number_within("phase_rad", limits::kAngle_rad)};
  try {
    validate_gear_spec(g);
  } catch (const InputError& err) {
    throw InputError(n.file().string() + ": gear '" + g.name + "': " + err.what());
  }
  return g;
}

// A mesh body: the file must be the one the run used (size and hash); its recognition is redone
// as the scenario reader did it, the recorded tooth layout kept.
physics::MeshSource mesh_of(const Node& n) {
  physics::MeshSource m;
  m.path = n.string("file");
  const std::optional<LengthUnit> u = parse_length_unit(n.string("unit"));
  if (!u) n.fail("unit", "expected a length unit (m, cm, mm, um, in, ft)");
  m.unit = *u;
  std::error_code ec;
  const auto bytes = fs::file_size(m.path, ec);
  if (ec) n.fail("file", m.path.string() + " no longer exists: the run's meshes must stay where they were");
  if (static_cast<double>(bytes) != n.number("bytes") || file_fnv1a64(m.path) != n.string("fnv1a64"))
    n.fail("file", m.path.string() + " changed since the run (size or FNV-1a hash differ from the record)");
  if (n.at("teeth").is_string()) {
    if (n.string("teeth") != "none") n.fail("teeth", "expected a tooth count or \"none\"");
    return m;
  }
  m.teeth = ToothLayout{n.integer("teeth", limits::kTeeth), n.number("tooth0_angle_rad")};
  m.teeth_recognised = n.boolean("teeth_recognised");
  const MeshGearFile f = read_mesh_gear(m.path, m.unit);
  if (f.gear && f.gear->recognition) m.recognised = *f.gear->recognition;
  return m;
}

physics::BodyDef body_of(const Node& n) {
  physics::BodyDef b;
  b.name = n.string("name");
  if (n.has("gear")) b.gear = gear_of(n.object("gear"));
  if (n.has("mesh")) b.mesh = mesh_of(n.object("mesh"));
  if (n.has("density_kg_m3")) b.density_kg_m3 = n.number_within("density_kg_m3", limits::kDensity_kg_m3);
  if (n.has("mass_kg")) b.mass_kg = n.number_within("mass_kg", limits::kMass_kg);
  if (n.has("principal_inertia_kg_m2")) b.principal_inertia_kg_m2 = n.vec3_within("principal_inertia_kg_m2", limits::kInertia_kg_m2);
  b.pose.position_m = n.vec3_within("position_m", limits::kPosition_m);
  const std::vector<double> q = n.numbers("orientation_wxyz", 4);
  b.pose.orientation = Eigen::Quaterniond(q[0], q[1], q[2], q[3]);
  if (std::abs(b.pose.orientation.norm() - 1) > 1e-9) n.fail("orientation_wxyz", "expected a unit quaternion");
  b.fixed = n.boolean("fixed");
  return b;
}

physics::JointDef joint_of(const Node& n) {
  physics::JointDef j{n.string("name"),
                      n.string("body"),
                      n.string("parent"),
                      n.vec3_within("pivot_m", limits::kPosition_m),
                      n.vec3_within("axis", {-1, 1, false, "", "a unit axis component"}),
                      {}};
  if (n.has("bearing")) {
    const Node b = n.object("bearing");
    // Records written before shafts existed have no radially_rigid (a bearing). A shaft has no
    // radial spring (0).
    const bool shaft = b.has("radially_rigid") && b.boolean("radially_rigid");
    j.bearing = physics::BearingDef{
        b.number_within("radial_stiffness_N_per_m",
                        shaft ? Limit{0, 0, false, "N/m", "a shaft's radial stiffness (none)"} : limits::kStiffness_N_per_m),
        b.number_within("radial_damping_N_s_per_m", limits::kDamping_N_s_per_m), 0, 0, shaft};
    // Records written before torsional supports existed have neither key (a torsionally free bearing).
    if (b.has("torsional_stiffness_N_m_per_rad"))
      j.bearing->torsional_stiffness_N_m_per_rad =
          b.number_within("torsional_stiffness_N_m_per_rad", limits::kTorsionalStiffness_N_m_per_rad);
    if (b.has("torsional_damping_N_m_s_per_rad"))
      j.bearing->torsional_damping_N_m_s_per_rad =
          b.number_within("torsional_damping_N_m_s_per_rad", limits::kTorsionalDamping_N_m_s_per_rad);
  }
  return j;
}

// The verification switches from `solver_keys` (row_solver, mass_matrix, locate_contact_onset)
// and `contact_keys` (friction_model and the search switches): both the verify object, or a
// record's solver and contact where it predates it. A key a record lacks takes what ran before
// the key existed.
void verify_switches_of(const Node& solver_keys, const Node& contact_keys, physics::Scenario& s) {
  s.solver.row_solver = physics::SolverDef::RowSolver::dantzig;  // before the active set
  if (solver_keys.has("row_solver")) {
    const std::string rs = solver_keys.string("row_solver");
    if (rs != "active_set" && rs != "dantzig") solver_keys.fail("row_solver", "expected active_set or dantzig");
    s.solver.row_solver = rs == "dantzig" ? physics::SolverDef::RowSolver::dantzig : physics::SolverDef::RowSolver::active_set;
  }
  s.solver.mass_matrix = physics::SolverDef::MassMatrix::articulated;  // before the planar mass matrix
  if (solver_keys.has("mass_matrix")) {
    const std::string mm = solver_keys.string("mass_matrix");
    if (mm != "planar" && mm != "articulated") solver_keys.fail("mass_matrix", "expected planar or articulated");
    s.solver.mass_matrix = mm == "planar" ? physics::SolverDef::MassMatrix::planar : physics::SolverDef::MassMatrix::articulated;
  }
  // Before: contacts started at the first step that began with the teeth overlapping.
  s.solver.locate_contact_onset = solver_keys.has("locate_contact_onset") && solver_keys.boolean("locate_contact_onset");
  physics::ContactDef& c = s.contact;
  c.friction_model = physics::ContactDef::FrictionModel::stick_slip;  // before: the stick–slip rows
  if (contact_keys.has("friction_model")) {
    const std::string fm = contact_keys.string("friction_model");
    if (fm != "sliding" && fm != "stick_slip") contact_keys.fail("friction_model", "expected sliding or stick_slip");
    c.friction_model = fm == "sliding" ? physics::ContactDef::FrictionModel::sliding : physics::ContactDef::FrictionModel::stick_slip;
  }
  // Before: the stateless search.
  c.coherent_search = contact_keys.has("coherent_search") && contact_keys.boolean("coherent_search");
  c.continued_search = contact_keys.has("continued_search") && contact_keys.boolean("continued_search");
  c.park_near_pairs = contact_keys.has("park_near_pairs") && contact_keys.boolean("park_near_pairs");
}

physics::ContactDef contact_of(const Node& n) {
  physics::ContactDef c;
  c.stiffness_N_per_m_per_m = n.number_within("stiffness_N_per_m_per_m", limits::kContactStiffness_N_per_m_per_m);
  c.damping_ratio = n.number_within("damping_ratio", limits::kDampingRatio);
  c.friction = n.number_within("friction", limits::kFriction);
  c.chordal_deviation_m = n.number_within("chordal_deviation_m", limits::kChordalDeviation_m);
  c.max_flank_departure_m = n.number_within("max_flank_departure_m", limits::kFlankDeparture_m);
  if (n.has("stiffness_tables"))
    for (const Node& t : n.list("stiffness_tables")) {
      physics::PairStiffnessDef d{t.string("body_a"),
                                  t.string("body_b"),
                                  {t.string("file"), t.numbers("radius_a_m"), t.numbers("stiffness_N_per_m_per_m")},
                                  t.number_within("body_stiffness_N_per_m", kBodyStiffness_N_per_m)};
      if (const Check ok = contact::check_stiffness_table(d.table); !ok) t.fail("radius_a_m", ok.reason());
      c.stiffness_tables.push_back(std::move(d));
    }
  if (n.has("mesh_stiffnesses"))
    for (const Node& m : n.list("mesh_stiffnesses"))
      c.mesh_stiffnesses.push_back(
          {m.string("body_a"), m.string("body_b"), m.number_within("stiffness_N_per_m", limits::kStiffness_N_per_m)});
  return c;
}

physics::RenderDef render_of(const Node& n) {
  physics::RenderDef r;
  r.camera = n.string("camera");
  r.fps = n.integer("fps", {1, 1000, false, "", "frames per second"});
  r.slowmo = n.number_within("slowmo", limits::kSlowMotion);
  r.width_px = n.integer("width_px", {16, 16384, false, "px", "a width"});
  r.height_px = n.integer("height_px", {16, 16384, false, "px", "a height"});
  r.msaa = n.integer("msaa", {0, 16, false, "", "multisampling samples"});
  r.png_every = n.integer("png_every", kCount);
  if (n.has("from_s")) r.from_s = n.number_within("from_s", limits::kRunTime_s);
  if (n.has("to_s")) r.to_s = n.number_within("to_s", limits::kRunTime_s);
  return r;
}

physics::FeTeDef fe_of(const Node& n) {
  physics::FeTeDef f;
  for (auto [key, field] : {std::pair{"flank_size_m", &f.flank_size_m},
                            {"core_size_m", &f.core_size_m},
                            {"transition_m", &f.transition_m},
                            {"max_sagitta_m", &f.max_sagitta_m},
                            {"thinning_per_flank_m", &f.thinning_per_flank_m},
                            {"sun_torque_N_m", &f.sun_torque_N_m},
                            {"friction", &f.friction},
                            {"mesh_periods", &f.mesh_periods}})
    *field = n.number(key);
  f.torque_source = n.string("torque_source");
  f.element_type = n.string("element_type");
  f.positions_per_mesh = n.integer("positions_per_mesh", kCount);
  f.jobs = n.integer("jobs", {1, 1024, false, "", "a number of processes"});
  return f;
}

physics::PlanetaryTrainDef planetary_of(const Node& n) {
  physics::PlanetaryTrainDef p;
  p.spec = {gear_of(n.object("sun")), gear_of(n.object("planet")), gear_of(n.object("ring")), n.integer("planets", limits::kPlanets)};
  for (const Node& g : n.list("planet_gears")) p.planet_gears.push_back(gear_of(g));
  p.ring_fixed = n.boolean("ring_fixed");
  return p;
}

physics::PairTableDef pair_table_of(const Node& n) {
  physics::PairTableDef t;
  t.driver = n.string("driver");
  t.driven = n.string("driven");
  t.centre_distance_derived = n.boolean("centre_distance_derived");
  t.figures = {n.number("centre_distance_m"),
               n.number("zero_backlash_centre_distance_m"),
               n.number("operating_pressure_angle_rad"),
               n.number("normal_backlash_m"),
               n.number("contact_ratio"),
               n.number("base_pitch_mismatch_m")};
  return t;
}

// The parts after the bodies and joints: drives, render, transmission and the macros' records.
void read_rest(const Node& r, physics::Scenario& s) {
  for (const Node& m : r.list("motors"))
    s.motors.push_back({m.string("joint"), m.number_within("target_speed_rad_s", limits::kMotorSpeed_rad_s),
                        m.number_within("ramp_time_s", limits::kRampTime_s), m.number_within("max_torque_N_m", limits::kMaxTorque_N_m)});
  for (const Node& l : r.list("loads"))
    s.loads.push_back({l.string("joint"), l.number_within("constant_torque_N_m", limits::kTorque_N_m),
                       l.number_within("viscous_N_m_s_per_rad", limits::kViscous_N_m_s_per_rad),
                       l.number_within("ramp_time_s", limits::kRampTime_s)});
  if (r.has("sensors"))
    for (const Node& d : r.list("sensors"))
      s.sensors.push_back({d.string("name"), d.string("body"), d.number_within("angle_rad", limits::kAngle_rad),
                           d.number_within("window_width_rad", {0, 2 * std::numbers::pi, true, "rad", "a window width"}),
                           d.number_within("other_meshes_weight", limits::kPathGain), d.number_within("resonance_hz", limits::kRate_Hz),
                           d.number_within("damping_ratio", limits::kDampingRatio), d.number_within("effective_mass_kg", limits::kMass_kg),
                           d.number_within("noise_rms_m_s2", limits::kNoise_m_s2), d.number_within("sample_rate_hz", limits::kRate_Hz)});
  if (r.has("impulses"))
    for (const Node& i : r.list("impulses"))
      s.impulses.push_back({i.string("body"), i.number_within("at_s", limits::kRunTime_s),
                            i.number_within("duration_s", limits::kDuration_s), i.vec3_within("force_N", limits::kImpulseForce_N),
                            i.vec3_within("torque_N_m", limits::kTorque_N_m)});
  if (r.has("render")) s.render = render_of(r.object("render"));
  if (r.has("transmission")) {
    const Node t = r.object("transmission");
    s.transmission = physics::TransmissionDef{t.string("input_joint"), t.string("output_joint"), t.number("ratio")};
    if (!within(std::abs(s.transmission->ratio), limits::kRatioMagnitude))
      t.fail("ratio", limit_message(limits::kRatioMagnitude, std::abs(s.transmission->ratio)));
  }
  if (r.has("gearset_spec")) s.gearset_spec = r.string("gearset_spec");
  if (r.has("reference")) {
    s.reference = r.string("reference");
    if (s.reference != "paper") r.fail("reference", "expected \"paper\"");
  }
  if (r.has("planetary")) s.planetary = planetary_of(r.object("planetary"));
  if (r.has("fe")) s.fe = fe_of(r.object("fe"));
  if (r.has("pair_tables"))
    for (const Node& t : r.list("pair_tables")) s.pair_tables.push_back(pair_table_of(t));
}

}  // namespace

std::string file_fnv1a64(const fs::path& file) {
  InputFile in(file, kMaxMeshFileBytes, "a mesh file");
  std::uint64_t h = 14695981039346656037ull;
  char buf[65536];
  while (in.read(buf, sizeof buf) || in.gcount() > 0) {
    for (std::streamsize i = 0; i < in.gcount(); ++i) h = (h ^ static_cast<unsigned char>(buf[i])) * 1099511628211ull;
    if (!in) break;
  }
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
  return hex;
}

physics::Scenario scenario_from_json(const nlohmann::json& j, const fs::path& file) {
  const Node r(j, "", file);
  physics::Scenario s;
  s.name = r.string("name");
  s.source = r.string("source");
  s.duration_s = r.number_within("duration_s", limits::kDuration_s);
  const double seed = r.number("seed");
  if (!(seed >= 0) || seed != std::floor(seed)) r.fail("seed", "expected a whole number ≥ 0");
  s.seed = r.at("seed").get<std::uint64_t>();
  const Node solver = r.object("solver"), output = r.object("output");
  s.solver = {solver.number_within("time_step_s", limits::kTimeStep_s), solver.integer("iterations", limits::kSolverIterations)};
  if (solver.has("engine")) {  // records written before the multibody engine have none: rigid bodies
    const std::string e = solver.string("engine");
    if (e != "rigid_bodies" && e != "multibody") solver.fail("engine", "expected rigid_bodies or multibody");
    s.solver.engine = e == "multibody" ? physics::SolverEngine::multibody : physics::SolverEngine::rigid_bodies;
  }
  if (solver.has("theta")) s.solver.theta = solver.number_within("theta", limits::kSolverTheta);
  s.solver.integrator = physics::SolverDef::Integrator::theta;  // records written before BDF2 have none: the θ-method
  if (solver.has("integrator")) {
    const std::string i = solver.string("integrator");
    if (i != "theta" && i != "bdf2" && i != "trapezoid_closed") solver.fail("integrator", "expected theta, bdf2 or trapezoid_closed");
    s.solver.integrator = i == "bdf2"               ? physics::SolverDef::Integrator::bdf2
                          : i == "trapezoid_closed" ? physics::SolverDef::Integrator::trapezoid_closed
                                                    : physics::SolverDef::Integrator::theta;
  }
  s.output = {output.number("sample_rate_hz"), output.boolean("per_step_log")};
  if (!(s.output.sample_rate_hz > 0)) output.fail("sample_rate_hz", "expected a positive rate in Hz");
  s.contact = contact_of(r.object("contact"));
  // The verification switches: a record's verify object, or in records written before it the
  // same keys in solver and contact.
  if (r.has("verify")) {
    const Node verify = r.object("verify");
    verify_switches_of(verify, verify, s);
  } else {
    verify_switches_of(solver, r.object("contact"), s);
  }
  for (const Node& b : r.list("bodies")) s.bodies.push_back(body_of(b));
  for (const Node& jd : r.list("joints")) s.joints.push_back(joint_of(jd));
  read_rest(r, s);
  return s;
}

void write_scenario_record(const physics::Scenario& s, const fs::path& dir) {
  physics::Scenario recorded = s;
  if (!s.gearset_spec.empty()) {
    write_output_file(dir / "gearset.yaml", read_input_file(s.gearset_spec, limits::kMaxYamlBytes, "a gear-set spec"), Durability::Record);
    recorded.gearset_spec = "gearset.yaml";  // relative to the run folder
  }
  nlohmann::ordered_json j = scenario_json(recorded);
  if (!s.gearset_spec.empty()) j["gearset_spec_original"] = s.gearset_spec.string();
  write_output_file(dir / "scenario.json", j.dump(1) + "\n", Durability::Record);
}

physics::Scenario read_scenario_record(const fs::path& dir) {
  const fs::path file = dir / "scenario.json";
  if (!fs::exists(fs::symlink_status(file))) throw InputError(file.string() + ": not found (a run folder of gearsim run holds it)");
  const std::string text = read_input_file(file, limits::kMaxRecordBytes, "a run's scenario record");
  json j;
  try {
    j = json::parse(text);
  } catch (const json::exception& e) {
    throw InputError(file.string() + ": not valid JSON: " + e.what());
  }
  physics::Scenario s = scenario_from_json(j, file);
  if (!s.gearset_spec.empty()) {
    if (s.gearset_spec != "gearset.yaml") throw InputError(file.string() + ": key gearset_spec: expected \"gearset.yaml\"");
    s.gearset_spec = dir / "gearset.yaml";
  }
  return s;
}

}  // namespace gearsim::input

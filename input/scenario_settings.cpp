// The run settings of a scenario file: solver, output, render and contact (the contact law and
// search; the stiffness tables are read once the bodies are known, scenario_stiffness.cpp).
// Values are checked against input_limits.hpp and against each other (a sample rate of whole
// steps, options of one engine only). Not the bodies, joints or drives (scenario_file.cpp).
#include <cmath>
#include <sstream>
#include <string>

#include "core/errors.hpp"
#include "input/input_limits.hpp"
#include "input/scenario_parts.hpp"

namespace gearsim::input::scenario_detail {
namespace {

// Output samples are taken at whole steps: 1/(sample_rate_hz · time_step_s) must be a whole
// number (to 1e-9 of it), else the rows would not be at the rate asked for (and the logs'
// anti-aliasing filter needs the whole ratio). "" when it is, else what to give instead.
std::string whole_steps_problem(const physics::Scenario& s) {
  const double steps = 1.0 / (s.output.sample_rate_hz * s.solver.time_step_s);
  const double whole = std::round(steps);
  if (whole >= 1 && std::abs(steps - whole) <= 1e-9 * steps) return "";
  std::ostringstream msg;
  msg << "sample rate " << s.output.sample_rate_hz << " Hz is " << steps << " time steps of " << s.solver.time_step_s
      << " s, not a whole number: samples are taken at whole steps; expected e.g. " << 1 / (std::floor(steps) * s.solver.time_step_s)
      << " Hz or " << 1 / (std::ceil(steps) * s.solver.time_step_s) << " Hz";
  return msg.str();
}

// solver: the engine, its time step and integrator, the row solver and mass matrix.
void parse_solver(const YamlMap& m, physics::Scenario& s) {
  s.solver.time_step_s = number_within_or(m, "time_step_s", s.solver.time_step_s, limits::kTimeStep_s);
  s.solver.iterations = integer_within_or(m, "iterations", s.solver.iterations, limits::kSolverIterations);
  s.solver.engine = m.choice_or("engine", {"rigid_bodies", "multibody"}, physics::engine_name(s.solver.engine)) == "multibody"
                        ? physics::SolverEngine::multibody
                        : physics::SolverEngine::rigid_bodies;
  s.solver.theta = number_within_or(m, "theta", s.solver.theta, limits::kSolverTheta);
  if (s.solver.engine == physics::SolverEngine::rigid_bodies && given(m, "theta"))
    m.fail("theta", "only engine multibody has the θ-method (rigid_bodies integrates its contacts by implicit Euler)");
  if (given(m, "theta") && !given(m, "integrator")) s.solver.integrator = physics::SolverDef::Integrator::theta;
  if (given(m, "integrator")) {
    const std::string i = m.choice_or("integrator", {"theta", "bdf2", "trapezoid_closed"}, "trapezoid_closed");
    s.solver.integrator = i == "bdf2"               ? physics::SolverDef::Integrator::bdf2
                          : i == "trapezoid_closed" ? physics::SolverDef::Integrator::trapezoid_closed
                                                    : physics::SolverDef::Integrator::theta;
    if (s.solver.engine == physics::SolverEngine::rigid_bodies)
      m.fail("integrator", "only engine multibody has a choice of integrator (rigid_bodies integrates its contacts by implicit Euler)");
    if (s.solver.integrator != physics::SolverDef::Integrator::theta && given(m, "theta"))
      m.fail("theta", std::string("integrator ") + physics::integrator_name(s.solver.integrator) +
                          " has no θ: remove theta or set integrator: theta");
  }
  for (const char* key : {"row_solver", "mass_matrix", "locate_contact_onset"})
    if (given(m, key))
      m.fail(key, std::string("a verification switch: write it as verify.") + key + " (docs/solver.md, \"Verification switches\")");
  if (s.solver.engine == physics::SolverEngine::multibody && given(m, "iterations"))
    m.fail(
        "iterations",
        "only engine rigid_bodies iterates (multibody, the default, solves its rows directly): remove the key or set engine: rigid_bodies");
  m.reject_unknown_keys();
}

// output: the logs' sample rate, a whole number of steps, and the per-step log.
void parse_output(const YamlMap& m, physics::Scenario& s) {
  s.output.sample_rate_hz = number_within_or(m, "sample_rate_hz", s.output.sample_rate_hz, limits::kRate_Hz);
  if (s.output.sample_rate_hz * s.solver.time_step_s > 1 + 1e-9) {
    std::ostringstream msg;
    msg << "sample rate " << s.output.sample_rate_hz << " Hz is above the step rate 1/time_step_s = " << 1 / s.solver.time_step_s << " Hz";
    m.fail("sample_rate_hz", msg.str());
  }
  if (const std::string w = whole_steps_problem(s); !w.empty()) m.fail("sample_rate_hz", w);
  if (s.output.sample_rate_hz * s.duration_s < 1)
    m.fail("sample_rate_hz",
           "expected at least one output row in duration_s: a rate ≥ 1/duration_s = " + std::to_string(1 / s.duration_s) + " Hz");
  s.output.per_step_log = m.boolean_or("per_step_log", s.output.per_step_log);
  m.reject_unknown_keys();
}

// render: the renders a run makes after it (camera, frame rate, window, size, anti-aliasing).
void parse_render(const YamlMap& m, physics::Scenario& s) {
  physics::RenderDef r;
  r.camera = m.choice_or("camera", {"overview", "tilted", "sun_mesh", "ring_mesh"}, r.camera);
  r.fps = m.integer_or("fps", r.fps);
  if (r.fps < 1 || r.fps > 240) m.fail("fps", "expected 1 to 240 frames per second");
  r.slowmo = number_within_or(m, "slowmo", r.slowmo, limits::kSlowMotion);
  r.from_s = m.optional_number("from_s");
  r.to_s = m.optional_number("to_s");
  if (r.from_s && !within(*r.from_s, limits::kRunTime_s)) m.fail("from_s", limit_message(limits::kRunTime_s, *r.from_s));
  if (r.to_s && !within(*r.to_s, limits::kRunTime_s)) m.fail("to_s", limit_message(limits::kRunTime_s, *r.to_s));
  if (r.from_s && r.to_s && !(*r.to_s > *r.from_s)) m.fail("to_s", "expected a time after from_s");
  r.width_px = m.integer_or("width_px", r.width_px);
  r.height_px = m.integer_or("height_px", r.height_px);
  for (const char* key : {"width_px", "height_px"}) {
    const int v = std::string(key) == "width_px" ? r.width_px : r.height_px;
    if (v < 16 || v > 4096 || v % 2) m.fail(key, "expected an even size of 16 to 4096 px (H.264 halves the chroma)");
  }
  r.msaa = m.integer_or("msaa", r.msaa);
  if (r.msaa < 0 || r.msaa == 1 || r.msaa > 16) m.fail("msaa", "expected 0 (edge anti-aliasing) or 2 to 16 samples");
  r.png_every = m.integer_or("png_every", r.png_every);
  if (r.png_every < 0) m.fail("png_every", "expected 0 (no PNG) or a positive frame interval");
  m.reject_unknown_keys();
  s.render = r;
}

// contact: the contact law and search (its tables are read once the bodies are known).
void parse_contact_settings(const YamlMap& m, physics::Scenario& s) {
  physics::ContactDef& c = s.contact;
  c.stiffness_N_per_m_per_m =
      number_within_or(m, "stiffness_N_per_m_per_m", c.stiffness_N_per_m_per_m, limits::kContactStiffness_N_per_m_per_m);
  c.damping_ratio = number_within_or(m, "damping_ratio", c.damping_ratio, limits::kDampingRatio);
  c.friction = number_within_or(m, "friction", c.friction, limits::kFriction);
  c.chordal_deviation_m = number_within_or(m, "chordal_deviation_m", c.chordal_deviation_m, limits::kChordalDeviation_m);
  c.max_flank_departure_m = number_within_or(m, "max_flank_departure_m", c.max_flank_departure_m, limits::kFlankDeparture_m);
  for (const char* key : {"friction_model", "coherent_search", "continued_search", "park_near_pairs"})
    if (given(m, key))
      m.fail(key, std::string("a verification switch: write it as verify.") + key + " (docs/solver.md, \"Verification switches\")");
  // Read once the bodies are known (parse_stiffness_tables); here only marked as known.
  if (given(m, "stiffness_tables")) m.list_of_maps("stiffness_tables");
  if (given(m, "mesh_stiffnesses")) m.list_of_maps("mesh_stiffnesses");
  m.reject_unknown_keys();
}

// verify: the switches that run another implementation of a step's part, to check one against
// the other (docs/solver.md, "Verification switches"). Each belongs to the multibody engine.
void parse_verify(const YamlMap& m, physics::Scenario& s) {
  const bool rigid = s.solver.engine == physics::SolverEngine::rigid_bodies;
  auto multibody_only = [&](const char* key, const char* why) {
    if (rigid) m.fail(key, std::string("only engine multibody ") + why);
  };
  if (given(m, "row_solver")) {
    s.solver.row_solver = m.choice_or("row_solver", {"active_set", "dantzig"}, "active_set") == "dantzig"
                              ? physics::SolverDef::RowSolver::dantzig
                              : physics::SolverDef::RowSolver::active_set;
    multibody_only("row_solver", "solves its rows directly (rigid_bodies iterates: solver.iterations)");
  }
  if (given(m, "mass_matrix")) {
    s.solver.mass_matrix = m.choice_or("mass_matrix", {"planar", "articulated"}, "planar") == "articulated"
                               ? physics::SolverDef::MassMatrix::articulated
                               : physics::SolverDef::MassMatrix::planar;
    multibody_only("mass_matrix", "solves its rows directly (rigid_bodies iterates: solver.iterations)");
  }
  if (given(m, "locate_contact_onset")) {
    s.solver.locate_contact_onset = m.boolean_or("locate_contact_onset", s.solver.locate_contact_onset);
    if (s.solver.locate_contact_onset)
      multibody_only("locate_contact_onset", "splits a step at a contact's onset (rigid_bodies steps Bullet's world whole)");
    if (s.solver.locate_contact_onset && s.solver.integrator == physics::SolverDef::Integrator::bdf2)
      m.fail("locate_contact_onset", "solver.integrator bdf2 needs equal steps: set locate_contact_onset: false or another integrator");
  }
  if (given(m, "friction_model")) {
    s.contact.friction_model = m.choice_or("friction_model", {"sliding", "stick_slip"}, "sliding") == "stick_slip"
                                   ? physics::ContactDef::FrictionModel::stick_slip
                                   : physics::ContactDef::FrictionModel::sliding;
    multibody_only("friction_model", "has a choice of friction model (rigid_bodies uses Bullet's friction: stick_slip)");
  }
  physics::ContactDef& c = s.contact;
  c.coherent_search = m.boolean_or("coherent_search", c.coherent_search);
  // A search option that is part of another (`parent`): off with it unless asked for, and then
  // refused.
  auto part_of = [&](const char* key, bool& flag, bool parent, const char* why) {
    if (given(m, key)) {
      flag = m.boolean_or(key, flag);
      if (flag && !parent) m.fail(key, std::string(key) + ": true needs " + why);
    } else if (!parent) {
      flag = false;
    }
  };
  part_of("continued_search", c.continued_search, c.coherent_search,
          "coherent_search: true (the continuation is part of the coherent search)");
  part_of("park_near_pairs", c.park_near_pairs, c.continued_search, "continued_search: true (near pairs are parked continued solutions)");
  m.reject_unknown_keys();
}

// What runs, as the record says: rigid_bodies integrates its rows by implicit Euler (the
// θ-method at θ = 1) with Bullet's friction box (stick_slip) and never splits a step; BDF2 never
// splits one either.
void settle_engine_switches(physics::Scenario& s) {
  if (s.solver.engine == physics::SolverEngine::rigid_bodies) {
    s.solver.integrator = physics::SolverDef::Integrator::theta;
    s.contact.friction_model = physics::ContactDef::FrictionModel::stick_slip;
  }
  if (s.solver.engine == physics::SolverEngine::rigid_bodies || s.solver.integrator == physics::SolverDef::Integrator::bdf2)
    s.solver.locate_contact_onset = false;
}

}  // namespace

void parse_settings(const YamlMap& top, physics::Scenario& s) {
  if (given(top, "solver")) parse_solver(top.map("solver"), s);
  if (given(top, "output")) parse_output(top.map("output"), s);
  if (!given(top, "output"))
    if (const std::string w = whole_steps_problem(s); !w.empty()) top.fail("solver", w + " (output.sample_rate_hz defaults to 2000 Hz)");
  if (given(top, "render")) parse_render(top.map("render"), s);
  if (given(top, "contact")) parse_contact_settings(top.map("contact"), s);
  if (given(top, "verify")) parse_verify(top.map("verify"), s);
  settle_engine_switches(s);
}

}  // namespace gearsim::input::scenario_detail

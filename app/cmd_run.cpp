// gearsim run SCENARIO --out DIR: a headless simulation. Writes state.csv and contacts.csv at
// the scenario's output rate and summary.json; a progress line on a terminal; Ctrl-C stops
// cleanly and keeps valid logs; a run that leaves its physical bounds (physics/run_bounds.hpp)
// stops at that step with status "diverged" and exit code kExitDiverged, its logs kept.
#include <unistd.h>

#include <array>
#include <chrono>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>

#include "app/analyze.hpp"
#include "app/commands.hpp"
#include "app/exit_codes.hpp"
#include "input/input_limits.hpp"
#include "app/render_run.hpp"
#include "app/run_analysis.hpp"
#include "app/run_dir.hpp"
#include "input/scenario_file.hpp"
#include "core/errors.hpp"
#include "geometry/gear_spec.hpp"
#include "physics/power_balance.hpp"
#include "physics/run_bounds.hpp"
#include "physics/step_log.hpp"
#include "physics/world.hpp"

namespace gearsim::app {
namespace {

using json = nlohmann::ordered_json;

// A tooth penetration beyond this is not a loaded mesh's deflection (≈ 1 µm at the paper's
// load) but interference or an unstable step, m.
constexpr double kPenetrationWarning_m = 10e-6;
// Share of the motor input the measured power flows may leave unexplained before the run warns
// (the 2 % acceptance figure; converged runs show ~1e-5).
constexpr double kPowerImbalanceWarning = 0.02;

// The signal (SIGINT or SIGTERM) that asked the run to stop, 0 while none did.
volatile std::sig_atomic_t g_interrupted = 0;
void on_stop_signal(int sig) { g_interrupted = sig; }

// The files a run, its analysis, report and renders write into the run folder. A run into a
// folder that holds them from an earlier run removes them first, so that no summary or analysis
// of the old run sits beside the new logs. Returns how many were removed; other files stay.
int clear_previous_outputs(const std::filesystem::path& dir) {
  namespace fs = std::filesystem;
  static const char* const kFiles[] = {"summary.json", "state.csv",    "contacts.csv", "steps.h5",   "analysis.json",
                                       "spectrum.csv", "sidebands.csv", "teeth.csv",    "report.html"};
  int removed = 0;
  std::error_code ec;
  for (const char* f : kFiles)
    if (fs::is_regular_file(fs::symlink_status(dir / f))) removed += fs::remove(dir / f, ec) ? 1 : 0;
  for (const fs::directory_entry& e : fs::directory_iterator(dir, ec)) {
    const std::string n = e.path().filename().string();
    if (e.is_regular_file() && n.starts_with("video") && n.ends_with(".mp4")) removed += fs::remove(e.path(), ec) ? 1 : 0;
  }
  if (fs::is_directory(fs::symlink_status(dir / "frames"))) removed += fs::remove_all(dir / "frames", ec) > 0 ? 1 : 0;
  return removed;
}

struct RunOptions {
  std::string scenario;
  std::string out_dir;
  std::vector<std::string> sets;
  double duration_s = 0;
  bool no_analyze = false;
};

int body_of_joint(const physics::Scenario& s, const std::string& joint) {
  for (const physics::JointDef& j : s.joints)
    if (j.name == joint)
      for (std::size_t b = 0; b < s.bodies.size(); ++b)
        if (s.bodies[b].name == j.body) return static_cast<int>(b);
  throw InputError(s.source.string() + ": transmission: no joint named '" + joint + "'");
}

// --duration in place of the scenario's duration_s: longer than a time step, and at least one
// output row (the scenario file's own duration was checked as it was read).
void set_duration(physics::Scenario& s, double duration_s) {
  s.duration_s = duration_s;
  if (!(duration_s > s.solver.time_step_s))
    throw InputError("--duration " + std::to_string(duration_s) + ": expected more than one time step (" +
                     std::to_string(s.solver.time_step_s) + " s in " + s.source.string() + ")");
  if (s.output.sample_rate_hz * duration_s < 1)
    throw InputError("--duration " + std::to_string(duration_s) + ": shorter than one output interval (1/" +
                     std::to_string(s.output.sample_rate_hz) + " Hz in " + s.source.string() + ")");
}

void run(const RunOptions& o) {
  physics::Scenario s = input::load_scenario(o.scenario, o.sets);
  if (o.duration_s > 0) set_duration(s, o.duration_s);
  const std::filesystem::path dir(o.out_dir);
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw InputError(dir.string() + ": cannot create the output folder: " + ec.message());
  if (const int n = clear_previous_outputs(dir); n > 0)
    std::cout << "removed " << n << " outputs of a previous run in " << dir.string() << "\n";

  const auto wall0 = std::chrono::steady_clock::now();
  physics::World world(s);
  const double dt = s.solver.time_step_s;
  const long total = std::lround(s.duration_s / dt);
  const long every = std::max(1L, std::lround(1.0 / (s.output.sample_rate_hz * dt)));
  int te_in = -1, te_out = -1;
  if (s.transmission) {
    te_in = body_of_joint(s, s.transmission->input_joint);
    te_out = body_of_joint(s, s.transmission->output_joint);
  }
  std::ofstream state = open_output(dir / "state.csv", 17), contacts = open_output(dir / "contacts.csv", 17);
  state << "time_s";
  for (const physics::BodyState& b : world.bodies()) state << ',' << b.name << "_angle_rad," << b.name << "_speed_rad_s";
  if (s.transmission) state << ",te_rad";
  state << '\n';
  contacts << "time_s";
  for (const physics::GearPairInfo& p : world.gear_pairs()) {
    const std::string n = p.body_a + "__" + p.body_b;
    contacts << ',' << n << "_force_N," << n << "_tooth_pairs," << n << "_max_depth_um";
  }
  contacts << '\n';

  std::unique_ptr<physics::StepLog> step_log;
  if (s.output.per_step_log) step_log = std::make_unique<physics::StepLog>(dir / "steps.h5", world, s.name, dt);

  const double setup_wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  physics::PowerBalance power;
  std::vector<double> speed_sum(world.bodies().size(), 0.0);
  // Per gear pair, the normal forces on the counter-clockwise and clockwise flanks of its first
  // gear's teeth, summed over the steady window's steps: drive and back flanks apart.
  std::vector<std::array<double, 2>> flank_force_sum(world.gear_pairs().size(), {0.0, 0.0});
  long speed_count = 0;
  double max_pen = 0;
  const double ramp_end = physics::ramps_end_s(s);
  std::string status = "completed";
  std::optional<physics::Divergence> diverged;
  physics::RunBounds bounds(s, world);
  const bool tty = isatty(STDERR_FILENO);
  g_interrupted = 0;
  auto old_int = std::signal(SIGINT, on_stop_signal);
  auto old_term = std::signal(SIGTERM, on_stop_signal);
  int last_percent = -1;
  // One row of state.csv and contacts.csv at the world's present time.
  auto write_rows = [&] {
    state << world.time_s();
    for (const physics::BodyState& b : world.bodies()) state << ',' << b.angle_rad << ',' << b.speed_rad_s;
    if (s.transmission)
      state << ',' << world.bodies()[te_in].angle_rad - s.transmission->ratio * world.bodies()[te_out].angle_rad;
    state << '\n';
    contacts << world.time_s();
    for (std::size_t p = 0; p < world.gear_pairs().size(); ++p) {
      double force = 0, depth = 0;
      int n = 0;
      for (const physics::ContactSample& c : world.contacts())
        if (c.pair == static_cast<int>(p)) force += c.normal_force_N, depth = std::max(depth, c.geometry.depth_m), ++n;
      contacts << ',' << force << ',' << n << ',' << depth * 1e6;
    }
    contacts << '\n';
  };
  for (long i = 1; i <= total; ++i) {
    world.step();
    if (step_log) step_log->append(world);
    max_pen = std::max(max_pen, world.max_penetration_m());
    // A run out of its physical bounds stops at this step, its last rows written.
    diverged = bounds.check(world);
    if (diverged) {
      status = "diverged";
      if (i % every != 0) write_rows();
    }
    if (!diverged && world.time_s() >= ramp_end) {
      for (std::size_t b = 0; b < world.bodies().size(); ++b) speed_sum[b] += world.bodies()[b].speed_rad_s;
      for (const physics::ContactSample& c : world.contacts())
        flank_force_sum[static_cast<std::size_t>(c.pair)][c.geometry.flank_a == Flank::Cw] += c.normal_force_N;
      power.add(world.power(), world.time_s());
      ++speed_count;
    }
    if (i % every == 0) write_rows();
    if (diverged) break;
    const int percent = static_cast<int>(100 * i / total);
    if (tty && percent != last_percent) {
      std::cerr << "\r  " << s.name << ": " << percent << "% (t = " << std::fixed << std::setprecision(4) << world.time_s() << " s)" << std::flush;
      last_percent = percent;
    }
    if (g_interrupted) {
      status = "interrupted";
      if (i % every != 0) write_rows();
      break;
    }
  }
  std::signal(SIGINT, old_int);
  std::signal(SIGTERM, old_term);
  const int stop_signal = g_interrupted;
  if (tty) std::cerr << "\n";
  state.flush();
  contacts.flush();
  if (step_log) step_log->close();
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  json summary;
  summary["scenario"] = s.name;
  summary["scenario_file"] = std::filesystem::absolute(o.scenario).lexically_normal().string();
  summary["overrides"] = o.sets;
  summary["status"] = status;
  if (status == "interrupted") summary["signal"] = stop_signal == SIGTERM ? "SIGTERM" : "SIGINT";
  if (diverged)
    summary["divergence"] = {{"what", diverged->what},   {"where", diverged->where}, {"message", diverged->message},
                             {"time_s", diverged->time_s}, {"step", diverged->step},   {"value", diverged->value},
                             {"limit", diverged->limit}};
  summary["created_energy_J"] = bounds.created_energy_J();
  summary["sim_seconds"] = world.time_s();
  summary["steps"] = world.steps();
  summary["time_step_s"] = dt;
  summary["wall_seconds"] = wall;
  summary["wall_seconds_per_sim_second"] = world.time_s() > 0 ? wall / world.time_s() : 0.0;
  summary["mean_speed_window_s"] = {ramp_end, world.time_s()};
  json bodies = json::object();
  for (std::size_t b = 0; b < world.bodies().size(); ++b)
    bodies[world.bodies()[b].name] = {{"mean_speed_rad_s", speed_count ? speed_sum[b] / static_cast<double>(speed_count) : 0.0}};
  summary["bodies"] = bodies;
  if (s.transmission && speed_count) {
    const double out = speed_sum[te_out] / static_cast<double>(speed_count);
    summary["ratio"] = out != 0 ? (speed_sum[te_in] / static_cast<double>(speed_count)) / out : 0.0;
    summary["ratio_nominal"] = s.transmission->ratio;
  }
  summary["max_penetration_um"] = max_pen * 1e6;
  if (power.samples() > 1)
    summary["power_W"] = {{"window_s", {ramp_end, world.time_s()}},
                          {"motor_input", power.motor_W()},
                          {"load_output", -power.load_W()},
                          {"contact_dissipation", -power.contact_W()},
                          {"joint_dissipation", -power.joint_W()},
                          {"kinetic_energy_rate", power.kinetic_rate_W()},
                          {"imbalance_fraction", power.imbalance_fraction()}};
  summary["wall_profile_s"] = {{"setup", setup_wall},
                               {"tooth_contact", world.profile().tooth_contact_s},
                               {"bullet_solver_and_measuring", world.profile().step_total_s - world.profile().tooth_contact_s},
                               {"logging_and_output", wall - setup_wall - world.profile().step_total_s}};
  json pairs = json::array();
  for (std::size_t i = 0; i < world.gear_pairs().size(); ++i) {
    const physics::GearPairInfo& p = world.gear_pairs()[i];
    pairs.push_back({{"a", p.body_a}, {"b", p.body_b}, {"stiffness_N_per_m", p.stiffness_N_per_m}, {"damping_N_s_per_m", p.damping_N_s_per_m}});
    if (!p.stiffness_table.empty()) pairs.back()["stiffness_table"] = p.stiffness_table;
    // Mean normal force on each flank side of a's teeth over the steady window (the speeds'):
    // one side drives, the other touches only without backlash (double-flank contact) or in
    // rattle. The torque they carry is their difference times the base radius.
    if (speed_count) {
      const double n = static_cast<double>(speed_count);
      pairs.back()["mean_normal_force_N"] = {{"ccw_flanks_of_a", flank_force_sum[i][0] / n},
                                             {"cw_flanks_of_a", flank_force_sum[i][1] / n}};
    }
  }
  summary["gear_pairs"] = pairs;
  // The pair macro's gear table at the centre distance it used (mesh members: from their fits).
  json tables = json::array();
  for (const physics::PairTableDef& t : s.pair_tables)
    tables.push_back({{"driver", t.driver},
                      {"driven", t.driven},
                      {"centre_distance_m", t.figures.centre_distance_m},
                      {"centre_distance_derived", t.centre_distance_derived},
                      {"zero_backlash_centre_distance_m", t.figures.zero_backlash_centre_distance_m},
                      {"operating_pressure_angle_rad", t.figures.operating_pressure_angle_rad},
                      {"normal_backlash_m", t.figures.normal_backlash_m},
                      {"contact_ratio", t.figures.contact_ratio},
                      {"base_pitch_mismatch_m", t.figures.base_pitch_mismatch_m}});
  if (!tables.empty()) summary["pair_tables"] = tables;
  // Numerical trouble, counted over the run (never printed mid-run).
  json warnings = json::array();
  if (world.dropped_contacts() > 0)
    warnings.push_back(std::to_string(world.dropped_contacts()) +
                       " tooth contacts dropped: a gear pair touched on more than 4 tooth pairs at once");
  if (!s.contact.stiffness_tables.empty()) summary["stiffness_table_misses"] = world.stiffness_table_misses();
  if (world.stiffness_table_misses() > 0)
    warnings.push_back(std::to_string(world.stiffness_table_misses()) +
                       " contact samples (per step) lay outside their pair's stiffness table and took its end row's value: "
                       "extend the table over the flank");
  if (max_pen > kPenetrationWarning_m)
    warnings.push_back("deepest tooth penetration " + std::to_string(max_pen * 1e6) + " um exceeds " +
                       std::to_string(kPenetrationWarning_m * 1e6) +
                       " um: interference or a time step too large for the contact stiffness");
  if (power.samples() > 1 && std::abs(power.imbalance_fraction()) > kPowerImbalanceWarning)
    warnings.push_back("power balance off by " + std::to_string(100 * power.imbalance_fraction()) +
                       " % of the motor input: the solver is not converged (more iterations or a smaller time step)");
  summary["warnings"] = warnings;
  json outputs = {"state.csv", "contacts.csv"};
  if (step_log) {
    outputs.push_back("steps.h5");
    const double bytes = static_cast<double>(step_log->bytes_on_disk());
    summary["step_log_bytes"] = bytes;
    summary["step_log_bytes_per_sim_second"] = world.time_s() > 0 ? bytes / world.time_s() : 0.0;
  }
  summary["outputs"] = outputs;
  std::ofstream(dir / "summary.json") << summary.dump(2) << "\n";
  std::cout << s.name << ": " << status << ", " << world.time_s() << " s simulated in " << std::setprecision(3) << wall
            << " s wall; logs in " << dir.string() << "\n";
  for (const auto& w : warnings) std::cout << "warning: " << w.get<std::string>() << "\n";
  if (diverged)
    throw RunStopped(kExitDiverged, "diverged at t = " + std::to_string(diverged->time_s) + " s (step " +
                                        std::to_string(diverged->step) + "): " + diverged->message +
                                        ". Logs up to that step are in " + dir.string());
  if (status == "interrupted")
    throw RunStopped(stop_signal == SIGTERM ? kExitSigterm : kExitSigint, std::string("interrupted by ") + (stop_signal == SIGTERM ? "SIGTERM" : "SIGINT") +
                                           ": the logs hold the run up to t = " + std::to_string(world.time_s()) +
                                           " s in " + dir.string() + " (not analysed)");
  // The analysis and the scenario's renders of the finished run; a run too short (or of a train
  // the analysis does not know) keeps its logs and says why it was not analysed or rendered.
  if (!o.no_analyze) try {
      print_analysis(analyze_run(open_run_dir(dir)), std::cout);
    } catch (const InputError& e) {
      std::cout << "not analysed: " << e.what() << "\n";
    }
  if (s.render) try {
      const RenderResult r = render_run(open_run_dir(dir), *s.render);
      std::cout << "rendered " << r.frames << " frames of " << r.from_s << "–" << r.to_s << " s: " << r.video.string() << "\n";
    } catch (const InputError& e) {
      std::cout << "not rendered: " << e.what() << "\n";
    }
}

}  // namespace

void register_run(CLI::App& app) {
  auto o = std::make_shared<RunOptions>();
  CLI::App* sub = app.add_subcommand("run", "Run a scenario headless: state.csv, contacts.csv and summary.json in --out.");
  sub->add_option("scenario", o->scenario, "Scenario file (YAML), e.g. assets/scenarios/paper_dynamics.yaml.")
      ->required()
      ->check(CLI::ExistingFile);
  sub->add_option("--out", o->out_dir, "Output folder (created if missing).")->required();
  sub->add_option("--set", o->sets, "Override a scenario value: key.path=value (repeatable), e.g. solver.time_step_s=1e-5.");
  sub->add_option("--duration", o->duration_s, "Simulated seconds, overriding the scenario's duration_s (at most 1e4 s).")
      ->check(input::cli_within(input::limits::kDuration_s));
  sub->add_flag("--no-analyze", o->no_analyze, "Do not analyse the run at the end (see `gearsim analyze`).");
  sub->callback([o] { run(*o); });
}

}  // namespace gearsim::app

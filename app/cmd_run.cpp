// gearsim run SCENARIO --out DIR: a headless simulation. Writes state.csv and contacts.csv at
// the scenario's output rate and summary.json; a progress line on a terminal; Ctrl-C stops
// cleanly and keeps valid logs; a run that leaves its physical bounds (sim/run_bounds.hpp)
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
#include "input/scenario_record.hpp"
#include "core/errors.hpp"
#include "geometry/gear_spec.hpp"
#include "sim/csv_logs.hpp"
#include "sim/sensor_log.hpp"
#include "sim/simulate.hpp"
#include "sim/step_log.hpp"
#include "physics/world.hpp"

namespace gearsim::app {
namespace {

using json = nlohmann::ordered_json;

// The signal (SIGINT or SIGTERM) that asked the run to stop, 0 while none did.
volatile std::sig_atomic_t g_interrupted = 0;
void on_stop_signal(int sig) { g_interrupted = sig; }

// The files a run, its analysis, report and renders write into the run folder. A run into a
// folder that holds them from an earlier run removes them first, so that no summary or analysis
// of the old run sits beside the new logs. Returns how many were removed; other files stay.
int clear_previous_outputs(const std::filesystem::path& dir) {
  namespace fs = std::filesystem;
  static const char* const kFiles[] = {"summary.json",  "scenario.json", "gearset.yaml",  "state.csv",
                                       "contacts.csv",  "steps.h5",      "analysis.json", "spectrum.csv",
                                       "sidebands.csv", "teeth.csv",     "report.html",   "sensors.csv"};
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

// summary.json of a run: what simulate() measured, in SI, with the scenario's pair tables.
json summary_json(const RunOptions& o, const physics::Scenario& s, const sim::RunSummary& r) {
  json j;
  j["scenario"] = s.name;
  j["scenario_file"] = std::filesystem::absolute(o.scenario).lexically_normal().string();
  j["overrides"] = o.sets;
  j["status"] = sim::status_name(r.status);
  if (r.status == sim::RunStatus::Interrupted) j["signal"] = r.stop_signal == SIGTERM ? "SIGTERM" : "SIGINT";
  if (const auto& d = r.divergence)
    j["divergence"] = {{"what", d->what}, {"where", d->where}, {"message", d->message}, {"time_s", d->time_s},
                       {"step", d->step}, {"value", d->value}, {"limit", d->limit}};
  j["created_energy_J"] = r.created_energy_J;
  j["sim_seconds"] = r.sim_seconds;
  j["steps"] = r.steps;
  j["time_step_s"] = r.time_step_s;
  j["wall_seconds"] = r.wall_seconds;
  j["wall_seconds_per_sim_second"] = r.sim_seconds > 0 ? r.wall_seconds / r.sim_seconds : 0.0;
  j["mean_speed_window_s"] = {r.steady_from_s, r.sim_seconds};
  json bodies = json::object();
  for (const sim::BodyResult& b : r.bodies) bodies[b.name] = {{"mean_speed_rad_s", b.mean_speed_rad_s}};
  j["bodies"] = bodies;
  if (r.ratio) {
    j["ratio"] = *r.ratio;
    j["ratio_nominal"] = s.transmission->ratio;
  }
  j["max_penetration_um"] = r.max_penetration_m * 1e6;
  if (r.power.samples() > 1)
    j["power_W"] = {{"window_s", {r.steady_from_s, r.sim_seconds}},
                    {"motor_input", r.power.motor_W()},
                    {"load_output", -r.power.load_W()},
                    {"contact_dissipation", -r.power.contact_W()},
                    {"joint_dissipation", -r.power.joint_W()},
                    {"kinetic_energy_rate", r.power.kinetic_rate_W()},
                    {"imbalance_fraction", r.power.imbalance_fraction()}};
  j["wall_profile_s"] = {{"setup", r.setup_wall_seconds},
                         {"tooth_contact", r.profile.tooth_contact_s},
                         {"bullet_solver_and_measuring", r.profile.step_total_s - r.profile.tooth_contact_s},
                         {"logging_and_output", r.wall_seconds - r.setup_wall_seconds - r.profile.step_total_s}};
  json pairs = json::array();
  for (const sim::PairResult& p : r.pairs) {
    pairs.push_back({{"a", p.info.body_a}, {"b", p.info.body_b}, {"stiffness_N_per_m", p.info.stiffness_N_per_m},
                     {"damping_N_s_per_m", p.info.damping_N_s_per_m}, {"reduced_mass_kg", p.info.reduced_mass_kg}});
    if (!p.info.stiffness_table.empty()) pairs.back()["stiffness_table"] = p.info.stiffness_table;
    if (r.steady_steps)
      pairs.back()["mean_normal_force_N"] = {{"ccw_flanks_of_a", p.mean_ccw_flank_force_N},
                                             {"cw_flanks_of_a", p.mean_cw_flank_force_N}};
  }
  j["gear_pairs"] = pairs;
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
  if (!tables.empty()) j["pair_tables"] = tables;
  if (!s.contact.stiffness_tables.empty()) j["stiffness_table_misses"] = r.stiffness_table_misses;
  j["warnings"] = r.warnings;
  return j;
}

// Ends a run that stopped early with its exit code, after its outputs were written.
void throw_if_stopped(const sim::RunSummary& r, const std::filesystem::path& dir) {
  if (const auto& d = r.divergence)
    throw RunStopped(kExitDiverged, "diverged at t = " + std::to_string(d->time_s) + " s (step " +
                                        std::to_string(d->step) + "): " + d->message +
                                        ". Logs up to that step are in " + dir.string());
  if (r.status == sim::RunStatus::Interrupted) {
    const bool term = r.stop_signal == SIGTERM;
    throw RunStopped(term ? kExitSigterm : kExitSigint,
                     std::string("interrupted by ") + (term ? "SIGTERM" : "SIGINT") + ": the logs hold the run up to t = " +
                         std::to_string(r.sim_seconds) + " s in " + dir.string() + " (not analysed)");
  }
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

  input::write_scenario_record(s, dir);  // what analyze, report and render read back
  sim::CsvLogs csv(dir, s);
  sim::StepLogObserver step_log(dir / "steps.h5", s.name, s.solver.time_step_s);
  std::vector<sim::Observer*> observers{&csv};
  if (s.output.per_step_log) observers.push_back(&step_log);
  std::optional<sim::SensorLog> sensors;
  if (!s.sensors.empty()) observers.push_back(&sensors.emplace(dir, s));
  const bool tty = isatty(STDERR_FILENO);
  int last_percent = -1;
  sim::SimOptions options;
  options.stop_requested = [] { return static_cast<int>(g_interrupted); };
  options.progress = [&](long i, long total, double t) {
    const int percent = static_cast<int>(100 * i / total);
    if (!tty || percent == last_percent) return;
    std::cerr << "\r  " << s.name << ": " << percent << "% (t = " << std::fixed << std::setprecision(4) << t << " s)" << std::flush;
    last_percent = percent;
  };
  g_interrupted = 0;
  auto old_int = std::signal(SIGINT, on_stop_signal);
  auto old_term = std::signal(SIGTERM, on_stop_signal);
  sim::RunSummary r;
  try {
    r = sim::simulate(s, observers, options);
  } catch (...) {
    std::signal(SIGINT, old_int);
    std::signal(SIGTERM, old_term);
    throw;
  }
  std::signal(SIGINT, old_int);
  std::signal(SIGTERM, old_term);
  if (tty) std::cerr << "\n";
  json summary = summary_json(o, s, r);
  json outputs = {"state.csv", "contacts.csv"};
  if (!s.sensors.empty()) outputs.push_back("sensors.csv");
  if (s.output.per_step_log) {
    outputs.push_back("steps.h5");
    const double bytes = static_cast<double>(step_log.bytes_on_disk());
    summary["step_log_bytes"] = bytes;
    summary["step_log_bytes_per_sim_second"] = r.sim_seconds > 0 ? bytes / r.sim_seconds : 0.0;
  }
  summary["outputs"] = outputs;
  if (const auto& f = csv.force_filter())
    summary["force_filter"] = {{"what", "contacts.csv <pair>_force_N: every step's force through a zero-phase "
                                        "Kaiser-windowed sinc low-pass, decimated to the output rate; "
                                        "<pair>_force_point_N is the point sample"},
                               {"input_rate_hz", f->input_rate_hz},
                               {"output_rate_hz", f->output_rate_hz},
                               {"passband_edge_hz", f->passband_edge_hz},
                               {"stopband_edge_hz", f->stopband_edge_hz},
                               {"stopband_attenuation_dB", f->stopband_attenuation_dB},
                               {"passband_ripple", f->passband_ripple},
                               {"taps", f->length()},
                               {"edge_held_s", f->group_delay_s}};
  std::ofstream(dir / "summary.json") << summary.dump(2) << "\n";
  std::cout << s.name << ": " << sim::status_name(r.status) << ", " << r.sim_seconds << " s simulated in "
            << std::setprecision(3) << r.wall_seconds << " s wall; logs in " << dir.string() << "\n";
  for (const std::string& w : r.warnings) std::cout << "warning: " << w << "\n";
  throw_if_stopped(r, dir);
  // The analysis and the scenario's renders of the finished run; a run too short (or of a train
  // the analysis does not know) keeps its logs and says why it was not analysed or rendered.
  if (!o.no_analyze) try {
      print_analysis(analyze_run(open_run_dir(dir)), std::cout);
    } catch (const InputError& e) {
      std::cout << "not analysed: " << e.what() << "\n";
    }
  if (s.render) try {
      const RenderResult rendered = render_run(open_run_dir(dir), *s.render);
      std::cout << "rendered " << rendered.frames << " frames of " << rendered.from_s << "–" << rendered.to_s
                << " s: " << rendered.video.string() << "\n";
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

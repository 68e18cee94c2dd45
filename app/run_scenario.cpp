#include "app/run_scenario.hpp"

#include <csignal>
#include <fstream>
#include <optional>

#include "core/errors.hpp"
#include "input/scenario_events.hpp"
#include "input/scenario_record.hpp"
#include "sim/csv_logs.hpp"
#include "sim/sensor_log.hpp"
#include "sim/step_log.hpp"
#include "core/output_file.hpp"
#include "app/output_folder.hpp"

namespace gearsim::app {
namespace {

using json = nlohmann::ordered_json;

// summary.json's description of the anti-aliasing filter of contacts.csv's force columns.
json force_filter_json(const DecimationFilter& f) {
  return {{"what",
           "contacts.csv <pair>_force_N: every step's force through a zero-phase "
           "Kaiser-windowed sinc low-pass, decimated to the output rate; "
           "<pair>_force_point_N is the point sample"},
          {"input_rate_hz", f.input_rate_hz},
          {"output_rate_hz", f.output_rate_hz},
          {"passband_edge_hz", f.passband_edge_hz},
          {"stopband_edge_hz", f.stopband_edge_hz},
          {"stopband_attenuation_dB", f.stopband_attenuation_dB},
          {"passband_ripple", f.passband_ripple},
          {"taps", f.length()},
          {"edge_held_s", f.group_delay_s}};
}

}  // namespace

void set_duration(physics::Scenario& s, double duration_s) {
  s.duration_s = duration_s;
  if (!(duration_s > s.solver.time_step_s))
    throw InputError("--duration " + std::to_string(duration_s) + ": expected more than one time step (" +
                     std::to_string(s.solver.time_step_s) + " s in " + s.source.string() + ")");
  if (s.output.sample_rate_hz * duration_s < 1)
    throw InputError("--duration " + std::to_string(duration_s) + ": shorter than one output interval (1/" +
                     std::to_string(s.output.sample_rate_hz) + " Hz in " + s.source.string() + ")");
  // An impulse the shorter run would never reach is refused, as in the file.
  input::check_events_within_duration(s, "--duration " + std::to_string(duration_s));
}

json summary_json(const RunSource& source, const physics::Scenario& s, const sim::RunSummary& r) {
  json j;
  j["scenario"] = s.name;
  j["scenario_file"] = std::filesystem::absolute(source.scenario_file).lexically_normal().string();
  j["overrides"] = source.overrides;
  j["status"] = sim::status_name(r.status);
  if (!r.not_written.empty()) j["not_written"] = r.not_written;
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
  for (const sim::BodyResult& b : r.bodies)
    bodies[b.name] = {{"parent", b.parent},
                      {"mean_absolute_speed_rad_s", b.mean_absolute_speed_rad_s},
                      {"mean_speed_relative_to_parent_rad_s", b.mean_speed_relative_rad_s}};
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
    pairs.push_back({{"a", p.info.body_a},
                     {"b", p.info.body_b},
                     {"stiffness_N_per_m", p.info.stiffness_N_per_m},
                     {"damping_N_s_per_m", p.info.damping_N_s_per_m},
                     {"reduced_mass_kg", p.info.reduced_mass_kg}});
    if (!p.info.stiffness_table.empty()) pairs.back()["stiffness_table"] = p.info.stiffness_table;
    if (r.steady_steps)
      pairs.back()["mean_normal_force_N"] = {{"ccw_flanks_of_a", p.mean_ccw_flank_force_N}, {"cw_flanks_of_a", p.mean_cw_flank_force_N}};
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
                      {"base_pitch_mismatch_m", t.figures.base_pitch_mismatch_m},
                      {"zero_backlash_tolerance_m", t.figures.zero_backlash_tolerance_m}});
  for (std::size_t i = 0; i < s.pair_tables.size(); ++i)
    if (!s.pair_tables[i].placement_note.empty()) tables[i]["placement_note"] = s.pair_tables[i].placement_note;
  if (!tables.empty()) j["pair_tables"] = tables;
  if (!s.contact.stiffness_tables.empty()) j["stiffness_table_misses"] = r.stiffness_table_misses;
  j["warnings"] = r.warnings;
  return j;
}

DirRun run_into_dir(const physics::Scenario& s, const RunSource& source, OutputFolder& folder, const sim::SimOptions& options) {
  const std::filesystem::path& dir = folder.dir();
  // Every name this run may write, in the manifest before any is written.
  std::vector<std::string> logs{"state.csv", "contacts.csv"};
  if (!s.sensors.empty()) logs.push_back("sensors.csv");
  if (s.output.per_step_log) logs.push_back("steps.h5");
  std::vector<std::string> names = logs;
  names.insert(names.end(), {"scenario.json", "summary.json"});
  if (!s.gearset_spec.empty()) names.push_back("gearset.yaml");
  folder.declare(names);
  input::write_scenario_record(s, dir);  // what analyze, report and render read back
  sim::CsvLogs csv(dir, s);
  sim::StepLogObserver step_log(dir / "steps.h5", s.name, s.solver.time_step_s);
  std::vector<sim::Observer*> observers{&csv};
  std::optional<sim::SensorLog> sensors;
  if (!s.sensors.empty()) {
    observers.push_back(&sensors.emplace(dir, s));
    step_log.log_sensors(&*sensors);  // the sensors step first: the log takes this step's values
  }
  if (s.output.per_step_log) observers.push_back(&step_log);
  DirRun run;
  run.result = sim::simulate(s, observers, options);
  const sim::RunSummary& r = run.result;
  json& summary = run.summary;
  summary = summary_json(source, s, r);
  // The logs in place (those not written are named in not_written).
  json outputs = json::array();
  for (const std::string& f : logs)
    if (std::filesystem::is_regular_file(std::filesystem::symlink_status(dir / f))) outputs.push_back(f);
  if (s.output.per_step_log && r.status != sim::RunStatus::OutputFailed) {
    const double bytes = static_cast<double>(step_log.bytes_on_disk());
    summary["step_log_bytes"] = bytes;
    summary["step_log_bytes_per_sim_second"] = r.sim_seconds > 0 ? bytes / r.sim_seconds : 0.0;
  }
  summary["outputs"] = outputs;
  if (const auto& f = csv.force_filter()) summary["force_filter"] = force_filter_json(*f);
  write_output_file(dir / "summary.json", summary.dump(2) + "\n", Durability::Record);
  return run;
}

}  // namespace gearsim::app

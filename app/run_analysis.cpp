#include "app/run_analysis.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <optional>

#include "analysis/constants.hpp"
#include "analysis/run_analysis.hpp"
#include "app/analysis_json.hpp"
#include "app/analysis_outputs.hpp"
#include "core/errors.hpp"
#include "input/csv_table.hpp"
#include "input/gear_train.hpp"
#include "sim/step_log_reader.hpp"
#include "app/output_folder.hpp"
#include "core/output_file.hpp"

namespace gearsim::app {
namespace {

using json = nlohmann::ordered_json;

// The run's gear pairs as `gearsim run` listed them, in the world's order: summary.json's
// gear_pairs, [{"a": body, "b": body}, …].
std::vector<PairId> gear_pairs_of(const RunDir& run) {
  const std::string where = (run.dir / "summary.json").string() + ": gear_pairs";
  if (!run.summary.contains("gear_pairs") || !run.summary.at("gear_pairs").is_array())
    throw InputError(where + ": missing; expected the array of {\"a\": body, \"b\": body} gearsim run writes");
  std::vector<PairId> pairs;
  const json& list = run.summary.at("gear_pairs");
  for (std::size_t i = 0; i < list.size(); ++i) {
    const json& p = list[i];
    const auto body = [&](const char* key) { return p.is_object() && p.contains(key) && p.at(key).is_string(); };
    if (!body("a") || !body("b")) throw InputError(where + "[" + std::to_string(i) + "]: expected {\"a\": body name, \"b\": body name}");
    pairs.push_back({p.at("a").get<std::string>(), p.at("b").get<std::string>()});
  }
  if (pairs.empty()) throw InputError(where + ": empty (a run with no gear pairs has nothing to analyse)");
  return pairs;
}

// Refuses a log with fewer than kMinRunSamples rows from `from_s` on, naming file and window.
void check_rows(const input::CsvTable& table, double from_s) {
  const std::size_t n = samples_from(table.column("time_s"), from_s);
  if (n < analysis_constants::kMinRunSamples)
    throw InputError(table.path.string() + ": only " + std::to_string(n) + " rows after t = " + std::to_string(from_s) +
                     " s (the end of the motors' and loads' ramps, or --from): at least " +
                     std::to_string(analysis_constants::kMinRunSamples) + " are needed to analyse; run longer");
}

// state.csv and contacts.csv are written at the same instants: one time base for every signal.
void check_same_times(const input::CsvTable& state, const input::CsvTable& contacts) {
  const std::vector<double>&ts = state.column("time_s"), &tc = contacts.column("time_s");
  const std::string files = state.path.string() + " and " + contacts.path.string();
  if (ts.size() != tc.size())
    throw InputError(files + ": " + std::to_string(ts.size()) + " and " + std::to_string(tc.size()) +
                     " rows; the logs of one run have one row per output sample each");
  for (std::size_t i = 0; i < ts.size(); ++i)
    if (ts[i] != tc[i])
      throw InputError(files + ": time_s differs in row " + std::to_string(i + 1) +
                       "; the logs of one run are written at the same instants");
}

// Each pair's force column of contacts.csv, a__b_force_N.
std::vector<PairForce> pair_forces(const input::CsvTable& contacts, const std::vector<PairId>& pairs) {
  std::vector<PairForce> forces;
  for (const PairId& p : pairs) {
    const std::string column = pair_name(p) + "_force_N";
    if (!contacts.has(column))
      throw InputError(contacts.path.string() + ": no <pair>_force_N column '" + column + "' for the gear pair " + pair_label(p) +
                       " of summary.json's gear_pairs: expected one contact-force column per gear " + "pair, as gearsim run writes them");
    const std::string point = pair_name(p) + "_force_point_N";  // runs that filter the force keep it
    forces.push_back({p, contacts.column(column), contacts.has(point) ? contacts.column(point) : std::vector<double>{}});
    for (const auto& [name, values] : {std::pair{column, &forces.back().force_N}, std::pair{point, &forces.back().point_force_N}})
      for (std::size_t r = 0; r < values->size(); ++r)
        if (!std::isfinite((*values)[r]))
          throw InputError(contacts.path.string() + ": column " + name + ", data row " + std::to_string(r + 1) +
                           ": expected a finite force in N");
  }
  return forces;
}

// The per-step tooth contacts of steps.h5, its pairs those of summary.json (same order, same names).
ToothContactLog tooth_contacts(const std::filesystem::path& path, const std::vector<PairId>& pairs) {
  sim::StepLogContacts log = sim::read_step_log_contacts(path);
  if (log.pairs.size() != pairs.size())
    throw InputError(path.string() + ": " + std::to_string(log.pairs.size()) + " gear pairs, summary.json's gear_pairs " +
                     std::to_string(pairs.size()) + ": not the logs of one run");
  for (std::size_t p = 0; p < pairs.size(); ++p)
    if (log.pairs[p] != pair_name(pairs[p]))
      throw InputError(path.string() + ": pair " + std::to_string(p) + " is '" + log.pairs[p] + "', summary.json's gear_pairs[" +
                       std::to_string(p) + "] is " + pair_label(pairs[p]) + ": not the logs of one run");
  ToothContactLog t;
  t.pairs = pairs;
  t.time_s = std::move(log.time_s);
  t.pair = std::move(log.pair);
  t.tooth_a = std::move(log.tooth_a);
  t.tooth_b = std::move(log.tooth_b);
  t.normal_impulse_N_s = std::move(log.normal_impulse_N_s);
  t.time_step_s = log.time_step_s;
  return t;
}

const physics::BodyDef* body_named(const physics::Scenario& s, const std::string& name) {
  for (const physics::BodyDef& b : s.bodies)
    if (b.name == name) return &b;
  return nullptr;
}

// Where the sun lies seen from the planet at t = 0 (carrier frame = world frame then), less the
// planet's tooth-0 angle, rad.
double sun_direction_rad(const physics::Scenario& s, const std::string& planet, const std::string& sun) {
  const physics::BodyDef* b = body_named(s, planet);
  if (!b) return 0;
  const physics::BodyDef* c = body_named(s, sun);
  const Eigen::Vector3d p = b->pose.position_m - (c ? c->pose.position_m : Eigen::Vector3d::Zero());
  return std::atan2(-p.y(), -p.x()) - (b->gear ? b->gear->tooth0_angle_rad : 0.0);
}

// The sum of the chain's joint angles at the start poses, rad, as the run logs them at t = 0: each
// body's turn about z against its parent's (the ground's x axis for none), wrapped to (−π, π].
double start_angle_rad(const physics::Scenario& s, const std::vector<std::string>& chain) {
  const auto turn = [&](const std::string& body) {
    const physics::BodyDef* b = body_named(s, body);
    if (!b) return 0.0;
    const Eigen::Matrix3d r = b->pose.orientation.toRotationMatrix();
    return std::atan2(r(1, 0), r(0, 0));
  };
  double sum = 0;
  for (const std::string& body : chain) {
    std::string parent = "ground";
    for (const physics::JointDef& j : s.joints)
      if (j.body == body) parent = j.parent;
    sum += std::remainder(turn(body) - (parent == "ground" ? 0.0 : turn(parent)), 2 * std::numbers::pi);
  }
  return sum;
}

// What the analysis needs of the train: frequencies, planets, the gears whose teeth are counted
// (each planet of a set; the driven gear of a pair); with several stages each pair's stage and
// each stage's transmission error.
TrainDescription train_description(const input::GearTrain& train, const physics::Scenario& s) {
  const auto teeth = [&](const std::string& body) { return body_named(s, body) ? input::teeth_of(*body_named(s, body)) : 0; };
  TrainDescription d;
  d.frequencies = train.frequencies;
  // The set a housing sensor watches: the train's one planetary stage, or, with several, the one
  // whose members the sensors sit on (all on one: a sensor watches the set whose ring it is on).
  int planetary_stages = 0;
  for (const input::TrainStage& st : train.stages) planetary_stages += st.planetary;
  d.planetary = planetary_stages > 0;
  const input::TrainStage* watched = planetary_stages == 1 ? train.first_planetary() : nullptr;
  if (planetary_stages > 1 && !s.sensors.empty()) {
    for (const physics::SensorDef& sensor : s.sensors) {
      const input::TrainStage* st = train.stage_of(sensor.body);
      if (!st || !st->planetary)
        throw InputError(s.source.string() + ": sensor '" + sensor.name + "' sits on '" + sensor.body +
                         "', a member of no planetary stage of the train: a housing sensor is analysed against the planetary set "
                         "whose ring (or sun) it sits on");
      if (watched && watched != st)
        throw InputError(s.source.string() + ": sensors on two planetary stages ('" + watched->name + "', '" + st->name +
                         "'): the sensor analysis takes one set at a time; run the sensors of each stage apart");
      watched = st;
    }
  }
  if (watched) {
    const input::TrainStage& st = *watched;
    d.sun = st.sun;
    d.carrier = st.carrier;
    d.sun_teeth = st.sun_teeth;
    d.planets_in_phase = !st.planets.empty() && st.sun_teeth % static_cast<int>(st.planets.size()) == 0;
  }
  for (const input::TrainStage& st : train.stages) {
    for (const std::string& planet : st.planets) {
      const physics::BodyDef* b = body_named(s, planet);
      const physics::BodyDef* c = body_named(s, st.carrier);
      const Eigen::Vector3d r = b && c ? Eigen::Vector3d(b->pose.position_m - c->pose.position_m) : Eigen::Vector3d::Zero();
      d.planets.push_back({planet, st.planet_teeth, sun_direction_rad(s, planet, st.sun), std::atan2(r.y(), r.x()), st.sun});
      d.counted_gears.push_back({planet, teeth(planet)});
    }
    if (!st.planetary) d.counted_gears.push_back({st.driven, teeth(st.driven)});
  }
  if (train.stages.size() > 1)
    for (const input::TrainStage& st : train.stages) {
      const double fault = st.planetary ? st.frequencies.at("planet_fault").value_hz : 0.0;
      if (st.planetary)
        for (const std::string& planet : st.planets) {
          d.pair_stages.push_back({{st.sun, planet}, st.name, st.frequencies.mesh_hz, fault});
          d.pair_stages.push_back({{planet, st.ring}, st.name, st.frequencies.mesh_hz, fault});
        }
      else
        d.pair_stages.push_back({{st.driver, st.driven}, st.name, st.frequencies.mesh_hz, 0.0});
      const std::vector<std::string>&in = train.angle_chain.at(st.input), &out = train.angle_chain.at(st.output);
      d.stage_te.push_back({st.name, in, out, st.ratio, start_angle_rad(s, in) - st.ratio * start_angle_rad(s, out)});
    }
  return d;
}

// How long the ends of the run's anti-aliased force hold their end values (summary.json
// force_filter.edge_held_s), s; 0 for a run that did not filter.
double edge_held_s(const RunDir& run) {
  if (!run.summary.contains("force_filter")) return 0;
  const json& f = run.summary["force_filter"];
  if (!f.is_object() || !f.contains("edge_held_s") || !f["edge_held_s"].is_number() || !(f["edge_held_s"].get<double>() >= 0))
    throw InputError((run.dir / "summary.json").string() + ": key force_filter.edge_held_s: expected a duration ≥ 0 in s");
  return f["edge_held_s"].get<double>();
}

// The output-rate samples after t_last − edge_s left out: there the filtered force holds the
// run's last value (sim/csv_logs.hpp). Every series is cut at the same sample.
void drop_edge_held_end(RunSignals& s, double edge_s) {
  if (edge_s <= 0 || s.time_s.empty()) return;
  const double end = s.time_s.back() - edge_s;
  std::size_t n = 0;
  while (n < s.time_s.size() && s.time_s[n] <= end) ++n;
  auto cut = [n](std::vector<double>& v) {
    if (v.size() > n) v.resize(n);
  };
  cut(s.time_s);
  for (PairForce& p : s.pair_forces) cut(p.force_N), cut(p.point_force_N);
  for (BodyAngle& a : s.angles) cut(a.angle_rad);
  if (s.te) cut(s.te->time_s), cut(s.te->te_rad);
}

// The run's signals from its logs: state.csv (angles, te_rad), contacts.csv (pair forces),
// steps.h5 when it was kept.
RunSignals run_signals(const RunDir& run, const TrainDescription& train, double from_s) {
  const input::CsvTable state = input::read_csv(run.dir / "state.csv"), contacts = input::read_csv(run.dir / "contacts.csv");
  check_rows(contacts, from_s);
  check_rows(state, from_s);
  check_same_times(state, contacts);
  const std::vector<PairId> pairs = gear_pairs_of(run);
  RunSignals s;
  s.from_s = from_s;
  s.time_s = contacts.column("time_s");
  s.pair_forces = pair_forces(contacts, pairs);
  if (state.has("te_rad")) {
    if (!run.scenario.transmission)
      throw InputError(state.path.string() + ": te_rad logged, but the run's scenario.json names no transmission");
    try {
      s.te = transmission_error_series(state.column("time_s"), state.column("te_rad"), run.scenario.transmission->ratio);
    } catch (const InputError& e) {
      throw InputError(state.path.string() + ": column te_rad: " + e.what());
    }
  }
  for (const CountedGear& g : train.counted_gears) s.angles.push_back({g.body, state.column(g.body + "_angle_rad")});
  const auto add_angle = [&](const std::string& body) {
    if (std::none_of(s.angles.begin(), s.angles.end(), [&](const BodyAngle& a) { return a.body == body; }))
      s.angles.push_back({body, state.column(body + "_angle_rad")});
  };
  for (const PlanetGear& p : train.planets) add_angle(p.body);
  for (const TrainDescription::StageTe& st : train.stage_te)
    for (const auto* chain : {&st.input_chain, &st.output_chain})
      for (const std::string& body : *chain) add_angle(body);
  // The logs the run's scenario says it wrote are read (a missing one is refused by its reader,
  // naming it), never skipped.
  if (run.scenario.output.per_step_log) s.tooth_contacts = tooth_contacts(run.dir / "steps.h5", pairs);
  if (!run.scenario.sensors.empty()) {
    const input::CsvTable sensors = input::read_csv(run.dir / "sensors.csv");
    for (const physics::SensorDef& d : run.scenario.sensors)
      s.sensors.push_back({d.name, d.angle_rad, d.window_width_rad, d.resonance_hz, sensors.column("time_s"),
                           sensors.column(d.name + "_acceleration_m_s2")});
    if (!train.carrier.empty()) s.angles.push_back({train.carrier, state.column(train.carrier + "_angle_rad")});
    if (!train.sun.empty() && std::none_of(s.angles.begin(), s.angles.end(), [&](const BodyAngle& a) { return a.body == train.sun; }))
      s.angles.push_back({train.sun, state.column(train.sun + "_angle_rad")});
  }
  drop_edge_held_end(s, edge_held_s(run));
  return s;
}

}  // namespace

// Per logged pair, the flank of gear a that carried its load over the steady window: the larger
// of summary.json's gear_pairs[].mean_normal_force_N {ccw_flanks_of_a, cw_flanks_of_a}.
std::vector<TrainDescription::LoadedFlank> loaded_flanks(const RunDir& run) {
  std::vector<TrainDescription::LoadedFlank> out;
  const json& list = run.summary.at("gear_pairs");
  for (const json& p : list) {
    if (!p.contains("mean_normal_force_N")) continue;
    const json& m = p.at("mean_normal_force_N");
    if (!m.contains("ccw_flanks_of_a") || !m.contains("cw_flanks_of_a") || !m.at("ccw_flanks_of_a").is_number() ||
        !m.at("cw_flanks_of_a").is_number())
      throw InputError((run.dir / "summary.json").string() +
                       ": gear_pairs[].mean_normal_force_N: expected {ccw_flanks_of_a, cw_flanks_of_a} in N");
    const double ccw = m.at("ccw_flanks_of_a").get<double>(), cw = m.at("cw_flanks_of_a").get<double>();
    TrainDescription::LoadedFlank l{{p.at("a").get<std::string>(), p.at("b").get<std::string>()}, "", false};
    if (ccw > 0 || cw > 0) l.flank_of_a = ccw >= cw ? "ccw" : "cw";
    const physics::BodyDef* b = body_named(run.scenario, l.pair.b);
    l.b_internal = b && input::is_internal(*b);
    out.push_back(l);
  }
  return out;
}

// A train of several stages: summary.json's `stages`, each stage's ratio ω_in/ω_out measured
// (the run's mean absolute speeds of its input and output members, summary.json's bodies) beside
// the rigid kinematics' (`ratio_nominal`).
static void add_stage_ratios(json& summary, const input::GearTrain& train) {
  if (train.stages.size() < 2) return;
  json stages = json::array();
  for (const input::TrainStage& st : train.stages) {
    json e = {{"name", st.name}, {"input", st.input}, {"output", st.output}};
    const auto speed = [&](const std::string& body) -> std::optional<double> {
      if (!summary.contains("bodies") || !summary["bodies"].contains(body)) return std::nullopt;
      const json& b = summary["bodies"][body];
      if (!b.contains("mean_absolute_speed_rad_s") || !b["mean_absolute_speed_rad_s"].is_number()) return std::nullopt;
      return b["mean_absolute_speed_rad_s"].get<double>();
    };
    const std::optional<double> in = speed(st.input), out = speed(st.output);
    e["ratio"] = in && out && *out != 0 ? json(*in / *out) : json();
    e["ratio_nominal"] = st.ratio;
    stages.push_back(e);
  }
  summary["stages"] = stages;
}

input::GearTrain run_gear_train(const RunDir& run) {
  std::vector<input::Mesh> meshes;
  for (const PairId& p : gear_pairs_of(run)) meshes.emplace_back(p.a, p.b);
  return input::gear_train_of(run.scenario, meshes);
}

// The analysis of the run whose train is `train` (run_gear_train's, found once).
static RunAnalysis analyze_train(const RunDir& run, const input::GearTrain& train, const AnalyzeOptions& o) {
  const physics::Scenario& s = run.scenario;
  TrainDescription description = train_description(train, s);
  description.loaded_flanks = loaded_flanks(run);
  double from_s = o.from_s;
  // Not before the anti-aliased force is free of its start (held at the first value before t = 0).
  const double edge = edge_held_s(run);
  if (from_s >= 0 && from_s < edge)
    throw InputError("--from " + std::to_string(from_s) + ": the run's anti-aliased force holds its start value until t = " +
                     std::to_string(edge) + " s (summary.json force_filter.edge_held_s); expected a start at or after it");
  if (from_s < 0) from_s = std::max(physics::ramps_end_s(s), edge);
  return analyze_signals(run_signals(run, description, from_s), description);
}

RunAnalysis analyze_run_dir(const RunDir& run, const AnalyzeOptions& o) { return analyze_train(run, run_gear_train(run), o); }

json write_run_analysis(const RunDir& run, const AnalyzeOptions& o) {
  const physics::Scenario& s = run.scenario;
  const input::GearTrain train = run_gear_train(run);
  const RunAnalysis a = analyze_train(run, train, o);
  const json j = analysis_json(a, train, s.name);
  declare_outputs(run.dir, {"analysis.json", "spectrum.csv", "sidebands.csv", "teeth.csv", "summary.json"});
  write_output_file(run.dir / "analysis.json", j.dump(2) + "\n", Durability::Record);
  // To 1000 Hz, or a fifth past the highest mesh harmonic analysed when a fast stage's lie above.
  double top_hz = analysis_constants::kRunFloorBandTop_hz;
  for (const PairForceAnalysis& p : a.pairs)
    for (const MeshHarmonic& h : p.mesh.harmonics)
      if (h.expected_hz >= top_hz) top_hz = std::max(top_hz, 1.2 * h.expected_hz);
  write_spectrum_csv(run.dir / "spectrum.csv", a, top_hz);
  write_sidebands_csv(run.dir / "sidebands.csv", a);
  write_teeth_csv(run.dir / "teeth.csv", a);
  RunDir updated = run;
  add_to_summary(updated.summary, a, train.frequencies.mesh_hz);
  add_stage_ratios(updated.summary, train);
  save_summary(updated);
  return j;
}

}  // namespace gearsim::app

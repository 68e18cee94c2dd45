#include "app/analysis_json.hpp"

namespace gearsim::app {
namespace {

using json = nlohmann::ordered_json;

// A mesh harmonic: where it was expected, its peak over the pair's floor, its sidebands.
json harmonic_json(const MeshHarmonic& h, const std::optional<double>& over_floor_db) {
  json hj{{"order", h.order}, {"expected_hz", h.expected_hz}};
  if (h.peak) {
    hj["peak_hz"] = h.peak->frequency_hz;
    hj["amplitude_N"] = h.peak->amplitude;
    hj["over_median_floor_0_1000_hz_db"] = *over_floor_db;
  }
  json sides = json::array();
  for (const Sideband& b : h.sidebands) {
    json bj{{"frequency_hz", b.peak.frequency_hz},
            {"offset_hz", b.offset_hz},
            {"amplitude_N", b.peak.amplitude},
            {"level_db_re_harmonic", b.level_db_re_harmonic},
            {"over_floor_db", b.height_over_floor_db}};
    if (b.match) bj["match"] = match_label(*b.match);
    if (b.mesh_line) bj["mesh_line"] = b.mesh_line->key;
    sides.push_back(bj);
  }
  hj["sidebands"] = sides;
  return hj;
}

json pair_json(const PairForceAnalysis& p, bool planetary) {
  json j;
  j["resolution_hz"] = p.spectrum.resolution_hz;
  j["bin_width_hz"] = p.spectrum.bin_width_hz;
  j["median_floor_0_1000_hz_N"] = p.floor_N;
  json harmonics = json::array();
  for (std::size_t k = 0; k < p.mesh.harmonics.size(); ++k)
    harmonics.push_back(harmonic_json(p.mesh.harmonics[k], p.harmonic_over_floor_db[k]));
  j["mesh_harmonics"] = harmonics;
  if (planetary) {
    json family = json::array();
    for (const FaultLine& l : p.planet_fault_family) {
      json e{{"multiple", l.multiple}, {"expected_hz", l.expected_hz}};
      if (l.peak)
        e["peak_hz"] = l.peak->frequency_hz, e["amplitude_N"] = l.peak->amplitude, e["over_median_floor_0_1000_hz_db"] = l.over_floor_db;
      family.push_back(e);
    }
    j["planet_fault_family"] = family;
  }
  j["mean_force_N"] = p.mean_force_N;
  j["peak_force_N"] = p.peak_force_N;
  j["dynamic_factor_band_limited"] = p.dynamic_factor_band_limited;
  if (p.dynamic_factor_per_step) {
    j["mean_step_force_N"] = *p.mean_step_force_N;
    j["peak_step_force_N"] = *p.peak_step_force_N;
    j["dynamic_factor_per_step"] = *p.dynamic_factor_per_step;
  }
  j["zero_force_share"] = p.zero_force_share;
  if (p.steps_without_force_share) j["steps_without_force_share"] = *p.steps_without_force_share;
  return j;
}

json te_json(const SeriesStats& te) {
  return {{"mean_rad", te.mean}, {"min_rad", te.min}, {"max_rad", te.max}, {"peak_to_peak_rad", te.peak_to_peak}, {"rms_rad", te.rms}};
}

// Per tooth: its mean force and z-score.
json teeth_json(const std::vector<double>& mean_force_N, const std::vector<double>& z_score) {
  json list = json::array();
  for (std::size_t k = 0; k < mean_force_N.size(); ++k)
    list.push_back({{"tooth", k}, {"mean_force_N", mean_force_N[k]}, {"z_score", z_score[k]}});
  return list;
}

json synchronous_json(const SynchronousTeeth& s) {
  json j;
  j["pair"] = pair_name(s.pair);
  j["gear"] = s.planet;
  j["method"] = "angle-synchronous average of the pair force over the planet's rotation relative to the carrier";
  j["revolutions"] = s.revolutions;
  j["samples_per_revolution"] = s.samples_per_revolution;
  j["z_threshold"] = s.z_threshold;
  j["min_relative_deviation"] = s.min_relative_deviation;
  j["flagged_teeth"] = s.flagged_teeth;
  j["teeth"] = teeth_json(s.mean_force_N, s.z_score);
  // NaN (a difference signal without variance) is written as null.
  auto num_or_null = [](double v) { return std::isfinite(v) ? json(v) : json(nullptr); };
  const ConditionIndicators& c = s.indicators;
  j["condition_indicators"] = {
      {"signal", "the averaged force (one planet revolution); mesh order " + std::to_string(s.mean_force_N.size())},
      {"rms_N", num_or_null(c.rms)},
      {"crest_factor", num_or_null(c.crest_factor)},
      {"kurtosis", num_or_null(c.kurtosis)},
      {"fm0", num_or_null(c.fm0)},
      {"fm4", num_or_null(c.fm4)},
      {"m6a", num_or_null(c.m6a)},
      {"na4", num_or_null(c.na4)},
      {"er", num_or_null(c.er)}};
  return j;
}

json tooth_loads_json(const ToothLoads& t) {
  json j;
  j["pair"] = pair_name(t.pair);
  j["gear"] = t.gear;
  j["window_s"] = {t.from_s, t.to_s};
  j["revolutions"] = t.revolutions;
  j["z_threshold"] = t.z_threshold;
  j["min_relative_deviation"] = t.min_relative_deviation;
  j["flagged_teeth"] = t.flagged;
  j["teeth"] = teeth_json(t.mean_force_N, t.z_score);
  // Each tooth's share of its own mesh (diagnosis.hpp), in steps, with its z-score.
  for (std::size_t k = 0; k < t.share_steps.size(); ++k) {
    j["teeth"][k]["share_of_mesh_steps"] = t.share_steps[k];
    j["teeth"][k]["share_z_score"] = t.share_z[k];
  }
  j["share_flagged_teeth"] = t.share_flagged;
  return j;
}

json fault_json(const ToothFault& f) {
  return {{"gear", f.gear},     {"tooth", f.tooth},       {"flank", f.flank},          {"pair", f.pair.a.empty() ? "" : pair_name(f.pair)},
          {"source", f.source}, {"evidence", f.evidence}, {"confidence", f.confidence}};
}

json diagnosis_json(const Diagnosis& d) {
  json faults = json::array();
  for (const ToothFault& f : d.faults) faults.push_back(fault_json(f));
  return {{"faults", faults}};
}

json response_json(const ToothResponse& r) {
  auto num_or_null = [](double v) { return std::isfinite(v) ? json(v) : json(nullptr); };
  return {{"gear", r.gear},
          {"tooth", r.tooth},
          {"pair", r.pair.a.empty() ? "" : pair_name(r.pair)},
          {"load_z_score", num_or_null(r.load_z)},
          {"share_z_score", num_or_null(r.share_z)},
          {"source", r.source},
          {"reason", r.reason}};
}

json responses_json(const Diagnosis& d) {
  json list = json::array();
  for (const ToothResponse& r : d.responses) list.push_back(response_json(r));
  return list;
}

// The in-phase localisation (in_phase_localisation.hpp): per planet its event and background,
// the correlations of the event waveforms, what was named.
json in_phase_json(const InPhaseLocalisation& l, const std::vector<PlanetSensorView>& planets) {
  json per = json::array();
  for (std::size_t k = 0; k < l.planets.size(); ++k)
    per.push_back({{"planet", k < planets.size() ? planets[k].planet : ""},
                   {"event_rms_m_s2", l.planets[k].event_rms_m_s2},
                   {"background_rms_m_s2", l.planets[k].background_rms_m_s2}});
  return {
      {"samples_per_revolution", l.samples_per_revolution},
      {"event_tooth_facing_sun", l.event_tooth},
      {"planets", per},
      {"correlation", l.correlation},
      {"min_correlation", l.min_correlation},
      {"event", l.event},
      {"named", l.named >= 0 && static_cast<std::size_t>(l.named) < planets.size() ? json(planets[static_cast<std::size_t>(l.named)].planet)
                                                                                   : json(nullptr)},
      {"confidence", l.confidence},
      {"reason", l.reason}};
}

json sensors_json(const std::vector<SensorAnalysis>& list) {
  auto num_or_null = [](double v) { return std::isfinite(v) ? json(v) : json(nullptr); };
  json out = json::array();
  for (const SensorAnalysis& a : list) {
    json planets = json::array();
    for (const PlanetSensorView& v : a.planets) {
      const ConditionIndicators& c = v.indicators;
      planets.push_back({{"planet", v.planet},
                         {"passes", v.passes},
                         {"coverage", v.coverage},
                         {"peak_tooth_facing_sun", v.peak_tooth},
                         {"difference_peak_m_s2", v.difference_peak_m_s2},
                         {"condition_indicators",
                          {{"rms_m_s2", num_or_null(c.rms)},
                           {"crest_factor", num_or_null(c.crest_factor)},
                           {"kurtosis", num_or_null(c.kurtosis)},
                           {"fm0", num_or_null(c.fm0)},
                           {"fm4", num_or_null(c.fm4)},
                           {"m6a", num_or_null(c.m6a)},
                           {"na4", num_or_null(c.na4)},
                           {"er", num_or_null(c.er)}}}});
    }
    json j = {{"sensor", a.sensor},
              {"sample_rate_hz", a.sample_rate_hz},
              {"method", "McFadden's planet-separated averages (1991)"},
              {"planets", planets}};
    if (!a.envelope_lines.empty()) {
      json lines = json::array();
      for (const SensorAnalysis::EnvelopeLine& l : a.envelope_lines)
        lines.push_back({{"key", l.key}, {"multiple", l.multiple}, {"frequency_hz", l.frequency_hz}, {"amplitude_m_s2", l.amplitude_m_s2}});
      j["envelope"] = {{"band_hz", {a.envelope_band_lo_hz, a.envelope_band_hi_hz}}, {"lines", lines}};
    }
    if (a.sun) {
      const ConditionIndicators& c = a.sun->indicators;
      j["sun"] = {{"gear", a.sun->planet},
                  {"passes", a.sun->passes},
                  {"coverage", a.sun->coverage},
                  {"condition_indicators",
                   {{"rms_m_s2", num_or_null(c.rms)},
                    {"crest_factor", num_or_null(c.crest_factor)},
                    {"kurtosis", num_or_null(c.kurtosis)},
                    {"fm0", num_or_null(c.fm0)},
                    {"fm4", num_or_null(c.fm4)},
                    {"m6a", num_or_null(c.m6a)},
                    {"na4", num_or_null(c.na4)},
                    {"er", num_or_null(c.er)}}}};
    }
    if (a.in_phase) j["in_phase"] = in_phase_json(*a.in_phase, a.planets);
    if (a.in_phase_refined) j["in_phase_refined_grid"] = in_phase_json(*a.in_phase_refined, a.planets);
    j["fault"] = a.fault ? fault_json(*a.fault) : json(nullptr);
    if (!a.note.empty()) j["note"] = a.note;
    out.push_back(j);
  }
  return out;
}

const char* stage_kind(const input::TrainStage& st) {
  return st.planetary ? "planetary" : st.internal_pair ? "internal pair" : "external pair";
}

json gear_train_json(const input::GearTrain& train, const RunAnalysis& a) {
  json freqs = json::array();
  for (const CharacteristicFrequency& f : train.frequencies.frequencies)
    freqs.push_back({{"key", f.key}, {"name", f.name}, {"value_hz", f.value_hz}, {"formula", f.formula}});
  json j = {{"kind", train.stages.size() > 1 ? "train" : stage_kind(train.stages.front())},
            {"mesh_hz", train.frequencies.mesh_hz},
            {"characteristic_frequencies", freqs}};
  if (train.stages.size() == 1) return j;
  // Several stages: each with its members, kinematics, mesh frequency and transmission error.
  json stages = json::array();
  double ratio = 1;
  for (const input::TrainStage& st : train.stages) {
    json e = {{"name", st.name}, {"kind", stage_kind(st)}};
    if (st.planetary)
      e["members"] = {{"sun", st.sun}, {"planets", st.planets}, {"ring", st.ring}, {"carrier", st.carrier}, {"fixed", st.fixed}},
      e["teeth"] = {{"sun", st.sun_teeth}, {"planet", st.planet_teeth}, {"ring", st.ring_teeth}};
    else
      e["members"] = {{"driver", st.driver}, {"driven", st.driven}},
      e["teeth"] = {{"driver", st.driver_teeth}, {"driven", st.driven_teeth}};
    e["input"] = st.input;
    e["output"] = st.output;
    e["input_speed_rad_s"] = st.input_speed_rad_s;
    e["output_speed_rad_s"] = st.output_speed_rad_s;
    e["ratio"] = st.ratio;
    e["mesh_hz"] = st.frequencies.mesh_hz;
    for (const RunAnalysis::StageTe& te : a.stage_te)
      if (te.stage == st.name) {
        e["transmission_error"] = te_json(te.te.rad);
        e["transmission_error"]["samples_peak_to_peak_rad"] = te.samples_peak_to_peak_rad;
      }
    ratio *= st.ratio;
    stages.push_back(e);
  }
  j["ratio"] = ratio;
  j["stages"] = stages;
  return j;
}

}  // namespace

std::string pair_name(const PairId& pair) { return pair.a + "__" + pair.b; }

std::string match_label(const SidebandMatch& match) { return std::to_string(match.multiple) + "x" + match.key; }

json analysis_json(const RunAnalysis& a, const input::GearTrain& train, const std::string& scenario_name) {
  json j;
  j["scenario"] = scenario_name;
  j["window_s"] = {a.from_s, a.to_s};
  j["sample_rate_hz"] = a.sample_rate_hz;
  j["gear_train"] = gear_train_json(train, a);
  json pairs = json::object();
  for (const PairForceAnalysis& p : a.pairs) {
    const input::TrainStage* st = train.stage_of(p.pair.a);
    json& e = pairs[pair_name(p.pair)] = pair_json(p, st && st->planetary);
    if (train.stages.size() > 1 && st) e["stage"] = st->name;
  }
  j["pairs"] = pairs;
  // Teeth that lose contact and strike again: their lines need a finer step than a run in mesh.
  json separating = json::array();
  for (const PairForceAnalysis& p : a.pairs)
    if (p.zero_force_share > 0 || p.steps_without_force_share.value_or(0) > 0) separating.push_back(pair_name(p.pair));
  if (!separating.empty())
    j["contact_loss"] = {{"pairs", separating},
                         {"note",
                          "the teeth of these pairs separate (steps or samples without force) and strike again: the mesh-harmonic "
                          "amplitudes of such a run depend on the time step more than those of a run that stays in mesh "
                          "(the paper's faulty set: within 1.8 % between dt 2e-5, 1e-5 and 5e-6 s, the healthy set 1.1 %; "
                          "docs/solver.md); check them by rerunning at half solver.time_step_s"}};
  if (a.te) {
    j["transmission_error"] = te_json(a.te->rad);
    if (a.te_samples_peak_to_peak_rad) j["transmission_error"]["samples_peak_to_peak_rad"] = *a.te_samples_peak_to_peak_rad;
  }
  if (a.synchronous) {
    json tsa = json::array();
    for (const SynchronousTeeth& s : *a.synchronous) tsa.push_back(synchronous_json(s));
    j["synchronous_average"] = tsa;
    if (!a.synchronous_note.empty()) j["synchronous_average_note"] = a.synchronous_note;
  }
  if (a.tooth_loads) {
    json loads = json::array();
    for (const ToothLoads& t : *a.tooth_loads) loads.push_back(tooth_loads_json(t));
    j["tooth_loads"] = loads;
  }
  if (a.diagnosis) {
    j["diagnosis"] = diagnosis_json(*a.diagnosis);
    j["tooth_responses"] = responses_json(*a.diagnosis);
  }
  if (!a.sensors.empty()) {
    j["sensors"] = sensors_json(a.sensors);
    if (!j.contains("diagnosis")) j["diagnosis"] = {{"faults", json::array()}};
    for (const SensorAnalysis& s : a.sensors) {
      if (s.fault) j["diagnosis"]["faults"].push_back(fault_json(*s.fault));
      for (const ToothResponse& r : s.responses) {
        if (!j.contains("tooth_responses")) j["tooth_responses"] = json::array();
        j["tooth_responses"].push_back(response_json(r));
      }
    }
  }
  return j;
}

}  // namespace gearsim::app

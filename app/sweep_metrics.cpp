#include "app/sweep_metrics.hpp"

#include <algorithm>
#include <fstream>
#include <optional>

#include "core/input_file.hpp"
#include "input/input_limits.hpp"
#include "analysis/run_analysis.hpp"
#include "app/analysis_json.hpp"
#include "app/run_analysis.hpp"
#include "app/run_dir.hpp"
#include "core/errors.hpp"
#include "input/gear_train.hpp"
#include "sweep/json_path.hpp"

namespace gearsim::app {

using json = nlohmann::ordered_json;

namespace {

json read_json(const std::filesystem::path& p) {
  if (!std::filesystem::exists(std::filesystem::symlink_status(p)))
    throw InputError(p.string() + ": not found (the case was not analysed?)");
  const std::string text = read_input_file(p, input::limits::kMaxRecordBytes, "a case's JSON record");
  try {
    return json::parse(text);
  } catch (const json::exception& e) {
    throw InputError(p.string() + ": not valid JSON: " + e.what());
  }
}

// A named metric from the run's analysis over its steady window.
void add_named_metric(json& m, const std::string& name, const RunDir& run, const RunAnalysis& a) {
  if (name == "dynamic_factor_band_limited") {
    // Peak over mean of each pair's anti-aliased force; the sweep's column is the worst pair.
    double worst = 0;
    for (const PairForceAnalysis& p : a.pairs) worst = std::max(worst, p.dynamic_factor_band_limited);
    m[name] = worst;
    for (const PairForceAnalysis& p : a.pairs) m[name + "." + pair_name(p.pair)] = p.dynamic_factor_band_limited;
  } else if (name == "dynamic_factor_per_step") {
    // Peak over mean of each pair's per-step force (steps.h5): ISO 6336's K_v.
    double worst = 0;
    for (const PairForceAnalysis& p : a.pairs) {
      if (!p.dynamic_factor_per_step)
        throw InputError((run.dir / "summary.json").string() +
                         ": metric dynamic_factor_per_step needs the per-step log (output.per_step_log: true), which this case did "
                         "not keep");
      worst = std::max(worst, *p.dynamic_factor_per_step);
    }
    m[name] = worst;
    for (const PairForceAnalysis& p : a.pairs) m[name + "." + pair_name(p.pair)] = *p.dynamic_factor_per_step;
  } else if (name == "mean_force_N") {
    for (const PairForceAnalysis& p : a.pairs) m["mean_force_N." + pair_name(p.pair)] = p.mean_force_N;
  } else if (name == "mesh_frequency_hz") {
    const input::GearTrain train = run_gear_train(run);
    m["mesh_frequency_hz"] = train.frequencies.mesh_hz;  // the first stage's
    if (train.stages.size() > 1)
      for (const input::TrainStage& st : train.stages) m["mesh_frequency_hz." + st.name] = st.frequencies.mesh_hz;
  } else if (name == "rms_dynamic_te_rad") {
    if (!a.te) throw InputError((run.dir / "state.csv").string() + ": no te_rad column: the run has no transmission error");
    m["rms_dynamic_te_rad"] = a.te->rad.rms;  // about the window's mean: the dynamic part
  }
}

}  // namespace

json collect_case_metrics(const std::filesystem::path& case_dir, const input::SweepCollect& c) {
  json m = json::object();
  const RunDir run = open_run_dir(case_dir);
  for (const std::string& key : c.summary)
    m["summary." + key] = sweep::number_at_path(run.summary, key, (case_dir / "summary.json").string());
  if (!c.analysis.empty()) {
    const json analysis = read_json(case_dir / "analysis.json");
    for (const std::string& key : c.analysis)
      m["analysis." + key] = sweep::number_at_path(analysis, key, (case_dir / "analysis.json").string());
  }
  if (c.metrics.empty()) return m;
  // Only mesh_frequency_hz needs no analysis of the logs.
  std::optional<RunAnalysis> a;
  for (const std::string& name : c.metrics) {
    if (!a && name != "mesh_frequency_hz") a = analyze_run_dir(run);
    add_named_metric(m, name, run, a ? *a : RunAnalysis{});
  }
  return m;
}

}  // namespace gearsim::app

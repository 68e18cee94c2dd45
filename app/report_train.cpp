// Report section: the gearbox that was run, whatever it is — its stages (kind, members, input and
// output, ratio, mesh frequency, transmission error) and its gears (teeth, module, pressure angle,
// face width, speed by the rigid kinematics beside the run's mean), from the run's scenario record
// and analysis.json.
#include <cmath>
#include <numbers>

#include "app/html.hpp"
#include "app/report.hpp"
#include "app/run_analysis.hpp"

namespace gearsim::app {

using json = nlohmann::ordered_json;

namespace {

constexpr double kRpmPerRadPerS = 60 / (2 * std::numbers::pi);

std::string stage_members(const input::TrainStage& st) {
  if (!st.planetary) return html_escape(st.driver) + " → " + html_escape(st.driven);
  return "sun " + html_escape(st.sun) + ", " + std::to_string(st.planets.size()) + " planets on " + html_escape(st.carrier) + ", ring " +
         html_escape(st.ring) + "; " + html_escape(st.fixed) + " fixed";
}

std::string stage_teeth(const input::TrainStage& st) {
  if (!st.planetary) return std::to_string(st.driver_teeth) + " / " + std::to_string(st.driven_teeth);
  return std::to_string(st.sun_teeth) + " / " + std::to_string(st.planet_teeth) + " / " + std::to_string(st.ring_teeth);
}

// A gear's role in its stage.
std::string role(const input::TrainStage& st, const std::string& gear) {
  if (gear == st.sun) return "sun";
  if (gear == st.ring) return "ring";
  if (gear == st.driver) return "driver";
  if (gear == st.driven) return "driven";
  return "planet";
}

}  // namespace

std::string report_train_section(const RunDir& run) {
  std::string h = "<h2>The gearbox</h2>\n";
  const json a = read_json_record(run.dir / "analysis.json");
  const input::GearTrain train = run_gear_train(run);
  // Stages, from the motor down.
  std::vector<std::vector<std::string>> rows;
  double ratio = 1;
  for (std::size_t k = 0; k < train.stages.size(); ++k) {
    const input::TrainStage& st = train.stages[k];
    std::string te = "–";
    if (train.stages.size() == 1 && a.contains("transmission_error"))
      te = num(a["transmission_error"]["peak_to_peak_rad"].get<double>(), 4);
    else if (a["gear_train"].contains("stages") && a["gear_train"]["stages"][k].contains("transmission_error"))
      te = num(a["gear_train"]["stages"][k]["transmission_error"]["peak_to_peak_rad"].get<double>(), 4);
    rows.push_back({html_escape(st.name.empty() ? std::string("(one stage)") : st.name),
                    st.planetary       ? "planetary"
                    : st.internal_pair ? "internal pair"
                                       : "external pair",
                    stage_members(st), stage_teeth(st), html_escape(st.input) + " → " + html_escape(st.output), num(st.ratio, 7),
                    num(st.frequencies.mesh_hz, 6), te});
    ratio *= st.ratio;
  }
  h += "<p>Stages from the motor (" + html_escape(train.input_body) + " at " + num(train.input_speed_rad_s, 6) +
       " rad/s = " + num(train.input_speed_rad_s * kRpmPerRadPerS, 6) +
       " rpm) down; ratio ω<sub>in</sub>/ω<sub>out</sub> by the rigid kinematics, " + "overall " + num(ratio, 9) +
       (run.summary.contains("ratio") ? ", measured " + num(run.summary["ratio"].get<double>(), 9) : "") +
       ". Transmission error θ<sub>in</sub> − i·θ<sub>out</sub> of each stage, in rad of its input member, peak to peak over the "
       "analysed window.</p>\n";
  h += html_table({"stage", "kind", "members", "z", "input → output", "ratio", "f<sub>m</sub>, Hz", "TE peak-to-peak, rad"}, rows);
  // Gears.
  rows.clear();
  for (const physics::BodyDef& b : run.scenario.bodies) {
    const input::TrainStage* st = train.stage_of(b.name);
    if (!st) continue;
    std::string module = "–", alpha = "–", width = "–", shift = "–", source = "mesh";
    if (b.gear) {
      module = num(b.gear->module_m * 1e3, 6);
      alpha = num(b.gear->pressure_angle_rad * 180 / std::numbers::pi, 4);
      width = num(b.gear->face_width_m * 1e3, 5);
      shift = num(b.gear->profile_shift, 4);
      source = "generated";
    } else if (b.mesh && b.mesh->recognised && b.mesh->recognised->involute) {
      module = num(b.mesh->recognised->module_m * 1e3, 6);
      alpha = num(b.mesh->recognised->pressure_angle_rad * 180 / std::numbers::pi, 4);
      source = "mesh, recognised";
    }
    std::string measured = "–";
    if (run.summary.contains("bodies") && run.summary["bodies"].contains(b.name) &&
        run.summary["bodies"][b.name].contains("mean_absolute_speed_rad_s"))
      measured = num(run.summary["bodies"][b.name]["mean_absolute_speed_rad_s"].get<double>() * kRpmPerRadPerS, 6);
    rows.push_back({html_escape(b.name), html_escape(st->name), role(*st, b.name), input::is_internal(b) ? "internal" : "external",
                    std::to_string(input::teeth_of(b)), module, alpha, width, shift, source,
                    num(train.speed_rad_s.at(b.name) * kRpmPerRadPerS, 6), measured});
  }
  h += "<h3>Gears</h3>\n" + html_table({"gear", "stage", "role", "kind", "z", "m, mm", "α, °", "b, mm", "x", "from", "speed (rigid), rpm",
                                        "mean speed (run), rpm"},
                                       rows);
  return h;
}

double pair_mesh_hz(const json& a, const std::string& pair) {
  const json& train = a["gear_train"];
  if (train.contains("stages") && a["pairs"][pair].contains("stage"))
    for (const auto& st : train["stages"])
      if (st["name"] == a["pairs"][pair]["stage"]) return st["mesh_hz"].get<double>();
  return train["mesh_hz"].get<double>();
}

bool reproduces_paper(const RunDir& run) { return run.scenario.reference == "paper"; }

}  // namespace gearsim::app

#include "input/run_record_check.hpp"

#include <cmath>
#include <limits>
#include <vector>

#include "core/errors.hpp"
#include "input/input_limits.hpp"

namespace gearsim::input {
namespace {

using Record = nlohmann::ordered_json;  // not `json`: a unity batch may hold another file's alias of another type

// Bounds of recorded values that no input limit covers; sanity limits, far beyond a real run.
// Steps: the longest run at the shortest step, kDuration_s.max / kTimeStep_s.min, is 1e11.
constexpr Limit kSteps{0, 1e11, false, "", "a number of steps"};
// Wall time, s: 1e9 s is thirty years.
constexpr Limit kWallTime_s{0, 1e9, false, "s", "a wall time"};
// Powers, W, and their imbalance: a 1e6 kg body at 1e5 rad/s holds ~1e16 J; 1e15 W is past any drive.
constexpr Limit kPower_W{-1e15, 1e15, false, "W", "a power"};
// Mesh stiffness along the line of action, N/m: 1.4e10 N/m per m of face × 2 m is ~3e10.
constexpr Limit kStiffness_N_per_m{0, 1e15, true, "N/m", "a stiffness"};
constexpr Limit kDamping_N_s_per_m{0, 1e15, false, "N·s/m", "a damping"};
// A tooth pair's reduced mass along the line of action, kg: no more than a body's (kMass_kg).
constexpr Limit kReducedMass_kg{0, 1e6, true, "kg", "a reduced mass"};
// Mean flank forces, N: 1e12 N is past any gear's strength.
constexpr Limit kForce_N{-1e12, 1e12, false, "N", "a force"};
// The anti-aliasing filter: taps, stopband attenuation (doubles resolve ~320 dB), passband ripple.
constexpr Limit kTaps{1, 1e8, false, "", "a number of taps"};
constexpr Limit kAttenuation_dB{0, 1000, false, "dB", "an attenuation"};
constexpr Limit kRipple{0, 1, false, "", "a passband ripple"};
// Measured ratios (speed ratio, power imbalance over input): any finite value, as a stalled
// output's can be huge.
constexpr Limit kFiniteRatio{-std::numeric_limits<double>::max(), std::numeric_limits<double>::max(), false, "", "a finite ratio"};

// A value as a message quotes it: compact ASCII JSON, at most 80 characters.
std::string shown(const Record& v) {
  const std::string text = v.dump(-1, ' ', true);
  return text.size() > 80 ? text.substr(0, 80) + "..." : text;
}

// One object of the record with its key path, for messages: "FILE: key force_filter.taps: …".
class Field {
 public:
  Field(const Record& j, std::string path, const std::string& file) : j_(j), path_(std::move(path)), file_(file) {}
  [[noreturn]] void fail(const std::string& key, const std::string& what) const {
    throw InputError(file_ + ": key " + where(key) + ": " + what);
  }
  [[noreturn]] void fail_here(const std::string& what) const { throw InputError(file_ + ": key " + path_ + ": " + what); }
  bool has(const std::string& key) const { return j_.contains(key); }
  const Record& at(const std::string& key) const {
    if (!j_.contains(key)) fail(key, "missing (gearsim run writes it)");
    return j_.at(key);
  }
  double number(const std::string& key, const Limit& limit) const {
    const Record& v = at(key);
    if (!v.is_number()) fail(key, "expected a number, got " + shown(v));
    const double x = v.get<double>();
    if (!within(x, limit)) fail(key, limit_message(limit, x));
    return x;
  }
  void whole(const std::string& key, const Limit& limit) const {
    if (const double x = number(key, limit); x != std::floor(x)) fail(key, "expected a whole number, got " + shown(at(key)));
  }
  void text(const std::string& key) const {
    if (!at(key).is_string()) fail(key, "expected a string, got " + shown(at(key)));
  }
  Field object(const std::string& key) const {
    if (!at(key).is_object()) fail(key, "expected an object, got " + shown(at(key)));
    return Field(at(key), where(key), file_);
  }
  std::vector<Field> list(const std::string& key) const {
    if (!at(key).is_array()) fail(key, "expected a list, got " + shown(at(key)));
    std::vector<Field> out;
    for (std::size_t i = 0; i < at(key).size(); ++i) out.emplace_back(at(key)[i], where(key) + "[" + std::to_string(i) + "]", file_);
    return out;
  }
  const Record& value() const { return j_; }

 private:
  std::string where(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }
  const Record& j_;
  std::string path_;
  const std::string& file_;
};

void check_gear_pair(const Field& p) {
  if (!p.value().is_object()) p.fail_here("expected an object {\"a\": body, \"b\": body, ...}, got " + shown(p.value()));
  p.text("a");
  p.text("b");
  if (p.has("stiffness_N_per_m")) p.number("stiffness_N_per_m", kStiffness_N_per_m);
  if (p.has("damping_N_s_per_m")) p.number("damping_N_s_per_m", kDamping_N_s_per_m);
  if (p.has("reduced_mass_kg")) {
    p.number("reduced_mass_kg", kReducedMass_kg);
    p.number("stiffness_N_per_m", kStiffness_N_per_m);  // the report's ringing needs both
  }
  if (p.has("mean_normal_force_N")) {
    const Field f = p.object("mean_normal_force_N");
    f.number("ccw_flanks_of_a", kForce_N);
    f.number("cw_flanks_of_a", kForce_N);
  }
}

void check_force_filter(const Field& f) {
  for (const char* key : {"input_rate_hz", "output_rate_hz", "passband_edge_hz", "stopband_edge_hz"}) f.number(key, limits::kRate_Hz);
  f.whole("taps", kTaps);
  f.number("stopband_attenuation_dB", kAttenuation_dB);
  if (f.has("passband_ripple")) f.number("passband_ripple", kRipple);
  f.number("edge_held_s", limits::kRunTime_s);
}

}  // namespace

void validate_summary_record(const Record& summary, const std::string& file) {
  if (!summary.is_object()) throw InputError(file + ": expected a JSON object (the summary gearsim run writes)");
  const Field s(summary, "", file);
  s.number("sim_seconds", limits::kDuration_s);
  s.number("time_step_s", limits::kTimeStep_s);
  s.whole("steps", kSteps);
  s.text("status");
  if (s.has("wall_seconds")) s.number("wall_seconds", kWallTime_s);
  if (s.has("ratio")) s.number("ratio", kFiniteRatio);
  if (s.has("power_W")) {
    const Field p = s.object("power_W");
    for (const char* key : {"motor_input", "load_output", "contact_dissipation", "joint_dissipation"}) p.number(key, kPower_W);
    p.number("imbalance_fraction", kFiniteRatio);
  }
  if (s.has("warnings"))
    for (const Field& w : s.list("warnings"))
      if (!w.value().is_string()) w.fail_here("expected a string, got " + shown(w.value()));
  if (s.has("gear_pairs"))
    for (const Field& p : s.list("gear_pairs")) check_gear_pair(p);
  if (s.has("force_filter")) check_force_filter(s.object("force_filter"));
}

}  // namespace gearsim::input

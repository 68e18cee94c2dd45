// A run folder's summary.json as analyze, report and render read it (input/run_record_check.hpp):
// the record gearsim run writes passes; a value of the wrong type or out of range is refused
// naming the file and key, before anything reads it as a JSON type error.
#include <gtest/gtest.h>

#include <string>

#include "core/errors.hpp"
#include "input/run_record_check.hpp"

namespace gearsim::input {
namespace test_run_record_check {

using json = nlohmann::ordered_json;

// The keys gearsim run writes that the later commands read, with a run's values (the spur pair's).
json good_summary() {
  return json::parse(R"({
    "scenario": "spur", "status": "completed", "sim_seconds": 0.05, "steps": 2500, "time_step_s": 2e-5,
    "wall_seconds": 3.2, "ratio": -2.0, "warnings": [],
    "power_W": {"motor_input": 10.0, "load_output": 9.9, "contact_dissipation": 0.05, "joint_dissipation": 0.05,
                "kinetic_energy_rate": 0.0, "imbalance_fraction": 1e-4},
    "gear_pairs": [{"a": "pinion", "b": "wheel", "stiffness_N_per_m": 1.4e8, "damping_N_s_per_m": 120.0,
                    "reduced_mass_kg": 0.05, "mean_normal_force_N": {"ccw_flanks_of_a": 0.0, "cw_flanks_of_a": 250.0}}],
    "force_filter": {"input_rate_hz": 50000, "output_rate_hz": 2000, "passband_edge_hz": 800, "stopband_edge_hz": 1000,
                     "stopband_attenuation_dB": 100, "passband_ripple": 0.001, "taps": 301, "edge_held_s": 0.003}})");
}

// The message validate_summary_record gives for `summary` ("" when it passes).
std::string error_of(const json& summary) {
  try {
    validate_summary_record(summary, "run/summary.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// good_summary() with the value at JSON pointer `at` replaced by `value`.
json with(const std::string& at, const json& value) {
  json j = good_summary();
  j[json::json_pointer(at)] = value;
  return j;
}

#define EXPECT_REFUSED(summary, message)                                                          \
  do {                                                                                            \
    const std::string e_ = error_of(summary);                                                     \
    EXPECT_NE(e_.find(std::string("run/summary.json: key ") + message), std::string::npos) << e_; \
  } while (0)

TEST(RunRecordCheck, TheSummaryARunWritesPasses) { EXPECT_EQ(error_of(good_summary()), ""); }

TEST(RunRecordCheck, SimulatedSecondsMustBeADurationNumber) {
  // Unchecked, "abc" ends report with a JSON type error (exit 1 or 3) instead of naming the key.
  EXPECT_REFUSED(with("/sim_seconds", "abc"), "sim_seconds: expected a number, got \"abc\"");
  EXPECT_REFUSED(with("/sim_seconds", 0), "sim_seconds: expected a duration in (0, 10000] s, got 0");
  EXPECT_REFUSED(with("/sim_seconds", 1e300), "sim_seconds: expected a duration in (0, 10000] s, got 1e+300");
  json j = good_summary();
  j.erase("sim_seconds");
  EXPECT_REFUSED(j, "sim_seconds: missing");
}

TEST(RunRecordCheck, TimeStepStepsAndStatusHaveTheirTypesAndRanges) {
  EXPECT_REFUSED(with("/time_step_s", 1.0), "time_step_s: expected a time step in [1e-07, 0.01] s, got 1");
  EXPECT_REFUSED(with("/steps", -1), "steps: expected a number of steps in [0, 1e+11], got -1");
  EXPECT_REFUSED(with("/steps", 2.5), "steps: expected a whole number, got 2.5");
  EXPECT_REFUSED(with("/steps", "many"), "steps: expected a number, got \"many\"");
  EXPECT_REFUSED(with("/status", 5), "status: expected a string, got 5");
  EXPECT_REFUSED(with("/wall_seconds", -3), "wall_seconds: expected a wall time in [0, 1e+09] s, got -3");
}

TEST(RunRecordCheck, RatesInHertzAreBounded) {
  EXPECT_REFUSED(with("/force_filter/output_rate_hz", 1e300), "force_filter.output_rate_hz: expected a rate in (0, 1e+07] Hz, got 1e+300");
  EXPECT_REFUSED(with("/force_filter/stopband_edge_hz", 0), "force_filter.stopband_edge_hz: expected a rate in (0, 1e+07] Hz, got 0");
  EXPECT_REFUSED(with("/force_filter/taps", 30.5), "force_filter.taps: expected a whole number");
  EXPECT_REFUSED(with("/force_filter/edge_held_s", -1), "force_filter.edge_held_s: expected a time in [0, 10000] s, got -1");
}

TEST(RunRecordCheck, TheReportsOtherKeysHaveTheirTypes) {
  EXPECT_REFUSED(with("/ratio", "fast"), "ratio: expected a number");
  EXPECT_REFUSED(with("/power_W/motor_input", nullptr), "power_W.motor_input: expected a number, got null");
  EXPECT_REFUSED(with("/warnings", json::array({"ok", 3})), "warnings[1]: expected a string, got 3");
  EXPECT_REFUSED(with("/gear_pairs/0/stiffness_N_per_m", 1e300), "gear_pairs[0].stiffness_N_per_m: expected a stiffness in (0, 1e+15] N/m");
  EXPECT_REFUSED(with("/gear_pairs/0/reduced_mass_kg", -1), "gear_pairs[0].reduced_mass_kg: expected a reduced mass in (0, 1e+06] kg");
  EXPECT_REFUSED(with("/gear_pairs/0/b", 7), "gear_pairs[0].b: expected a string, got 7");
  EXPECT_REFUSED(with("/gear_pairs/0/mean_normal_force_N/cw_flanks_of_a", "x"),
                 "gear_pairs[0].mean_normal_force_N.cw_flanks_of_a: expected a number");
  EXPECT_REFUSED(with("/gear_pairs/0", 3), "gear_pairs[0]: expected an object");
  EXPECT_REFUSED(with("/gear_pairs", "none"), "gear_pairs: expected a list, got \"none\"");
}

TEST(RunRecordCheck, ASummaryThatIsNoObjectIsRefused) {
  const std::string e = error_of(json::array());
  EXPECT_NE(e.find("run/summary.json: expected a JSON object"), std::string::npos) << e;
}

}  // namespace test_run_record_check
}  // namespace gearsim::input

// The output-rate logs (sim/csv_logs.hpp) on the spur pair: contacts.csv's force column is every
// step's force through the anti-aliasing decimator — the same numbers as decimating the per-step
// force of the run as one record — and the point column is the force at the sample's step; so is
// state.csv's transmission error; a run stopped between samples ends state.csv and contacts.csv at
// the same time, on the same rows.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "analysis/decimator.hpp"
#include "input/csv_table.hpp"
#include "input/scenario_file.hpp"
#include "sim/csv_logs.hpp"
#include "sim/simulate.hpp"
#include "tests/support/asset_scenario.hpp"

namespace gearsim::sim {
namespace test_csv_logs {

namespace fs = std::filesystem;

physics::Scenario spur_pair(const std::string& duration_s) {
  return input::load_scenario(fs::path(GEARSIM_SOURCE_DIR) / "assets/scenarios/spur_pair.yaml",
                              {"duration_s=" + duration_s, "output.per_step_log=false"});
}

// Every step's summed force of pair 0 and transmission error (θ_pinion − ratio·θ_wheel, less its
// value at the start poses: the assembly phase), from t = 0 (the world before the first step).
struct ForceRecorder : Observer {
  explicit ForceRecorder(double r) : ratio(r) {}
  void on_start(const physics::World& w) override { add(w); }
  void on_step(const physics::World& w) override { add(w); }
  void add(const physics::World& w) {
    double f = 0;
    for (const physics::ContactSample& c : w.contacts())
      if (c.pair == 0) f += c.normal_force_N;
    force_N.push_back(f);
    double pinion = 0, wheel = 0;
    for (const physics::BodyState& b : w.bodies()) (b.name == "pinion" ? pinion : b.name == "wheel" ? wheel : f) = b.angle_rad;
    if (force_N.size() == 1) assembly_phase_rad = pinion - ratio * wheel;
    te_rad.push_back(pinion - ratio * wheel - assembly_phase_rad);
  }
  double ratio, assembly_phase_rad = 0;
  std::vector<double> force_N, te_rad;
};

TEST(CsvLogs, ForceColumnIsTheDecimatedPerStepForceAndThePointColumnTheSample) {
  const fs::path dir = test::fresh_test_dir();
  const physics::Scenario s = spur_pair("0.12");
  CsvLogs csv(dir, s);
  ASSERT_TRUE(s.transmission.has_value());
  ForceRecorder rec(s.transmission->ratio);
  const RunSummary r = simulate(s, {&csv, &rec});
  ASSERT_EQ(r.status, RunStatus::Completed);
  ASSERT_TRUE(csv.force_filter().has_value());
  const DecimationFilter& filter = *csv.force_filter();
  EXPECT_EQ(filter.ratio, 25);  // 2e-5 s steps, 2 kHz
  const UniformSignal expected = decimate(rec.force_N, filter, 0.0);
  const input::CsvTable t = input::read_csv(dir / "contacts.csv");
  const std::vector<double>& time = t.column("time_s");
  const std::vector<double>& filtered = t.column("pinion__wheel_force_N");
  const std::vector<double>& point = t.column("pinion__wheel_force_point_N");
  ASSERT_EQ(time.size(), 240u);  // 0.12 s at 2 kHz, no row at t = 0
  ASSERT_EQ(expected.values.size(), time.size() + 1);  // the decimated record includes t = 0
  for (std::size_t k = 0; k < time.size(); ++k) {
    EXPECT_NEAR(time[k], static_cast<double>(k + 1) / 2000.0, 1e-12);
    EXPECT_EQ(filtered[k], expected.values[k + 1]) << "row " << k;  // the same kernel: bit for bit
    EXPECT_EQ(point[k], rec.force_N[25 * (k + 1)]) << "row " << k;
  }
  // state.csv's transmission error the same way: te_rad through the filter, te_point_rad the sample,
  // both from 0 at the start poses. The wheel starts turned so that a pinion tooth sits in its gap
  // (the assembly phase, here 3π/2 = 4.712 rad of θ_pinion − ratio·θ_wheel): a TE is the departure from it.
  EXPECT_GT(std::abs(rec.assembly_phase_rad), 0.1);
  EXPECT_EQ(rec.te_rad.front(), 0.0);
  std::printf("assembly phase %.6f rad\n", rec.assembly_phase_rad);
  const UniformSignal te = decimate(rec.te_rad, filter, 0.0);
  const input::CsvTable st = input::read_csv(dir / "state.csv");
  ASSERT_EQ(st.column("time_s"), time);
  for (std::size_t k = 0; k < time.size(); ++k) {
    EXPECT_EQ(st.column("te_rad")[k], te.values[k + 1]) << "row " << k;
    EXPECT_EQ(st.column("te_point_rad")[k], rec.te_rad[25 * (k + 1)]) << "row " << k;
  }
}

TEST(CsvLogs, AStopBetweenSamplesEndsBothFilesOnTheSameRow) {
  const fs::path dir = test::fresh_test_dir();
  const physics::Scenario s = spur_pair("0.1");
  CsvLogs csv(dir, s);
  SimOptions o;
  long polls = 0;
  o.stop_requested = [&] { return ++polls == 2013 ? 2 : 0; };  // step 2013: between samples
  const RunSummary r = simulate(s, {&csv}, o);
  ASSERT_EQ(r.status, RunStatus::Interrupted);
  const input::CsvTable state = input::read_csv(dir / "state.csv"), contacts = input::read_csv(dir / "contacts.csv");
  const std::vector<double>& ts = state.column("time_s");
  const std::vector<double>& tc = contacts.column("time_s");
  ASSERT_EQ(ts.size(), 2013u / 25 + 1);  // 80 samples, then the stop
  ASSERT_EQ(tc.size(), ts.size());
  for (std::size_t k = 0; k < ts.size(); ++k) EXPECT_EQ(ts[k], tc[k]) << "row " << k;
  EXPECT_NEAR(ts.back(), 2013 * 2e-5, 1e-12);
  // The stop row carries point samples in every column.
  EXPECT_EQ(contacts.column("pinion__wheel_force_N").back(), contacts.column("pinion__wheel_force_point_N").back());
  EXPECT_EQ(state.column("te_rad").back(), state.column("te_point_rad").back());
}

}  // namespace test_csv_logs
}  // namespace gearsim::sim

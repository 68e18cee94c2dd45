// A real sweep of the spur pair through the gearsim binary: a case that diverges is recorded
// (status, exit code 4, its error) while the others complete and the sweep ends with exit 5; the
// dynamic factor is the window's peak over mean of contacts.csv's anti-aliased force; running it
// again runs nothing twice; an edited sweep file is refused unless --fresh; a bad key is refused
// before any case runs, naming the sweep file, the case and the key.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "input/csv_table.hpp"
#include "tests/sweep/sweep_cli.hpp"
#include "tests/support/asset_scenario.hpp"
#include "tests/support/cli_run.hpp"

namespace gearsim::sweep {
namespace test_sweep_run {

namespace fs = std::filesystem;

// Three cases; the 200 N·m load (10× the motor's torque limit through the ratio) drives the teeth
// through each other: case 2 diverges.
const std::string kCases =
    "cases:\n"
    "  - loads[0].constant_torque_N_m: 5\n"
    "  - loads[0].constant_torque_N_m: 10\n"
    "  - loads[0].constant_torque_N_m: 200\n"
    "collect:\n"
    "  summary: [bodies.wheel.mean_absolute_speed_rad_s]\n"
    "  metrics: [dynamic_factor_band_limited, dynamic_factor_per_step, mesh_frequency_hz, rms_dynamic_te_rad]\n";

class SweepRun : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = test::fresh_test_dir();
    file_ = test::spur_sweep_file(dir_, kCases, "sweep.yaml", true);  // the per-step log: dynamic_factor_per_step
    out_ = dir_ / "out";
  }
  test::CliRun sweep(const std::string& extra = "") {
    return test::gearsim("sweep " + file_.string() + " --out " + out_.string() + " --jobs 2 " + extra);
  }
  fs::path dir_, file_, out_;
};

TEST_F(SweepRun, DivergedCaseIsRecordedAndTheOthersComplete) {
  const test::CliRun r = sweep();
  EXPECT_EQ(r.exit_code, 5) << r.output;  // some cases did not complete
  const auto rows = test::csv_rows(out_ / "sweep.csv");
  ASSERT_EQ(rows.size(), 4u) << r.output;
  EXPECT_EQ(rows[0],
            (std::vector<std::string>{"index", "loads[0].constant_torque_N_m", "status", "summary.bodies.wheel.mean_absolute_speed_rad_s",
                                      "dynamic_factor_band_limited", "dynamic_factor_band_limited.pinion__wheel", "dynamic_factor_per_step",
                                      "dynamic_factor_per_step.pinion__wheel", "mesh_frequency_hz", "rms_dynamic_te_rad"}));
  EXPECT_EQ(rows[1][2], "completed");
  EXPECT_EQ(rows[2][2], "completed");
  EXPECT_EQ(rows[3][2], "diverged");
  EXPECT_EQ(rows[3][3], "");  // no metrics of a diverged run
  const nlohmann::json c2 = test::case_json(out_, 2);
  EXPECT_EQ(c2["exit_code"], 4);
  EXPECT_NE(c2["error"].get<std::string>().find("diverged"), std::string::npos) << c2.dump(2);
  // The wheel turns at 50·20/31 rad/s against the pinion (external pair: the other way).
  EXPECT_NEAR(std::stod(rows[1][3]), -50.0 * 20 / 31, 0.5);
  // f_m = z·ω/2π = 20·50/2π Hz, from the scenario.
  EXPECT_NEAR(std::stod(rows[1][8]), 20 * 50 / (2 * M_PI), 1e-9);
}

TEST_F(SweepRun, DynamicFactorIsPeakOverMeanOfTheSteadyWindow) {
  sweep();
  const fs::path case0 = out_ / "cases/00000";
  const nlohmann::json c0 = test::case_json(out_, 0);
  ASSERT_EQ(c0["status"], "completed") << c0.dump(2);
  // The steady window as `gearsim analyze` takes it: after the 0.05 s ramp (and the filter's
  // edge_held_s, shorter), up to the end less edge_held_s.
  const nlohmann::json summary = nlohmann::json::parse(test::file_text(case0 / "summary.json"));
  const double edge = summary["force_filter"]["edge_held_s"].get<double>();
  const input::CsvTable contacts = input::read_csv(case0 / "contacts.csv");
  const std::vector<double>& t = contacts.column("time_s");
  const std::vector<double>& f = contacts.column("pinion__wheel_force_N");
  const double from = std::max(0.05, edge), to = t.back() - edge;
  double peak = 0, sum = 0;
  int n = 0;
  for (std::size_t i = 0; i < t.size(); ++i)
    if (t[i] >= from && t[i] <= to) peak = std::max(peak, f[i]), sum += f[i], ++n;
  ASSERT_GT(n, 64);
  // Same samples, same arithmetic: equal to rounding of the mean's sum (1e-12 relative).
  EXPECT_NEAR(c0["metrics"]["dynamic_factor_band_limited"].get<double>(), peak / (sum / n), 1e-12 * peak / (sum / n));
  EXPECT_GT(c0["metrics"]["dynamic_factor_band_limited"].get<double>(), 1.0);  // the peak lies above the mean
  // The per-step figure sees what the output band does not: every step's force, its peak higher.
  EXPECT_GT(c0["metrics"]["dynamic_factor_per_step"].get<double>(), c0["metrics"]["dynamic_factor_band_limited"].get<double>());
}

TEST_F(SweepRun, ResumeRunsNothingTwice) {
  sweep();
  const auto summary_time = fs::last_write_time(out_ / "cases/00001/summary.json");
  const std::string table = test::file_text(out_ / "sweep.csv");
  const test::CliRun again = sweep();
  EXPECT_EQ(again.exit_code, 5) << again.output;  // the diverged case is still recorded as such
  EXPECT_NE(again.output.find("0 to run"), std::string::npos) << again.output;
  EXPECT_EQ(fs::last_write_time(out_ / "cases/00001/summary.json"), summary_time);
  EXPECT_EQ(test::file_text(out_ / "sweep.csv"), table);
  // An interrupted case (no final status) is run again, and only it.
  nlohmann::json c1 = test::case_json(out_, 1);
  c1["status"] = "interrupted";
  std::ofstream(out_ / "cases/00001/case.json") << c1.dump(2);
  const test::CliRun third = sweep();
  EXPECT_NE(third.output.find("1 to run"), std::string::npos) << third.output;
  EXPECT_NE(fs::last_write_time(out_ / "cases/00001/summary.json"), summary_time);
  EXPECT_EQ(test::case_json(out_, 1)["status"], "completed");
}

TEST_F(SweepRun, EditedSweepFileRefusedUnlessFresh) {
  sweep();
  test::spur_sweep_file(dir_, kCases + "# an edit\n");
  const test::CliRun refused = sweep();
  EXPECT_EQ(refused.exit_code, 2) << refused.output;
  EXPECT_NE(refused.output.find("its content changed"), std::string::npos) << refused.output;
  const test::CliRun fresh = sweep("--fresh");
  EXPECT_EQ(fresh.exit_code, 5) << fresh.output;
  EXPECT_NE(fresh.output.find("3 to run"), std::string::npos) << fresh.output;
}

TEST_F(SweepRun, BadKeyRefusedBeforeAnyCaseRuns) {
  file_ = test::spur_sweep_file(dir_,
                                "cases:\n  - loads[0].constant_torque_N_m: 5\n  - loads[0].constant_torque_N_m: 6\n"
                                "  - loads[0].torque_typo_N_m: 7\n");
  const test::CliRun r = sweep();
  EXPECT_EQ(r.exit_code, 2) << r.output;
  // The sweep file, line and key of the case; the case's number; the scenario's own complaint.
  EXPECT_NE(r.output.find("sweep.yaml:7:"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find(": cases[2].loads[0].torque_typo_N_m: case 2 "), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("torque_typo_N_m: unknown key"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(out_ / "cases/00000"));  // nothing ran
}

}  // namespace test_sweep_run
}  // namespace gearsim::sweep

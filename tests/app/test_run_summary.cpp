// What `gearsim run` reports in summary.json: the measured ratio and power balance of a short
// paper run, numerical trouble counted as warnings, a run that leaves its physical bounds
// stopped as "diverged" with exit code 4 and its logs complete up to that step, and a completed
// run whose analysis is refused ending with exit code 9.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "tests/support/cli_run.hpp"

namespace test_run_summary {

namespace fs = std::filesystem;

nlohmann::json run_paper(const std::string& tag, const std::string& extra) {
  const fs::path dir = fs::temp_directory_path() / ("gearsim_summary_" + tag);
  fs::remove_all(dir);
  const std::string cmd = std::string(GEARSIM_BINARY_DIR) + "/bin/gearsim run " + GEARSIM_SOURCE_DIR +
                          "/assets/scenarios/paper_dynamics_healthy.yaml --out " + dir.string() +
                          " --duration 0.02 --set motors[0].ramp_time_s=0.004 " + extra + " --no-analyze > /dev/null 2>&1";
  EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
  std::ifstream f(dir / "summary.json");
  return nlohmann::json::parse(f);
}

TEST(RunSummary, ReportsTheWillisRatioAndABalancedPowerFlow) {
  const nlohmann::json s = run_paper("sound", "");
  // 16 ms at speed: ~5 mesh periods, the ratio within the TE ripple's 0.5 %.
  EXPECT_NEAR(s["ratio"].get<double>(), 5.0, 0.025);
  EXPECT_NEAR(s["power_W"]["imbalance_fraction"].get<double>(), 0.0, 0.02);
  // 20 N·m at 104.7/5 rad/s.
  EXPECT_NEAR(s["power_W"]["load_output"].get<double>(), 20 * 104.7 / 5, 0.01 * 20 * 104.7 / 5);
  EXPECT_TRUE(s["warnings"].empty()) << s["warnings"].dump();
}

TEST(RunSummary, ASoftContactIsReportedAsDeepPenetration) {
  // Contact 100x softer than ISO 6336's 14 N/(mm·µm): 118 N per mesh presses ~80 µm.
  const nlohmann::json s = run_paper("soft", "--set contact.stiffness_N_per_m_per_m=1.4e8");
  EXPECT_GT(s["max_penetration_um"].get<double>(), 10.0);
  ASSERT_FALSE(s["warnings"].empty());
  EXPECT_NE(s["warnings"][0].get<std::string>().find("penetration"), std::string::npos) << s["warnings"].dump();
}

// The last time_s of a CSV log.
double last_time(const fs::path& csv) {
  std::ifstream f(csv);
  std::string line, last;
  while (std::getline(f, line))
    if (!line.empty()) last = line;
  return std::stod(last.substr(0, last.find(',')));
}

TEST(RunSummary, ADivergingRunStopsWithItsOwnExitCodeAndCompleteLogs) {
  // dt 0.5 ms against the 1.4e8 N/m tooth contact: the teeth pass through each other at once.
  const fs::path dir = fs::temp_directory_path() / "gearsim_summary_diverged";
  fs::remove_all(dir);
  const gearsim::test::CliRun r = gearsim::test::gearsim(
      std::string("run ") + GEARSIM_SOURCE_DIR + "/assets/scenarios/paper_dynamics_healthy.yaml --out " + dir.string() +
      " --duration 0.05 --set solver.time_step_s=5e-4 --set output.sample_rate_hz=500 --set sensors=null");
  EXPECT_EQ(r.exit_code, 4) << r.output;
  EXPECT_NE(r.output.find("diverged at t ="), std::string::npos) << r.output;
  std::ifstream f(dir / "summary.json");
  const nlohmann::json s = nlohmann::json::parse(f);
  EXPECT_EQ(s["status"], "diverged");
  ASSERT_TRUE(s.contains("divergence"));
  EXPECT_FALSE(s["divergence"]["message"].get<std::string>().empty());
  const double t = s["sim_seconds"].get<double>();
  EXPECT_LT(t, 0.05);
  EXPECT_EQ(s["divergence"]["time_s"].get<double>(), t);
  // Both CSV logs end at the step the run stopped at.
  EXPECT_DOUBLE_EQ(last_time(dir / "state.csv"), t);
  EXPECT_DOUBLE_EQ(last_time(dir / "contacts.csv"), t);
  EXPECT_FALSE(fs::exists(dir / "analysis.json"));  // a diverged run is not analysed
}

TEST(RunSummary, ACompletedRunWhoseAnalysisIsRefusedEndsWithItsOwnExitCode) {
  // 10 ms of the spur pair: its load ramp alone lasts longer, the analysis has no steady window.
  const fs::path dir = fs::temp_directory_path() / "gearsim_summary_not_analysed";
  fs::remove_all(dir);
  const gearsim::test::CliRun r = gearsim::test::gearsim(std::string("run ") + GEARSIM_SOURCE_DIR +
                                                         "/assets/scenarios/spur_pair.yaml --out " + dir.string() + " --duration 0.01");
  EXPECT_EQ(r.exit_code, 9) << r.output;
  EXPECT_NE(r.output.find("not analysed: "), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("the run completed (logs in"), std::string::npos) << r.output;
  std::ifstream f(dir / "summary.json");
  EXPECT_EQ(nlohmann::json::parse(f)["status"], "completed");
  EXPECT_FALSE(fs::exists(dir / "analysis.json"));
  // --no-analyze asks for no analysis: nothing refused, exit 0.
  const gearsim::test::CliRun plain =
      gearsim::test::gearsim(std::string("run ") + GEARSIM_SOURCE_DIR + "/assets/scenarios/spur_pair.yaml --out " + dir.string() +
                             " --duration 0.01 --no-analyze");
  EXPECT_EQ(plain.exit_code, 0) << plain.output;
}

}  // namespace test_run_summary

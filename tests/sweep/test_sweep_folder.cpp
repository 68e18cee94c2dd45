// A sweep's folder holds only what the sweep writes: a link planted under a case's log or in place
// of a case folder is never followed (the log is made afresh in the case folder; a case whose
// folder is a link or a file fails, named, and nothing there is touched), and a second sweep into
// the same folder is refused at once (exit 7) naming the one that writes there.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <thread>

#include "sweep/case_list.hpp"
#include "tests/support/asset_scenario.hpp"
#include "tests/support/cli_run.hpp"
#include "tests/sweep/sweep_cli.hpp"

namespace gearsim::sweep {
namespace test_sweep_folder {

namespace fs = std::filesystem;

const std::string kTwoCases = "cases:\n  - loads[0].constant_torque_N_m: 5\n  - loads[0].constant_torque_N_m: 6\n";

class SweepFolder : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = test::fresh_test_dir();
    file_ = test::spur_sweep_file(dir_, kTwoCases);
    out_ = dir_ / "out";
    fs::create_directories(out_ / "cases");
    std::ofstream(precious_ = dir_ / "precious.txt") << "the user's\n";
  }
  test::CliRun sweep() { return test::gearsim("sweep " + file_.string() + " --out " + out_.string()); }
  fs::path case_dir(std::size_t i) const { return out_ / "cases" / case_folder_name(i); }
  fs::path dir_, file_, out_, precious_;
};

TEST_F(SweepFolder, ALinkPlantedUnderACaseLogIsReplacedNotFollowed) {
  fs::create_directories(case_dir(0));
  for (const char* log : {"run.out.log", "run.err.log"}) fs::create_symlink(precious_, case_dir(0) / log);
  const test::CliRun r = sweep();
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(test::file_text(precious_), "the user's\n");
  for (const char* log : {"run.out.log", "run.err.log"}) EXPECT_TRUE(fs::is_regular_file(fs::symlink_status(case_dir(0) / log))) << log;
}

TEST_F(SweepFolder, ACaseFolderThatIsALinkFailsThatCaseAndWritesNothingThrough) {
  const fs::path victim = dir_ / "victim";
  fs::create_directories(victim);
  std::ofstream(victim / "state.csv") << "the user's\n";
  fs::create_symlink(victim, case_dir(0));
  const test::CliRun r = sweep();
  EXPECT_EQ(r.exit_code, 5) << r.output;  // a case did not complete
  EXPECT_EQ(test::file_text(victim / "state.csv"), "the user's\n");
  EXPECT_EQ(std::distance(fs::directory_iterator(victim), fs::directory_iterator()), 1);
  const auto rows = test::csv_rows(out_ / "sweep.csv");
  ASSERT_EQ(rows.size(), 3u) << r.output;
  EXPECT_EQ(rows[1][2], "failed");
  EXPECT_EQ(rows[2][2], "completed");
}

TEST_F(SweepFolder, AFileWhereACaseFolderBelongsFailsThatCaseNotTheSweep) {
  std::ofstream(case_dir(1)) << "not a folder\n";
  const test::CliRun r = sweep();
  EXPECT_EQ(r.exit_code, 5) << r.output;
  const auto rows = test::csv_rows(out_ / "sweep.csv");
  ASSERT_EQ(rows.size(), 3u) << r.output;
  EXPECT_EQ(rows[1][2], "completed");
  EXPECT_EQ(rows[2][2], "failed");
  EXPECT_EQ(test::file_text(case_dir(1)), "not a folder\n");
  // A resume meets the same file: the same recorded failure, no crash.
  EXPECT_EQ(sweep().exit_code, 5);
}

TEST_F(SweepFolder, ASecondSweepIntoTheSameFolderIsRefused) {
  const std::string first =
      std::string(GEARSIM_BINARY_DIR) + "/bin/gearsim sweep " + file_.string() + " --out " + out_.string() + " > /dev/null 2>&1";
  std::thread t([&] { std::system(first.c_str()); });
  for (int i = 0; i < 200 && test::file_text(out_ / ".gearsim.lock").find("gearsim sweep") == std::string::npos; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  const test::CliRun second = sweep();
  t.join();
  EXPECT_EQ(second.exit_code, 7) << second.output;
  EXPECT_NE(second.output.find("in use by gearsim sweep"), std::string::npos) << second.output;
}

}  // namespace test_sweep_folder
}  // namespace gearsim::sweep

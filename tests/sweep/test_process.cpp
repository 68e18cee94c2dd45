// A case's child process gets its arguments verbatim, never through a shell; a stop request
// reaches the running child as its signal; the error kept of a failing child is its stderr's tail.
#include <gtest/gtest.h>
#include <signal.h>

#include <chrono>
#include <filesystem>
#include <fstream>

#include "sweep/process.hpp"
#include "tests/support/asset_scenario.hpp"
#include "tests/sweep/sweep_cli.hpp"

namespace gearsim::sweep {
namespace test_process {

namespace fs = std::filesystem;

TEST(Process, ArgumentsReachTheChildVerbatim) {
  const fs::path dir = test::fresh_test_dir();
  const std::string hostile = "x; touch " + (dir / "pwned").string() + " $(touch " + (dir / "pwned2").string() + ") `id` | cat";
  const ProcessOutcome o = run_process({"/bin/echo", hostile}, dir / "out", dir / "err", {});
  EXPECT_EQ(o.exit_code, 0);
  EXPECT_EQ(test::file_text(dir / "out"), hostile + "\n");
  EXPECT_FALSE(fs::exists(dir / "pwned"));
  EXPECT_FALSE(fs::exists(dir / "pwned2"));
}

TEST(Process, StopRequestIsPassedToTheChild) {
  const fs::path dir = test::fresh_test_dir();
  const auto start = std::chrono::steady_clock::now();
  const ProcessOutcome o = run_process({"/bin/sleep", "30"}, dir / "out", dir / "err", [] { return SIGTERM; });
  const double wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(o.signal, SIGTERM);
  EXPECT_EQ(o.exit_code, 128 + SIGTERM);
  EXPECT_LT(wall_s, 5.0);  // stopped within a poll or two, not after 30 s
}

TEST(Process, MissingProgramIsAFailureNotAThrow) {
  const fs::path dir = test::fresh_test_dir();
  const ProcessOutcome o = run_process({(dir / "no_such_program").string()}, dir / "out", dir / "err", {});
  EXPECT_EQ(o.exit_code, 127);
  EXPECT_NE(o.failure.find("cannot start"), std::string::npos) << o.failure;
}

TEST(Process, TailKeepsTheLastWholeLines) {
  const fs::path dir = test::fresh_test_dir();
  std::ofstream(dir / "log") << "first line that is long\nsecond\nthird\n";
  EXPECT_EQ(file_tail(dir / "log", 14), "second\nthird");
  EXPECT_EQ(file_tail(dir / "absent", 100), "");
}

}  // namespace test_process
}  // namespace gearsim::sweep

// Nothing lost: a command whose writes fail (a full disk) ends with exit code 6 naming the file and
// the reason, never exit 0 with a truncated file, and never damages an earlier record; a second
// command writing into the same folder is refused at once (exit 7) naming the holder. Failures are
// injected by a preloaded writer (tests/support/fail_writes.cpp) that fails the Nth write to a
// regular file and every later one, and by a small tmpfs where one can be mounted.
#include <gtest/gtest.h>
#include <sys/mount.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <thread>

#include "core/folder_lock.hpp"
#include "tests/support/asset_scenario.hpp"
#include "tests/support/cli_run.hpp"

namespace gearsim::app {
namespace test_output_faults {

namespace fs = std::filesystem;

const std::string kSpur = std::string(GEARSIM_SOURCE_DIR) + "/assets/scenarios/spur_pair.yaml";

std::string text_of(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// `gearsim args` with the Nth write to a file and every later one failing (ENOSPC).
test::CliRun with_writes_failing_from(long n, const std::string& args) {
  return test::gearsim_under("env LD_PRELOAD=" GEARSIM_FAIL_WRITES_LIB " GEARSIM_FAIL_WRITES_FROM=" + std::to_string(n) + " ", args);
}

// Empty when every CSV, JSON and HDF5 file in `dir` (not the hidden lock and manifest, not a
// leftover temporary, which must not exist) is whole: CSV rows as wide as the header and ending
// in a newline, JSON that parses, HDF5 with its signature. Else what is wrong.
std::string broken_outputs(const fs::path& dir) {
  std::string broken;
  for (const fs::directory_entry& e : fs::recursive_directory_iterator(dir)) {
    if (!e.is_regular_file()) continue;
    const std::string name = e.path().filename().string();
    if (name.find(".partial-") != std::string::npos) broken += name + ": a temporary left; ";
    if (name[0] == '.') continue;
    const std::string text = text_of(e.path());
    if (name.ends_with(".csv")) {
      std::istringstream in(text);
      std::string header, line;
      std::getline(in, header);
      const auto width = std::count(header.begin(), header.end(), ',');
      while (std::getline(in, line))
        if (std::count(line.begin(), line.end(), ',') != width) broken += name + ": a short row; ";
      if (text.empty() || text.back() != '\n') broken += name + ": cut mid-line; ";
    } else if (name.ends_with(".json")) {
      if (!nlohmann::json::accept(text)) broken += name + ": not whole JSON; ";
    } else if (name.ends_with(".h5")) {
      if (text.size() < 8 || text.compare(0, 8, "\x89HDF\r\n\x1a\n") != 0) broken += name + ": no HDF5 signature; ";
    }
  }
  return broken;
}

class OutputFaults : public ::testing::Test {
 protected:
  void SetUp() override {
    if (GEARSIM_SANITIZED) GTEST_SKIP() << "the failing writer cannot be preloaded ahead of the sanitizers' runtime";
  }
};

TEST_F(OutputFaults, ARunWhoseWritesFailNeverEndsWithExitZeroOrATruncatedFile) {
  // The run writes a few dozen times (64 KiB buffers): failing from the 1st, 10th and 20th write
  // fails it at its start, in its logs and at its end; from the 10 000th, nothing fails.
  for (const long n : {1L, 10L, 20L, 10000L}) {
    const fs::path dir = test::fresh_test_dir() / ("from_" + std::to_string(n));
    const test::CliRun r = with_writes_failing_from(n, "run " + kSpur + " --out " + dir.string() + " --duration 0.3");
    if (n < 10000) {
      EXPECT_EQ(r.exit_code, 6) << "writes failing from the " << n << "th\n" << r.output;
      EXPECT_NE(r.output.find("No space left on device"), std::string::npos) << r.output;
    } else {
      EXPECT_EQ(r.exit_code, 0) << r.output;
      EXPECT_TRUE(fs::exists(dir / "analysis.json"));
    }
    EXPECT_EQ(broken_outputs(dir), "") << "writes failing from the " << n << "th";
    // A summary that was written says whether the run's outputs all were.
    if (fs::exists(dir / "summary.json") && r.exit_code != 0 && !fs::exists(dir / "analysis.json")) {
      EXPECT_EQ(nlohmann::json::parse(text_of(dir / "summary.json"))["status"], "output_failed") << n;
    }
  }
}

TEST_F(OutputFaults, AnAnalysisWhoseWritesFailLeavesTheRunRecordAsItWas) {
  const fs::path dir = test::fresh_test_dir() / "run";
  ASSERT_EQ(test::gearsim("run " + kSpur + " --out " + dir.string() + " --duration 0.3 --no-analyze").exit_code, 0);
  const std::string summary = text_of(dir / "summary.json");
  // The analysis writes its manifest entry, four files and summary.json: failing from each of them.
  for (const long n : {1L, 2L, 3L, 4L, 5L, 6L}) {
    const test::CliRun r = with_writes_failing_from(n, "analyze " + dir.string());
    EXPECT_EQ(r.exit_code, 6) << n << "\n" << r.output;
    EXPECT_EQ(r.output.find("written:"), std::string::npos) << r.output;
    EXPECT_TRUE(text_of(dir / "summary.json") == summary) << "the run record changed (writes failing from the " << n << "th)";
    EXPECT_EQ(broken_outputs(dir), "") << n;
  }
  EXPECT_EQ(test::gearsim("analyze " + dir.string()).exit_code, 0);
  EXPECT_FALSE(text_of(dir / "summary.json") == summary);  // now with the analysis keys
}

TEST_F(OutputFaults, ASweepWhoseWritesFailLeavesWholeRecordsOnly) {
  const fs::path dir = test::fresh_test_dir();
  std::ofstream(dir / "sweep.yaml") << "name: faults\nscenario: " << kSpur
                                    << "\nset: [\"duration_s=0.15\", \"output.per_step_log=false\"]\n"
                                       "cases:\n  - loads[0].constant_torque_N_m: 5\n  - loads[0].constant_torque_N_m: 6\n";
  // The sweep and each of its cases' runs (the failing writer is inherited) fail from their Nth
  // write: from the 1st and 5th, the sweep's own records fail; from the 10 000th, nothing does.
  for (const long n : {1L, 5L, 10000L}) {
    const fs::path out = dir / ("out_" + std::to_string(n));
    const test::CliRun r = with_writes_failing_from(n, "sweep " + (dir / "sweep.yaml").string() + " --out " + out.string());
    if (n < 10000) {
      EXPECT_EQ(r.exit_code, 6) << n << "\n" << r.output;
    } else {
      EXPECT_EQ(r.exit_code, 0) << r.output;
    }
    if (fs::exists(out)) {
      EXPECT_EQ(broken_outputs(out), "") << n;
    }
  }
}

TEST(OutputFolderLock, ASecondRunIntoTheSameFolderIsRefusedAndTheFirstIsWhole) {
  const fs::path dir = test::fresh_test_dir() / "run";
  const std::string first = std::string(GEARSIM_BINARY_DIR) + "/bin/gearsim run " + kSpur + " --out " + dir.string() +
                            " --duration 3 --no-analyze > /dev/null 2>&1";
  std::thread t([&] { ASSERT_EQ(std::system(first.c_str()), 0); });
  // The first holds the folder once its lock file names it.
  for (int i = 0; i < 200 && text_of(dir / ".gearsim.lock").find("gearsim run") == std::string::npos; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  const test::CliRun second = test::gearsim("run " + kSpur + " --out " + dir.string() + " --duration 0.2");
  t.join();
  EXPECT_EQ(second.exit_code, 7) << second.output;
  EXPECT_NE(second.output.find(dir.string() + ": in use by gearsim run (pid "), std::string::npos) << second.output;
  const nlohmann::json s = nlohmann::json::parse(text_of(dir / "summary.json"));
  EXPECT_EQ(s["status"], "completed");
  EXPECT_NEAR(s["sim_seconds"].get<double>(), 3.0, 1e-9);  // the first run's record, not the second's
  EXPECT_EQ(broken_outputs(dir), "");
}

TEST(OutputFolderLock, AnalyzeIntoAFolderARunIsWritingIsRefused) {
  const fs::path dir = test::fresh_test_dir() / "run";
  ASSERT_EQ(test::gearsim("run " + kSpur + " --out " + dir.string() + " --duration 0.2 --no-analyze").exit_code, 0);
  const std::string rerun = std::string(GEARSIM_BINARY_DIR) + "/bin/gearsim run " + kSpur + " --out " + dir.string() +
                            " --duration 3 --no-analyze > /dev/null 2>&1";
  const std::string before = text_of(dir / ".gearsim.lock");
  std::thread t([&] { std::system(rerun.c_str()); });
  for (int i = 0; i < 200 && text_of(dir / ".gearsim.lock") == before; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(20));
  const test::CliRun r = test::gearsim("analyze " + dir.string());
  t.join();
  EXPECT_EQ(r.exit_code, 7) << r.output;
}

TEST(OutputFolderLock, AFolderGivenAsALinkIsTheFolderItNamesAndTheLinkStays) {
  // A user's `latest -> runs/today`: run, analyze and report use runs/today; the link is theirs.
  const fs::path dir = test::fresh_test_dir(), target = dir / "runs" / "today", link = dir / "latest";
  fs::create_directories(target);
  fs::create_symlink(target, link);
  EXPECT_EQ(test::gearsim("run " + kSpur + " --out " + link.string() + " --duration 0.3").exit_code, 0);
  EXPECT_EQ(test::gearsim("analyze " + link.string()).exit_code, 0);
  EXPECT_EQ(test::gearsim("report " + link.string()).exit_code, 0);
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(link)));
  for (const char* f : {"summary.json", "analysis.json", "report.html", ".gearsim-manifest"})
    EXPECT_TRUE(fs::is_regular_file(fs::symlink_status(target / f))) << f;
}

TEST(OutputFolderLock, GearsAndModesIntoAFolderAnotherCommandHoldsAreRefused) {
  const fs::path dir = test::fresh_test_dir() / "held";
  fs::create_directories(dir);
  const FolderLock held(dir, "a test");
  const std::string spec = std::string(GEARSIM_SOURCE_DIR) + "/assets/specs/spur_pair_gearset.yaml";
  const test::CliRun gears = test::gearsim("gears " + spec + " --out " + dir.string());
  EXPECT_EQ(gears.exit_code, 7) << gears.output;
  EXPECT_NE(gears.output.find(dir.string() + ": in use by a test (pid "), std::string::npos) << gears.output;
  const test::CliRun modes = test::gearsim("modes " + kSpur + " --out " + dir.string());
  EXPECT_EQ(modes.exit_code, 7) << modes.output;
  EXPECT_FALSE(fs::exists(dir / "gearset.json"));
  EXPECT_FALSE(fs::exists(dir / "modes.json"));
}

TEST(OutputFolderManifest, GearsAndModesListWhatTheyWroteAndANewRunRemovesOnlyThat) {
  const fs::path dir = test::fresh_test_dir() / "gears";
  const std::string spec = std::string(GEARSIM_SOURCE_DIR) + "/assets/specs/spur_pair_gearset.yaml";
  ASSERT_EQ(test::gearsim("gears " + spec + " --out " + dir.string() + " --formats stl").exit_code, 0);
  ASSERT_EQ(test::gearsim("modes " + kSpur + " --out " + dir.string()).exit_code, 0);
  std::ofstream(dir / "notes.txt") << "mine\n";
  const std::string manifest = text_of(dir / ".gearsim-manifest");
  for (const char* f : {"gearset.json", "pinion.stl", "wheel.stl", "modes.json", "mode_shapes.csv", "campbell.csv", "modes.svg"}) {
    EXPECT_NE(manifest.find(std::string(f) + "\n"), std::string::npos) << f << " not in the manifest:\n" << manifest;
    EXPECT_TRUE(fs::is_regular_file(dir / f)) << f;
  }
  // A run into the folder removes the outputs gearsim listed there, and nothing else.
  const test::CliRun run = test::gearsim("run " + kSpur + " --out " + dir.string() + " --duration 0.05 --no-analyze");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("removed 7 outputs of a previous run"), std::string::npos) << run.output;
  EXPECT_FALSE(fs::exists(dir / "pinion.stl"));
  EXPECT_FALSE(fs::exists(dir / "modes.json"));
  EXPECT_EQ(text_of(dir / "notes.txt"), "mine\n");
}

TEST(InputBounds, AFifoOrADeviceAsAScenarioIsRefusedAtOnce) {
  const fs::path dir = test::fresh_test_dir();
  ASSERT_EQ(::mkfifo((dir / "s.yaml").c_str(), 0600), 0);
  for (const std::string& s : {(dir / "s.yaml").string(), std::string("/dev/zero")}) {
    const test::CliRun r = test::gearsim("run " + s + " --out " + (dir / "out").string());
    EXPECT_EQ(r.exit_code, 2) << s << "\n" << r.output;
    EXPECT_NE(r.output.find(s + ": expected a scenario or gear-set file (a regular file), got a"), std::string::npos) << r.output;
  }
}

TEST(InputBounds, ALogLinkedToADeviceIsRefusedNotRead) {
  const fs::path dir = test::fresh_test_dir() / "run";
  ASSERT_EQ(test::gearsim("run " + kSpur + " --out " + dir.string() + " --duration 0.2 --no-analyze").exit_code, 0);
  fs::remove(dir / "state.csv");
  fs::create_symlink("/dev/zero", dir / "state.csv");
  const test::CliRun r = test::gearsim("analyze " + dir.string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("state.csv: expected a run's CSV log (a regular file), got a device"), std::string::npos) << r.output;
}

TEST(InputBounds, ReportCompareOnlyReadsTheComparedFolder) {
  const fs::path a = test::fresh_test_dir() / "a", b = a.parent_path() / "b";
  for (const fs::path& d : {a, b}) ASSERT_EQ(test::gearsim("run " + kSpur + " --out " + d.string() + " --duration 0.3").exit_code, 0);
  std::vector<std::pair<std::string, fs::file_time_type>> before;
  for (const fs::directory_entry& e : fs::directory_iterator(b)) before.emplace_back(e.path().filename().string(), e.last_write_time());
  const test::CliRun r = test::gearsim("report " + a.string() + " --compare " + b.string());
  EXPECT_EQ(r.exit_code, 0) << r.output;
  std::vector<std::pair<std::string, fs::file_time_type>> after;
  for (const fs::directory_entry& e : fs::directory_iterator(b)) after.emplace_back(e.path().filename().string(), e.last_write_time());
  EXPECT_EQ(after, before);
}

// A 2 MiB disk, where one can be mounted (root in a container; skipped elsewhere): the audit's case.
TEST(FullDisk, ARunOnASmallDiskEndsWithExitSixAndWholeFilesOnly) {
  const fs::path dir = test::fresh_test_dir();
  if (::mount("tmpfs", dir.c_str(), "tmpfs", 0, "size=2m") != 0) GTEST_SKIP() << "cannot mount a tmpfs here";
  const test::CliRun r = test::gearsim("run " + kSpur + " --out " + (dir / "r").string() + " --duration 0.5");
  const std::string broken = broken_outputs(dir);
  const bool summary = fs::exists(dir / "r/summary.json");
  const std::string status = summary ? nlohmann::json::parse(text_of(dir / "r/summary.json"))["status"] : "";
  ::umount(dir.c_str());
  EXPECT_EQ(r.exit_code, 6) << r.output;
  EXPECT_NE(r.output.find("No space left on device"), std::string::npos) << r.output;
  EXPECT_EQ(broken, "");
  if (summary) {
    EXPECT_EQ(status, "output_failed");
  }
}

}  // namespace test_output_faults
}  // namespace gearsim::app

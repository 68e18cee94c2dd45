// A run stopped from outside (SIGTERM, SIGINT) ends at one step with every log complete up to it,
// status "interrupted" and the signal's exit code (128 + signal); a run into a folder that holds an
// earlier run's outputs removes them first (those its manifest lists), so no stale summary or
// analysis sits beside new logs, and refuses a folder of files gearsim did not write.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "sim/step_log_reader.hpp"
#include "tests/support/cli_run.hpp"

namespace test_run_stop {

namespace fs = std::filesystem;

// Data rows of a CSV log (after the header), and whether the file ends with a complete line.
struct CsvTail {
  std::size_t columns_header = 0;
  std::size_t rows = 0;
  bool every_row_complete = true;
  double last_time_s = -1;
};

std::size_t count_columns(const std::string& line) { return static_cast<std::size_t>(std::count(line.begin(), line.end(), ',')) + 1; }

CsvTail read_csv(const fs::path& p) {
  std::ifstream f(p);
  std::stringstream all;
  all << f.rdbuf();
  const std::string text = all.str();
  CsvTail t;
  if (text.empty()) return t;
  t.every_row_complete = text.back() == '\n';
  std::istringstream in(text);
  std::string line;
  std::getline(in, line);
  t.columns_header = count_columns(line);
  while (std::getline(in, line)) {
    ++t.rows;
    if (count_columns(line) != t.columns_header) t.every_row_complete = false;
    t.last_time_s = std::stod(line.substr(0, line.find(',')));
  }
  return t;
}

// Starts `gearsim run` on the healthy paper scenario for 2 s, waits until it has logged rows, sends
// it `sig` and returns its exit status.
int run_and_signal(const fs::path& dir, int sig) {
  fs::remove_all(dir);
  const std::string bin = std::string(GEARSIM_BINARY_DIR) + "/bin/gearsim";
  const std::string scenario = std::string(GEARSIM_SOURCE_DIR) + "/assets/scenarios/paper_dynamics_healthy.yaml";
  const pid_t pid = fork();
  if (pid == 0) {
    std::freopen("/dev/null", "w", stdout);
    std::freopen("/dev/null", "w", stderr);
    execl(bin.c_str(), bin.c_str(), "run", scenario.c_str(), "--out", dir.c_str(), "--duration", "2", static_cast<char*>(nullptr));
    _exit(127);
  }
  // Wait for a few rows past the header (the run logs at 2 kHz), at most 5 minutes. Until the
  // run ends, state.csv is written under its temporary name (.state.csv.partial-PID-N).
  const auto logged_bytes = [&] {
    std::error_code ec;
    std::uintmax_t bytes = 0;
    for (const fs::directory_entry& e : fs::directory_iterator(dir, ec))
      if (e.path().filename().string().starts_with(".state.csv.partial-")) bytes += e.file_size(ec);
    return bytes;
  };
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(5);
  while (std::chrono::steady_clock::now() < deadline) {
    if (logged_bytes() > 4096) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  kill(pid, sig);
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

void expect_interrupted(const fs::path& dir, const std::string& signal_name) {
  std::ifstream f(dir / "summary.json");
  ASSERT_TRUE(f) << "no summary.json after " << signal_name;
  const nlohmann::json s = nlohmann::json::parse(f);
  EXPECT_EQ(s["status"], "interrupted");
  EXPECT_EQ(s["signal"], signal_name);
  const double t = s["sim_seconds"].get<double>();
  EXPECT_GT(t, 0.0);
  EXPECT_LT(t, 2.0);
  // Both logs end at the same, complete row: the step the run stopped at.
  const CsvTail state = read_csv(dir / "state.csv"), contacts = read_csv(dir / "contacts.csv");
  EXPECT_TRUE(state.every_row_complete);
  EXPECT_TRUE(contacts.every_row_complete);
  EXPECT_GT(state.rows, 1u);
  EXPECT_EQ(state.rows, contacts.rows);
  EXPECT_DOUBLE_EQ(state.last_time_s, t);
  EXPECT_DOUBLE_EQ(contacts.last_time_s, t);
  // steps.h5 closed and valid, its last contact row at that step (the paper set touches every step).
  const gearsim::sim::StepLogContacts log = gearsim::sim::read_step_log_contacts(dir / "steps.h5");
  ASSERT_FALSE(log.step.empty());
  EXPECT_EQ(log.step.back(), s["steps"].get<std::int64_t>());
  EXPECT_DOUBLE_EQ(log.time_s.back(), t);
  EXPECT_FALSE(fs::exists(dir / "analysis.json"));  // an interrupted run is not analysed
}

TEST(RunStop, SigtermEndsTheRunAtOneStepWithExitCode143) {
  const fs::path dir = fs::temp_directory_path() / "gearsim_stop_term";
  EXPECT_EQ(run_and_signal(dir, SIGTERM), 143);
  expect_interrupted(dir, "SIGTERM");
}

// Whether process `pid` has a handler for `sig` (its SigCgt mask in /proc).
bool catches(pid_t pid, int sig) {
  std::ifstream f("/proc/" + std::to_string(pid) + "/status");
  for (std::string line; std::getline(f, line);)
    if (line.starts_with("SigCgt:")) return (std::stoull(line.substr(7), nullptr, 16) >> (sig - 1)) & 1u;
  return false;
}

TEST(RunStop, ASignalWhileTheScenarioLoadsEndsTheCommandWithItsCodeAndNothingWritten) {
  // SIGTERM as soon as `gearsim run` catches it: the handlers come before the scenario is read,
  // so the signal falls in the loading (the paper set's, ~0.2 s) and the command ends with 143
  // before it takes the output folder. Before, the handlers came after the folder was taken and
  // its records written: a signal in the loading killed the process by the default action.
  const fs::path dir = fs::temp_directory_path() / "gearsim_run_stop_loading";
  fs::remove_all(dir);
  const std::string bin = std::string(GEARSIM_BINARY_DIR) + "/bin/gearsim";
  const std::string scenario = std::string(GEARSIM_SOURCE_DIR) + "/assets/scenarios/paper_dynamics_healthy.yaml";
  const pid_t pid = fork();
  if (pid == 0) {
    std::freopen("/dev/null", "w", stdout);
    std::freopen("/dev/null", "w", stderr);
    execl(bin.c_str(), bin.c_str(), "run", scenario.c_str(), "--out", dir.c_str(), "--duration", "2", static_cast<char*>(nullptr));
    _exit(127);
  }
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(1);
  while (!catches(pid, SIGTERM) && std::chrono::steady_clock::now() < deadline) std::this_thread::sleep_for(std::chrono::microseconds(200));
  kill(pid, SIGTERM);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status)) << "ended by signal " << (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
  EXPECT_EQ(WEXITSTATUS(status), 143);
  EXPECT_FALSE(fs::exists(dir)) << "the output folder was taken before the signal was caught";
}

TEST(RunStop, SigintEndsTheRunAtOneStepWithExitCode130) {
  const fs::path dir = fs::temp_directory_path() / "gearsim_stop_int";
  EXPECT_EQ(run_and_signal(dir, SIGINT), 130);
  expect_interrupted(dir, "SIGINT");
}

TEST(RunStop, ASignalDuringTheAnalysisEndsTheCommandWithItsCodeOnceTheAnalysisIsWritten) {
  // `gearsim run` prints the run's outcome line before it analyses the run (flushed, also into a
  // pipe); a SIGTERM sent as soon as that line arrives falls in the analysis (≈ 0.5 s for 4 s of
  // the spur pair, whose scenario renders nothing). The analysis is written whole, then the
  // command ends with 143 — it used to end with 0 there, the signal unanswered.
  const fs::path dir = fs::temp_directory_path() / "gearsim_stop_analysis";
  fs::remove_all(dir);
  const std::string bin = std::string(GEARSIM_BINARY_DIR) + "/bin/gearsim";
  const std::string scenario = std::string(GEARSIM_SOURCE_DIR) + "/assets/scenarios/spur_pair.yaml";
  int out[2];
  ASSERT_EQ(pipe(out), 0);
  const pid_t pid = fork();
  if (pid == 0) {
    dup2(out[1], STDOUT_FILENO);
    close(out[0]);
    close(out[1]);
    std::freopen("/dev/null", "w", stderr);
    execl(bin.c_str(), bin.c_str(), "run", scenario.c_str(), "--out", dir.c_str(), "--duration", "4", static_cast<char*>(nullptr));
    _exit(127);
  }
  close(out[1]);
  std::string text;
  char buf[4096];
  bool signalled = false;
  for (ssize_t got; (got = read(out[0], buf, sizeof buf)) > 0;) {
    text.append(buf, static_cast<std::size_t>(got));
    if (!signalled && text.find(": completed, ") != std::string::npos) {
      kill(pid, SIGTERM);
      signalled = true;
    }
  }
  close(out[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(signalled) << text;
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 143) << text;
  // The run and its analysis complete: summary.json says completed, analysis.json parses whole.
  std::ifstream summary(dir / "summary.json");
  ASSERT_TRUE(summary);
  EXPECT_EQ(nlohmann::json::parse(summary)["status"], "completed");
  std::ifstream analysis(dir / "analysis.json");
  ASSERT_TRUE(analysis) << "no analysis.json";
  const nlohmann::json a = nlohmann::json::parse(analysis);
  EXPECT_TRUE(a.contains("pairs"));
}

TEST(RunStop, ARunIntoAUsedFolderRemovesTheEarlierRunsOutputsOnly) {
  // The earlier run's outputs are the ones its manifest lists (run, analysis, report); a file the
  // user put beside them, also one named like a render's frame, stays.
  const fs::path dir = fs::temp_directory_path() / "gearsim_stop_reused";
  fs::remove_all(dir);
  const std::string run =
      std::string("run ") + GEARSIM_SOURCE_DIR + "/assets/scenarios/spur_pair.yaml --out " + dir.string() + " --duration 0.3";
  ASSERT_EQ(gearsim::test::gearsim(run).exit_code, 0);
  ASSERT_EQ(gearsim::test::gearsim("report " + dir.string()).exit_code, 0);
  std::ofstream(dir / "notes.txt") << "the user's own file\n";
  fs::create_directories(dir / "frames");
  std::ofstream(dir / "frames" / "f_000001.png") << "the user's own picture\n";
  const gearsim::test::CliRun r = gearsim::test::gearsim(run + " --no-analyze");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  // state, contacts, steps, scenario, summary; analysis, spectrum, sidebands, teeth; report.
  EXPECT_NE(r.output.find("removed 10 outputs of a previous run"), std::string::npos) << r.output;
  for (const char* f : {"analysis.json", "report.html", "spectrum.csv", "sidebands.csv", "teeth.csv"})
    EXPECT_FALSE(fs::exists(dir / f)) << f;
  EXPECT_TRUE(fs::exists(dir / "notes.txt"));
  EXPECT_TRUE(fs::exists(dir / "frames" / "f_000001.png"));
  EXPECT_TRUE(fs::exists(dir / "summary.json"));
  EXPECT_TRUE(fs::exists(dir / "state.csv"));
}

TEST(RunStop, AFolderOfTheUsersFilesIsRefusedAndNothingInItRemoved) {
  // The audit's case: a folder that never held a run, with files named like a run's outputs.
  const fs::path dir = fs::temp_directory_path() / "gearsim_stop_users_folder";
  fs::remove_all(dir);
  fs::create_directories(dir / "frames");
  for (const char* f : {"frames/holiday.png", "video_of_my_cat.mp4", "state.csv"}) std::ofstream(dir / f) << "mine\n";
  const std::string run =
      std::string("run ") + GEARSIM_SOURCE_DIR + "/assets/scenarios/spur_pair.yaml --out " + dir.string() + " --duration 0.1 --no-analyze";
  const gearsim::test::CliRun r = gearsim::test::gearsim(run);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find(dir.string() + ": the folder holds files that gearsim did not write"), std::string::npos) << r.output;
  for (const char* f : {"frames/holiday.png", "video_of_my_cat.mp4", "state.csv"}) EXPECT_TRUE(fs::exists(dir / f)) << f;
  EXPECT_FALSE(fs::exists(dir / ".gearsim.lock"));  // refused before anything was made there
  // --force writes beside them: nothing of the user's is removed; state.csv, an output's name, is replaced.
  const gearsim::test::CliRun forced = gearsim::test::gearsim(run + " --force");
  EXPECT_EQ(forced.exit_code, 0) << forced.output;
  EXPECT_TRUE(fs::exists(dir / "frames/holiday.png"));
  EXPECT_TRUE(fs::exists(dir / "video_of_my_cat.mp4"));
  EXPECT_GT(fs::file_size(dir / "state.csv"), 100u);
}

TEST(RunStop, LinksNamedLikeOutputsAreReplacedNotFollowed) {
  // Outputs go only inside the chosen folder: a symbolic link planted under an output's name is
  // replaced by the output (a rename over it, never a write through it); the file it pointed to
  // is left as it was. The folder holds files gearsim did not write, hence --force.
  const fs::path dir = fs::temp_directory_path() / "gearsim_stop_links";
  const fs::path outside = fs::temp_directory_path() / "gearsim_stop_links_outside.txt";
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(outside) << "not the run's\n";
  const std::vector<std::string> names = {"state.csv",     "contacts.csv", "steps.h5",      "summary.json",
                                          "scenario.json", "gearset.yaml", "analysis.json", "spectrum.csv"};
  for (const std::string& n : names) fs::create_symlink(outside, dir / n);
  const gearsim::test::CliRun r =
      gearsim::test::gearsim(std::string("run ") + GEARSIM_SOURCE_DIR + "/assets/scenarios/paper_dynamics_healthy.yaml --out " +
                             dir.string() + " --duration 0.2 --force");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  std::ifstream f(outside);
  std::stringstream text;
  text << f.rdbuf();
  EXPECT_EQ(text.str(), "not the run's\n");
  for (const std::string& n : names) {
    const fs::file_status st = fs::symlink_status(dir / n);
    EXPECT_FALSE(fs::is_symlink(st)) << n;
  }
  for (const char* n : {"state.csv", "contacts.csv", "steps.h5", "summary.json", "scenario.json", "gearset.yaml", "analysis.json"})
    EXPECT_TRUE(fs::is_regular_file(fs::symlink_status(dir / n))) << n;
  // The commands that write into a finished run's folder (analyze, report) replace such links too.
  for (const char* n : {"analysis.json", "spectrum.csv", "report.html"}) {
    fs::remove(dir / n);
    fs::create_symlink(outside, dir / n);
  }
  EXPECT_EQ(gearsim::test::gearsim("analyze " + dir.string()).exit_code, 0);
  EXPECT_EQ(gearsim::test::gearsim("report " + dir.string()).exit_code, 0);
  std::ifstream g(outside);
  std::stringstream after;
  after << g.rdbuf();
  EXPECT_EQ(after.str(), "not the run's\n");
  for (const char* n : {"analysis.json", "spectrum.csv", "report.html"}) EXPECT_TRUE(fs::is_regular_file(fs::symlink_status(dir / n))) << n;
  fs::remove(outside);
}

}  // namespace test_run_stop

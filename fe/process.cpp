#include "fe/process.hpp"

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "core/errors.hpp"
#include "fe/constants.hpp"

namespace gearsim::fe {
namespace fs = std::filesystem;
namespace {

std::string read_text(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// The log's *ERROR lines, or its tail when it has none.
std::string error_excerpt(const std::string& log) {
  std::istringstream in(log);
  std::string line, errors;
  while (std::getline(in, line))
    if (line.find("*ERROR") != std::string::npos) errors += line + "\n";
  if (!errors.empty()) return errors;
  const size_t n = static_cast<size_t>(kLogTailChars);
  return log.size() > n ? log.substr(log.size() - n) : log;
}

}  // namespace

fs::path find_executable(const std::string& name) {
  if (name.find('/') != std::string::npos) return ::access(name.c_str(), X_OK) == 0 ? fs::path(name) : fs::path();
  const char* path = std::getenv("PATH");
  std::istringstream dirs(path ? path : "");
  std::string dir;
  while (std::getline(dirs, dir, ':')) {
    const fs::path cand = fs::path(dir.empty() ? "." : dir) / name;
    if (::access(cand.c_str(), X_OK) == 0) return cand;
  }
  return {};
}

CcxRunResult run_ccx(const CcxRunDef& def) {
  // Demand the solver and the deck before starting anything.
  const fs::path exe = find_executable(def.executable);
  if (exe.empty())
    throw InputError("ccx executable '" + def.executable + "' not found on PATH (install calculix-ccx, scripts/install-deps.sh)");
  const fs::path deck = def.work_dir / (def.job + ".inp");
  if (!fs::exists(deck)) throw InputError("ccx deck not found: " + deck.string());

  CcxRunResult res;
  res.dat_path = def.work_dir / (def.job + ".dat");
  res.log_path = def.work_dir / (def.job + ".log");
  fs::remove(res.dat_path);

  // Fork, chdir into the work folder, send both streams to the log, exec ccx -i job.
  const auto t0 = std::chrono::steady_clock::now();
  const pid_t pid = ::fork();
  if (pid < 0) throw std::runtime_error("ccx: fork failed");
  if (pid == 0) {
    if (::chdir(def.work_dir.c_str()) != 0) ::_exit(126);
    const int fd = ::open(res.log_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd < 0) ::_exit(126);
    ::dup2(fd, 1);
    ::dup2(fd, 2);
    ::setenv("OMP_NUM_THREADS", "1", 1);
    ::execl(exe.c_str(), exe.c_str(), "-i", def.job.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  res.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  // ccx may exit 0 after an *ERROR: the log decides, then the exit code, then the .dat.
  const std::string log = read_text(res.log_path);
  const bool failed_exit = !WIFEXITED(status) || WEXITSTATUS(status) != 0;
  const bool has_error = log.find("*ERROR") != std::string::npos;
  if (has_error || failed_exit || !fs::exists(res.dat_path))
    throw std::runtime_error("ccx failed on " + deck.string() + " (log " + res.log_path.string() + "):\n" + error_excerpt(log));
  return res;
}

}  // namespace gearsim::fe

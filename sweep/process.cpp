#include "sweep/process.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <fstream>
#include <sstream>
#include <thread>

#include "core/output_file.hpp"

extern char** environ;

namespace gearsim::sweep {
namespace {

// How often a running child's stop request is looked at, ms.
constexpr int kPollInterval_ms = 20;

// Waits for pid, polling `stop`; returns waitpid's status.
int wait_polling(pid_t pid, const std::function<int()>& stop) {
  bool signalled = false;
  while (true) {
    int status = 0;
    const pid_t r = waitpid(pid, &status, WNOHANG);
    if (r == pid) return status;
    if (r < 0 && errno != EINTR) return -1;
    if (!signalled && stop) {
      if (const int sig = stop(); sig > 0) {
        kill(pid, sig);
        signalled = true;
      }
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(kPollInterval_ms));
  }
}

// A child's log file, created (truncated) for writing; -1 (errno set) when it cannot be.
int open_log(const std::filesystem::path& p) {
  unlink_output(p);
  return ::open(p.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_NOFOLLOW | O_CLOEXEC, 0644);
}

}  // namespace

ProcessOutcome run_process(const std::vector<std::string>& argv, const std::filesystem::path& stdout_file,
                           const std::filesystem::path& stderr_file, const std::function<int()>& stop) {
  ProcessOutcome out;
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  // The logs opened here, never through a link: one planted under a log's name is removed
  // (the link, not its target) and the log made afresh with O_NOFOLLOW.
  const int out_fd = open_log(stdout_file), err_fd = out_fd < 0 ? -1 : open_log(stderr_file);
  if (out_fd < 0 || err_fd < 0) {
    const int e = errno;
    if (out_fd >= 0) ::close(out_fd);
    out.exit_code = 127;
    out.failure = "cannot write " + (out_fd < 0 ? stdout_file : stderr_file).string() + ": " + std::strerror(e);
    return out;
  }
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_adddup2(&actions, out_fd, STDOUT_FILENO);
  posix_spawn_file_actions_adddup2(&actions, err_fd, STDERR_FILENO);
  pid_t pid = 0;
  const int err = posix_spawn(&pid, args[0], &actions, nullptr, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  ::close(out_fd);
  ::close(err_fd);
  if (err != 0) {
    out.exit_code = 127;
    out.failure = "cannot start " + argv[0] + ": " + std::strerror(err);
    return out;
  }
  const int status = wait_polling(pid, stop);
  if (status < 0) {
    out.failure = "lost the child process of " + argv[0] + ": " + std::strerror(errno);
  } else if (WIFEXITED(status)) {
    out.exit_code = WEXITSTATUS(status);
  } else if (WIFSIGNALED(status)) {
    out.signal = WTERMSIG(status);
    out.exit_code = 128 + out.signal;
  }
  return out;
}

std::filesystem::path self_executable() { return std::filesystem::read_symlink("/proc/self/exe"); }

std::string file_tail(const std::filesystem::path& file, std::size_t max_bytes) {
  // Only a log this sweep wrote: a link under its name is not followed.
  std::error_code ec;
  if (!std::filesystem::is_regular_file(std::filesystem::symlink_status(file, ec))) return "";
  std::ifstream in(file, std::ios::binary);
  if (!in) return "";
  std::stringstream all;
  all << in.rdbuf();
  std::string text = all.str();
  if (text.size() > max_bytes) {
    text = text.substr(text.size() - max_bytes);
    if (const std::size_t nl = text.find('\n'); nl != std::string::npos && nl + 1 < text.size()) text = text.substr(nl + 1);
  }
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
  return text;
}

}  // namespace gearsim::sweep

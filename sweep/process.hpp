// One child process, started without a shell: posix_spawn with an argument vector, so names and
// values from input files are arguments, never shell text. Its stdout and stderr go to files of
// the case folder, its stdin is /dev/null. posix_spawn (no fork) keeps OpenMPI quiet about
// children of an MPI rank. Not a job scheduler: schedulers.hpp runs many.
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace gearsim::sweep {

struct ProcessOutcome {
  int exit_code = -1;  // the child's exit code; 128 + signal when a signal ended it
  int signal = 0;  // the signal that ended it, 0 when it exited
  std::string failure;  // non-empty when the child could not be started (then exit_code 127)
};

// Runs argv (argv[0] the program's path) to its end. `stop` is polled every 20 ms while it runs:
// when it returns a signal number > 0 that signal is sent to the child once (a child that was
// asked to stop still gets waited for). The log files are made afresh, never through a link
// (failure names the one that could not be).
ProcessOutcome run_process(const std::vector<std::string>& argv, const std::filesystem::path& stdout_file,
                           const std::filesystem::path& stderr_file, const std::function<int()>& stop);

// This program's own executable (/proc/self/exe), to run `gearsim run` as a child.
std::filesystem::path self_executable();

// The last `max_bytes` of a text file (whole lines where possible), "" when it is missing.
std::string file_tail(const std::filesystem::path& file, std::size_t max_bytes);

}  // namespace gearsim::sweep

// Test helper: runs the built gearsim binary with arguments and returns its exit code and its
// stdout and stderr together, as a user at a terminal sees them.
#pragma once

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <string>

namespace gearsim::test {

struct CliRun {
  int exit_code;
  std::string output;  // stdout and stderr
};

// `launcher` runs the binary (e.g. "mpirun -np 3 "), "" for none.
inline CliRun gearsim_under(const std::string& launcher, const std::string& args) {
  const std::string cmd = launcher + std::string(GEARSIM_BINARY_DIR) + "/bin/gearsim " + args + " 2>&1";
  FILE* pipe = popen(cmd.c_str(), "r");
  std::string out;
  std::array<char, 4096> buf{};
  while (std::size_t n = std::fread(buf.data(), 1, buf.size(), pipe)) out.append(buf.data(), n);
  const int status = pclose(pipe);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, out};
}

inline CliRun gearsim(const std::string& args) { return gearsim_under("", args); }

}  // namespace gearsim::test

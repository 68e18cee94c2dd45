// Error tiers shared by every Gearsim library.
//  - InputError: bad user input (a spec file, a mesh, a CLI value). The message names the file,
//    key or line and what was expected. Thrown, caught and printed by app/.
//  - OutputError: an output that could not be written (a full disk, a lost permission). The
//    message names the file and the system's reason. Nothing half-written is left in its place.
//  - GEARSIM_CHECK: a broken internal invariant (a bug, not bad input). Always on, also in Release.
#pragma once

#include <stdexcept>
#include <string>

namespace gearsim {

class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class InternalError : public std::logic_error {
 public:
  using std::logic_error::logic_error;
};

[[noreturn]] inline void internal_check_failed(const char* expr, const char* file, int line, const std::string& msg) {
  throw InternalError(std::string("internal check failed: ") + expr + " (" + file + ":" + std::to_string(line) + "): " + msg);
}

}  // namespace gearsim

#define GEARSIM_CHECK(cond, msg)                                                   \
  do {                                                                             \
    if (!(cond)) ::gearsim::internal_check_failed(#cond, __FILE__, __LINE__, msg); \
  } while (0)

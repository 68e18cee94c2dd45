// SIGINT and SIGTERM as requests to stop: a run between two steps, a render between two frames.
// While a StopSignals lives, either signal is latched instead of ending the process; the command
// then finishes what it has written and exits with the signal's code (app/exit_codes.hpp).
#pragma once

#include <filesystem>
#include <string>

#include "app/render_run.hpp"

namespace gearsim::app {

// The latched signal (SIGINT or SIGTERM), 0 while none came since the last StopSignals began.
int stop_signal();
std::string signal_name(int sig);  // "SIGINT" or "SIGTERM"

class StopSignals {
 public:
  StopSignals();  // clears the latch, installs the handlers
  ~StopSignals();  // puts the previous handlers back
  StopSignals(const StopSignals&) = delete;
  StopSignals& operator=(const StopSignals&) = delete;

 private:
  void (*old_int_)(int);
  void (*old_term_)(int);
};

// RunStopped with the signal's exit code when a signal stopped the render `r` of the run in `dir`.
void throw_if_render_stopped(const RenderResult& r, const std::filesystem::path& dir);

}  // namespace gearsim::app

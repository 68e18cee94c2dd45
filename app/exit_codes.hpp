// The exit codes of the gearsim binary, and the exception a subcommand throws to end with one
// of them after it has written its outputs. Documented in `gearsim --help` and the README.
#pragma once

#include <stdexcept>
#include <string>

namespace gearsim::app {

constexpr int kExitOk = 0;
constexpr int kExitInputError = 2;  // bad input: the message names the file, key or value
constexpr int kExitInternalError = 3;  // a broken invariant: a bug, please report
constexpr int kExitDiverged = 4;  // the run left its physical bounds; logs kept up to that step
constexpr int kExitSweepCasesFailed = 5;  // a sweep ran to its end, some cases did not complete (each recorded)
constexpr int kExitOutputError = 6;  // an output could not be written (disk full, permission): named, nothing half-written left
constexpr int kExitFolderBusy = 7;  // another gearsim command is writing into the output folder (named)
constexpr int kExitToolFailed = 8;  // a program or library gearsim drives failed (CalculiX, OSMesa, FFmpeg): named, what was kept said
constexpr int kExitNotAnalysed = 9;  // a run completed (logs valid) but its analysis was refused: the message says why
constexpr int kExitSigint = 130;  // a run stopped by SIGINT (128 + 2): logs kept up to that step
constexpr int kExitSigterm = 143;  // the same for SIGTERM (128 + 15)

// A run that ended early but wrote valid outputs (summary.json says why).
class RunStopped : public std::runtime_error {
 public:
  RunStopped(int code, const std::string& message) : std::runtime_error(message), code_(code) {}
  int code() const { return code_; }

 private:
  int code_;
};

}  // namespace gearsim::app

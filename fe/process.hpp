// Runs CalculiX (ccx) as a subprocess on a deck already written in a work folder.
// Not a deck writer and not a result reader: it runs, keeps the log, and turns failures into
// exceptions that quote the solver's own error lines.
#pragma once

#include <filesystem>
#include <string>

namespace gearsim::fe {

// How to run ccx.
struct CcxRunDef {
  std::string executable = "ccx";  // name looked up on PATH, or a path
  std::filesystem::path work_dir;  // holds <job>.inp; ccx writes <job>.dat/.frd/.log here
  std::string job = "job";  // job name (deck file without .inp)
};

// What a finished run left behind.
struct CcxRunResult {
  std::filesystem::path dat_path;  // <job>.dat, node/element prints
  std::filesystem::path log_path;  // <job>.log, ccx's stdout and stderr
  double wall_time_s = 0.0;  // solver wall time, in s
};

// Finds an executable on PATH (or checks a given path); empty when absent.
std::filesystem::path find_executable(const std::string& name);

// Runs ccx; throws InputError when ccx or the deck is missing, and std::runtime_error quoting
// the log's *ERROR lines (or its tail) when ccx fails or leaves no .dat.
CcxRunResult run_ccx(const CcxRunDef& def);

}  // namespace gearsim::fe

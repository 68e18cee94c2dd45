// One writer per output folder: a command that writes into a folder (run, analyze, report,
// render, sweep, gears, modes, fe-te) holds an exclusive flock on DIR/.gearsim.lock for as long as it writes. A second
// command is refused at once, naming the holder (its command, process id and start time, which
// the holder writes into the lock file). The lock goes with the process (the kernel releases it,
// also after a crash or SIGKILL); the file stays, harmless. Not a guard against other programs
// writing into the folder.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>

namespace gearsim {

// A second writer: the message names the folder and the holder.
class FolderBusy : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class FolderLock {
 public:
  // Locks `dir` (which must exist) for `command` (e.g. "gearsim run"). FolderBusy when another
  // process holds it; InputError naming the folder when the lock file cannot be made (a link or
  // a folder under its name, no permission).
  FolderLock(const std::filesystem::path& dir, const std::string& command);
  ~FolderLock();
  FolderLock(const FolderLock&) = delete;
  FolderLock& operator=(const FolderLock&) = delete;

  static constexpr const char* kFileName = ".gearsim.lock";

 private:
  int fd_ = -1;
};

}  // namespace gearsim

// An output folder as a command holds it while it writes: created where missing (a link given as
// the folder is followed to the folder it names, and left as it is), locked against a second gearsim command (core/folder_lock.hpp), and
// with its manifest (core/folder_manifest.hpp) of what gearsim wrote there, to which the command
// adds each output's name before writing it. Not the writer of the outputs themselves
// (core/output_file.hpp) and not a reader of a run's record (run_dir.hpp).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/folder_lock.hpp"
#include "core/folder_manifest.hpp"

namespace gearsim::app {

class OutputFolder {
 public:
  // DIR held for `command` ("gearsim run"): created where missing, locked (in the folder a link
  // given as DIR names). FolderBusy naming
  // the holder when another command writes there; InputError when DIR cannot be created or
  // its manifest is damaged.
  OutputFolder(const std::filesystem::path& dir, const std::string& command);
  // The same for a new run into DIR: a folder that holds files but no manifest (not made by
  // gearsim, or by a gearsim before manifests) is refused with InputError before anything is
  // made in it, unless `force`, which keeps every file that is there; then, under the lock, the
  // outputs the manifest lists are removed (removed() says how many).
  struct ForNewRun {
    bool force = false;
  };
  OutputFolder(const std::filesystem::path& dir, const std::string& command, ForNewRun new_run);

  const std::filesystem::path& dir() const { return dir_; }
  // Adds the names (relative to DIR) to the manifest before they are written.
  void declare(const std::vector<std::string>& names);
  // Outputs of a previous run removed by the ForNewRun constructor.
  int removed() const { return removed_; }

 private:
  std::filesystem::path dir_;
  FolderLock lock_;
  FolderManifest manifest_;
  int removed_ = 0;
};

// Adds the names to DIR's manifest before they are written, for code that writes into a folder
// its caller holds (write_run_analysis() inside run, report and the Python module).
void declare_outputs(const std::filesystem::path& dir, const std::vector<std::string>& names);

}  // namespace gearsim::app

// The files gearsim wrote into an output folder, listed in DIR/.gearsim-manifest: one name per
// line relative to DIR (a plain name, or one level below it such as frames/overview_00000.png).
// A command adds the names of what it is about to write before writing (so a killed command's
// files are listed too), under the folder's lock (core/folder_lock.hpp). A new run into the
// folder removes exactly the listed files (and their ".NAME.partial-*" leftovers), never
// anything else, never through a link; a folder that holds files but no manifest was not made by
// gearsim and is not cleaned. The manifest is read as untrusted input: a name that would leave
// the folder is refused.
#pragma once

#include <filesystem>
#include <set>
#include <string>
#include <vector>

namespace gearsim {

class FolderManifest {
 public:
  static constexpr const char* kFileName = ".gearsim-manifest";

  // DIR's manifest, empty when DIR has none. InputError naming the file and line when it is not
  // a manifest (too large, a name with "..", "/" at the start, or deeper than one folder).
  static FolderManifest read(const std::filesystem::path& dir);

  bool exists() const { return exists_; }
  const std::set<std::string>& files() const { return files_; }
  // Adds the names (checked as when read) and writes the manifest (a Record, core/output_file.hpp).
  void add_and_write(const std::filesystem::path& dir, const std::vector<std::string>& names);
  // Removes every listed file that is a regular file or a link (the link itself), the
  // ".NAME.partial-*" leftovers beside them, and the folders that held them once empty; forgets
  // them and writes the manifest. Returns how many files were removed.
  int remove_listed(const std::filesystem::path& dir);

 private:
  bool exists_ = false;
  std::set<std::string> files_;
};

// True when DIR holds anything but gearsim's lock and manifest (a folder a user filled).
bool holds_other_files(const std::filesystem::path& dir);

}  // namespace gearsim

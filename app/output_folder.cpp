#include "app/output_folder.hpp"

#include "core/errors.hpp"

namespace gearsim::app {
namespace {

// DIR created where missing; InputError naming it otherwise (or when it is not a folder). A link
// the user gives as DIR is theirs: its target folder is used, the link is left as it is.
const std::filesystem::path& made(const std::filesystem::path& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw InputError(dir.string() + ": cannot create the output folder: " + ec.message());
  if (!std::filesystem::is_directory(dir, ec)) throw InputError(dir.string() + ": expected a folder for the outputs");
  return dir;
}

}  // namespace

OutputFolder::OutputFolder(const std::filesystem::path& dir, const std::string& command)
    : dir_(dir), lock_(made(dir), command), manifest_(FolderManifest::read(dir)) {}

void OutputFolder::declare(const std::vector<std::string>& names) { manifest_.add_and_write(dir_, names); }

namespace {

// InputError when DIR holds files but no manifest (`has_manifest`) and `force` is not given.
void refuse_foreign(const std::filesystem::path& dir, bool has_manifest, bool force) {
  if (force || has_manifest || !holds_other_files(dir)) return;
  throw InputError(dir.string() + ": the folder holds files that gearsim did not write (it has no " + FolderManifest::kFileName +
                   "): choose an empty or new folder, or give --force to write beside them (none is removed)");
}

// DIR, refused before the lock file is made in a folder that is not gearsim's.
const std::filesystem::path& checked(const std::filesystem::path& dir, bool force) {
  std::error_code ec;
  if (!force && std::filesystem::is_directory(dir, ec)) refuse_foreign(dir, FolderManifest::read(dir).exists(), force);
  return dir;
}

}  // namespace

OutputFolder::OutputFolder(const std::filesystem::path& dir, const std::string& command, ForNewRun new_run)
    : OutputFolder(checked(dir, new_run.force), command) {
  refuse_foreign(dir_, manifest_.exists(), new_run.force);  // again under the lock: it may have changed
  if (manifest_.exists()) removed_ = manifest_.remove_listed(dir_);
}

void declare_outputs(const std::filesystem::path& dir, const std::vector<std::string>& names) {
  FolderManifest::read(dir).add_and_write(dir, names);
}

}  // namespace gearsim::app

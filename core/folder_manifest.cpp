#include "core/folder_manifest.hpp"

#include <sstream>

#include "core/errors.hpp"
#include "core/folder_lock.hpp"
#include "core/input_file.hpp"
#include "core/output_file.hpp"

namespace gearsim {
namespace fs = std::filesystem;
namespace {

// A manifest of a run with a long render lists ~1e4 frames of ~30 bytes.
constexpr std::size_t kMaxManifestBytes = 16u << 20;
constexpr const char* kHeader = "# gearsim: the files gearsim wrote into this folder (removed by the next run into it)";

// Empty when `name` is a name a manifest may hold, else why not.
std::string refusal(const std::string& name) {
  if (name.empty()) return "an empty name";
  if (name.size() > 4096) return "a name longer than 4096 bytes";
  const fs::path p(name);
  if (p.is_absolute()) return "an absolute path";
  int parts = 0;
  for (const fs::path& part : p) {
    const std::string s = part.string();
    if (s.empty() || s == "." || s == "..") return "a path with '" + s + "' in it";
    ++parts;
  }
  if (parts > 2) return "a path deeper than one folder";
  if (name.find('\0') != std::string::npos) return "a name with a NUL byte";
  return "";
}

// True for ".NAME.partial-…" (core/output_file.cpp's temporaries of NAME).
bool is_leftover_of(const std::string& entry, const std::string& name) { return entry.starts_with("." + name + ".partial-"); }

}  // namespace

FolderManifest FolderManifest::read(const fs::path& dir) {
  FolderManifest m;
  const fs::path file = dir / kFileName;
  std::error_code ec;
  if (!fs::exists(fs::symlink_status(file, ec))) return m;
  std::istringstream in(read_input_file(file, kMaxManifestBytes, "gearsim's manifest of the folder"));
  m.exists_ = true;
  std::string line;
  for (int n = 1; std::getline(in, line); ++n) {
    if (line.empty() || line[0] == '#') continue;
    if (const std::string why = refusal(line); !why.empty())
      throw InputError(file.string() + ":" + std::to_string(n) + ": not a manifest of gearsim's: " + why);
    m.files_.insert(line);
  }
  return m;
}

void FolderManifest::add_and_write(const fs::path& dir, const std::vector<std::string>& names) {
  for (const std::string& n : names) {
    GEARSIM_CHECK(refusal(n).empty(), "manifest entry '" + n + "': " + refusal(n));
    files_.insert(n);
  }
  std::string text = std::string(kHeader) + "\n";
  for (const std::string& f : files_) text += f + "\n";
  write_output_file(dir / kFileName, text, Durability::Record);
  exists_ = true;
}

int FolderManifest::remove_listed(const fs::path& dir) {
  int removed = 0;
  std::error_code ec;
  std::set<fs::path> folders;
  for (const std::string& name : files_) {
    const fs::path p = dir / name;
    const fs::path parent = p.parent_path();
    // A listed file below a folder that is now a link is not ours to reach through it.
    if (parent != dir && !fs::is_directory(fs::symlink_status(parent, ec))) continue;
    if (parent != dir) folders.insert(parent);
    const fs::file_status st = fs::symlink_status(p, ec);
    if (fs::is_regular_file(st) || fs::is_symlink(st)) removed += fs::remove(p, ec) ? 1 : 0;
    for (const fs::directory_entry& e : fs::directory_iterator(parent, ec))
      if (is_leftover_of(e.path().filename().string(), p.filename().string()) && !e.is_directory(ec)) fs::remove(e.path(), ec);
  }
  for (const fs::path& f : folders) fs::remove(f, ec);  // only when empty: a user's file keeps it
  files_.clear();
  add_and_write(dir, {});
  return removed;
}

bool holds_other_files(const fs::path& dir) {
  std::error_code ec;
  for (const fs::directory_entry& e : fs::directory_iterator(dir, ec)) {
    const std::string n = e.path().filename().string();
    if (n != FolderLock::kFileName && n != FolderManifest::kFileName) return true;
  }
  return false;
}

}  // namespace gearsim

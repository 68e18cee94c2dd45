// Files a command writes into its output folder never go through a link: a symbolic link already
// there under an output's name (planted, or left by someone else) is removed first, so the write
// makes a regular file inside the folder instead of following the link out of it — outputs go
// only inside the chosen folder. Header-only, like the rest of core/.
#pragma once

#include <filesystem>
#include <fstream>

namespace gearsim {

// Removes a symbolic link at p (the link, not what it points to); anything else stays.
inline void unlink_output(const std::filesystem::path& p) {
  std::error_code ec;
  if (std::filesystem::is_symlink(std::filesystem::symlink_status(p, ec))) std::filesystem::remove(p, ec);
}

// The output file p opened for writing (truncated), never through a link.
inline std::ofstream open_output_file(const std::filesystem::path& p, std::ios::openmode mode = std::ios::out) {
  unlink_output(p);
  return std::ofstream(p, mode);
}

// The output folder p, created where missing, never through a link under its name.
inline void make_output_dir(const std::filesystem::path& p, std::error_code& ec) {
  unlink_output(p);
  std::filesystem::create_directories(p, ec);
}

}  // namespace gearsim

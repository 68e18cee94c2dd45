// Fuzz support: a private temporary folder per fuzzing process, into which each input is written
// as a file (the loaders under test take paths). Removed when the process ends normally; a
// crashed process leaves it in the temporary directory (gearsim_fuzz_<name>_XXXXXX).
// Not a test helper: nothing here checks results.
#pragma once

#include <stdlib.h>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>

namespace gearsim::fuzz {

class InputFolder {
 public:
  explicit InputFolder(const std::string& name) {
    std::string pattern = (std::filesystem::temp_directory_path() / ("gearsim_fuzz_" + name + "_XXXXXX")).string();
    if (!mkdtemp(pattern.data())) {
      std::perror("mkdtemp");
      std::abort();
    }
    dir_ = pattern;
  }
  ~InputFolder() {
    std::error_code ec;
    std::filesystem::remove_all(dir_, ec);
  }
  InputFolder(const InputFolder&) = delete;
  InputFolder& operator=(const InputFolder&) = delete;

  const std::filesystem::path& dir() const { return dir_; }

  // Writes the bytes to `relative` inside the folder (replacing it) and returns its path.
  std::filesystem::path write(const std::filesystem::path& relative, const std::uint8_t* data, std::size_t size) const {
    const std::filesystem::path p = dir_ / relative;
    std::ofstream out(p, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    if (!out) {
      std::perror(p.c_str());
      std::abort();
    }
    return p;
  }

 private:
  std::filesystem::path dir_;
};

}  // namespace gearsim::fuzz

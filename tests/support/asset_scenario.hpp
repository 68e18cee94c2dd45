// Test helper: a copy of a scenario from assets/scenarios/ with some of its text replaced,
// written into a folder of the test's own; its relative paths (`../specs/`) made absolute so the
// copy loads from there. Also a fresh temporary folder per test.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace gearsim::test {

// temp/gearsim_<suite>_<test>_<pid>, emptied.
inline std::filesystem::path fresh_test_dir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::filesystem::path d = std::filesystem::temp_directory_path() /
                                  ("gearsim_" + std::string(info->test_suite_name()) + "_" + info->name() + "_" + std::to_string(getpid()));
  std::filesystem::remove_all(d);
  std::filesystem::create_directories(d);
  return d;
}

inline std::filesystem::path asset_scenario_copy(const std::string& asset, const std::filesystem::path& dir,
                                                 const std::vector<std::pair<std::string, std::string>>& edits) {
  std::ifstream in(std::filesystem::path(GEARSIM_SOURCE_DIR) / "assets/scenarios" / asset);
  std::stringstream buf;
  buf << in.rdbuf();
  std::string text = buf.str();
  auto replace = [&](const std::string& from, const std::string& to) {
    const std::size_t at = text.find(from);
    if (at == std::string::npos) throw std::runtime_error(asset + " lacks the text '" + from + "'");
    text.replace(at, from.size(), to);
  };
  for (const char* rel : {"../specs/", "../gears/"})
    for (std::size_t at = text.find(rel); at != std::string::npos; at = text.find(rel, at + 1))
      text.replace(at, std::string(rel).size(), std::string(GEARSIM_SOURCE_DIR) + "/assets/" + std::string(rel).substr(3));
  for (const auto& [from, to] : edits) replace(from, to);
  const std::filesystem::path out = dir / asset;
  std::ofstream(out) << text;
  return out;
}

}  // namespace gearsim::test

// Test helper for the sweep tests that run the built gearsim: a sweep file over
// assets/scenarios/spur_pair.yaml written into the test's folder, and small readers of what a
// sweep wrote (sweep.csv rows, case.json).
#pragma once

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "sweep/case_list.hpp"

namespace gearsim::test {

// A sweep of spur_pair.yaml: short runs (0.15 s simulated: 0.06 s of steady window after the
// 0.05 s ramp and the force filter's 0.04 s edges, 120 samples at 2 kHz; ~0.5 s wall each).
inline std::filesystem::path spur_sweep_file(const std::filesystem::path& dir, const std::string& body,
                                             const std::string& name = "sweep.yaml", bool per_step_log = false) {
  const std::filesystem::path p = dir / name;
  std::ofstream(p) << "name: spur test sweep\n"
                   << "scenario: " << GEARSIM_SOURCE_DIR << "/assets/scenarios/spur_pair.yaml\n"
                   << "set: [\"duration_s=0.15\", \"output.per_step_log=" << (per_step_log ? "true" : "false") << "\"]\n"
                   << body;
  return p;
}

inline std::string file_text(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// sweep.csv as rows of cells (no quoting in these tests' values).
inline std::vector<std::vector<std::string>> csv_rows(const std::filesystem::path& p) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(file_text(p));
  std::string line;
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    std::string cell;
    std::istringstream l(line);
    while (std::getline(l, cell, ',')) cells.push_back(cell);
    if (!line.empty() && line.back() == ',') cells.push_back("");
    rows.push_back(cells);
  }
  return rows;
}

inline nlohmann::json case_json(const std::filesystem::path& out, std::size_t index) {
  return nlohmann::json::parse(file_text(out / "cases" / sweep::case_folder_name(index) / "case.json"));
}

}  // namespace gearsim::test

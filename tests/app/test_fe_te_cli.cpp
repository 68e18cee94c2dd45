// gearsim fe-te end to end on a coarse mesh (one position, flank 1 mm, ~40 s of ccx): the
// three planets share the load, the sun turns forward under load from the geometric closing
// 4t/r_b,s of the backlash allowance, and a second run reuses the finished solve (resume).
// Also: a missing solver is a clear error.
#include <gtest/gtest.h>

#include "tests/support/cli_run.hpp"

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <sys/wait.h>

namespace test_fe_te_cli {

namespace fs = std::filesystem;

using gearsim::test::CliRun;
using gearsim::test::gearsim;

std::string read(const fs::path& p) {
  std::ifstream f(p);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

const std::string kScenario = std::string(GEARSIM_SOURCE_DIR) + "/assets/scenarios/paper_te_loaded.yaml";
// Healthy set, one position, coarse: 1 mm flanks, boundary within 20 µm of the outline.
const std::string kCoarse =
    " --set planetary.faulty_planets=null --set fe.flank_size_m=1.0e-3 --set fe.core_size_m=3.0e-3"
    " --set fe.max_sagitta_m=20.0e-6 --set fe.positions_per_mesh=1 --set fe.jobs=1 --no-plots";

TEST(FeTeCli, CoarseHealthyPositionSharesTheLoadAndResumes) {
  const fs::path dir = fs::temp_directory_path() / "gearsim_fe_te_cli";
  fs::remove_all(dir);
  const CliRun r = gearsim("fe-te " + kScenario + " --out " + dir.string() + kCoarse);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const nlohmann::json s = nlohmann::json::parse(read(dir / "summary.json"));
  EXPECT_EQ(s["status"], "completed");
  EXPECT_EQ(s["positions_solved"], 1);
  EXPECT_DOUBLE_EQ(s["fe"]["sun_torque_N_m"].get<double>(), 4.0);  // 20 N·m carrier / 5
  // Equally spaced planets in phase (z_s/N, z_r/N whole): equal shares (measured 0.7 %).
  EXPECT_LT(s["load_sharing_max_over_mean"]["max"].get<double>(), 1.02);
  // The sun turns forward under load, by more than zero and less than the 20 µm backlash's own
  // closing (measured 4.4e-4 rad at 1 mm: 5 µm on the base circle).
  const double elastic = s["te_elastic"]["max_rad"].get<double>();
  EXPECT_GT(elastic, 0.0);
  EXPECT_LT(elastic, 4 * 20e-6 / s["sun_base_radius_m"].get<double>());
  // Geometric part: 20 µm thinning per flank on sun, planet and ring close by 4t/r_b,s
  // (the sun's side and the ring's side of each planet) = 7.094e-3 rad.
  const std::string te = read(dir / "te_loaded.csv");
  std::istringstream lines(te);
  std::string header, row;
  std::getline(lines, header);
  std::getline(lines, row);
  ASSERT_NE(header.find("te_geometric_rad"), std::string::npos);
  std::vector<double> v;
  std::stringstream cells(row);
  for (std::string c; std::getline(cells, c, ',');) v.push_back(std::stod(c));
  ASSERT_GE(v.size(), 6u);
  EXPECT_NEAR(v[3], 4 * 20e-6 / s["sun_base_radius_m"].get<double>(), 0.005 * v[3]);
  EXPECT_NEAR(v[5], v[3] + v[4], 1e-12);  // te_loaded = te_geometric + te_elastic
  // Positive mesh stiffness.
  EXPECT_GT(s["mesh_stiffness_N_per_m"]["min"].get<double>(), 0.0);
  // The teeth take at most the applied torque off the sun (ccx's CPS4R hubs keep a part: measured
  // 85 % at this coarse mesh, 96 % at 0.4 mm).
  EXPECT_LE(s["sun_mesh_torque_over_applied"]["max"].get<double>(), 1.0);
  EXPECT_GT(s["sun_mesh_torque_over_applied"]["min"].get<double>(), 0.8);
  // Planet 0's tooth 0 (tracked, healthy here) carries the sun's load on its ccw flank at this
  // position: the ccw fillet is in tension, the cw fillet in compression, and the compressive
  // peak is the larger one (bending plus the radial component of the tooth force pressing the
  // root; measured 14.6 MPa tension, −20.4 MPa compression at 102 N).
  const auto& t = s["tracked_tooth"];
  EXPECT_EQ(t["planet"], 0);
  EXPECT_EQ(t["tooth"], 0);
  EXPECT_FALSE(t["faulty"].get<bool>());
  EXPECT_GT(t["sun_force_N"]["max"].get<double>(), 50.0);
  EXPECT_EQ(t["root_stress_peak_by_tooth"]["0"]["side"], "ccw");
  std::map<std::string, std::vector<double>> root;  // side → sigma1_max, sigma2_min of tooth 0
  {
    std::istringstream rs(read(dir / "root_stress.csv"));
    std::string line;
    std::getline(rs, line);
    ASSERT_NE(line.find("sigma1_max_Pa"), std::string::npos);
    while (std::getline(rs, line)) {
      std::vector<std::string> c;
      std::stringstream row_cells(line);
      for (std::string x; std::getline(row_cells, x, ',');) c.push_back(x);
      ASSERT_GE(c.size(), 9u);
      if (c[4] == "0") root[c[5]] = {std::stod(c[7]), std::stod(c[8])};
    }
  }
  ASSERT_EQ(root.size(), 2u);
  EXPECT_GT(root["ccw"][0], 0.0);
  EXPECT_LT(root["cw"][1], 0.0);
  EXPECT_GT(-root["cw"][1], root["ccw"][0]);
  EXPECT_LT(root["cw"][0], root["ccw"][0]);
  // A second run of the same command reuses the finished solve: the same CSV, byte for byte
  // (a new solve would record a different ccx wall time).
  const CliRun again = gearsim("fe-te " + kScenario + " --out " + dir.string() + kCoarse);
  ASSERT_EQ(again.exit_code, 0) << again.output;
  EXPECT_EQ(read(dir / "te_loaded.csv"), te);
}

TEST(FeTeCli, MissingSolverIsAClearError) {
  const fs::path dir = fs::temp_directory_path() / "gearsim_fe_te_cli_noccx";
  const CliRun r = gearsim("fe-te " + kScenario + " --out " + dir.string() + " --ccx /nonexistent/ccx");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("calculix-ccx"), std::string::npos) << r.output;
}

TEST(FeTeCli, ScenarioWithoutAnFeSectionIsRefused) {
  const std::string dyn = std::string(GEARSIM_SOURCE_DIR) + "/assets/scenarios/paper_dynamics.yaml";
  const CliRun r = gearsim("fe-te " + dyn + " --out " + (fs::temp_directory_path() / "gearsim_fe_te_nofe").string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("no fe: section"), std::string::npos) << r.output;
}

}  // namespace test_fe_te_cli

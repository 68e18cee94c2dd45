// The gearsim binary as a user meets it: subcommands, JSON, exit codes and error messages.
#include <gtest/gtest.h>

#include "tests/support/cli_run.hpp"

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <sys/wait.h>

namespace test_cli {

using gearsim::test::CliRun;
using gearsim::test::gearsim;

TEST(Cli, HelpListsEverySubcommand) {
  const CliRun r = gearsim("--help");
  EXPECT_EQ(r.exit_code, 0);
  for (const char* sub : {"tolerance", "gears", "inspect"}) EXPECT_NE(r.output.find(sub), std::string::npos) << sub;
}

TEST(Cli, ToleranceJsonGivesThePapers43Micrometres) {
  const CliRun r = gearsim("tolerance --module 1 --teeth 36 --diameter 36 --quality 8 --json");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const nlohmann::json j = nlohmann::json::parse(r.output);
  EXPECT_DOUBLE_EQ(j["single_flank_error_um"].get<double>(), 43.0);
  EXPECT_DOUBLE_EQ(j["iso1328"]["single_flank_error_um"].get<double>(), 44.0);
}

TEST(Cli, MissingSpecFileIsAUsageErrorNamingIt) {
  const CliRun r = gearsim("gears /nonexistent/spec.yaml");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("/nonexistent/spec.yaml"), std::string::npos) << r.output;
}

TEST(Cli, OpenMeshIsRefusedWithTheFirstOpenEdge) {
  // A tetrahedron missing one face, ASCII STL in mm.
  const std::filesystem::path p = std::filesystem::temp_directory_path() / "gearsim_cli_open.stl";
  std::ofstream(p) << "solid t\n"
                      "facet normal 0 0 -1\nouter loop\nvertex 0 0 0\nvertex 0 1 0\nvertex 1 0 0\nendloop\nendfacet\n"
                      "facet normal 0 -1 0\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 0 1\nendloop\nendfacet\n"
                      "facet normal -1 0 0\nouter loop\nvertex 0 0 0\nvertex 0 0 1\nvertex 0 1 0\nendloop\nendfacet\n"
                      "endsolid t\n";
  const CliRun r = gearsim("inspect " + p.string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("not watertight"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find(p.string()), std::string::npos) << r.output;
  std::filesystem::remove(p);
}

TEST(Cli, InspectOfTheCommittedRingFindsAnExactPrism) {
  const CliRun r = gearsim("inspect " + std::string(GEARSIM_SOURCE_DIR) + "/assets/gears/ring.stl --teeth 96 --json");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const nlohmann::json j = nlohmann::json::parse(r.output);
  EXPECT_TRUE(j["watertight"].get<bool>());
  EXPECT_TRUE(j["prismatic"].get<bool>());
  EXPECT_TRUE(j["tooth_sectors_exact"].get<bool>());
  // Through float32 STL (~3 nm at 55 mm), still far inside the 1 µm bound.
  EXPECT_LE(j["max_deviation_um"].get<double>(), 1.0);
}

}  // namespace test_cli

// `gearsim modes`: the JSON a script reads (natural_frequencies_hz sorted and repeated by
// multiplicity, rigid modes as 0; modes[] with frequency_hz, multiplicity, type), the files
// --out writes, and a bad --drive refused as bad input.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/support/asset_scenario.hpp"
#include "tests/support/cli_run.hpp"

namespace gearsim {
namespace test_modes_cli {

const std::string kLinParker = std::string(GEARSIM_SOURCE_DIR) + "/assets/scenarios/lin_parker_1999.yaml";

TEST(ModesCli, JsonListsEveryFrequencyByMultiplicityAndEachModeOnce) {
  const std::filesystem::path dir = test::fresh_test_dir();
  const test::CliRun r = test::gearsim("modes " + kLinParker + " --json --out " + dir.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::ifstream in(dir / "modes.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  const std::vector<double> f = j.at("natural_frequencies_hz").get<std::vector<double>>();
  ASSERT_EQ(f.size(), 18u);  // 3 coordinates × (sun, ring, carrier, 3 planets)
  EXPECT_TRUE(std::is_sorted(f.begin(), f.end()));
  EXPECT_EQ(f.front(), 0.0);  // the rigid-body mode
  std::size_t listed = 0;
  for (const nlohmann::json& m : j.at("modes")) {
    const int mult = m.at("multiplicity").get<int>();
    const double fm = m.at("frequency_hz").get<double>();
    // Each mode's frequency appears in the list exactly `multiplicity` times, in a row.
    EXPECT_EQ(std::count_if(f.begin(), f.end(), [&](double x) { return std::abs(x - fm) <= 1e-6 * (1 + fm); }), mult) << fm;
    EXPECT_EQ(m.at("shapes").size(), static_cast<std::size_t>(mult));
    const std::string type = m.at("type");
    EXPECT_TRUE(type == "rigid" || type == "rotational" || type == "translational") << type;
    listed += static_cast<std::size_t>(mult);
  }
  EXPECT_EQ(listed, f.size());
  for (const char* file : {"mode_shapes.csv", "campbell.csv", "modes.svg"})
    EXPECT_TRUE(std::filesystem::is_regular_file(dir / file)) << file;
}

TEST(ModesCli, ADriveThatIsNoBodyIsBadInput) {
  const test::CliRun r = test::gearsim("modes " + kLinParker + " --drive moon=ccw");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("no body named 'moon'"), std::string::npos) << r.output;
  const test::CliRun s = test::gearsim("modes " + kLinParker + " --drive sun=left");
  EXPECT_EQ(s.exit_code, 2) << s.output;
  EXPECT_NE(s.output.find("BODY=ccw or BODY=cw"), std::string::npos) << s.output;
}

}  // namespace test_modes_cli
}  // namespace gearsim

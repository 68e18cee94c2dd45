// `gearsim report DIR` on a sweep folder: the gathered table with every case, each metric
// plotted against mesh_frequency_hz with the lines f_m = f_n/k of modes.json inside the plotted
// range, and a hostile parameter value shown escaped, never as markup.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "sweep/case_record.hpp"
#include "sweep/sweep_dir.hpp"
#include "tests/support/asset_scenario.hpp"
#include "tests/support/cli_run.hpp"
#include "tests/sweep/sweep_cli.hpp"

namespace gearsim::sweep {
namespace test_sweep_report {

namespace fs = std::filesystem;

// A sweep folder written by hand: three completed cases at f_m = 100, 200, 300 Hz.
fs::path sweep_folder() {
  const fs::path dir = test::fresh_test_dir();
  std::ofstream(dir / "sweep.json") << R"({"name": "s", "content_hash": "0", "case_count": 3,
                                          "parameters": ["motors[0].target_speed_rad_s", "tag"]})";
  for (std::size_t i = 0; i < 3; ++i) {
    fs::create_directories(case_dir(dir, i));
    CaseRecord r;
    r.index = i;
    r.status = CaseStatus::Completed;
    r.parameters = {{"motors[0].target_speed_rad_s", std::to_string(10 * (i + 1))}, {"tag", "<script>x</script>"}};
    r.metrics = {{"dynamic_factor_band_limited", 1.1 + 0.1 * static_cast<double>(i)},
                 {"mesh_frequency_hz", 100.0 * static_cast<double>(i + 1)}};
    write_case_record(case_dir(dir, i), r);
  }
  // f_n = 400 Hz: f_n/2 = 200 and f_n/3 = 133.3 fall inside 100–300 Hz, f_n/1 does not.
  std::ofstream(dir / "modes.json") << R"({"natural_frequencies_hz": [400], "modes": [{"frequency_hz": 400,
                                           "multiplicity": 1, "type": "rotational"}]})";
  return dir;
}

TEST(SweepReport, TableAndModeLinesOnTheMeshFrequencyPlot) {
  const fs::path dir = sweep_folder();
  const test::CliRun r = test::gearsim("report " + dir.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::string html = test::file_text(dir / "report.html");
  EXPECT_NE(html.find("<h3>dynamic_factor_band_limited</h3>"), std::string::npos);
  EXPECT_NE(html.find("<svg"), std::string::npos);
  EXPECT_NE(html.find("400 Hz / 2"), std::string::npos);  // f_m = 200 Hz: the 2nd harmonic meets f_n
  EXPECT_NE(html.find("400 Hz / 3"), std::string::npos);
  EXPECT_EQ(html.find("400 Hz / 1"), std::string::npos);  // 400 Hz lies outside the swept 100–300 Hz
  EXPECT_EQ(html.find("<script>"), std::string::npos);
  EXPECT_NE(html.find("&lt;script&gt;"), std::string::npos);
  EXPECT_NE(html.find("3: 3 completed"), std::string::npos);
}

}  // namespace test_sweep_report
}  // namespace gearsim::sweep

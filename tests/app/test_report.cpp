// `gearsim report` on short paper runs: one self-contained HTML file with every section, plots
// drawn by gnuplot inline, the paper's figures beside ours, and no external resource.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace test_report {

namespace fs = std::filesystem;

fs::path run(const std::string& scenario, const std::string& tag) {
  const fs::path dir = fs::temp_directory_path() / ("gearsim_report_" + tag + "_" + std::to_string(getpid()));
  fs::remove_all(dir);
  const std::string cmd = std::string(GEARSIM_BINARY_DIR) + "/bin/gearsim run " + GEARSIM_SOURCE_DIR + "/assets/scenarios/" + scenario +
                          " --out " + dir.string() + " --duration 0.3 --set motors[0].ramp_time_s=0.004 --no-analyze > /dev/null 2>&1";
  EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
  return dir;
}

TEST(Report, HoldsEverySectionInOneSelfContainedFile) {
  const fs::path faulty = run("paper_dynamics.yaml", "faulty"), healthy = run("paper_dynamics_healthy.yaml", "healthy");
  // The compared folder is only read: its analysis is its own analyze's.
  ASSERT_EQ(std::system((std::string(GEARSIM_BINARY_DIR) + "/bin/gearsim analyze " + healthy.string() + " > /dev/null 2>&1").c_str()), 0);
  const std::string cmd =
      std::string(GEARSIM_BINARY_DIR) + "/bin/gearsim report " + faulty.string() + " --compare " + healthy.string() + " > /dev/null 2>&1";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
  std::ifstream f(faulty / "report.html");
  const std::string html((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  for (const char* section : {"The run", "The paper and this run", "Against the paper's Table 1", "Single flank error",
                              "Characteristic frequencies", "paper Fig. 4", "paper Fig. 5", "paper Fig. 6", "paper Fig. 7",
                              "Per-tooth load", "planet local-fault family", "Sampling: why the paper", "anti-aliased / point samples",
                              "Contact ringing above the band", "Rendered frames", "Housing sensors", "separated average (McFadden 1991)"})
    EXPECT_NE(html.find(section), std::string::npos) << "missing section: " << section;
  // Plots are gnuplot's SVG, inline: force (2), spectrum, three harmonic zooms, TE, teeth; the
  // housing sensor's signal and its three harmonic zooms.
  std::size_t svgs = 0;
  for (std::size_t at = html.find("<svg"); at != std::string::npos; at = html.find("<svg", at + 4)) ++svgs;
  EXPECT_EQ(svgs, 12u);
  // The diagnosis in one sentence: the cause, from the contact forces.
  EXPECT_NE(html.find("<b>Diagnosis:</b> planet_0 tooth 0 (ccw flank) from contact forces"), std::string::npos);
  EXPECT_NE(html.find("Gnuplot"), std::string::npos);
  // Opens offline: nothing fetched from elsewhere.
  EXPECT_EQ(html.find("src=\"http"), std::string::npos);
  EXPECT_EQ(html.find("href=\"http"), std::string::npos);
  // The paper's 43 µm comes out of the tolerance code, and this faulty run shows a fault line.
  EXPECT_NE(html.find("43 µm (DIN 3961 step 1.4)"), std::string::npos);
  EXPECT_NE(html.find("fault line f<sub>m</sub>/36: "), std::string::npos);
  EXPECT_EQ(html.find("fault line f<sub>m</sub>/36: no line"), std::string::npos);
  // The ringing of a sun–planet tooth pair, √(k/m)/2π with k = 1.4e8 N/m (1.4e10 N/m per m over
  // 10 mm) and the pair's reduced mass from summary.json: 16.35 kHz for the paper's gears.
  EXPECT_NE(html.find("<td>1.635e+04</td>"), std::string::npos);
}

}  // namespace test_report

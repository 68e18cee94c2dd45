// Names from input files are data: a scenario name built to close a gnuplot string and run a
// shell command goes through `gearsim run` and `gearsim report` (also as the --compare label)
// and runs nothing; gnuplot_string() keeps any text one literal, html_escape() covers & < > " '.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "app/gnuplot.hpp"
#include "app/html.hpp"
#include "tests/support/asset_scenario.hpp"
#include "tests/support/cli_run.hpp"

namespace gearsim::app {
namespace test_report_injection {

namespace fs = std::filesystem;
using test::fresh_test_dir;

TEST(ReportInjection, AScenarioNameRunsNoCommandThroughRunAndReport) {
  const fs::path dir = fresh_test_dir(), marker = dir / "owned";
  const std::string name = "x' ; system 'touch " + marker.string() + "' ; #";
  const fs::path scenario =
      test::asset_scenario_copy("paper_dynamics_healthy.yaml", dir, {{"name: paper_dynamics_healthy", "name: \"" + name + "\""}});
  const fs::path run = dir / "run";
  const test::CliRun r = test::gearsim("run " + scenario.string() + " --out " + run.string() +
                                       " --duration 0.3 --set motors[0].ramp_time_s=0.004 --no-analyze");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const test::CliRun rep = test::gearsim("report " + run.string() + " --compare " + run.string());
  ASSERT_EQ(rep.exit_code, 0) << rep.output;
  EXPECT_FALSE(fs::exists(marker)) << "gnuplot ran the command in the scenario's name";
  std::ifstream f(run / "report.html");
  const std::string html((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  EXPECT_NE(html.find("x&#39; ; system &#39;touch"), std::string::npos) << "the name is shown, escaped";
}

TEST(ReportInjection, GnuplotStringDoublesQuotesAndDropsLineBreaks) {
  EXPECT_EQ(gnuplot_string("sun__planet_0"), "'sun__planet_0'");
  EXPECT_EQ(gnuplot_string("it's"), "'it''s'");
  EXPECT_EQ(gnuplot_string("a\nb\rc\td"), "'a?b?c?d'");
  EXPECT_EQ(gnuplot_string("`x` @m \\"), "'`x` @m \\'");  // literal inside single quotes
}

TEST(ReportInjection, NoTitleTextRunsACommandInGnuplot) {
  const fs::path dir = fresh_test_dir();
  int k = 0;
  for (const std::string& attack : {std::string("x' ; system 'touch ") + (dir / "m0").string() + "' ; #",
                                    std::string("x\nsystem 'touch ") + (dir / "m1").string() + "'\n#",
                                    std::string("`touch ") + (dir / "m2").string() + "`", std::string("@m")}) {
    const std::string svg = gnuplot_svg(data_block("d", {{0, 1}, {0, 1}}) + "m = \"system('touch " + (dir / "m3").string() +
                                        "')\"\n"
                                        "plot $d using 1:2 with lines title " +
                                        gnuplot_string(attack) + "\n");
    EXPECT_NE(svg.find("<svg"), std::string::npos) << k;
    ++k;
  }
  for (const char* m : {"m0", "m1", "m2", "m3"}) EXPECT_FALSE(fs::exists(dir / m)) << m;
}

TEST(ReportInjection, HtmlEscapeCoversTheFiveSpecialCharacters) {
  EXPECT_EQ(html_escape("a & b < c > d \" e ' f"), "a &amp; b &lt; c &gt; d &quot; e &#39; f");
}

}  // namespace test_report_injection
}  // namespace gearsim::app

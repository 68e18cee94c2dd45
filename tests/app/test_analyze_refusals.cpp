// `gearsim analyze` and `gearsim report` on run folders that do not hold enough to analyse: a
// state.csv with no rows after the motors' ramp while contacts.csv has them, a contacts.csv
// without the force column of a pair the summary names, or a summary without its gear pairs.
// Each is refused with exit code 2 and a message naming the file — never a crash. The folders
// are made by hand: a summary.json, the paper scenario's record, and logs at its 2 kHz output
// rate. And a run folder reads its own scenario record, not the original file: editing or
// deleting that after the run changes nothing.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <algorithm>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "input/scenario_file.hpp"
#include "input/scenario_record.hpp"
#include "tests/support/asset_scenario.hpp"
#include "tests/support/cli_run.hpp"

namespace test_analyze_refusals {

namespace fs = std::filesystem;

// The paper set's six meshes, as gearsim run lists them in summary.json's gear_pairs.
const std::vector<std::pair<std::string, std::string>> kPaperPairs = {{"sun", "planet_0"},  {"sun", "planet_1"},  {"sun", "planet_2"},
                                                                      {"planet_0", "ring"}, {"planet_1", "ring"}, {"planet_2", "ring"}};

std::string paper_gear_pairs() {
  std::string list;
  for (const auto& [a, b] : kPaperPairs) list += (list.empty() ? "" : ", ") + std::string("{\"a\": \"") + a + "\", \"b\": \"" + b + "\"}";
  return ", \"gear_pairs\": [" + list + "]";
}

// contacts.csv's header with the three columns gearsim run writes per pair, sun–planet_0 first.
std::string paper_contacts_header() {
  std::string h = "time_s";
  for (const auto& [a, b] : kPaperPairs)
    h += "," + a + "__" + b + "_force_N," + a + "__" + b + "_tooth_pairs," + a + "__" + b + "_max_depth_um";
  return h;
}

// A run folder of paper_dynamics_healthy.yaml (ramps end at 0.05 s): a summary naming its six gear
// pairs (`gear_pairs` as gearsim run writes it, unless told otherwise), contacts.csv with
// `contacts_header` and rows every 0.5 ms to 0.3 s (118 N, 1 tooth pair, 0.9 µm in each pair's
// columns), state.csv (time_s, te_rad) up to `state_to_s`.
fs::path hand_made_run(const std::string& contacts_header, double state_to_s, const std::string& gear_pairs = paper_gear_pairs()) {
  const fs::path dir = gearsim::test::fresh_test_dir();
  // The record's required keys as gearsim run writes them (input/run_record_check.hpp checks them first).
  std::ofstream(dir / "summary.json") << "{\"status\": \"completed\", \"sim_seconds\": 0.3, \"time_step_s\": 2e-5, "
                                         "\"steps\": 15000"
                                      << gear_pairs << "}\n";
  gearsim::input::write_scenario_record(
      gearsim::input::load_scenario(fs::path(GEARSIM_SOURCE_DIR) / "assets/scenarios/paper_dynamics_healthy.yaml"), dir);
  std::ofstream contacts(dir / "contacts.csv"), state(dir / "state.csv");
  contacts << contacts_header << "\n";
  state << "time_s,te_rad\n";
  const auto columns = std::count(contacts_header.begin(), contacts_header.end(), ',');
  for (int k = 1; k <= 600; ++k) {
    const double t = 0.0005 * k;
    contacts << t;
    for (long c = 0; c < columns; ++c) contacts << (c % 3 == 0 ? ",118.0" : c % 3 == 1 ? ",1" : ",0.9");
    contacts << "\n";
    if (t <= state_to_s) state << t << ",1e-5\n";
  }
  return dir;
}

void expect_refused(const fs::path& dir, const std::string& file, const std::string& why) {
  for (const char* cmd : {"analyze ", "report "}) {
    const gearsim::test::CliRun r = gearsim::test::gearsim(cmd + dir.string());
    EXPECT_EQ(r.exit_code, 2) << cmd << r.output;
    EXPECT_NE(r.output.find((dir / file).string() + ": "), std::string::npos) << cmd << r.output;
    EXPECT_NE(r.output.find(why), std::string::npos) << cmd << r.output;
  }
  EXPECT_FALSE(fs::exists(dir / "report.html"));
}

TEST(AnalyzeRefusals, StateWithoutRowsAfterTheRampIsRefusedNotACrash) {
  const fs::path dir = hand_made_run(paper_contacts_header(), 0.04);
  expect_refused(dir, "state.csv", "only 0 rows after t = 0.05");
}

TEST(AnalyzeRefusals, StateWithTooFewRowsAfterTheRampIsRefused) {
  const fs::path dir = hand_made_run(paper_contacts_header(), 0.06);
  expect_refused(dir, "state.csv", "at least 64 are needed");
}

TEST(AnalyzeRefusals, ContactsWithoutAForceColumnIsRefused) {
  const fs::path dir = hand_made_run("time_s,a,b,c", 0.3);
  expect_refused(dir, "contacts.csv", "no <pair>_force_N column");
}

// A value that is not a number in a log the analysis reads: refused naming the file, the column
// and the row, not deep inside the spectra.
void replace_in_row(const fs::path& file, int data_row, const std::string& value, int column) {
  std::ifstream in(file);
  std::string line, out;
  for (int row = 0; std::getline(in, line); ++row) {
    if (row == data_row) {
      std::size_t start = 0;
      for (int c = 0; c < column; ++c) start = line.find(',', start) + 1;
      const std::size_t end = line.find(',', start);
      line = line.substr(0, start) + value + (end == std::string::npos ? "" : line.substr(end));
    }
    out += line + "\n";
  }
  std::ofstream(file) << out;
}

TEST(AnalyzeRefusals, ANonFiniteForceOrTransmissionErrorIsRefusedWithItsPlace) {
  const std::string header = paper_contacts_header();
  const fs::path force = hand_made_run(header, 0.3);
  replace_in_row(force / "contacts.csv", 300, "nan", 1);
  expect_refused(force, "contacts.csv", "column sun__planet_0_force_N, data row 300: expected a finite force in N");
  const fs::path te = hand_made_run(header, 0.3);
  replace_in_row(te / "state.csv", 300, "inf", 1);
  expect_refused(te, "state.csv", "column te_rad");
}

TEST(AnalyzeRefusals, ASummaryWithoutGearPairsIsRefused) {
  // The pairs come from the summary, never from the column names.
  const std::string header = paper_contacts_header();
  expect_refused(hand_made_run(header, 0.3, ""), "summary.json", "gear_pairs: missing");
  // Checked when the record is read (input/run_record_check.hpp), before the analysis looks at it.
  expect_refused(hand_made_run(header, 0.3, R"(, "gear_pairs": [{"a": "sun"}])"), "summary.json", "key gear_pairs[0].b: missing");
}

TEST(AnalyzeRefusals, ARunReadsItsOwnScenarioRecordNotTheEditedOriginal) {
  const fs::path dir = gearsim::test::fresh_test_dir();
  const fs::path scenario = gearsim::test::asset_scenario_copy("paper_dynamics_healthy.yaml", dir, {});
  const gearsim::test::CliRun run =
      gearsim::test::gearsim("run " + scenario.string() + " --out " + (dir / "run").string() + " --duration 0.4 --no-analyze");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const auto analysis = [&] {
    std::ifstream in(dir / "run" / "analysis.json");
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  ASSERT_EQ(gearsim::test::gearsim("analyze " + (dir / "run").string()).exit_code, 0);
  const std::string before = analysis();
  std::ofstream(scenario) << "name: [this is no longer a scenario\n";  // the original, edited
  const gearsim::test::CliRun again = gearsim::test::gearsim("analyze " + (dir / "run").string());
  EXPECT_EQ(again.exit_code, 0) << again.output;
  EXPECT_EQ(analysis(), before);
  fs::remove(scenario);
  EXPECT_EQ(gearsim::test::gearsim("analyze " + (dir / "run").string()).exit_code, 0);
  EXPECT_EQ(analysis(), before);
}

TEST(AnalyzeRefusals, TheWindowLeavesOutTheAntiAliasedForcesEdgeHeldEnds) {
  // contacts.csv's force is filtered with a 4009-tap zero-phase filter at 50 kHz → 2 kHz: its
  // first and last 40.08 ms hold the end values (summary.json force_filter.edge_held_s).
  const fs::path dir = gearsim::test::fresh_test_dir();
  const fs::path scenario = gearsim::test::asset_scenario_copy("paper_dynamics_healthy.yaml", dir, {});
  ASSERT_EQ(gearsim::test::gearsim("run " + scenario.string() + " --out " + (dir / "run").string() + " --duration 0.4").exit_code, 0);
  std::ifstream in(dir / "run" / "analysis.json");
  const nlohmann::json a = nlohmann::json::parse(in);
  std::ifstream sin(dir / "run" / "summary.json");
  const double edge = nlohmann::json::parse(sin)["force_filter"]["edge_held_s"].get<double>();
  EXPECT_NEAR(edge, 2004 / 50000.0, 1e-12);
  const double end = a["window_s"][1].get<double>();
  EXPECT_LE(end, 0.4 - edge);
  EXPECT_GT(end, 0.4 - edge - 0.0005);  // the last sample before the held end
  const gearsim::test::CliRun early = gearsim::test::gearsim("analyze " + (dir / "run").string() + " --from 0.01");
  EXPECT_EQ(early.exit_code, 2) << early.output;
  EXPECT_NE(early.output.find("holds its start value until t = 0.04008"), std::string::npos) << early.output;
}

}  // namespace test_analyze_refusals

// The gathered table comes only from the cases' case.json files, in index order: parameters as
// their texts, status, metrics as %.17g (reading back to the same double), empty where a case has
// none, "not run" for a case without a record; a case.json of another case is refused.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/errors.hpp"
#include "sweep/case_record.hpp"
#include "sweep/sweep_dir.hpp"
#include "sweep/table.hpp"
#include "tests/support/asset_scenario.hpp"

namespace gearsim::sweep {
namespace test_table {

namespace fs = std::filesystem;

void record(const fs::path& dir, std::size_t i, CaseStatus s, nlohmann::ordered_json metrics) {
  fs::create_directories(case_dir(dir, i));
  CaseRecord r;
  r.index = i;
  r.parameters = {{"a", std::to_string(i)}};
  r.status = s;
  r.metrics = std::move(metrics);
  write_case_record(case_dir(dir, i), r);
}

std::string text(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(Table, RowsInIndexOrderFromTheRecords) {
  const fs::path dir = test::fresh_test_dir();
  record(dir, 2, CaseStatus::Completed, {{"m_N", 0.1}, {"k", 3}});
  record(dir, 0, CaseStatus::Diverged, nlohmann::ordered_json::object());
  const SweepTable t = gather_table(dir, {"a"}, 4);
  write_table_csv(t, dir / "sweep.csv");
  EXPECT_EQ(text(dir / "sweep.csv"),
            "index,a,status,m_N,k\n"
            "0,0,diverged,,\n"
            "1,,not run,,\n"
            "2,2,completed,0.10000000000000001,3\n"
            "3,,not run,,\n");
  const StatusCounts c = count_statuses(t);
  EXPECT_EQ(c.completed, 1u);
  EXPECT_EQ(c.diverged, 1u);
  EXPECT_EQ(c.not_run, 2u);
}

TEST(Table, MetricTextReadsBackExactly) {
  for (const double v : {0.1, 1.0 / 3.0, 6.02214076e23, -1e-300}) EXPECT_EQ(std::stod(metric_text(v)), v) << metric_text(v);
  EXPECT_EQ(metric_text(std::nullopt), "");
}

TEST(Table, RecordOfAnotherCaseRefused) {
  const fs::path dir = test::fresh_test_dir();
  record(dir, 1, CaseStatus::Completed, nlohmann::ordered_json::object());
  fs::create_directories(case_dir(dir, 0));
  fs::copy_file(case_dir(dir, 1) / "case.json", case_dir(dir, 0) / "case.json");
  EXPECT_THROW(gather_table(dir, {"a"}, 2), InputError);
}

TEST(Table, HdfFileIsWrittenTheSameTwice) {
  // No timestamps in the file: the same table gives the same bytes.
  const fs::path dir = test::fresh_test_dir();
  record(dir, 0, CaseStatus::Completed, {{"m_N", 1.5}});
  const SweepTable t = gather_table(dir, {"a"}, 1);
  write_table_h5(t, dir / "a.h5");
  write_table_h5(t, dir / "b.h5");
  EXPECT_GT(fs::file_size(dir / "a.h5"), 0u);
  EXPECT_EQ(text(dir / "a.h5"), text(dir / "b.h5"));
}

}  // namespace test_table
}  // namespace gearsim::sweep

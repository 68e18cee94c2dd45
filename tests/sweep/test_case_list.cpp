// A grid expands to the cartesian product in index order (first key slowest), every case's
// overrides the sweep's `set:` first, then its own; a case list keeps its cases and leaves the
// keys a case does not set at the scenario's value; the validation loads the cases it promises.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "input/sweep_file.hpp"
#include "sweep/case_list.hpp"
#include "sweep/validate.hpp"
#include "tests/support/asset_scenario.hpp"

namespace gearsim::sweep {
namespace test_case_list {

namespace fs = std::filesystem;
using KeyValue = std::pair<std::string, std::string>;

input::SweepFile load(const std::string& body) {
  const fs::path p = test::fresh_test_dir() / "s.yaml";
  std::ofstream(p) << "name: t\nscenario: " << GEARSIM_SOURCE_DIR << "/assets/scenarios/spur_pair.yaml\n" << body;
  return input::load_sweep_file(p);
}

TEST(CaseList, GridIsTheProductFirstKeySlowest) {
  const std::vector<Case> cases = expand_cases(load("set: [duration_s=0.2]\ngrid:\n  a: [1, 2, 3]\n  b: [x, y]\n"));
  ASSERT_EQ(cases.size(), 6u);
  const char* expected[6][2] = {{"1", "x"}, {"1", "y"}, {"2", "x"}, {"2", "y"}, {"3", "x"}, {"3", "y"}};
  for (std::size_t i = 0; i < 6; ++i) {
    EXPECT_EQ(cases[i].index, i);
    EXPECT_EQ(cases[i].parameters[0], KeyValue("a", expected[i][0])) << i;
    EXPECT_EQ(cases[i].parameters[1], KeyValue("b", expected[i][1])) << i;
    EXPECT_EQ(cases[i].overrides,
              (std::vector<std::string>{"duration_s=0.2", std::string("a=") + expected[i][0], std::string("b=") + expected[i][1]}));
  }
}

TEST(CaseList, ThreeAxesCountAndLastCase) {
  const std::vector<Case> cases = expand_cases(load("grid:\n  a: {from: 0, to: 1, steps: 5}\n  b: [1, 2, 3]\n  c: [7, 8]\n"));
  ASSERT_EQ(cases.size(), 30u);
  EXPECT_EQ(cases[29].overrides, (std::vector<std::string>{"a=1", "b=3", "c=8"}));
  EXPECT_EQ(cases[7].overrides, (std::vector<std::string>{"a=0.25", "b=1", "c=8"}));  // 7 = 1·6 + 0·2 + 1
}

TEST(CaseList, ListedCasesLeaveUnsetKeysEmpty) {
  const std::vector<Case> cases = expand_cases(load("cases:\n  - {a: 1}\n  - {b: 2}\n"));
  ASSERT_EQ(cases.size(), 2u);
  EXPECT_EQ(cases[0].parameters[1], KeyValue("b", ""));
  EXPECT_EQ(cases[0].overrides, std::vector<std::string>{"a=1"});
  EXPECT_EQ(cases[1].overrides, std::vector<std::string>{"b=2"});
}

TEST(CaseList, FolderNamesArePaddedToSortInIndexOrder) {
  EXPECT_EQ(case_folder_name(7), "00007");
  EXPECT_EQ(case_folder_name(99999), "99999");
}

TEST(Validate, SmallAxesLoadEveryValueOnce) {
  const input::SweepFile f = load("grid:\n  a: [1, 2, 3]\n  b: [x, y]\n");
  // Case 0 (a=1, b=x), the first cases of a=2 (2) and a=3 (4), of b=y (1).
  EXPECT_EQ(cases_to_validate(f, expand_cases(f)), (std::vector<std::size_t>{0, 1, 2, 4}));
}

TEST(Validate, LongAxesLoadTheirExtremes) {
  // 40 values of a (more than kMaxValuesLoaded): its first, smallest, largest and last cases.
  const input::SweepFile f = load("grid:\n  a: {from: 5, to: -5, steps: 40}\n");
  EXPECT_EQ(cases_to_validate(f, expand_cases(f)), (std::vector<std::size_t>{0, 39}));
}

}  // namespace test_case_list
}  // namespace gearsim::sweep

// Tooth contact stiffness from a table (contact/stiffness_table.hpp): linear interpolation between
// rows, the end row outside the range (and the caller told), and malformed tables refused by row.
// The same tables in the Bullet world: tests/physics/test_stiffness_table_world.cpp.
#include <gtest/gtest.h>

#include <string>

#include "contact/stiffness_table.hpp"

namespace gearsim::contact {
namespace test_stiffness_table {

TEST(StiffnessTable, InterpolatesLinearlyBetweenRows) {
  const StiffnessTable t{"t", {0.011, 0.012, 0.013}, {1e10, 2e10, 4e10}};
  bool outside = true;
  EXPECT_DOUBLE_EQ(stiffness_at(t, 0.0115, &outside), 1.5e10);
  EXPECT_FALSE(outside);
  EXPECT_DOUBLE_EQ(stiffness_at(t, 0.01275, &outside), 3.5e10);
  EXPECT_DOUBLE_EQ(stiffness_at(t, 0.013, &outside), 4e10);
  EXPECT_FALSE(outside);
}

TEST(StiffnessTable, OutsideTheRangeTakesTheEndRowAndSaysSo) {
  const StiffnessTable t{"t", {0.011, 0.013}, {1e10, 3e10}};
  bool outside = false;
  EXPECT_DOUBLE_EQ(stiffness_at(t, 0.0135, &outside), 3e10);
  EXPECT_TRUE(outside);
  EXPECT_DOUBLE_EQ(stiffness_at(t, 0.010, &outside), 1e10);
  EXPECT_TRUE(outside);
}

TEST(StiffnessTable, ProblemsNameTheRow) {
  int row = -1;
  EXPECT_NE(stiffness_table_problem({"t", {0.011, 0.013, 0.012}, {1, 1, 1}}, &row).find("increase"), std::string::npos);
  EXPECT_EQ(row, 2);
  EXPECT_NE(stiffness_table_problem({"t", {0.011, 0.013}, {1, 0}}, &row).find("not positive"), std::string::npos);
  EXPECT_EQ(row, 1);
  EXPECT_EQ(stiffness_table_problem({"t", {0.011, 0.013}, {1, 2}}, &row), "");
}

}  // namespace test_stiffness_table
}  // namespace gearsim::contact

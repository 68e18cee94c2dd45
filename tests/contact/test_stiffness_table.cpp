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
  EXPECT_DOUBLE_EQ(stiffness_at(t, 0.0115).stiffness_N_per_m_per_m, 1.5e10);
  EXPECT_FALSE(stiffness_at(t, 0.0115).outside);
  EXPECT_DOUBLE_EQ(stiffness_at(t, 0.01275).stiffness_N_per_m_per_m, 3.5e10);
  EXPECT_DOUBLE_EQ(stiffness_at(t, 0.013).stiffness_N_per_m_per_m, 4e10);
  EXPECT_FALSE(stiffness_at(t, 0.013).outside);
}

TEST(StiffnessTable, OutsideTheRangeTakesTheEndRowAndSaysSo) {
  const StiffnessTable t{"t", {0.011, 0.013}, {1e10, 3e10}};
  EXPECT_DOUBLE_EQ(stiffness_at(t, 0.0135).stiffness_N_per_m_per_m, 3e10);
  EXPECT_TRUE(stiffness_at(t, 0.0135).outside);
  EXPECT_DOUBLE_EQ(stiffness_at(t, 0.010).stiffness_N_per_m_per_m, 1e10);
  EXPECT_TRUE(stiffness_at(t, 0.010).outside);
}

TEST(StiffnessTable, ProblemsNameTheRow) {
  const Check unsorted = check_stiffness_table({"t", {0.011, 0.013, 0.012}, {1, 1, 1}});
  ASSERT_FALSE(unsorted);
  EXPECT_NE(unsorted.reason().find("increase"), std::string::npos);
  EXPECT_EQ(unsorted.refusal().index, 2);
  const Check zero = check_stiffness_table({"t", {0.011, 0.013}, {1, 0}});
  ASSERT_FALSE(zero);
  EXPECT_NE(zero.reason().find("not positive"), std::string::npos);
  EXPECT_EQ(zero.refusal().index, 1);
  EXPECT_TRUE(check_stiffness_table({"t", {0.011, 0.013}, {1, 2}}));
  const Check short_table = check_stiffness_table({"t", {0.011}, {1}});
  ASSERT_FALSE(short_table);
  EXPECT_EQ(short_table.refusal().index, -1);  // not one row's fault
}

}  // namespace test_stiffness_table
}  // namespace gearsim::contact

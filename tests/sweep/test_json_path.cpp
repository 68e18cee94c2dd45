// Key paths into summary.json and analysis.json: dotted keys, list items, and keys that hold dots
// themselves (a body named "gear.a") resolved by the longest matching key.
#include <gtest/gtest.h>

#include "core/errors.hpp"
#include "sweep/json_path.hpp"

namespace gearsim::sweep {
namespace test_json_path {

using json = nlohmann::ordered_json;

const json kDoc = json::parse(R"({"bodies": {"gear": {"x": 1}, "gear.a": {"mean_speed_rad_s": 2.5}},
                                  "gear_pairs": [{"a": "p"}, {"mean_N": {"ccw": 7}}], "name": "s", "none": null})");

TEST(JsonPath, DottedKeysAndListItems) {
  EXPECT_EQ(number_at_path(kDoc, "gear_pairs[1].mean_N.ccw", "f"), json(7));
  EXPECT_EQ(number_at_path(kDoc, "bodies.gear.x", "f"), json(1));
}

TEST(JsonPath, KeyHoldingADotWinsByLength) { EXPECT_EQ(number_at_path(kDoc, "bodies.gear.a.mean_speed_rad_s", "f"), json(2.5)); }

TEST(JsonPath, NullStaysNull) { EXPECT_TRUE(number_at_path(kDoc, "none", "f").is_null()); }

TEST(JsonPath, MissingOrTextRefusedNamingFileAndKey) {
  EXPECT_EQ(find_json_path(kDoc, "gear_pairs[2]"), nullptr);
  EXPECT_EQ(find_json_path(kDoc, "bodies.gearx"), nullptr);
  try {
    number_at_path(kDoc, "name", "summary.json");
    FAIL() << "text taken for a number";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "summary.json: key name: expected a number, got string");
  }
}

}  // namespace test_json_path
}  // namespace gearsim::sweep

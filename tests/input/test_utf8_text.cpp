// UTF-8 checks of input text (input/utf8_text.hpp): RFC 3629's sequences pass, every other byte
// sequence is found at its first byte, and messages quote invalid bytes as \xHH.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/errors.hpp"
#include "input/scenario_file.hpp"
#include "input/utf8_text.hpp"
#include "input/yaml_reader.hpp"

namespace gearsim::input {
namespace test_utf8_text {

TEST(Utf8Text, ValidSequencesOfOneToFourBytesPass) {
  EXPECT_TRUE(is_utf8(""));
  EXPECT_TRUE(is_utf8("sun_planet 0"));
  EXPECT_TRUE(is_utf8("r\xc3\xa9sum\xc3\xa9 \xe2\x82\xac \xf0\x9d\x84\x9e"));  // é, €, U+1D11E
  EXPECT_TRUE(is_utf8("\xf4\x8f\xbf\xbf"));  // U+10FFFF, the last code point
}

TEST(Utf8Text, InvalidSequencesAreFoundAtTheirFirstByte) {
  EXPECT_EQ(invalid_utf8_at("ab\xff"), 2u);  // never in UTF-8
  EXPECT_EQ(invalid_utf8_at("a\x80"), 1u);  // a continuation byte alone
  EXPECT_EQ(invalid_utf8_at("a\xe2\x82"), 1u);  // a truncated sequence
  EXPECT_EQ(invalid_utf8_at("\xc0\xaf"), 0u);  // overlong '/'
  EXPECT_EQ(invalid_utf8_at("x\xe0\x80\xaf"), 1u);  // overlong, three bytes
  EXPECT_EQ(invalid_utf8_at("\xed\xa0\x80"), 0u);  // a surrogate (U+D800)
  EXPECT_EQ(invalid_utf8_at("\xf4\x90\x80\x80"), 0u);  // past U+10FFFF
  EXPECT_EQ(invalid_utf8_at("gear\xe9"), 4u);  // Latin-1 é
}

TEST(Utf8Text, MessagesQuoteInvalidBytesAsHex) { EXPECT_EQ(escaped_bytes("gear\xe9 \xc3\xa9"), "gear\\xE9 \xc3\xa9"); }

TEST(Utf8Text, TheFirstKeyOrValueThatIsNotUtf8IsNamedWithItsLine) {
  const YAML::Node root = parse_yaml_mapping("name: ok\nbodies:\n  - {name: \"w\xff\"}\n", "f.yaml");
  try {
    require_utf8_tree(root, "f.yaml");
    ADD_FAILURE() << "invalid UTF-8 accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "f.yaml:3:12: bodies[0].name: expected UTF-8 text, got 'w\\xFF' (invalid byte 0xFF at byte 2)");
  }
  const YAML::Node key = parse_yaml_mapping("name: ok\nbodies:\n  - {\"k\xfe\": 1}\n", "f.yaml");
  try {
    require_utf8_tree(key, "f.yaml");
    ADD_FAILURE() << "an invalid key accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("f.yaml:3:6: bodies[0]: expected UTF-8 text, got 'k\\xFE'"), std::string::npos) << e.what();
  }
}

TEST(Utf8Text, AnOverrideThatIsNotUtf8IsRefusedBeforeItIsApplied) {
  // A YAML comment drops the bytes from the tree, but summary.json records the override whole.
  const std::filesystem::path p = std::filesystem::temp_directory_path() / "gearsim_utf8_override.yaml";
  std::ofstream(p) << "name: t\nduration_s: 0.1\n";
  try {
    load_scenario(p, {"name=t # \xff"});
    ADD_FAILURE() << "an override with invalid UTF-8 accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("gearsim_utf8_override.yaml: --set 'name=t # \\xFF': expected UTF-8 text"), std::string::npos)
        << e.what();
  }
  std::filesystem::remove(p);
}

}  // namespace test_utf8_text
}  // namespace gearsim::input

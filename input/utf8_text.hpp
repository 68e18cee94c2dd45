// Text read from input files must be UTF-8: the records a run writes are JSON, which holds nothing
// else (nlohmann's writer throws at the first invalid byte, leaving scenario.json empty). The keys and
// values of a scenario, gear-set or sweep file are checked once, when it is read, naming
// file:line:col and key. Not a normaliser: valid text is kept byte for byte.
#pragma once

#include <yaml-cpp/yaml.h>

#include <cstddef>
#include <string>
#include <string_view>

namespace gearsim::input {

// The byte offset of the first invalid UTF-8 sequence in `text` (a stray continuation byte, a
// truncated sequence, an overlong form, a surrogate, a code point past U+10FFFF), or npos.
std::size_t invalid_utf8_at(std::string_view text);
inline bool is_utf8(std::string_view text) { return invalid_utf8_at(text) == std::string_view::npos; }

// `text` as a message may quote it: each byte of an invalid sequence as \xHH, the rest as it is.
std::string escaped_bytes(std::string_view text);

// InputError "source:line:col: key.path: expected UTF-8 text, got 'ab\xFF' (invalid byte 0xFF at
// byte 3)" for the first key or scalar value under `root` that is not UTF-8.
void require_utf8_tree(const YAML::Node& root, const std::string& source_name);

}  // namespace gearsim::input

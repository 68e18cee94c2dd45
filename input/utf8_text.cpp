#include "input/utf8_text.hpp"

#include <cstdio>

#include "core/errors.hpp"

namespace gearsim::input {
namespace {

// Length of the valid UTF-8 sequence starting at text[i], or 0 when it is invalid (RFC 3629:
// the second byte's range excludes overlong forms, surrogates and code points past U+10FFFF).
std::size_t sequence_length(std::string_view text, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char b0 = byte(i);
  if (b0 < 0x80) return 1;
  std::size_t n = 0;
  unsigned char lo = 0x80, hi = 0xBF;  // the allowed range of the second byte
  if (b0 >= 0xC2 && b0 <= 0xDF) {
    n = 2;
  } else if (b0 >= 0xE0 && b0 <= 0xEF) {
    n = 3;
    lo = b0 == 0xE0 ? 0xA0 : 0x80;  // no overlong forms
    hi = b0 == 0xED ? 0x9F : 0xBF;  // no surrogates
  } else if (b0 >= 0xF0 && b0 <= 0xF4) {
    n = 4;
    lo = b0 == 0xF0 ? 0x90 : 0x80;  // no overlong forms
    hi = b0 == 0xF4 ? 0x8F : 0xBF;  // nothing past U+10FFFF
  } else {
    return 0;
  }
  if (i + n > text.size()) return 0;
  if (byte(i + 1) < lo || byte(i + 1) > hi) return 0;
  for (std::size_t k = 2; k < n; ++k)
    if (byte(i + k) < 0x80 || byte(i + k) > 0xBF) return 0;
  return n;
}

std::string hex_byte(unsigned char b) {
  char buf[8];
  std::snprintf(buf, sizeof buf, "\\x%02X", b);
  return buf;
}

class Utf8Check {
 public:
  explicit Utf8Check(const std::string& source) : source_(source) {}

  void walk(const YAML::Node& node, const std::string& path) const {
    if (node.IsScalar()) check(node, node.Scalar(), path);
    if (node.IsSequence())
      for (std::size_t i = 0; i < node.size(); ++i) walk(node[i], path + "[" + std::to_string(i) + "]");
    if (!node.IsMap()) return;
    for (const auto& kv : node) {
      const std::string key = kv.first.IsScalar() ? kv.first.Scalar() : "";
      check(kv.first, key, path);  // the key itself, named by its mapping's path
      walk(kv.second, path.empty() ? key : path + "." + key);
    }
  }

 private:
  void check(const YAML::Node& node, const std::string& text, const std::string& path) const {
    const std::size_t at = invalid_utf8_at(text);
    if (at == std::string::npos) return;
    const YAML::Mark m = node.Mark();
    const std::string file = escaped_bytes(source_);
    const std::string where = m.line < 0 ? file : file + ":" + std::to_string(m.line + 1) + ":" + std::to_string(m.column + 1);
    throw InputError(where + ": " + (path.empty() ? "" : escaped_bytes(path) + ": ") + "expected UTF-8 text, got '" +
                     escaped_bytes(text.substr(0, 80)) + (text.size() > 80 ? "…" : "") + "' (invalid byte 0x" +
                     hex_byte(static_cast<unsigned char>(text[at])).substr(2) + " at byte " + std::to_string(at + 1) + ")");
  }
  const std::string& source_;
};

}  // namespace

std::size_t invalid_utf8_at(std::string_view text) {
  for (std::size_t i = 0; i < text.size();) {
    const std::size_t n = sequence_length(text, i);
    if (n == 0) return i;
    i += n;
  }
  return std::string_view::npos;
}

std::string escaped_bytes(std::string_view text) {
  std::string out;
  for (std::size_t i = 0; i < text.size();) {
    const std::size_t n = sequence_length(text, i);
    if (n == 0) {
      out += hex_byte(static_cast<unsigned char>(text[i++]));
    } else {
      out.append(text.substr(i, n));
      i += n;
    }
  }
  return out;
}

void require_utf8_tree(const YAML::Node& root, const std::string& source_name) { Utf8Check(source_name).walk(root, ""); }

}  // namespace gearsim::input

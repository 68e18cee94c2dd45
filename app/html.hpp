// Small pieces of a self-contained HTML report: escaping, headings, tables, embedded images.
// Not a template engine.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace gearsim::app {

// Text as HTML: & < > " ' replaced by their entities (safe in element content and in quoted
// attribute values). Every name or value from an input file passes through it.
std::string html_escape(const std::string& s);
// A table: header cells, then rows of already-escaped (or plain) cell text.
std::string html_table(const std::vector<std::string>& header, const std::vector<std::vector<std::string>>& rows);
// A PNG file embedded as a data: URI image (base64). InputError when it cannot be read.
std::string html_png(const std::filesystem::path& png, const std::string& alt, int width_px);
// A number with `digits` significant digits.
std::string num(double v, int digits = 4);
// The whole document around `body`.
std::string html_document(const std::string& title, const std::string& body);

}  // namespace gearsim::app

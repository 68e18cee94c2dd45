// Numbers as CSV text, fast: the exact characters an iostream with std::setprecision(17) writes
// (printf's "%.17g": enough digits to read every double back bit for bit; "nan", "inf" as printf
// spells them), and integers in decimal — through std::to_chars, without an iostream's locale
// and formatting state for every number. The logs write one row per output sample this way
// (sim/csv_logs.cpp, sim/sensor_log.cpp).
#pragma once

#include <charconv>
#include <string>
#include <system_error>

namespace gearsim {

inline void append_number(std::string& out, double v) {
  char buf[40];
  const std::to_chars_result r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::general, 17);
  out.append(buf, static_cast<std::size_t>(r.ptr - buf));
}

inline void append_number(std::string& out, long long v) {
  char buf[24];
  const std::to_chars_result r = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, static_cast<std::size_t>(r.ptr - buf));
}

}  // namespace gearsim

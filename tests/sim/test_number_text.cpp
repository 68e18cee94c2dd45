// The CSV logs' number text (core/number_text.hpp, used by sim/csv_logs.cpp and
// sim/sensor_log.cpp) is character for character what an iostream with setprecision(17) writes,
// which the logs were written with before: the same bytes in every log, and every double read
// back bit for bit.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <cstdint>
#include <cstring>
#include <iomanip>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "core/number_text.hpp"

namespace test_number_text {

std::string via_stream(double v) {
  std::ostringstream s;
  s << std::setprecision(17) << v;
  return s.str();
}

TEST(NumberText, DoublesAreWhatAnIostreamWithPrecision17Writes) {
  std::vector<double> values = {0.0,
                                -0.0,
                                1.0,
                                -1.0,
                                0.1,
                                1.0 / 3,
                                2.0 / 3,
                                1e-300,
                                4.9406564584124654e-324,
                                2.2250738585072014e-308,
                                1e300,
                                1.7976931348623157e308,
                                123456789012345678.0,
                                1e17,
                                1e16,
                                9.999999999999999e16,
                                0.5e-5,
                                4.0000000000000003e-05,
                                104.7,
                                -118.78,
                                std::numeric_limits<double>::infinity(),
                                -std::numeric_limits<double>::infinity(),
                                std::numeric_limits<double>::quiet_NaN()};
  std::mt19937_64 rng(36);
  for (int i = 0; i < 200000; ++i) {  // every bit pattern: subnormals, huge, tiny, NaNs with payloads
    const std::uint64_t bits = rng();
    double v;
    std::memcpy(&v, &bits, sizeof v);
    values.push_back(v);
  }
  std::uniform_real_distribution<double> log_scale(-12, 6);
  for (int i = 0; i < 100000; ++i) values.push_back((i % 2 ? -1 : 1) * std::pow(10.0, log_scale(rng)));  // the logs' own range
  long differ = 0;
  std::string first;
  for (const double v : values) {
    std::string text;
    gearsim::append_number(text, v);
    if (text != via_stream(v) && differ++ == 0) first = text + " against " + via_stream(v);
    if (std::isfinite(v)) {
      EXPECT_EQ(std::strtod(text.c_str(), nullptr), v) << text;  // read back exactly (subnormals too)
    }
  }
  EXPECT_EQ(differ, 0) << "first: " << first;
}

TEST(NumberText, IntegersAreDecimal) {
  for (const long long v :
       {0LL, 1LL, -1LL, 42LL, -32768LL, 2147483647LL, std::numeric_limits<long long>::min(), std::numeric_limits<long long>::max()}) {
    std::string text = "x";
    gearsim::append_number(text, v);
    std::ostringstream s;
    s << 'x' << v;
    EXPECT_EQ(text, s.str());
  }
}

}  // namespace test_number_text

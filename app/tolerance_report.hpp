// Text and JSON forms of tolerance results (geometry/tolerance.hpp), shared by the `tolerance`
// and `gears` subcommands and the Python module. Units are the standards' own: µm.
#pragma once

#include <nlohmann/json.hpp>
#include <ostream>
#include <string>
#include <vector>

#include "geometry/tolerance.hpp"

namespace gearsim::app {

using json = nlohmann::ordered_json;  // keeps keys in the order written

// Pads to `width` terminal columns; counts UTF-8 code points, not bytes, so "µm" lines up.
std::string pad(const std::string& s, std::size_t width, bool right = false);
// Fixed-point text with `digits` decimals.
std::string fixed(double v, int digits);

// "din3961 = DIN 3961/3962, class 8: step factor 1.4^(Q-5), 1.4 per class = 2.7440", rounding.
void print_tolerance_grading(std::ostream& out, const ToleranceResult& r);
// One table: class-5 value, then (unrounded, rounded) per result, side by side.
void print_tolerance_table(std::ostream& out, const std::vector<ToleranceResult>& results);
// One standard's result: flat `<key>_um` values plus every intermediate in `components`.
json tolerance_result_json(const ToleranceResult& r);

// What `gearsim tolerance --json` prints: `standard` "din" or "iso" gives that standard's object
// (ISO's with its own formulas under iso1328_formulas), "both" the paper's DIN answer on top and
// each standard's object under din3961 and iso1328; the input under `input`. InputError naming
// the parameter for out-of-range input, or `standard` when it is none of the three.
json tolerance_json(const ToleranceInput& input, const std::string& standard);

}  // namespace gearsim::app

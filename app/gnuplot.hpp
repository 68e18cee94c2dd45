// Plots for reports, drawn by gnuplot (Debian's gnuplot-nox) as SVG: a script with its data in
// inline blocks goes in, the SVG text comes out. Not a plotting API: callers write gnuplot.
// Text that comes from input files (scenario, body and pair names) enters a script only through
// gnuplot_string(): gnuplot runs without a shell, in a private temporary folder.
#pragma once

#include <string>
#include <vector>

namespace gearsim::app {

// A named inline data block: `$name << EOD` … `EOD`, columns separated by spaces.
std::string data_block(const std::string& name, const std::vector<std::vector<double>>& columns);

// `text` as a gnuplot single-quoted string literal, quotes included: ' doubled (gnuplot's only
// escape inside single quotes, where backquotes and @macros are not expanded), control
// characters (which would end the script line) replaced by '?'. Plain data, whatever the text.
std::string gnuplot_string(const std::string& text);

// Runs gnuplot on `script` with an SVG terminal of the given size (pixels) prepended and returns
// the SVG. gnuplot is started by posix_spawnp with the script's path as its only argument (no
// shell), in a folder of its own made by mkdtemp and removed afterwards. InputError when gnuplot
// is missing or fails (its message included).
std::string gnuplot_svg(const std::string& script, int width_px = 900, int height_px = 360);

}  // namespace gearsim::app

// Plots for reports, drawn by gnuplot (Debian's gnuplot-nox) as SVG: a script with its data in
// inline blocks goes in, the SVG text comes out. Not a plotting API: callers write gnuplot.
#pragma once

#include <string>
#include <vector>

namespace gearsim::app {

// A named inline data block: `$name << EOD` … `EOD`, columns separated by spaces.
std::string data_block(const std::string& name, const std::vector<std::vector<double>>& columns);

// Runs gnuplot on `script` with an SVG terminal of the given size (pixels) prepended and returns
// the SVG. InputError when gnuplot is missing or fails (its message included).
std::string gnuplot_svg(const std::string& script, int width_px = 900, int height_px = 360);

}  // namespace gearsim::app

#include "app/gnuplot.hpp"

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "geometry/errors.hpp"

namespace gearsim::app {

std::string data_block(const std::string& name, const std::vector<std::vector<double>>& columns) {
  std::ostringstream out;
  out.precision(10);
  out << "$" << name << " << EOD\n";
  const std::size_t rows = columns.empty() ? 0 : columns.front().size();
  for (std::size_t r = 0; r < rows; ++r) {
    for (std::size_t c = 0; c < columns.size(); ++c) out << (c ? " " : "") << columns[c].at(r);
    out << "\n";
  }
  out << "EOD\n";
  return out.str();
}

std::string gnuplot_svg(const std::string& script, int width_px, int height_px) {
  namespace fs = std::filesystem;
  const fs::path base = fs::temp_directory_path() / ("gearsim_plot_" + std::to_string(getpid()));
  const fs::path gp = base.string() + ".gp", svg = base.string() + ".svg", err = base.string() + ".err";
  {
    std::ofstream f(gp);
    if (!f) throw InputError(gp.string() + ": cannot write the plot script");
    f << "set terminal svg size " << width_px << "," << height_px << " dynamic font 'sans,11'\n";
    f << "set output '" << svg.string() << "'\n";
    f << "set termoption noenhanced\n";  // labels and keys are literal (underscores in names)
    f << script << "\nunset output\n";
  }
  const std::string cmd = "gnuplot '" + gp.string() + "' 2> '" + err.string() + "'";
  const int status = std::system(cmd.c_str());
  std::ifstream e(err);
  const std::string message((std::istreambuf_iterator<char>(e)), std::istreambuf_iterator<char>());
  if (status != 0) {
    fs::remove(gp);
    throw InputError("gnuplot failed (is gnuplot-nox installed? scripts/install-deps.sh installs it): " + message);
  }
  std::ifstream s(svg);
  const std::string out((std::istreambuf_iterator<char>(s)), std::istreambuf_iterator<char>());
  fs::remove(gp);
  fs::remove(svg);
  fs::remove(err);
  // The inline SVG starts at its <svg> element (no XML prolog inside HTML).
  const std::size_t at = out.find("<svg");
  if (at == std::string::npos) throw InputError("gnuplot wrote no SVG: " + message);
  return out.substr(at);
}

}  // namespace gearsim::app

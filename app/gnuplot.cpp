#include "app/gnuplot.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

#include "core/errors.hpp"

extern char** environ;

namespace gearsim::app {
namespace {

namespace fs = std::filesystem;

// A folder only this process uses (mode 0700), removed with everything in it when it goes.
class PrivateTempDir {
 public:
  PrivateTempDir() {
    std::string pattern = (fs::temp_directory_path() / "gearsim_plot_XXXXXX").string();
    if (!mkdtemp(pattern.data())) throw InputError(pattern + ": cannot create a temporary folder: " + std::strerror(errno));
    path_ = pattern;
  }
  ~PrivateTempDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  PrivateTempDir(const PrivateTempDir&) = delete;
  PrivateTempDir& operator=(const PrivateTempDir&) = delete;
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

std::string read_all(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
}

// Runs `gnuplot script` (found on PATH, no shell) with stdout to /dev/null and stderr to `err`;
// returns its wait status, or -1 with errno's text in `why` when it could not be started.
int run_gnuplot(const fs::path& script, const fs::path& err, std::string& why) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
  std::string program = "gnuplot", arg = script.string();
  char* argv[] = {program.data(), arg.data(), nullptr};
  pid_t pid = 0;
  const int rc = posix_spawnp(&pid, "gnuplot", &actions, nullptr, argv, environ);
  posix_spawn_file_actions_destroy(&actions);
  if (rc != 0) {
    why = std::strerror(rc);
    return -1;
  }
  int status = 0;
  while (waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) {
      why = std::strerror(errno);
      return -1;
    }
  return status;
}

}  // namespace

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

std::string gnuplot_string(const std::string& text) {
  std::string out = "'";
  for (char c : text) {
    const auto u = static_cast<unsigned char>(c);
    if (c == '\'')
      out += "''";
    else if (u < 0x20 || u == 0x7f)
      out += '?';
    else
      out += c;
  }
  return out + "'";
}

std::string gnuplot_svg(const std::string& script, int width_px, int height_px) {
  const PrivateTempDir tmp;
  const fs::path gp = tmp.path() / "plot.gp", svg = tmp.path() / "plot.svg", err = tmp.path() / "plot.err";
  {
    std::ofstream f(gp);
    if (!f) throw InputError(gp.string() + ": cannot write the plot script");
    f << "set terminal svg size " << width_px << "," << height_px << " dynamic font 'sans,11'\n";
    f << "set output " << gnuplot_string(svg.string()) << "\n";
    f << "set termoption noenhanced\n";  // labels and keys are literal (underscores in names)
    f << script << "\nunset output\n";
  }
  std::string why;
  const int status = run_gnuplot(gp, err, why);
  if (status == -1) throw InputError("cannot run gnuplot (is gnuplot-nox installed? scripts/install-deps.sh installs it): " + why);
  const std::string message = read_all(err);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw InputError("gnuplot failed (is gnuplot-nox installed? scripts/install-deps.sh installs it): " + message);
  const std::string out = read_all(svg);
  // The inline SVG starts at its <svg> element (no XML prolog inside HTML).
  const std::size_t at = out.find("<svg");
  if (at == std::string::npos) throw InputError("gnuplot wrote no SVG: " + message);
  return out.substr(at);
}

}  // namespace gearsim::app

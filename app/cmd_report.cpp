// gearsim report DIR [--compare DIR2]: DIR/report.html (app/report.hpp), after analysing the
// folders afresh.
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>

#include "app/commands.hpp"
#include "app/output_folder.hpp"
#include "app/report.hpp"
#include "app/run_analysis.hpp"
#include "core/errors.hpp"
#include "sweep/sweep_dir.hpp"
#include "core/output_file.hpp"

namespace gearsim::app {
namespace {

// The run folder, analysed afresh (about a second): the report always shows the analysis of
// this build, never a stale one.
RunDir analysed(const std::string& dir) {
  write_run_analysis(open_run_dir(dir));
  return open_run_dir(dir);
}

void write_report_html(const std::filesystem::path& out, const std::string& html) {
  declare_outputs(out.parent_path(), {out.filename().string()});
  write_output_file(out, html);
  std::cout << "written: " << out.string() << "\n";
}

}  // namespace

void register_report(CLI::App& app) {
  auto dir = std::make_shared<std::string>();
  auto compare = std::make_shared<std::string>();
  CLI::App* sub = app.add_subcommand(
      "report",
      "Write DIR/report.html: the run against the paper, in one self-contained page; for a sweep folder, its table and metric plots.");
  sub->add_option("dir", *dir, "A folder written by `gearsim run --out` or `gearsim sweep --out`.")
      ->required()
      ->check(CLI::ExistingDirectory);
  sub->add_option("--compare", *compare, "A second run folder (e.g. the healthy twin) overlaid on spectra and tooth loads.")
      ->check(CLI::ExistingDirectory);
  sub->callback([dir, compare] {
    const OutputFolder folder(*dir, "gearsim report");
    if (sweep::is_sweep_dir(*dir)) {
      if (!compare->empty()) throw InputError("--compare: takes run folders; " + *dir + " is a sweep folder (sweep.json)");
      write_report_html(std::filesystem::path(*dir) / "report.html", build_sweep_report(*dir));
      return;
    }
    const RunDir run = analysed(*dir);
    // The compared folder is read only, as its own analyze wrote it.
    std::optional<RunDir> other;
    if (!compare->empty()) {
      if (!std::filesystem::exists(std::filesystem::path(*compare) / "analysis.json"))
        throw InputError("--compare " + *compare + ": no analysis.json (run `gearsim analyze " + *compare +
                         "` first: the compared folder is only read)");
      other = open_run_dir(*compare);
    }
    write_report_html(run.dir / "report.html", build_report(run, other));
  });
}

}  // namespace gearsim::app

// gearsim run SCENARIO --out DIR: a headless simulation (run_scenario.hpp writes state.csv and
// contacts.csv at the scenario's output rate and summary.json); a progress line on a terminal; Ctrl-C stops
// cleanly and keeps valid logs; a run that leaves its physical bounds (sim/run_bounds.hpp)
// stops at that step with status "diverged" and exit code kExitDiverged, its logs kept.
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>

#include "app/analyze.hpp"
#include "app/commands.hpp"
#include "app/exit_codes.hpp"
#include "app/output_folder.hpp"
#include "input/input_limits.hpp"
#include "app/render_run.hpp"
#include "app/run_analysis.hpp"
#include "app/run_dir.hpp"
#include "app/run_scenario.hpp"
#include "app/stop_signals.hpp"
#include "input/scenario_file.hpp"
#include "core/errors.hpp"
#include "geometry/gear_spec.hpp"
#include "sim/simulate.hpp"
#include "physics/world.hpp"

namespace gearsim::app {
namespace {

struct RunOptions {
  std::string scenario;
  std::string out_dir;
  std::vector<std::string> sets;
  double duration_s = 0;
  bool no_analyze = false;
  bool force = false;
};

// Ends a run that stopped early with its exit code, after its outputs were written.
void throw_if_stopped(const sim::RunSummary& r, const std::filesystem::path& dir) {
  if (r.status == sim::RunStatus::OutputFailed) {
    std::string what;
    for (const std::string& w : r.not_written) what += (what.empty() ? "" : "; ") + w;
    throw OutputError("the run stopped at t = " + std::to_string(r.sim_seconds) + " s: " + what + " (summary.json in " + dir.string() +
                      " says what was written)");
  }
  if (const auto& d = r.divergence)
    throw RunStopped(kExitDiverged, "diverged at t = " + std::to_string(d->time_s) + " s (step " + std::to_string(d->step) +
                                        "): " + d->message + ". Logs up to that step are in " + dir.string());
  if (r.status == sim::RunStatus::Interrupted) {
    throw RunStopped(r.stop_signal == SIGTERM ? kExitSigterm : kExitSigint,
                     "interrupted by " + signal_name(r.stop_signal) + ": the logs hold the run up to t = " + std::to_string(r.sim_seconds) +
                         " s in " + dir.string() + " (not analysed)");
  }
}

void run(const RunOptions& o) {
  // SIGINT and SIGTERM are caught from the start until the command ends: while the scenario loads
  // (seconds for a large set) the command ends before it writes anything; once the output folder
  // is taken they stop the run between two steps, and its render between two frames.
  const StopSignals stop_signals;
  physics::Scenario s = input::load_scenario(o.scenario, o.sets);
  if (o.duration_s > 0) set_duration(s, o.duration_s);
  const std::filesystem::path dir(o.out_dir);
  if (const int sig = stop_signal())
    throw RunStopped(sig == SIGTERM ? kExitSigterm : kExitSigint,
                     "interrupted by " + signal_name(sig) + " while the scenario loaded: nothing was written to " + dir.string());
  // Held until the command ends: the run, its analysis and its renders write into it.
  OutputFolder folder(dir, "gearsim run", OutputFolder::ForNewRun{o.force});
  if (const int n = folder.removed(); n > 0) std::cout << "removed " << n << " outputs of a previous run in " << dir.string() << "\n";
  const bool tty = isatty(STDERR_FILENO);
  int last_percent = -1;
  sim::SimOptions options;
  options.stop_requested = stop_signal;
  options.progress = [&](long i, long total, double t) {
    const int percent = static_cast<int>(100 * i / total);
    if (!tty || percent == last_percent) return;
    std::cerr << "\r  " << s.name << ": " << percent << "% (t = " << std::fixed << std::setprecision(4) << t << " s)" << std::flush;
    last_percent = percent;
  };
  const DirRun run = run_into_dir(s, RunSource{o.scenario, o.sets}, folder, options);
  if (tty) std::cerr << "\n";
  const sim::RunSummary& r = run.result;
  std::cout << s.name << ": " << sim::status_name(r.status) << ", " << r.sim_seconds << " s simulated in " << std::setprecision(3)
            << r.wall_seconds << " s wall; logs in " << dir.string() << "\n";
  for (const std::string& w : r.warnings) std::cout << "warning: " << w << "\n";
  for (const physics::PairTableDef& t : s.pair_tables)
    if (!t.placement_note.empty()) std::cout << "note: " << t.placement_note << "\n";
  std::cout << std::flush;  // the run's outcome before its analysis starts, also through a pipe
  throw_if_stopped(r, dir);
  // The analysis and the scenario's renders of the finished run; a run too short (or of a train
  // the analysis does not know) keeps its logs and says why it was not analysed or rendered.
  std::string not_analysed;  // why the analysis was refused: the command's exit code says so at its end
  if (!o.no_analyze) try {
      print_analysis(write_run_analysis(open_run_dir(dir)), std::cout);
    } catch (const InputError& e) {
      not_analysed = e.what();
      std::cout << "not analysed: " << not_analysed << "\n";
    }
  // A signal during the analysis (not interruptible: it takes a fraction of the run's time)
  // ends the command with the signal's code once the analysis is written, and what was asked
  // after it is not started.
  if (const int sig = stop_signal())
    throw RunStopped(sig == SIGTERM ? kExitSigterm : kExitSigint,
                     std::string("interrupted by ") + signal_name(sig) + " after the run and its analysis" +
                         (s.render ? ": not rendered" : "") + " (the run is complete in " + dir.string() + ")");
  if (s.render) try {
      const RenderResult rendered = render_run(open_run_dir(dir), *s.render, stop_signal);
      throw_if_render_stopped(rendered, dir);
      std::cout << "rendered " << rendered.frames << " frames of " << rendered.from_s << "–" << rendered.to_s
                << " s: " << rendered.video.string() << "\n";
    } catch (const InputError& e) {
      std::cout << "not rendered: " << e.what() << "\n";
    }
  if (!not_analysed.empty())
    throw RunStopped(kExitNotAnalysed, "the run completed (logs in " + dir.string() + ") but was not analysed: " + not_analysed);
}

}  // namespace

void register_run(CLI::App& app) {
  auto o = std::make_shared<RunOptions>();
  CLI::App* sub = app.add_subcommand("run", "Run a scenario headless: state.csv, contacts.csv and summary.json in --out.");
  sub->add_option("scenario", o->scenario, "Scenario file (YAML), e.g. assets/scenarios/paper_dynamics.yaml.")
      ->required()
      ->check(CLI::ExistingFile);
  sub->add_option("--out", o->out_dir, "Output folder (created if missing).")->required();
  sub->add_option("--set", o->sets, "Override a scenario value: key.path=value (repeatable), e.g. solver.time_step_s=1e-5.");
  sub->add_option("--duration", o->duration_s, "Simulated seconds, overriding the scenario's duration_s (at most 1e4 s).")
      ->check(input::cli_within(input::limits::kDuration_s));
  sub->add_flag("--no-analyze", o->no_analyze, "Do not analyse the run at the end (see `gearsim analyze`).");
  sub->add_flag("--force", o->force,
                "Write into a folder that holds files gearsim did not write (none of them is removed; one named as an "
                "output is replaced). Without it such a folder is refused.");
  sub->callback([o] { run(*o); });
}

}  // namespace gearsim::app

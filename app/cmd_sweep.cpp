// gearsim sweep SWEEP.yaml --out DIR [--jobs N] [--fresh]: a parameter sweep (sweep/), each case a
// `gearsim run` of this binary in DIR/cases/<index>/, on --jobs local processes at once, or over
// MPI ranks when started by mpirun (rank 0 hands out the cases). Progress on stderr; the table in
// DIR/sweep.csv and DIR/sweep.h5; exit 0 when every case completed, kExitSweepCasesFailed when
// some did not (each recorded), 130/143 when stopped by a signal.
#include <csignal>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <thread>

#include "app/commands.hpp"
#include "app/exit_codes.hpp"
#include "app/sweep_metrics.hpp"
#include "core/errors.hpp"
#include "input/input_limits.hpp"
#include "sweep/process.hpp"
#include "sweep/sweep_runner.hpp"

namespace gearsim::app {
namespace {

struct SweepCliOptions {
  std::string file;
  std::string out;
  int jobs = 0;  // 0: the number of cores
  bool fresh = false;
};

// The signal (SIGINT or SIGTERM) that asked the sweep to stop, 0 while none did.
volatile std::sig_atomic_t g_sweep_stop = 0;
void on_sweep_stop_signal(int sig) { g_sweep_stop = sig; }
int sweep_stop_requested() { return static_cast<int>(g_sweep_stop); }

std::string sweep_duration_text(double s) {
  std::ostringstream o;
  if (s < 0) return "?";
  if (s < 90)
    o << std::fixed << std::setprecision(0) << s << " s";
  else if (s < 5400)
    o << std::fixed << std::setprecision(1) << s / 60 << " min";
  else
    o << std::fixed << std::setprecision(1) << s / 3600 << " h";
  return o.str();
}

// One line per finished case: which, how it ended, done/total, failures, ETA.
void print_sweep_progress(const sweep::Progress& p) {
  const sweep::CaseRecord& r = *p.last;
  std::cerr << "sweep: case " << r.index << " " << sweep::status_name(r.status);
  if (r.status != sweep::CaseStatus::Completed) std::cerr << " (exit " << r.exit_code << ")";
  std::cerr << "; " << p.done << "/" << p.to_run << " done, " << p.failed << " not completed, ETA " << sweep_duration_text(p.eta_s) << "\n";
}

sweep::CaseContext sweep_case_context() { return {sweep::self_executable(), collect_case_metrics, sweep_stop_requested}; }

// The end of a sweep: what it did, and the exit code it ends with.
void finish_sweep(const sweep::SweepOutcome& out) {
  const sweep::StatusCounts& c = out.statuses;
  std::cout << "sweep: " << out.cases << " cases (" << out.ran << " run now, " << out.skipped << " finished before): " << c.completed
            << " completed, " << c.diverged << " diverged, " << c.failed << " failed, " << c.interrupted << " interrupted, " << c.not_run
            << " not run\n"
            << "written: " << out.csv.string() << ", " << out.h5.string() << "\n";
  if (const int sig = sweep_stop_requested())
    throw RunStopped(sig == SIGTERM ? kExitSigterm : kExitSigint,
                     std::string("sweep stopped by ") + (sig == SIGTERM ? "SIGTERM" : "SIGINT") + "; run it again to resume");
  if (c.completed != out.cases)
    throw RunStopped(kExitSweepCasesFailed, std::to_string(out.cases - c.completed) + " of " + std::to_string(out.cases) +
                                                " cases did not complete; see their case.json (status, error) and sweep.csv");
}

void announce_sweep(std::size_t cases, std::size_t to_run, const std::string& where) {
  std::cerr << "sweep: " << cases << " cases validated; " << to_run << " to run " << where << " (" << cases - to_run
            << " finished before)\n";
}

// Under mpirun: rank 0 runs the sweep and hands out the cases, the other ranks run them.
void run_sweep_mpi(const sweep::SweepOptions& options) {
  sweep::MpiSession mpi;
  if (mpi.rank() != 0) {
    sweep::run_mpi_worker(sweep_case_context());
    return;
  }
  bool released = false;
  const auto schedule = [&](const std::vector<sweep::CaseJob>& jobs) {
    released = true;
    return sweep::run_mpi_master(jobs, print_sweep_progress, sweep_stop_requested);
  };
  const std::string where = "on " + std::to_string(mpi.size() - 1) + " MPI workers";
  try {
    finish_sweep(sweep::run_sweep(options, schedule, [&](std::size_t n, std::size_t r) { announce_sweep(n, r, where); }));
  } catch (...) {
    if (!released) sweep::run_mpi_master({}, {}, {});  // the workers wait for a job: release them
    throw;
  }
}

void run_sweep_cli(const SweepCliOptions& o) {
  g_sweep_stop = 0;
  std::signal(SIGINT, on_sweep_stop_signal);
  std::signal(SIGTERM, on_sweep_stop_signal);
  const sweep::SweepOptions options{o.file, o.out, o.fresh};
  if (sweep::mpi_requested()) return run_sweep_mpi(options);
  const int jobs = o.jobs > 0 ? o.jobs : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  const auto schedule = [&](const std::vector<sweep::CaseJob>& list) {
    return sweep::run_local(list, jobs, sweep_case_context(), print_sweep_progress);
  };
  const std::string where = "on " + std::to_string(jobs) + " local processes at once";
  finish_sweep(sweep::run_sweep(options, schedule, [&](std::size_t n, std::size_t r) { announce_sweep(n, r, where); }));
}

}  // namespace

void register_sweep(CLI::App& app) {
  auto o = std::make_shared<SweepCliOptions>();
  CLI::App* sub =
      app.add_subcommand("sweep",
                         "Run a parameter sweep: each case a `gearsim run` in DIR/cases/<index>/, the table in DIR/sweep.csv and "
                         "DIR/sweep.h5. Under mpirun, rank 0 hands the cases out to the other ranks. Exit 5 when some cases did "
                         "not complete (each recorded in its case.json).");
  sub->add_option("sweep_file", o->file, "Sweep file (YAML), e.g. assets/sweeps/spur_speed_sweep.yaml.")
      ->required()
      ->check(CLI::ExistingFile);
  sub->add_option("--out", o->out, "Output folder (created if missing); run again into it to resume.")->required();
  sub->add_option("--jobs", o->jobs, "Cases run at once on this machine (default: the number of cores); not under mpirun.")
      ->check(input::cli_within(input::limits::kJobs));
  sub->add_flag("--fresh", o->fresh, "Remove the folder's sweep outputs (cases/, sweep.json, the table) and start over.");
  sub->callback([o] { run_sweep_cli(*o); });
}

}  // namespace gearsim::app

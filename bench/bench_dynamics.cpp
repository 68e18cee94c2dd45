// Benchmark (issues 3 and 18): CPU and wall seconds per simulated second, microseconds per step
// by part, and peak memory of a scenario's run on one thread, through the same sim::simulate the
// CLI uses (bounds checks and steady-window means included). Without --log nothing is written;
// with --log the output-rate CSVs (anti-aliasing filter included) and the per-step HDF5 log go to
// a temporary folder, removed afterwards. Wall time includes waiting for a core on a shared
// machine; CPU time is this thread's work.
// Usage: bench_dynamics [scenario.yaml=assets/scenarios/paper_dynamics_healthy.yaml] [sim_seconds=0.2]
//                       [--set key.path=value]… [--log]
//   e.g. bench_dynamics assets/scenarios/paper_dynamics_healthy.yaml 0.2 --set solver.time_step_s=1e-5 --log
#include <sys/resource.h>
#include <time.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "input/scenario_file.hpp"
#include "sim/csv_logs.hpp"
#include "sim/simulate.hpp"
#include "sim/step_log.hpp"

namespace {

using Clock = std::chrono::steady_clock;

// CPU time of this thread, s: the work done, apart from waiting for a core on a busy machine.
double thread_cpu_s() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// The CPU and wall clocks when stepping starts (the world built) and ends (observers closed).
struct Stopwatch : gearsim::sim::Observer {
  void on_start(const gearsim::physics::World&) override { cpu0 = thread_cpu_s(), wall0 = Clock::now(); }
  void on_stop(const gearsim::physics::World&) override { cpu1 = thread_cpu_s(), wall1 = Clock::now(); }
  double cpu0 = 0, cpu1 = 0;
  Clock::time_point wall0, wall1;
};

struct Args {
  std::string scenario = std::string(GEARSIM_SOURCE_DIR) + "/assets/scenarios/paper_dynamics_healthy.yaml";
  double seconds = 0.2;
  std::vector<std::string> sets;
  bool log = false;
};

Args parse(int argc, char** argv) {
  Args a;
  int positional = 0;
  for (int i = 1; i < argc; ++i) {
    const std::string s = argv[i];
    if (s == "--log") {
      a.log = true;
    } else if (s == "--set" && i + 1 < argc) {
      a.sets.push_back(argv[++i]);
    } else if (!s.empty() && s[0] != '-' && positional == 0) {
      a.scenario = s, ++positional;
    } else if (!s.empty() && s[0] != '-' && positional == 1) {
      a.seconds = std::atof(s.c_str()), ++positional;
    } else {
      std::fprintf(stderr, "bench_dynamics: unexpected argument '%s'\nusage: bench_dynamics [scenario] [seconds] [--set k=v]… [--log]\n",
                   s.c_str());
      std::exit(2);
    }
  }
  if (!(a.seconds > 0)) {
    std::fprintf(stderr, "bench_dynamics: expected a positive number of simulated seconds\n");
    std::exit(2);
  }
  return a;
}

}  // namespace

int main(int argc, char** argv) {
  namespace sim = gearsim::sim;
  const Args a = parse(argc, argv);
  const auto t0 = Clock::now();
  std::vector<std::string> sets = a.sets;
  sets.push_back("duration_s=" + std::to_string(a.seconds));
  if (!a.log) sets.push_back("output.per_step_log=false");
  const gearsim::physics::Scenario s = gearsim::input::load_scenario(a.scenario, sets);
  const auto t1 = Clock::now();
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("gearsim_bench_dynamics_" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  Stopwatch watch;
  sim::CsvLogs csv(dir, s);
  sim::StepLogObserver steps_h5(dir / "steps.h5", s.name, s.solver.time_step_s);
  std::vector<sim::Observer*> observers{&watch};
  if (a.log) observers.push_back(&csv), observers.push_back(&steps_h5);
  const sim::RunSummary r = sim::simulate(s, observers);
  const double log_bytes = static_cast<double>(steps_h5.bytes_on_disk());
  std::filesystem::remove_all(dir);
  auto sec = [](Clock::time_point x, Clock::time_point y) { return std::chrono::duration<double>(y - x).count(); };
  const double wall = sec(watch.wall0, watch.wall1), cpu = watch.cpu1 - watch.cpu0;
  const double n = static_cast<double>(r.steps), sim_s = r.sim_seconds;
  const double contact = r.profile.tooth_contact_s, bullet = r.profile.step_total_s - contact;
  const double rest = wall - r.profile.step_total_s;  // bounds, steady sums, observers (logs)
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  std::printf("scenario %s: dt = %g s, %ld steps (%g s simulated), %s, status %s\n", s.name.c_str(), s.solver.time_step_s, r.steps, sim_s,
              a.log ? "with the logs (CSV + steps.h5)" : "without logs", sim::status_name(r.status));
  std::printf("load + expand scenario  %8.3f s\n", sec(t0, t1));
  std::printf("build world             %8.3f s\n", r.setup_wall_seconds);
  std::printf("stepping                %8.3f s = %.2f s per simulated second (%.1f us per step)\n", wall, wall / sim_s, 1e6 * wall / n);
  std::printf("stepping, CPU time      %8.3f s = %.2f s per simulated second (%.1f us per step)\n", cpu, cpu / sim_s, 1e6 * cpu / n);
  std::printf("  tooth contact         %8.3f s (%.0f %%, %.1f us per step)\n", contact, 100 * contact / wall, 1e6 * contact / n);
  if (const auto& v = r.profile.flank_visits; v.searched + v.tracked + v.skipped + v.continued + v.shared + v.parked > 0) {
    auto per = [&](long c) { return static_cast<double>(c) / n; };
    std::printf(
        "    flanks per step     %.1f skipped by their records, %.1f renewed, %.1f continued (%.2f at a tip circle), %.2f shared, "
        "%.1f parked near pairs, %.2f searched, %.2f tracked\n",
        per(v.skipped), per(v.renewed), per(v.continued), per(v.crossings), per(v.shared), per(v.parked), per(v.searched), per(v.tracked));
  }
  std::printf("  Bullet + measuring    %8.3f s (%.0f %%, %.1f us per step)\n", bullet, 100 * bullet / wall, 1e6 * bullet / n);
  if (r.profile.row_solve_s > 0) {
    const double rows = r.profile.row_solve_s;
    std::printf("    of it rows + solve  %8.3f s (%.0f %%, %.1f us per step: Jacobians, M⁻¹, the solve)\n", rows, 100 * rows / wall,
                1e6 * rows / n);
    std::printf(
        "    row solves          %ld by the active set, %ld by Dantzig, %ld again at slip reversals; %ld steps split at contact onsets\n",
        r.profile.active_set_solves, r.profile.dantzig_solves, r.profile.friction_rounds, r.profile.onset_splits);
  }
  std::printf("  bounds, means, logs   %8.3f s (%.0f %%, %.1f us per step)\n", rest, 100 * rest / wall, 1e6 * rest / n);
  if (a.log) std::printf("per-step log            %8.1f MB per simulated second\n", log_bytes / sim_s / 1e6);
  std::printf("peak resident memory    %8.1f MiB\n", static_cast<double>(usage.ru_maxrss) / 1024.0);
  return r.status == sim::RunStatus::Completed ? 0 : 4;
}

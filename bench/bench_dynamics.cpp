// Benchmark (issue 3): wall seconds per simulated second and peak memory of a scenario's
// simulation on one thread, with where the time goes (tooth contact, Bullet's solver and
// measuring), without writing logs. Prints wall and CPU time of the stepping: on a shared machine
// the wall time includes waiting for a core. The scenario's own time step is used, so the figure belongs
// to the step size its acceptance was measured at.
// Usage: bench_dynamics [scenario.yaml=assets/scenarios/paper_dynamics_healthy.yaml] [sim_seconds=0.2]
#include <sys/resource.h>
#include <time.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "input/scenario_file.hpp"
#include "physics/world.hpp"

using Clock = std::chrono::steady_clock;

// CPU time of this thread, s: the work done, apart from waiting for a core on a busy machine.
double thread_cpu_s() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

int main(int argc, char** argv) {
  const std::string file =
      argc > 1 ? argv[1] : std::string(GEARSIM_SOURCE_DIR) + "/assets/scenarios/paper_dynamics_healthy.yaml";
  const double seconds = argc > 2 ? std::atof(argv[2]) : 0.2;
  const auto t0 = Clock::now();
  const gearsim::physics::Scenario s = gearsim::input::load_scenario(file);
  const auto t1 = Clock::now();
  gearsim::physics::World world(s);
  const auto t2 = Clock::now();
  const long steps = std::lround(seconds / s.solver.time_step_s);
  const double cpu0 = thread_cpu_s();
  for (long i = 0; i < steps; ++i) world.step();
  const double cpu = thread_cpu_s() - cpu0;
  const auto t3 = Clock::now();
  auto sec = [](Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double>(b - a).count(); };
  const double run = sec(t2, t3);
  const auto& p = world.profile();
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  std::printf("scenario %s: dt = %g s, %ld steps (%g s simulated)\n", s.name.c_str(), s.solver.time_step_s, steps, seconds);
  std::printf("load + expand scenario  %8.3f s\n", sec(t0, t1));
  std::printf("build world             %8.3f s\n", sec(t1, t2));
  std::printf("stepping                %8.3f s = %.2f s per simulated second (%.1f us per step)\n", run, run / seconds,
              1e6 * run / static_cast<double>(steps));
  std::printf("stepping, CPU time      %8.3f s = %.2f s per simulated second (%.1f us per step)\n", cpu, cpu / seconds,
              1e6 * cpu / static_cast<double>(steps));
  std::printf("  tooth contact         %8.3f s (%.0f %%)\n", p.tooth_contact_s, 100 * p.tooth_contact_s / run);
  std::printf("  Bullet + measuring    %8.3f s (%.0f %%)\n", p.step_total_s - p.tooth_contact_s,
              100 * (p.step_total_s - p.tooth_contact_s) / run);
  std::printf("peak resident memory    %8.1f MiB\n", static_cast<double>(usage.ru_maxrss) / 1024.0);
  return 0;
}

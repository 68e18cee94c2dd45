// simulate(): one run of a scenario — build the world, step it for the scenario's duration, check
// its physical bounds every step (run_bounds.hpp), measure the steady window after the ramps
// (mean speeds, flank forces, power balance), hand every step and output sample to the observers,
// and say how it ended. No files, no printing: the CLI (app/cmd_run.cpp) and the tests call it
// with the observers they want. The same scenario gives bit-identical observations.
#pragma once

#include <array>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "physics/scenario.hpp"
#include "physics/world.hpp"
#include "sim/observer.hpp"
#include "sim/power_balance.hpp"
#include "sim/run_bounds.hpp"

namespace gearsim::sim {

// OutputFailed: an observer could not write its outputs (a full disk); the run stopped at the
// next output sample and RunSummary::not_written says which and why.
enum class RunStatus { Completed, Diverged, Interrupted, OutputFailed };
const char* status_name(RunStatus s);  // "completed", "diverged", "interrupted", "output_failed"

struct SimOptions {
  // Polled after every step: a nonzero value (e.g. the signal that asked) stops the run there,
  // status Interrupted, stop_signal set to it.
  std::function<int()> stop_requested;
  // Called after every step with the steps done and the total (for a progress line).
  std::function<void(long step, long total, double time_s)> progress;
};

// One body's mean speed over the steady window, rad/s, about its joint's axis (+z for a body
// without a joint): relative to the body it turns on (its joint's parent; a planet on its
// carrier), and absolute (in the world frame: the parent's absolute angular velocity along that
// axis added, down the joint tree).
struct BodyResult {
  std::string name;
  std::string parent;  // the joint's parent body, or "ground"
  double mean_speed_relative_rad_s = 0;
  double mean_absolute_speed_rad_s = 0;
};

// One gear pair as the world built it, with the mean normal force on each flank side of body a's
// teeth over the steady window (one side drives; the other touches only without backlash or in
// rattle). The torque they carry is their difference times the base radius.
struct PairResult {
  physics::GearPairInfo info;
  double mean_ccw_flank_force_N = 0;  // on the counter-clockwise flanks of a's teeth
  double mean_cw_flank_force_N = 0;  // on the clockwise flanks of a's teeth
};

struct RunSummary {
  RunStatus status = RunStatus::Completed;
  int stop_signal = 0;  // Interrupted: what stop_requested returned
  std::optional<Divergence> divergence;  // Diverged: which bound, where, when
  double sim_seconds = 0;
  long steps = 0;
  double time_step_s = 0;
  double wall_seconds = 0;  // building the world, stepping and observing
  double setup_wall_seconds = 0;  // building the world and starting the observers
  physics::World::Profile profile;
  double steady_from_s = 0;  // the steady window: after the motor and load ramps …
  long steady_steps = 0;  // … this many steps, to sim_seconds
  std::vector<BodyResult> bodies;
  std::optional<double> ratio;  // mean absolute input over output speed (scenario transmission)
  std::vector<PairResult> pairs;
  double max_penetration_m = 0;
  double created_energy_J = 0;  // energy the solver created over the run (run_bounds.hpp)
  PowerBalance power;  // over the steady window
  long dropped_contacts = 0;
  long stiffness_table_misses = 0;
  std::vector<std::string> warnings;  // numerical trouble counted over the run
  std::vector<std::string> not_written;  // OutputFailed: each output not written, with the reason
};

// Index into World::bodies() of the body a joint turns; InputError naming the scenario when no
// joint has that name.
int body_of_joint(const physics::Scenario& s, const std::string& joint);

// Steps between output samples: 1/(sample_rate_hz · time_step_s) rounded, at least 1. The
// samples are at whole steps, so the output rate is 1/(this · time_step_s).
long output_interval_steps(const physics::Scenario& s);

// Runs the scenario to its duration_s (or until a bound is crossed or a stop is requested).
// Throws InputError when the scenario cannot be built (physics::World's refusals).
RunSummary simulate(const physics::Scenario& scenario, const std::vector<Observer*>& observers, const SimOptions& options = {});

}  // namespace gearsim::sim

#include "sim/simulate.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>

#include "core/errors.hpp"

namespace gearsim::sim {
namespace {

// A tooth penetration beyond this is not a loaded mesh's deflection (≈ 1 µm at the paper's
// load) but interference or an unstable step, m — or beyond twice the deflection a steel tooth
// pair (ISO 6336's c' = 14 N/(mm·µm)) takes under the heaviest mesh's mean force, when that is
// larger: a heavily loaded gearbox deflects further (the wind turbine's stage 1, 197 kN on a
// 220 mm face: 64 µm). Judged against steel, not the scenario's own stiffness, so that a contact
// set too soft is still reported.
constexpr double kPenetrationWarning_m = 10e-6;
constexpr double kPenetrationOverSteelDeflection = 2.0;
constexpr double kSteelSinglePairStiffness_N_per_m_per_m = 1.4e10;

// The penetration the run warns beyond, m.
double penetration_warning_m(const RunSummary& r) {
  double deflection = 0;
  for (const PairResult& p : r.pairs)
    if (p.info.face_width_m > 0)
      deflection = std::max(deflection, std::max(p.mean_ccw_flank_force_N, p.mean_cw_flank_force_N) /
                                            (kSteelSinglePairStiffness_N_per_m_per_m * p.info.face_width_m));
  return std::max(kPenetrationWarning_m, kPenetrationOverSteelDeflection * deflection);
}

// Share of the motor input the measured power flows may leave unexplained before the run warns
// (the 2 % acceptance figure; converged runs show ~1e-5).
constexpr double kPowerImbalanceWarning = 0.02;

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Over the steady window's steps: each body's turn (its angle where the window starts and where it
// ends: the mean speed is the angle's rate — under a θ < 1 the positions advance with a mean of the
// step's start and end velocities, so a mean of the end velocities would not be the rate the
// body turns at), the normal forces on each flank side of each pair's first gear, and the power
// flows.
struct SteadyWindow {
  explicit SteadyWindow(const physics::World& w)
      : angle_start(w.bodies().size(), 0.0), angle_last(w.bodies().size(), 0.0), flank_sum(w.gear_pairs().size(), {0.0, 0.0}) {
    track(w);
  }
  // Every step before the window: the angles it will start from.
  void track(const physics::World& w) {
    for (std::size_t b = 0; b < w.bodies().size(); ++b) angle_last[b] = w.bodies()[b].angle_rad;
  }
  double mean_speed_rad_s(std::size_t b, double h) const {
    return steps ? (angle_last[b] - angle_start[b]) / (static_cast<double>(steps) * h) : 0.0;
  }
  void add(const physics::World& w) {
    if (steps == 0) angle_start = angle_last;
    track(w);
    for (const physics::ContactSample& c : w.contacts())
      flank_sum[static_cast<std::size_t>(c.pair)][c.geometry.flank_a == Flank::Cw] += c.normal_force_N;
    power.add(w.power(), w.time_s());
    ++steps;
  }
  std::vector<double> angle_start, angle_last;
  std::vector<std::array<double, 2>> flank_sum;
  PowerBalance power;
  long steps = 0;
};

// Each body's mean speeds, relative and absolute (world bodies in the scenario's order). A
// body's absolute angular velocity is its parent's plus its relative speed along its joint axis.
std::vector<BodyResult> body_results(const physics::Scenario& s, const physics::World& world, const SteadyWindow& steady, double h) {
  const std::size_t n = world.bodies().size();
  std::map<std::string, std::size_t> index;
  for (std::size_t b = 0; b < n; ++b) index[world.bodies()[b].name] = b;
  std::vector<int> parent(n, -1);
  std::vector<Eigen::Vector3d> axis(n, Eigen::Vector3d::UnitZ());
  std::vector<BodyResult> out(n);
  for (std::size_t b = 0; b < n; ++b) out[b] = {world.bodies()[b].name, "ground", steady.mean_speed_rad_s(b, h), 0.0};
  for (const physics::JointDef& j : s.joints) {
    const auto b = index.find(j.body), p = index.find(j.parent);
    if (b == index.end()) continue;
    axis[b->second] = j.axis.normalized();
    if (p != index.end()) parent[b->second] = static_cast<int>(p->second), out[b->second].parent = j.parent;
  }
  std::vector<Eigen::Vector3d> omega(n, Eigen::Vector3d::Zero());
  std::vector<char> done(n, 0);
  for (std::size_t b = 0; b < n; ++b) {
    // The chain up to the ground or a body already done (the joints form a tree; a loop, which
    // only rigid_bodies accepts, is cut where it closes), then down it.
    std::vector<std::size_t> chain{b};
    while (!done[chain.back()] && parent[chain.back()] >= 0 && chain.size() <= n)
      chain.push_back(static_cast<std::size_t>(parent[chain.back()]));
    for (auto c = chain.rbegin(); c != chain.rend(); ++c) {
      if (done[*c]) continue;
      const Eigen::Vector3d up = parent[*c] >= 0 && done[static_cast<std::size_t>(parent[*c])] ? omega[static_cast<std::size_t>(parent[*c])]
                                                                                               : Eigen::Vector3d::Zero();
      omega[*c] = up + out[*c].mean_speed_relative_rad_s * axis[*c];
      done[*c] = 1;
    }
    out[b].mean_absolute_speed_rad_s = omega[b].dot(axis[b]);
  }
  return out;
}

// Means over the steady window, the pairs and the counters into the summary.
void fill_results(const physics::Scenario& s, const physics::World& world, const SteadyWindow& steady, RunSummary& r) {
  const double n = static_cast<double>(steady.steps);
  r.sim_seconds = world.time_s();
  r.steps = world.steps();
  r.profile = world.profile();
  r.steady_steps = steady.steps;
  r.power = steady.power;
  r.dropped_contacts = world.dropped_contacts();
  r.stiffness_table_misses = world.stiffness_table_misses();
  const double h = s.solver.time_step_s;
  r.bodies = body_results(s, world, steady, h);
  if (s.transmission && steady.steps) {
    const double out = r.bodies[static_cast<std::size_t>(body_of_joint(s, s.transmission->output_joint))].mean_absolute_speed_rad_s;
    const double in = r.bodies[static_cast<std::size_t>(body_of_joint(s, s.transmission->input_joint))].mean_absolute_speed_rad_s;
    r.ratio = out != 0 ? in / out : 0.0;
  }
  for (std::size_t p = 0; p < world.gear_pairs().size(); ++p)
    r.pairs.push_back(
        {world.gear_pairs()[p], steady.steps ? steady.flank_sum[p][0] / n : 0.0, steady.steps ? steady.flank_sum[p][1] / n : 0.0});
}

// Numerical trouble counted over the run, one sentence each (never printed mid-run).
std::vector<std::string> warnings_of(const RunSummary& r) {
  std::vector<std::string> w;
  if (r.dropped_contacts > 0)
    w.push_back(std::to_string(r.dropped_contacts) + " tooth contacts dropped: a gear pair touched on more than 4 tooth pairs at once");
  if (r.stiffness_table_misses > 0)
    w.push_back(std::to_string(r.stiffness_table_misses) +
                " contact samples (per step) lay outside their pair's stiffness table and took its end row's value: "
                "extend the table over the flank");
  if (const double limit = penetration_warning_m(r); r.max_penetration_m > limit)
    w.push_back("deepest tooth penetration " + std::to_string(r.max_penetration_m * 1e6) + " um exceeds " + std::to_string(limit * 1e6) +
                " um (the larger of 10 um and twice a steel tooth pair's deflection under the heaviest mesh's mean force): interference or "
                "a time step too large "
                "for the contact stiffness");
  if (r.power.samples() > 1 && std::abs(r.power.imbalance_fraction()) > kPowerImbalanceWarning)
    w.push_back("power balance off by " + std::to_string(100 * r.power.imbalance_fraction()) +
                " % of the motor input: the solver is not converged (more iterations or a smaller time step)");
  return w;
}

// Every observer's on_stop(), also after one fails: an output not written makes the run
// OutputFailed and is named in not_written.
void stop_observers(const std::vector<Observer*>& observers, const physics::World& world, RunSummary& r) {
  for (Observer* o : observers) try {
      o->on_stop(world);
    } catch (const OutputError& e) {
      r.status = RunStatus::OutputFailed;
      r.not_written.push_back(e.what());
    }
}

}  // namespace

const char* status_name(RunStatus s) {
  switch (s) {
    case RunStatus::Completed:
      return "completed";
    case RunStatus::Diverged:
      return "diverged";
    case RunStatus::Interrupted:
      return "interrupted";
    case RunStatus::OutputFailed:
      return "output_failed";
  }
  return "unknown";
}

long output_interval_steps(const physics::Scenario& s) {
  return std::max(1L, std::lround(1.0 / (s.output.sample_rate_hz * s.solver.time_step_s)));
}

int body_of_joint(const physics::Scenario& s, const std::string& joint) {
  for (const physics::JointDef& j : s.joints)
    if (j.name == joint)
      for (std::size_t b = 0; b < s.bodies.size(); ++b)
        if (s.bodies[b].name == j.body) return static_cast<int>(b);
  throw InputError(s.source.string() + ": transmission: no joint named '" + joint + "'");
}

RunSummary simulate(const physics::Scenario& s, const std::vector<Observer*>& observers, const SimOptions& options) {
  const auto wall0 = std::chrono::steady_clock::now();
  physics::World world(s);
  for (Observer* o : observers) o->on_start(world);
  RunSummary r;
  r.time_step_s = s.solver.time_step_s;
  r.steady_from_s = physics::ramps_end_s(s);
  const long total = std::lround(s.duration_s / r.time_step_s);
  const long every = output_interval_steps(s);
  RunBounds bounds(s, world);
  SteadyWindow steady(world);
  r.setup_wall_seconds = seconds_since(wall0);
  const auto sample = [&] {
    for (Observer* o : observers) o->on_sample(world);
  };
  // An observer whose writes failed ends the run here: nothing after it could be kept.
  const auto write_failed = [&] {
    return std::any_of(observers.begin(), observers.end(), [](const Observer* o) { return o->write_failed(); });
  };
  try {
    for (long i = 1; i <= total; ++i) {
      world.step();
      for (Observer* o : observers) o->on_step(world);
      r.max_penetration_m = std::max(r.max_penetration_m, world.max_penetration_m());
      // A run out of its physical bounds stops at this step, its last sample taken.
      r.divergence = bounds.check(world);
      if (r.divergence) {
        r.status = RunStatus::Diverged;
        if (i % every != 0) sample();
      }
      if (!r.divergence && world.time_s() >= r.steady_from_s)
        steady.add(world);
      else if (steady.steps == 0)
        steady.track(world);
      if (i % every == 0) {
        sample();
        if (write_failed()) {
          r.status = RunStatus::OutputFailed;
          break;
        }
      }
      if (r.divergence) break;
      if (options.progress) options.progress(i, total, world.time_s());
      if (const int stop = options.stop_requested ? options.stop_requested() : 0; stop != 0) {
        r.status = RunStatus::Interrupted;
        r.stop_signal = stop;
        if (i % every != 0) sample();
        break;
      }
    }
  } catch (...) {
    // An exception out of a step (a bug, or the world refusing a state) keeps the logs up to it.
    stop_observers(observers, world, r);
    throw;
  }
  stop_observers(observers, world, r);
  r.wall_seconds = seconds_since(wall0);
  r.created_energy_J = bounds.created_energy_J();
  fill_results(s, world, steady, r);
  r.warnings = warnings_of(r);
  return r;
}

}  // namespace gearsim::sim

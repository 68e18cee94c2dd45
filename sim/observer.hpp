// What watches a run: simulate() (simulate.hpp) calls each observer as the world advances. The
// log writers (csv_logs.hpp, step_log.hpp) are observers; so is anything a caller adds (a live
// plot, a Python callback). Observers read the world; they never change it.
#pragma once

#include "physics/world.hpp"

namespace gearsim::sim {

class Observer {
 public:
  virtual ~Observer() = default;
  // Once, after the world is built and before the first step (t = 0).
  virtual void on_start(const physics::World& /*world*/) {}
  // After every step.
  virtual void on_step(const physics::World& /*world*/) {}
  // At every output sample (every 1/sample_rate_hz of simulated time), and once more at the
  // step a run stops early on (diverged or interrupted) when that step is not a sample already:
  // every output file then ends at the same time.
  virtual void on_sample(const physics::World& /*world*/) {}
  // Once, when the run ends for whatever reason: flush, close and put the outputs in place
  // (core/output_file.hpp); OutputError naming each output that could not be written.
  virtual void on_stop(const physics::World& /*world*/) {}
  // True once a write of this observer's outputs has failed (a full disk): simulate() stops the
  // run at the next output sample, status OutputFailed, and on_stop() says which and why.
  virtual bool write_failed() const { return false; }
};

}  // namespace gearsim::sim

// The output-rate logs of a run as an observer: state.csv (every body's angle and speed, and the
// transmission error when the scenario names a transmission) and contacts.csv (per gear pair the
// summed normal force, the tooth pairs in contact and the deepest penetration), one row per output
// sample, 17 significant digits, SI units in every column name. Point samples of the step at the
// sample time (not filtered).
#pragma once

#include <filesystem>
#include <fstream>

#include "physics/scenario.hpp"
#include "sim/observer.hpp"

namespace gearsim::sim {

class CsvLogs : public Observer {
 public:
  // DIR/state.csv and DIR/contacts.csv, created when the run starts (a scenario the world refuses
  // leaves no empty logs); InputError naming the file when one cannot be written. The scenario
  // must outlive the observer.
  CsvLogs(const std::filesystem::path& dir, const physics::Scenario& scenario);
  void on_start(const physics::World& world) override;
  void on_sample(const physics::World& world) override;
  void on_stop(const physics::World& world) override;

 private:
  std::filesystem::path dir_;
  const physics::Scenario& scenario_;
  std::ofstream state_, contacts_;
  int te_in_ = -1, te_out_ = -1;  // bodies of the transmission's input and output joints
};

}  // namespace gearsim::sim

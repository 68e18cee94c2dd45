// StepLog: the per-step binary log of a run, as HDF5 (readable by h5py, MATLAB, h5dump without
// our code). /state holds one row per step (time_s, then angle_rad and speed_rad_s of every
// body); /contacts holds one row per tooth-pair contact per step, column by column (time_s,
// step, pair, tooth_a, tooth_b, flank_a, point_x_m, point_y_m, normal_x, normal_y, depth_m,
// normal_impulse_N_s, friction_impulse_N_s); /pairs names the gear pairs "a__b". Rows are
// buffered and written in chunks; close() (or the destructor) leaves a valid file also after an
// interrupted run. Not a CSV writer and not a reader.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <utility>

#include "physics/world.hpp"
#include "sim/observer.hpp"

namespace gearsim::sim {

class StepLog {
 public:
  // Creates (truncates) the file. Throws InputError naming the path when it cannot.
  StepLog(const std::filesystem::path& path, const physics::World& world, const std::string& scenario_name,
          double time_step_s);
  ~StepLog();
  StepLog(const StepLog&) = delete;
  StepLog& operator=(const StepLog&) = delete;

  // Appends the world's state and contacts of its last step.
  void append(const physics::World& world);
  // Writes what is buffered and closes the file; further appends are errors.
  void close();
  // Bytes written so far (after the last flush), for the log-size report.
  std::uintmax_t bytes_on_disk() const;

  struct Impl;

 private:
  std::unique_ptr<Impl> impl_;
};

// The per-step log as a run observer (sim/observer.hpp): the file is created when the run starts,
// every step appended, closed when it stops.
class StepLogObserver : public Observer {
 public:
  StepLogObserver(std::filesystem::path path, std::string scenario_name, double time_step_s)
      : path_(std::move(path)), name_(std::move(scenario_name)), dt_(time_step_s) {}
  void on_start(const physics::World& world) override { log_ = std::make_unique<StepLog>(path_, world, name_, dt_); }
  void on_step(const physics::World& world) override { log_->append(world); }
  void on_stop(const physics::World&) override {
    if (log_) log_->close();
  }
  std::uintmax_t bytes_on_disk() const { return log_ ? log_->bytes_on_disk() : 0; }

 private:
  std::filesystem::path path_;
  std::string name_;
  double dt_;
  std::unique_ptr<StepLog> log_;
};

}  // namespace gearsim::sim

// StepLog: the per-step binary log of a run, as HDF5 (readable by h5py, MATLAB, h5dump without
// our code; layout, types and resolution per column in docs/hdf5-log.md, format 2). /state holds
// one row per step (angle_rad and speed_rad_s of every body, float64); /contacts one row per
// tooth-pair contact per step, column by column (step, pair, tooth_a, tooth_b, flank_a as narrow
// ints; point_x_m, point_y_m, normal_x, normal_y, depth_m, friction_impulse_N_s as float32;
// normal_impulse_N_s as float64). Time is stored once, as the attribute time_step_s: step k ends
// at k·time_step_s. Rows are buffered and written every few thousand steps, into a temporary
// file beside the target; close() (or the destructor, while an exception unwinds) puts a valid
// file holding every appended step in place (core/output_file.hpp) — or, when a write failed (a
// full disk), removes it and says so. Not a CSV writer and not a reader (step_log_reader.hpp).
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <utility>

#include "physics/world.hpp"
#include "sim/observer.hpp"
#include "sim/sensor_log.hpp"

namespace gearsim::sim {

class StepLog {
 public:
  // Creates the file (under a temporary name). Throws OutputError naming the path when it cannot. With sensor
  // names, a dataset /sensors holds one value per sensor and step (docs/hdf5-log.md).
  StepLog(const std::filesystem::path& path, const physics::World& world, const std::string& scenario_name, double time_step_s,
          const std::vector<std::string>& sensor_names = {});
  ~StepLog();
  StepLog(const StepLog&) = delete;
  StepLog& operator=(const StepLog&) = delete;

  // Appends the world's state and contacts of its last step, and the sensors' values then (one
  // per sensor name given at construction, m/s²).
  void append(const physics::World& world, const std::vector<double>& sensor_values_m_s2 = {});
  // Writes what is buffered, closes the file and puts it in place; further appends are errors.
  // OutputError naming the file and the reason when a write failed (nothing is put in place).
  void close();
  // True once a write failed (the rest of the run is not written).
  bool write_failed() const;
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
  // Also log the sensors' per-step values (SensorLog::step_acceleration_m_s2()); the SensorLog
  // must be an observer ahead of this one, so that its values are the same step's.
  void log_sensors(const SensorLog* sensors) { sensors_ = sensors; }
  void on_start(const physics::World& world) override {
    log_ = std::make_unique<StepLog>(path_, world, name_, dt_, sensors_ ? sensors_->names() : std::vector<std::string>{});
  }
  void on_step(const physics::World& world) override {
    if (sensors_)
      log_->append(world, sensors_->step_acceleration_m_s2());
    else
      log_->append(world);
  }
  void on_stop(const physics::World&) override {
    if (log_) log_->close();
  }
  bool write_failed() const override { return log_ && log_->write_failed(); }
  std::uintmax_t bytes_on_disk() const { return log_ ? log_->bytes_on_disk() : 0; }

 private:
  std::filesystem::path path_;
  std::string name_;
  double dt_;
  std::unique_ptr<StepLog> log_;
  const SensorLog* sensors_ = nullptr;
};

}  // namespace gearsim::sim

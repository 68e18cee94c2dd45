// Virtual accelerometers (physics::SensorDef, the McFadden & Smith planet-pass model) as an
// observer: every step each sensor's path-weighted sum of the tooth-contact forces drives its
// structural mode (analysis/resonator.hpp); the acceleration is low-passed and decimated to the
// sensors' sample rate (analysis/decimator.hpp, the same anti-aliasing design as contacts.csv),
// seeded measurement noise is added, and the rows go to DIR/sensors.csv:
// time_s,<sensor>_acceleration_m_s2,… docs/condition-monitoring.md.
#pragma once

#include <memory>

#include "core/output_file.hpp"

#include <filesystem>
#include <fstream>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "analysis/decimator.hpp"
#include "analysis/resonator.hpp"
#include "physics/scenario.hpp"
#include "sim/observer.hpp"

namespace gearsim::sim {

// The path gain of a contact at `point` for a sensor at `sensor_angle_rad` about `centre`: the
// Hann window of their angular distance (1 under the sensor, 0 beyond ±width/2).
double planet_pass_window(const Eigen::Vector2d& point, const Eigen::Vector2d& centre, double sensor_angle_rad, double width_rad);

class SensorLog : public Observer {
 public:
  // The scenario must outlive the observer and hold at least one sensor.
  SensorLog(const std::filesystem::path& dir, const physics::Scenario& scenario);
  void on_start(const physics::World& world) override;
  void on_step(const physics::World& world) override;
  void on_stop(const physics::World& world) override;
  bool write_failed() const override;
  // Each sensor's acceleration at the last step, before the acquisition's anti-aliasing filter,
  // decimation and noise, m/s² (what the per-step log records), and the sensors' names.
  const std::vector<double>& step_acceleration_m_s2() const { return row_; }
  std::vector<std::string> names() const;

 private:
  struct Channel {
    const physics::SensorDef* def = nullptr;
    Eigen::Vector2d centre = Eigen::Vector2d::Zero();
    std::vector<char> on_body;  // per gear pair: a mesh on the sensor's body
    Resonator mode;
  };
  void push(const physics::World& world);
  void write(const DecimatedRow& row);
  std::filesystem::path file_;
  const physics::Scenario& scenario_;
  std::unique_ptr<OutputFile> out_;
  std::vector<Channel> channels_;
  std::optional<Decimator> decimator_;
  std::vector<double> row_;
  std::mt19937_64 noise_;
  std::string row_text_;  // write(): a row's text before it is written
};

}  // namespace gearsim::sim

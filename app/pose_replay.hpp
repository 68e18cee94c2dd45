// Body poses of a finished run at any time, replayed from its state.csv: each body's logged
// angle about its joint (relative to the parent) composed down the joint chain, its pivot carried
// by the parent. Planar (all axes along z, as tooth contact requires); a bearing's radial float
// (µm) is not in state.csv and is not replayed. Not physics: nothing is integrated.
#pragma once

#include <Eigen/Geometry>

#include <string>
#include <vector>

#include "input/csv_table.hpp"
#include "physics/scenario.hpp"

namespace gearsim::app {

class PoseReplay {
 public:
  // InputError when state.csv lacks a body's angle column or a joint is not about z.
  PoseReplay(const physics::Scenario& scenario, input::CsvTable state);

  double start_s() const { return time_.front(); }
  double end_s() const { return time_.back(); }
  // Body frame → world of every scenario body at time t (linear interpolation of the angles),
  // in scenario order, m. t is clamped to nothing: outside [start, end] is an InputError.
  std::vector<Eigen::Isometry3d> poses(double t) const;

 private:
  const physics::Scenario& s_;
  std::vector<double> time_;
  std::vector<const std::vector<double>*> angle_;  // per body, null for a body without a joint
  std::vector<int> parent_;  // body index of the joint parent, −1: ground/none
  std::vector<Eigen::Vector3d> pivot0_;  // joint pivot, world at t = 0
  std::vector<double> angle0_;  // body frame's angle about z at t = 0
  input::CsvTable state_;
};

}  // namespace gearsim::app

// PowerBalance: the means of a run's power flows (World::power(), one sample per step) over a
// window, and how well they balance: what the motors put in leaves through the loads, is
// dissipated by tooth contacts (friction, contact damping) and joints (bearing damping), or is
// stored as kinetic energy. Not a checker: the caller decides what imbalance is acceptable.
#pragma once

#include "physics/world.hpp"

namespace gearsim::sim {

class PowerBalance {
 public:
  // One step's flows at time t (s); the first call opens the window.
  void add(const physics::PowerFlows& p, double time_s);

  long samples() const { return n_; }
  double motor_W() const { return mean(sum_.motor_W); }
  double load_W() const { return mean(sum_.load_W); }
  double contact_W() const { return mean(sum_.contact_W); }
  double joint_W() const { return mean(sum_.joint_W); }
  // Rate of change of the bodies' kinetic energy over the window, W.
  double kinetic_rate_W() const;
  // Sum of all mean flows minus the kinetic rate, divided by the motor input: the share of the
  // input power the measured flows do not account for (0 for a perfect balance).
  double imbalance_fraction() const;

 private:
  double mean(double sum) const { return n_ > 0 ? sum / static_cast<double>(n_) : 0.0; }
  physics::PowerFlows sum_, first_, last_;
  double t_first_ = 0, t_last_ = 0;
  long n_ = 0;
};

}  // namespace gearsim::sim

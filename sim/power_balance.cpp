#include "sim/power_balance.hpp"

namespace gearsim::sim {

void PowerBalance::add(const physics::PowerFlows& p, double time_s) {
  if (n_ == 0) {
    first_ = p;
    t_first_ = time_s;
  }
  last_ = p;
  t_last_ = time_s;
  sum_.motor_W += p.motor_W;
  sum_.load_W += p.load_W;
  sum_.contact_W += p.contact_W;
  sum_.joint_W += p.joint_W;
  sum_.impulse_W += p.impulse_W;
  ++n_;
}

double PowerBalance::kinetic_rate_W() const {
  return t_last_ > t_first_ ? (last_.kinetic_J - first_.kinetic_J) / (t_last_ - t_first_) : 0.0;
}

double PowerBalance::imbalance_fraction() const {
  const double in = motor_W();
  if (in == 0) return 0;
  return (motor_W() + load_W() + contact_W() + joint_W() + mean(sum_.impulse_W) - kinetic_rate_W()) / in;
}

}  // namespace gearsim::sim

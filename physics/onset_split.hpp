// verify.locate_contact_onset (docs/solver.md, "Contact onset"): a multibody step in which a near
// tooth pair closes is split at the instant it touches, so that the contact starts with its
// spring at rest; the sub-steps' impulses summed per contact (the step's forces: their sum over
// h), its power flows and motor torques averaged. The multibody engine takes the pieces; this
// says where to cut and sums what they did. Internal to physics/.
#pragma once

#include <vector>

#include "physics/model.hpp"
#include "physics/state.hpp"
#include "physics/world.hpp"

namespace gearsim::physics {

// At most this many splits of one step (a step with more onsets takes the rest late, as without
// the option), and no piece shorter than this fraction of the step (a pair that close starts
// with the piece: its onset is late by less).
constexpr int kMaxOnsetSplits = 4;
constexpr double kMinOnsetFraction = 0.01;

class OnsetSplit {
 public:
  OnsetSplit() = default;
  explicit OnsetSplit(bool on) : on_(on) {}
  bool on() const { return on_; }  // verify.locate_contact_onset (and an equal-step integrator)
  // Where to cut the rest of the step (within_s long) from the near pairs of state.pairs and the
  // bodies' velocities: within_s when no pair touches before it.
  double onset_s(const Model& model, const State& state, double within_s) const;
  // The sub-step of length h just taken (state's contacts and power, the motors' torques) into
  // the step's sums; `first`: the step's first piece.
  void accumulate(const State& state, const std::vector<double>& motor_torque, double h, bool first);
  // The step's contacts, power flows and motor torques from the sums (the step of length h).
  void finish(State& state, std::vector<double>& motor_torque, double h) const;

 private:
  bool on_ = false;
  struct Accumulated {
    std::vector<ContactSample> contacts;  // impulse-weighted: normal_force_N · h_sub summed
    PowerFlows power;
    std::vector<double> motor_torque;
  } accumulated_;
};

}  // namespace gearsim::physics

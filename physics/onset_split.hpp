// solver.locate_contact_onset (docs/solver.md, "Contact onset"): a multibody step in which a near
// tooth pair closes is split at the instant it touches; the sub-steps' impulses summed per
// contact (the step's forces: their sum over h), its power flows and motor torques averaged.
// Internal to physics/.
#pragma once

#include <vector>

#include "physics/world.hpp"

namespace gearsim::physics {

// At most this many splits of one step (a step with more onsets takes the rest late, as without
// the option), and no piece shorter than this fraction of the step (a pair that close starts
// with the piece: its onset is late by less).
constexpr int kMaxOnsetSplits = 4;
constexpr double kMinOnsetFraction = 0.01;

struct OnsetSplit {
  bool on = false;  // solver.locate_contact_onset (and an equal-step integrator)
  struct Accumulated {
    std::vector<ContactSample> contacts;  // impulse-weighted: normal_force_N · h_sub summed
    PowerFlows power;
    std::vector<double> motor_torque;
  } accumulated;
};

}  // namespace gearsim::physics

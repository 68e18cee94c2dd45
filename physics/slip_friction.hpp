// contact.friction_model sliding in the multibody engine (docs/solver.md, "Friction at the pitch
// point"): each friction row a fixed multiple of its normal's impulse, −μ·λ_n times the mean sign
// of the slip over the step, shared at the reversal. Its working data, kept from step to step.
// Internal to physics/.
#pragma once

#include <utility>
#include <vector>

#include "physics/state.hpp"

namespace gearsim::physics {

// The step is solved again while a friction share differs from the one its end slip asks for by
// more than kSlipShareTolerance (an impulse error of that fraction of μ·λ_n·h), at most
// kSlipRounds times.
constexpr int kSlipRounds = 30;
constexpr double kSlipShareTolerance = 1e-6;

struct SlipFriction {
  bool on = false;  // contact.friction_model sliding
  // Per row, its slip's change over the step by the contact's travel (slip_drift()), m/s; each
  // friction row's tooth pair and slip at the step's end, this step's and the last's, and the
  // length of the (sub)step those end slips close.
  std::vector<double> drift;
  double end_h = 0;
  std::vector<std::pair<ContactKey, double>> end, end_before;
  // Per row, the bracket of its friction share's root: the shares below and above it tried so
  // far and the g they gave (g_lo > 0 > g_hi once both are known).
  struct Bracket {
    double lo = -1, g_lo = 0, hi = 1, g_hi = 0;
    int last = 0;  // which end the last round moved: +1 lo, −1 hi
  };
  std::vector<Bracket> brackets;
};

}  // namespace gearsim::physics

// verify.friction_model sliding in the multibody engine (docs/solver.md, "Friction at the pitch
// point"): each friction row a fixed multiple of its normal's impulse, −μ·λ_n times the mean sign
// of the slip over the step, the reversal at the pitch point shared within the step where it
// falls. The rule and what it keeps from step to step (each contact's end slip, for the drift of
// the next; each row's bracket of its share); the engine solves the rows again while a share
// changes (multibody_solve.cpp). Internal to physics/.
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

#include "physics/multibody_rows.hpp"
#include "physics/state.hpp"

namespace gearsim::physics {

// The step is solved again while a friction share differs from the one its end slip asks for by
// more than kSlipShareTolerance (an impulse error of that fraction of μ·λ_n·h), at most
// kSlipRounds times.
constexpr int kSlipRounds = 30;
constexpr double kSlipShareTolerance = 1e-6;

class SlipFriction {
 public:
  SlipFriction() = default;
  explicit SlipFriction(bool on) : on_(on) {}
  bool on() const { return on_; }  // verify.friction_model sliding

  // Before the step's rows are set up (n of them).
  void begin_rows(std::size_t n);
  // Row i of rows at setup, s0 its rate at the step's start, contacts the step's: a friction row
  // sliding at the step's start is held at μ·λ_n against that slip (lo = hi), and its drift
  // (slip change by the contact's travel over a step of h_step) taken from the last step.
  void start_row(RowSystem& rows, std::size_t i, const std::vector<ContactSample>& contacts, double s0, double h_step);
  // Before the rounds of a step's solve.
  void begin_rounds(std::size_t n) { brackets_.assign(n, Bracket{}); }
  // One round: where a friction row's slip at the step's end (J·(v* + dv) plus its drift) asks
  // for another share than it was solved with, its bounds moved to the next guess of its root.
  // True when a row's changed (the rows are to be solved again).
  bool reshare(RowSystem& rows, const double* dv);
  // Each contact's slip at the step's end (J·(v* + dv)) for the next step's drift, the (sub)step
  // of length h_step closing them.
  void record_end_slips(const RowSystem& rows, const std::vector<ContactSample>& contacts, const double* dv, double h_step);

 private:
  double drift_of(const ContactKey& key, double s0);

  bool on_ = false;
  // Per row, its slip's change over the step by the contact's travel, m/s; each friction row's
  // tooth pair and slip at the step's end, this step's and the last's, and the length of the
  // (sub)step those end slips close; where the search for a key starts.
  std::vector<double> drift_;
  double end_h_ = 0;
  std::vector<std::pair<ContactKey, double>> end_, end_before_;
  std::size_t hint_ = 0;
  // Per row, the bracket of its friction share's root: the shares below and above it tried so
  // far and the g they gave (g_lo > 0 > g_hi once both are known).
  struct Bracket {
    double lo = -1, g_lo = 0, hi = 1, g_hi = 0;
    int last = 0;  // which end the last round moved: +1 lo, −1 hi
  };
  std::vector<Bracket> brackets_;
};

}  // namespace gearsim::physics

// How the multibody engine integrates (solver.integrator, docs/solver.md): the θ-method (spring
// rows at s + θ·h·ṡ_θ, positions with (1 − θ)·v + θ·v⁺; θ = 1: implicit Euler), trapezoid_closed
// (θ per step: ½ while every contact stays closed, more where one is new) and BDF2 (v⁺ = v̂ +
// h_eff·M⁻¹·F(x⁺, v⁺), x⁺ = x + h·v_move with v̂ = (4v − v_prev)/3, h_eff = 2h/3, v_move =
// (v_move_prev + 2v⁺)/3; implicit Euler until there is a step behind). The spring–damper row of
// each, the step's effective length and the velocities the positions and the rows' work move
// with; the joint velocities it keeps from step to step. Internal to physics/.
#pragma once

#include <Eigen/Dense>

#include <vector>

#include "physics/model.hpp"
#include "physics/multibody_rows.hpp"
#include "physics/state.hpp"

namespace gearsim::physics {

class Integrator {
 public:
  Integrator() = default;
  // For solver (its integrator, θ and time step) on a tree of `dofs` coordinates.
  Integrator(const SolverDef& solver, int dofs);

  bool bdf2() const { return bdf2_; }
  // A (sub)step of length h from the joint velocities v (dofs entries): h_eff and the start kept;
  // returns the velocities the step starts from instead where BDF2 extrapolates them (v̂), else
  // nullptr.
  const double* start(double h, const double* v);
  // trapezoid_closed: θ of this step from its tooth contacts (before its rows are formed).
  void choose_theta(const Model& model, const State& state);
  // A spring–damper row (stiffness k, damping c) whose spring force at the start of the step is
  // force0.
  MultibodyRow spring_row(double k, double c, double force0) const;
  // Whether the rows take the last step's v_move (BDF2 with a step behind).
  bool two_step() const { return bdf2_ && has_history_; }
  // After the solve, from v⁺ (v_end): the velocities the positions move with (v_end itself for
  // implicit Euler); BDF2's history moves on.
  const double* position_velocities(const double* v_end);
  // The velocities the positions moved with over the step (v_end: v⁺), for the rows' work.
  const Eigen::VectorXd& work_velocities(const double* v_end);

  double h_eff() const { return h_eff_; }  // this step's h_eff (h for the θ-method), s
  double h_step() const { return h_step_; }  // this (sub)step's length, s
  const std::vector<double>& v_start() const { return v_start_; }
  const std::vector<double>& v_move() const { return v_move_; }
  const std::vector<double>& v_mid() const { return v_mid_; }
  const std::vector<double>& v_end() const { return v_end_; }

 private:
  double trapezoid_closed_theta(const Model& model, const State& state);

  int dofs_ = 0;
  double time_step_s_ = 0;
  double theta_ = 1;
  bool bdf2_ = false, has_history_ = false, trapezoid_closed_ = false, two_step_ = false;
  double h_eff_ = 0, h_step_ = 0;
  std::vector<double> v_start_, v_end_, v_mid_;  // joint velocities at the step's start, end, mean
  std::vector<double> v_prev_, v_move_;  // BDF2: v at the last step's start; the last step's v_move
  Eigen::VectorXd v_theta_;
  std::vector<ContactKey> touching_, touching_before_;  // trapezoid_closed: this step's contacts, the last's
};

}  // namespace gearsim::physics

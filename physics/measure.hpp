// What both engines measure from the bodies they move: joint angles and speeds from the bodies'
// transforms and velocities, kinetic energy, the power of the scenario's force and torque pulses.
// (The multibody engine's planar path has closed forms of the first two: planar_kinematics.hpp.)
// Internal to physics/.
#pragma once

#include "physics/model.hpp"
#include "physics/state.hpp"

namespace gearsim::physics {

// The angle of joint j's body about its axis against its parent (the gear frames' x axes, as
// measured from the bodies' transforms), in (−π, π].
double joint_raw_angle(const Model& model, const ModelJoint& j);

// state.bodies: each joint's unwrapped angle and speed, each body's gear-frame origin.
void measure_joints_from_bodies(const Model& model, State& state);

// Kinetic energy of all bodies from their rigid bodies' velocities and inertia tensors, J.
double kinetic_energy_of_bodies_J(const Model& model);

// Power of the force and torque pulses applied in the (sub)step of length h just taken (at
// state.time − h), with the bodies' velocities after it, as load_W takes its joint speeds, W.
double impulse_power_W(const Model& model, const State& state, double h);

}  // namespace gearsim::physics

// How a World steps (solver.engine): one interface, two engines that each own their step and
// their working storage — rigid_body_engine.hpp (Bullet's btDiscreteDynamicsWorld: rigid bodies,
// hinges or bearing springs, tooth contacts as manifold points, sequential impulses) and
// multibody_engine.hpp (the joint tree as one btMultiBody, every other interaction a row of one
// direct solve). An engine reads the model (model.hpp) and writes the state (state.hpp): World
// (world.hpp) owns all three and calls nothing else. Internal to physics/.
#pragma once

#include <cstddef>
#include <memory>

#include "physics/model.hpp"
#include "physics/state.hpp"
#include "physics/world.hpp"

namespace gearsim::physics {

class Engine {
 public:
  virtual ~Engine() = default;
  // One step of the scenario's time step: the state's time, steps, bodies, contacts, power flows
  // and counters after it.
  virtual void step() = 0;
  // Torque the motor of joint `joint` (an index into Model::joints) applied in the last step, N·m.
  virtual double motor_torque_N_m(std::size_t joint) const = 0;
  // Steps since construction whose row solve found no solution (World::failed_solves()).
  virtual long failed_solves() const { return 0; }
  // World::set_mass_matrix_check, World::mass_matrix_check(): the multibody engine's only.
  virtual void set_mass_matrix_check(bool) {}
  virtual const World::MassMatrixCheck& mass_matrix_check() const;
};

// The engine solver.engine names, built on the model, its start measured into the state. Throws
// InputError where the scenario does not suit that engine.
std::unique_ptr<Engine> make_engine(const Model& model, State& state);

}  // namespace gearsim::physics

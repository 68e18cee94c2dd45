#include "physics/engine.hpp"

#include "physics/multibody_engine.hpp"
#include "physics/rigid_body_engine.hpp"

namespace gearsim::physics {

const World::MassMatrixCheck& Engine::mass_matrix_check() const {
  static const World::MassMatrixCheck kNone;
  return kNone;
}

std::unique_ptr<Engine> make_engine(const Model& model, State& state) {
  if (model.scenario.solver.engine == SolverEngine::multibody) return std::make_unique<MultibodyEngine>(model, state);
  return std::make_unique<RigidBodyEngine>(model, state);
}

}  // namespace gearsim::physics

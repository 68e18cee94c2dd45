#include "physics/world.hpp"

#include "core/errors.hpp"
#include "physics/engine.hpp"
#include "physics/model.hpp"
#include "physics/state.hpp"

// World: the model built from the scenario, the state it starts in and the engine that steps it
// (engine.hpp); every accessor reads the state or the model, or asks the engine.
namespace gearsim::physics {

struct World::Impl {
  explicit Impl(const Scenario& s) : model(s), state(model), engine(make_engine(model, state)) {}
  const Model model;
  State state;
  std::unique_ptr<Engine> engine;  // destroyed first: it takes its objects out of Bullet's world
};

World::World(const Scenario& s) : impl_(std::make_unique<Impl>(s)) {}

World::~World() = default;

void World::step() {
  State& state = impl_->state;
  const std::uint64_t start = state.clock.now();
  impl_->engine->step();
  state.step_total_ticks += state.clock.now() - start;
}

const World::Profile& World::profile() const {
  State& m = impl_->state;
  const double per_tick = m.clock.seconds_per_tick();
  m.profile.tooth_contact_s = static_cast<double>(m.tooth_contact_ticks) * per_tick;
  m.profile.row_solve_s = static_cast<double>(m.row_solve_ticks) * per_tick;
  m.profile.step_total_s = static_cast<double>(m.step_total_ticks) * per_tick;
  m.profile.flank_visits = {};
  for (const PairContacts& pr : m.pairs) m.profile.flank_visits += pr.search.counts();
  return m.profile;
}

double World::time_s() const { return impl_->state.time; }
long World::steps() const { return impl_->state.steps; }
const std::vector<BodyState>& World::bodies() const { return impl_->state.bodies; }
const std::vector<ContactSample>& World::contacts() const { return impl_->state.contacts; }
const std::vector<GearPairInfo>& World::gear_pairs() const { return impl_->model.pair_infos; }
double World::max_penetration_m() const { return impl_->state.max_penetration; }
const PowerFlows& World::power() const { return impl_->state.power; }
long World::dropped_contacts() const { return impl_->state.dropped_points; }
long World::stiffness_table_misses() const { return impl_->state.table_misses; }
long World::failed_solves() const { return impl_->engine->failed_solves(); }
void World::set_mass_matrix_check(bool on) { impl_->engine->set_mass_matrix_check(on); }
const World::MassMatrixCheck& World::mass_matrix_check() const { return impl_->engine->mass_matrix_check(); }

double World::motor_torque_N_m(const std::string& joint) const {
  const std::vector<ModelJoint>& joints = impl_->model.joints;
  for (std::size_t j = 0; j < joints.size(); ++j)
    if (joints[j].def.name == joint) return impl_->engine->motor_torque_N_m(j);
  throw InputError("no joint named '" + joint + "'");
}

WorldStructure World::structure() const {
  const Model& m = impl_->model;
  WorldStructure w;
  for (const BuiltBody& b : m.bodies) {
    StructureBody sb;
    sb.name = b.name;
    sb.mass_kg = b.mass_kg;
    sb.inertia_z_kg_m2 = b.inertia_axis_kg_m2;
    const btVector3 c = b.rigid->getCenterOfMassPosition();
    sb.centre_of_mass_m = {c.x(), c.y()};
    sb.fixed = b.fixed;
    sb.flanks = b.flanks.get();
    if (b.flanks) sb.gear_pose = planar_pose(b);
    w.bodies.push_back(sb);
  }
  for (const ModelJoint& j : m.joints) w.joints.push_back({&j.def, j.body, j.parent, j.motor, j.load});
  for (std::size_t p = 0; p < m.pairs.size(); ++p) w.pairs.push_back({m.pairs[p].a, m.pairs[p].b, &m.pair_infos[p], m.pairs[p].stiffness});
  return w;
}

}  // namespace gearsim::physics

#include "physics/tooth_contacts.hpp"

#include <algorithm>

namespace gearsim::physics {
namespace {

// A gear's planar velocity: its centre's (state.gear_poses[i].centre_m) and its angular
// velocity, world.
contact::CoherentToothSearch::PlanarTwist gear_twist(const Model& model, const State& state, std::size_t i) {
  const btRigidBody& r = *model.bodies[i].rigid;
  const contact::PlanarPose& p = state.gear_poses[i];
  const btVector3 at(p.centre_m.x(), p.centre_m.y(), r.getCenterOfMassPosition().z());
  const btVector3 v = r.getVelocityInLocalPoint(at - r.getCenterOfMassPosition());
  return {Eigen::Vector2d(v.x(), v.y()), r.getAngularVelocity().z()};
}

}  // namespace

void gear_poses_from_bodies(const Model& model, State& state) {
  state.gear_poses.resize(model.bodies.size());
  for (std::size_t i = 0; i < model.bodies.size(); ++i)
    if (model.bodies[i].flanks) state.gear_poses[i] = planar_pose(model.bodies[i]);
}

void find_tooth_contacts(const Model& model, State& state, const ContactSearchOptions& options) {
  const ContactDef& cd = model.scenario.contact;
  state.max_penetration = 0;
  // Where the near pairs predict onsets and some may be parked, each gear's velocity too: a
  // parked pair must not be one that closes within the step (CoherentToothSearch::find()).
  const bool with_motion = options.near_pairs && cd.park_near_pairs;
  if (with_motion) {
    state.gear_twists.resize(model.bodies.size());
    for (std::size_t i = 0; i < model.bodies.size(); ++i)
      if (model.bodies[i].flanks) state.gear_twists[i] = gear_twist(model, state, i);
  }
  for (std::size_t p = 0; p < model.pairs.size(); ++p) {
    const ModelPair& mp = model.pairs[p];
    PairContacts& pr = state.pairs[p];
    const BuiltBody &a = model.bodies[mp.a], &b = model.bodies[mp.b];
    std::vector<contact::ToothContact>& found = pr.found;
    // Gears from a spec: the continued contact stands; CAD meshes: the deeper of it and the search's.
    using Continuation = contact::CoherentToothSearch::Continuation;
    pr.search.set_continuation(!cd.continued_search                       ? Continuation::off
                               : a.flanks_from_spec && b.flanks_from_spec ? Continuation::replace
                                                                          : Continuation::deeper);
    pr.search.set_park_near_pairs(cd.park_near_pairs);
    std::vector<contact::ToothContact>* near = options.near_pairs ? &pr.near : nullptr;
    contact::CoherentToothSearch::Motion motion;
    if (with_motion) motion = {state.gear_twists[mp.a], state.gear_twists[mp.b], model.scenario.solver.time_step_s};
    const contact::PlanarPose &pose_a = state.gear_poses[mp.a], &pose_b = state.gear_poses[mp.b];
    if (cd.coherent_search)
      pr.search.find(*a.flanks, pose_a, *b.flanks, pose_b, found, near, with_motion ? &motion : nullptr);
    else
      contact::find_tooth_contacts(*a.flanks, pose_a, *b.flanks, pose_b, found, near);
    const int limit = options.max_points_per_pair;
    if (limit > 0 && static_cast<int>(found.size()) > limit) {
      std::sort(found.begin(), found.end(),
                [](const contact::ToothContact& x, const contact::ToothContact& y) { return x.depth_m > y.depth_m; });
      state.dropped_points += static_cast<long>(found.size()) - limit;
      found.resize(static_cast<std::size_t>(limit));
    }
    // Each contact's stiffness, and whether it is passed to the solver.
    const contact::PlanarPose table_gear =
        mp.stiffness.table ? state.gear_poses[mp.stiffness.table_on_a ? mp.a : mp.b] : contact::PlanarPose{};
    state.table_misses += tooth_pair_stiffnesses(mp.stiffness, pr.found, table_gear, pr.pair_stiffness, pr.active);
    for (const contact::ToothContact& c : found) state.max_penetration = std::max(state.max_penetration, c.depth_m);
  }
}

}  // namespace gearsim::physics

// Each step's tooth contacts, the same for both engines: every gear pair's touching tooth pairs
// (and, where asked, its near ones) at the gears' planar poses in State::gear_poses, with the
// stiffness each is given. How the contacts then act (manifold points or rows) is the engine's.
// Internal to physics/.
#pragma once

#include <cstddef>

#include "physics/model.hpp"
#include "physics/state.hpp"

namespace gearsim::physics {

struct ContactSearchOptions {
  int max_points_per_pair = 0;  // > 0: the deepest this many kept per pair, the rest dropped and counted
  bool near_pairs = false;  // also the near pairs (verify.locate_contact_onset)
};

// state.pairs' found, near, pair_stiffness and active, state.max_penetration and the counters,
// from state.gear_poses (set by the caller for every gear).
void find_tooth_contacts(const Model& model, State& state, const ContactSearchOptions& options);

// The gears' planar poses from their bodies' transforms, into state.gear_poses.
void gear_poses_from_bodies(const Model& model, State& state);

}  // namespace gearsim::physics

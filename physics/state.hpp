// The mutable part of a World (in MuJoCo's terms its data): what a step changes — time, the
// bodies' measured states, this step's tooth contacts and each pair's search through them, the
// gears' planar poses, power flows, the counters a run reports and the profile's ticks. Plain
// data, written by the engines (engine.hpp) and the shared contact search (tooth_contacts.hpp),
// read by World's accessors. Not the model it belongs to (model.hpp), and not an engine's own
// working storage (each engine keeps that). Internal to physics/.
#pragma once

#include <cstdint>
#include <tuple>
#include <vector>

#include "contact/coherent_contact.hpp"
#include "contact/tooth_contact.hpp"
#include "physics/model.hpp"
#include "physics/profile_clock.hpp"
#include "physics/world.hpp"

namespace gearsim::physics {

// One gear pair's tooth contacts this step (the vectors keep their storage from step to step).
struct PairContacts {
  std::vector<contact::ToothContact> found;  // touching tooth pairs
  std::vector<contact::ToothContact> near;  // near pairs, a gap of a few µm (verify.locate_contact_onset)
  std::vector<double> pair_stiffness;  // per found contact, N/m
  std::vector<char> active;  // per found contact: passed to the solver
  contact::CoherentToothSearch search;  // the pair's flank records (verify.coherent_search)
};

// A joint's angle measured from its bodies' transforms, unwrapped across turns.
struct UnwrappedAngle {
  double last_raw = 0, unwrapped = 0;
};

struct State {
  explicit State(const Model& model);

  double time = 0;
  long steps = 0;
  std::vector<BodyState> bodies;  // per body
  std::vector<UnwrappedAngle> joint_angles;  // per joint (measured from the bodies' transforms)
  std::vector<ContactSample> contacts;  // of the last step
  std::vector<PairContacts> pairs;  // per gear pair
  std::vector<contact::PlanarPose> gear_poses;  // this step's, per body (gears only)
  std::vector<contact::CoherentToothSearch::PlanarTwist> gear_twists;  // their velocities (parking near pairs only)
  double max_penetration = 0;  // m, this step
  long dropped_points = 0;  // since construction (World::dropped_contacts)
  long table_misses = 0;  // since construction (World::stiffness_table_misses)
  PowerFlows power;
  // The profile: its counts here, its times as ProfileClock ticks (World::profile() turns them
  // into seconds).
  World::Profile profile;
  ProfileClock clock;
  std::uint64_t tooth_contact_ticks = 0, row_solve_ticks = 0, step_total_ticks = 0;
};

inline State::State(const Model& model) : joint_angles(model.joints.size()), pairs(model.pairs.size()), gear_poses(model.start_poses) {
  for (const BuiltBody& b : model.bodies) bodies.push_back({b.name, 0, 0, Eigen::Vector3d::Zero()});
}

// A tooth contact's identity from step to step: (pair, tooth_a, tooth_b, flank_a).
using ContactKey = std::tuple<int, int, int, int>;
inline ContactKey contact_key(int pair, const contact::ToothContact& c) {
  return {pair, c.tooth_a, c.tooth_b, static_cast<int>(c.flank_a)};
}
inline ContactKey contact_key(const ContactSample& c) { return contact_key(c.pair, c.geometry); }

}  // namespace gearsim::physics

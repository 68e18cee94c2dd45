// Inside the planetary FE solve (planetary_fe.hpp), shared by its sources: one position's deck
// with what reading its results needs (built in planetary_fe_deck.cpp, read back in
// planetary_fe_results.cpp); planetary_fe.cpp places, solves and sweeps. Not for use outside fe/.
#pragma once

#include <string>
#include <vector>

#include "fe/deck.hpp"
#include "fe/planetary_fe.hpp"
#include "fe/planetary_positions.hpp"
#include "fe/process.hpp"
#include "geometry/gear_dimensions.hpp"
#include "geometry/gear_spec.hpp"

namespace gearsim::fe::planetary_detail {

// Planet k's gear: its own from def.planet_gears, else the spec's healthy planet.
const GearSpec& planet_gear(const PlanetaryFeDef& def, int k);

// One root-stress element set of the tracked planet: its deck name, tooth and side.
struct RootSet {
  std::string name;
  int tooth;
  Flank side;
};

// One position's deck, and what reading its results needs.
struct PositionDeck {
  PlanetaryPosition pos;  // the set placed and its clearances closed (rigid flank tables)
  GearDimensions sun_dims, ring_dims, planet_dims;  // the sun's, the ring's, the healthy planet's
  DeckDef deck;  // bodies, contact pairs, root-stress sets, loads
  Deck written;  // the deck's text and body layout
  // Per planet: the teeth with a contact pair of their own against the sun (pair "SPkTj").
  std::vector<std::vector<int>> sun_mesh_teeth;
  TrackedTooth tracked;
  std::vector<RootSet> root_sets;  // in the order of deck.stress_sets
};

// Places the set at sun_turn_rad and writes its deck: the sun driving, planets idling on held
// pins, the ring rim fixed; a contact pair per planet tooth near the sun and one per planet on
// the ring; root-stress sets of the tracked tooth and its neighbours. Throws InputError when one
// of those teeth has no root elements, and as write_deck does.
PositionDeck build_position_deck(const PlanetaryFeDef& def, const PlanetaryFeMeshes& meshes, double sun_turn_rad);

// The solved position from ccx's results (run.dat_path) at the end of the low (time 2) and full
// (time 3) load stages. Throws std::runtime_error naming the file when a result is missing.
PlanetaryFePosition read_position(const PositionDeck& p, const PlanetaryFeDef& def, const CcxRunResult& run, double sun_turn_rad);

}  // namespace gearsim::fe::planetary_detail

// Quasi-static positions of a simple planetary set for the finite-element loaded TE, in the
// carrier frame (the carrier is held in each FE solve): the sun turned by a given angle relative
// to the carrier, planets and ring at their kinematic angles, then the clearances closed the way
// the input torque closes them: each planet turned in its driven sense until it touches the ring,
// then the sun turned until it touches the first planet, each on its leading flank (a set without
// backlash may touch on the trailing flanks too; the FE contact pairs take both). Pure geometry (the rigid tooth-contact
// probe), no FE. Not a dynamics model: loads and deflections come from ccx.
#pragma once

#include <vector>

#include "geometry/planetary.hpp"
#include "contact/flank_table.hpp"
#include "contact/tooth_contact.hpp"

namespace gearsim::fe {

// Flank tables of the set's gears (planets may differ: errors), in their body frames.
struct PlanetaryTables {
  const contact::FlankTable* sun = nullptr;
  std::vector<const contact::FlankTable*> planets;  // one per planet
  const contact::FlankTable* ring = nullptr;
};

struct PlanetaryPosition {
  double sun_turn_rad = 0;  // sun turned relative to the carrier from the assembled position
  contact::PlanarPose sun, ring;
  std::vector<contact::PlanarPose> planets;
  double sun_closing_rad = 0;  // extra sun rotation that closed its clearance
  std::vector<double> planet_closing_rad;  // per planet, rotation that closed the ring side
  int touching_planet = -1;  // the planet the sun touches first
};

// Builds the flank table of a generated gear (as physics/ does for a scenario's gears).
contact::FlankTable flank_table_of(const GearSpec& spec);

// The set placed at sun_turn_rad (positive: the sun turns counter-clockwise relative to the
// carrier, driving; input torque +z). Throws InputError when a clearance cannot be closed within
// kMaxClosingTurn_rad (the gears do not mesh).
PlanetaryPosition place_closed(const PlanetarySpec& spec, const PlanetaryGeometry& geo, const PlanetaryTables& tables, double sun_turn_rad);

}  // namespace gearsim::fe

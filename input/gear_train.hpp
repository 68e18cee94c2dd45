// The gear train a scenario describes, recognised from its expanded bodies and joints, and its
// characteristic frequencies: a single-stage planetary set (an internal ring, planets on a
// carrier, a sun) or an external gear pair. For analysing a run; the simulation itself needs no
// such label. Not a general multi-stage kinematics solver.
#pragma once

#include <string>
#include <vector>

#include "analysis/characteristic_frequencies.hpp"
#include "physics/scenario.hpp"

namespace gearsim::input {

struct GearTrain {
  bool planetary = false;
  bool internal_pair = false;  // a pair: a pinion meshing inside a ring
  // Planetary: the members' body names; a pair: driver and driven.
  std::string sun, ring, carrier;
  std::vector<std::string> planets;
  std::string driver, driven;
  int sun_teeth = 0, planet_teeth = 0, ring_teeth = 0, driver_teeth = 0, driven_teeth = 0;
  std::string input_body;  // the body the motor drives
  double input_speed_rad_s = 0;  // its motor's target speed, signed
  GearTrainFrequencies frequencies;
};

// Throws InputError (naming the scenario file) when the scenario is neither a single-stage
// planetary set nor one external pair, or has no motor to say which member is the input.
GearTrain gear_train_of(const physics::Scenario& s);

// Teeth of a gear body (generated spec or mesh tooth layout); 0 for a body without teeth.
int teeth_of(const physics::BodyDef& b);
bool is_internal(const physics::BodyDef& b);

}  // namespace gearsim::input

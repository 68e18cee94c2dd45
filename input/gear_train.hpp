// The gear train a scenario describes, recognised from its expanded bodies and joints and the
// gear pairs that mesh: its stages (each a planetary set — an internal ring, planets on one
// carrier, a sun — or one gear pair), ordered from the motor down, every body's speed by the
// train's rigid kinematics, and each stage's characteristic frequencies. For analysing a run; the
// simulation itself needs no such label.
#pragma once

#include <map>
#include <string>
#include <utility>
#include <vector>

#include "analysis/characteristic_frequencies.hpp"
#include "physics/scenario.hpp"

namespace gearsim::input {

// One stage of a train: the gears that mesh with each other (a connected set of meshes).
struct TrainStage {
  // The prefix its members share ("<stage>_", as the `stages:` macro names them), else
  // "stage_<k>" counted from the input; "" when the train is one stage.
  std::string name;
  bool planetary = false;
  bool internal_pair = false;  // a pair: a pinion meshing inside a ring
  // Planetary: the members' body names; a pair: driver (the gear nearer the motor) and driven.
  std::string sun, ring, carrier;
  std::vector<std::string> planets;
  std::string driver, driven;
  int sun_teeth = 0, planet_teeth = 0, ring_teeth = 0, driver_teeth = 0, driven_teeth = 0;
  std::string fixed;  // planetary: the member that stands still ("" for a pair)
  // The member the stage is driven by and the one it drives (a planetary set's two turning
  // members, the one nearer the motor first; a pair's driver and driven gear).
  std::string input, output;
  double input_speed_rad_s = 0, output_speed_rad_s = 0;  // absolute, signed, rigid kinematics
  // ω_input/ω_output (signed): θ_input − ratio·θ_output is the stage's transmission error.
  double ratio = 0;
  GearTrainFrequencies frequencies;  // its own, keys as for a single stage ("mesh", "planet_fault" …)
};

struct GearTrain {
  std::vector<TrainStage> stages;  // from the input down; at least one
  std::string input_body;  // the body the motor drives
  double input_speed_rad_s = 0;  // its motor's target speed, signed
  // Every stage's frequencies. One stage: its own. Several: keys "<stage>.<key>" and names
  // "stage <stage>: <name>"; mesh_hz the first stage's.
  GearTrainFrequencies frequencies;
  // Every body's absolute speed about +z by the rigid kinematics, rad/s (welded bodies 0).
  std::map<std::string, double> speed_rad_s;
  // The bodies whose logged angles (each relative to its parent) sum to `body`'s absolute angle:
  // body, its parent, … up to the ground.
  std::map<std::string, std::vector<std::string>> angle_chain;
  // The stage a gear belongs to; nullptr for a body of none.
  const TrainStage* stage_of(const std::string& gear) const;
  // The first planetary stage; nullptr when there is none.
  const TrainStage* first_planetary() const;
};

// A pair of gear bodies that mesh (as gearsim run lists them in summary.json's gear_pairs).
using Mesh = std::pair<std::string, std::string>;

// The train of `meshes` in scenario s. Throws InputError (naming the scenario file) when a set of
// meshing gears is neither a planetary set nor one gear pair, when there is no motor to say which
// member is the input, when the motor leaves a stage's speeds free (a differential) or a planetary
// stage has no member standing still, or when a mesh names a body that is not a gear.
GearTrain gear_train_of(const physics::Scenario& s, const std::vector<Mesh>& meshes);

// Teeth of a gear body (generated spec or mesh tooth layout); 0 for a body without teeth.
int teeth_of(const physics::BodyDef& b);
bool is_internal(const physics::BodyDef& b);

}  // namespace gearsim::input

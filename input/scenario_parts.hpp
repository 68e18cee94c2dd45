// Internal pieces of the scenario reader (scenario_file.cpp), shared by its macro expansion
// (scenario_macros.cpp) and its --set overrides (scenario_overrides.cpp). Not a public API:
// use load_scenario() from scenario_file.hpp.
#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "input/input_limits.hpp"
#include "input/yaml_reader.hpp"
#include "physics/scenario.hpp"

namespace gearsim::input::scenario_detail {

// Bodies, joints and the ideal transmission a macro expands into.
struct Expansion {
  std::vector<physics::BodyDef> bodies;
  std::vector<physics::JointDef> joints;
  std::optional<physics::TransmissionDef> transmission;
  std::filesystem::path gearset_spec;  // the gear-set spec the macro took its gears from, if any
  std::optional<physics::PlanetaryTrainDef> planetary;  // the planetary macro's train
  std::vector<physics::PairTableDef> pair_tables;  // the pair macro's gear-table figures
};

// True when `key` holds a value; marks the key as known either way (so `key:` left empty, or
// set to null by an override, means "absent" rather than "unknown key").
bool given(const YamlMap& m, const std::string& key);

// m[key] as a number > 0, else InputError "expected a positive <what>, got <value>".
double positive(const YamlMap& m, const std::string& key, const std::string& what);

// `file` as a path relative to `dir` (unless absolute), lexically normalised.
std::filesystem::path resolve(const std::filesystem::path& dir, const std::string& file);

// [x, y, z] under `key`, or `fallback` when absent.
Eigen::Vector3d vec3_or(const YamlMap& m, const std::string& key, const Eigen::Vector3d& fallback);
// The same with each given component within `limit` (refused naming the key and x, y or z).
Eigen::Vector3d vec3_within_or(const YamlMap& m, const std::string& key, const Eigen::Vector3d& fallback, const Limit& limit);

// The shape (gear / gear_from / mesh / none) and mass keys of a body mapping into `body`
// (body.name must be set). Every body needs a mass, fixed ones too (physics builds them all).
// Does not reject unknown keys: the caller reads more.
void parse_shape_and_mass(const YamlMap& m, physics::BodyDef& body, const std::filesystem::path& dir);

// A `bearing:` mapping: radial stiffness (> 0) and damping, torsional stiffness and damping
// (≥ 0, default 0: free to turn); unknown keys refused.
physics::BearingDef parse_bearing(const YamlMap& m);

// The settings blocks of a scenario's top level (solver, output, render, contact) into `s`,
// before the bodies are read (scenario_settings.cpp).
void parse_settings(const YamlMap& top, physics::Scenario& s);

// The `planetary:` macro: sun, planet_0..planet_{N−1}, ring, carrier and their hinges.
Expansion expand_planetary(const YamlMap& m, const std::filesystem::path& dir);
// The `pair:` macro: two gears on hinges, meshing. External: driver at the origin, driven on
// +x. Internal (one member a ring, either the driver): the ring at the origin, the pinion on +x.
Expansion expand_pair(const YamlMap& m, const std::filesystem::path& dir);

// `stages:` — each stage a planetary or pair macro (its keys; origin_m places it), its bodies,
// joints and gear tables named "<stage>_<member>" (scenario_stages.cpp).
struct Stage {
  std::string name;
  std::string key;  // planetary or pair
  Expansion expansion;
};
std::vector<Stage> expand_stages(const YamlMap& top, const std::filesystem::path& dir);

// `shafts:` (after the joints): each {from, to, torsional_stiffness_N_m_per_rad or length_m and
// diameter_m [inner_diameter_m, shear_modulus_Pa], torsional_damping_N_m_s_per_rad, name} makes
// `to` turn on `from` about their common axis, held by the shaft's torsional spring and damper
// (a radially rigid BearingDef). InputError naming the entry for an unknown or fixed body, two
// members of one stage, members not on one axis line, a `to` that does not turn on the ground
// on a plain hinge or already turns on a shaft. Returns the joints that now turn on shafts.
std::set<std::string> apply_shafts(const YamlMap& top, physics::Scenario& s, const std::vector<Stage>& stages);

// The train's transmission when every stage proposes one and shafts join each stage's output
// member to the next one's input member: the first stage's input, the last one's output, the
// product of the ratios. None otherwise.
std::optional<physics::TransmissionDef> chained_transmission(const std::vector<Stage>& stages,
                                                             const std::vector<physics::JointDef>& joints);

// contact.stiffness_tables (after the bodies are known): each entry {gears: [A, B], file: CSV}
// becomes one physics::PairStiffnessDef per meshing body pair it matches (A names a body, or the
// planetary macro's numbered family: "planet" is planet_0, planet_1, ...), radius on A's body.
// InputError naming the entry when a file is missing or malformed (with its line), a name
// matches no gear, the names match no meshing pair, a pair gets two tables, or a generated
// pair's active flank on A (start of active profile to tip) is not inside the table's radii.
void parse_stiffness_tables(const std::vector<YamlMap>& entries, physics::Scenario& scenario, const std::filesystem::path& dir);

// contact.mesh_stiffnesses (after the bodies are known): each entry {gears: [A, B],
// stiffness_N_per_m: k} gives every meshing body pair it matches (names as for stiffness
// tables) the constant mesh stiffness k, shared by the tooth pairs in contact. InputError naming
// the entry when a name matches no gear, the names match no meshing pair, or a pair already has a
// mesh stiffness or a stiffness table.
void parse_mesh_stiffnesses(const std::vector<YamlMap>& entries, physics::Scenario& scenario);

// `sensors:` (after the bodies and the solver): virtual accelerometers; InputError naming the
// entry and key for an unknown body, a bad width, a resonance above the step's Nyquist
// frequency, a sample rate that is no whole number of steps or differs between sensors.
void parse_sensors(const std::vector<YamlMap>& entries, physics::Scenario& scenario);

// The `fe:` section (after the macros: the torque default needs the train and the loads).
physics::FeTeDef parse_fe(const YamlMap& m, const physics::Scenario& scenario);

// Applies "a.b[2].c=value" overrides to a parsed tree; InputError naming the override when one
// is malformed or walks through something that is not a mapping or list.
void apply_overrides(YAML::Node& root, const std::vector<std::string>& overrides, const std::string& file);
// When `message` concerns a key an override set, the message with " (set by --set 'TEXT')".
std::string blame_override(const std::string& message, const std::vector<std::string>& overrides);

}  // namespace gearsim::input::scenario_detail

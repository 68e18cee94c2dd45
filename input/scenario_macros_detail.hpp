// Inside the scenario macros (scenario_parts.hpp: expand_planetary, expand_pair), shared by their
// sources: placing and hinging bodies and checking a mesh's gear-table figures
// (scenario_macros.cpp), a planetary set's members before they are placed
// (scenario_planetary_members.cpp), the planetary macro (scenario_planetary.cpp) and the pair
// macro (scenario_pair.cpp). Not for use outside input/.
#pragma once

#include <Eigen/Geometry>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "geometry/involute_pair.hpp"
#include "geometry/planetary.hpp"
#include "input/scenario_parts.hpp"
#include "input/yaml_reader.hpp"
#include "physics/scenario.hpp"

namespace gearsim::input::scenario_detail {

// A rotation by angle_rad about +z.
Eigen::Quaterniond about_z(double angle_rad);

// A hinge about +z at pivot_m (m) turning body `name` in `parent`; the joint takes the body's name.
physics::JointDef hinge(const std::string& name, const std::string& parent, const Eigen::Vector3d& pivot_m);

// The involutes of a gear body: its spec's, or recognised from its mesh; none (and why) when the
// mesh shows no single involute (not a gear, flanks off the involute, asymmetric teeth).
std::optional<InvoluteTeeth> involutes_of(const physics::BodyDef& b, std::string& why);

// The gear-table figures of gears a and b (a external) at `centre_distance_m` (≤ 0: their
// zero-backlash distance), refused (naming centre_distance_m, or `key` when it was derived) when
// the involutes cannot act there, the teeth overlap or the tips do not reach the line of action.
physics::PairTableDef checked_pair_table(const YamlMap& m, const std::string& a, const std::string& b, const InvoluteTeeth& ta,
                                         const InvoluteTeeth& tb, double centre_distance_m, bool derived, const std::string& key);

// A planetary set's members before they are placed: from a gear-set spec (members named) or from
// shapes (CAD meshes, gear or gear_from; members given as mappings).
struct PlanetaryMembers {
  physics::BodyDef sun, planet, ring;  // unplaced; planet as planet_0
  std::vector<physics::BodyDef> planets;  // planet_0..: the spec's faulty ones in their place
  std::optional<PlanetarySpec> spec;  // spec members
  std::filesystem::path spec_file;
  // Shape members' involutes: all three, or none when a member's flanks are not recognised
  // involutes (then centre_distance_m is required and the start checks alone judge the meshes).
  std::optional<InvoluteTeeth> sun_teeth, planet_teeth, ring_teeth;
  int count = 0;
};

// From a gear-set spec: m["spec"] relative to dir, members named in it (defaulting to its planetary train).
PlanetaryMembers members_from_spec(const YamlMap& m, const std::filesystem::path& dir);
// From shapes: sun, planet and ring as mappings, each with teeth; their recognised involutes, or
// without them a given centre_distance_m.
PlanetaryMembers members_from_shapes(const YamlMap& m, const std::filesystem::path& dir);

}  // namespace gearsim::input::scenario_detail

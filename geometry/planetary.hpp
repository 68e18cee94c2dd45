// A simple planetary set (sun, N equal planets on one carrier, internal ring): kinematics,
// assembly and adjacency conditions, and the angles at which each part must be placed so that
// every planet meshes with both sun and ring. Not a general train solver: gear_mesh.hpp analyses
// one mesh, this file composes them.
#pragma once

#include <string>
#include <vector>

#include "geometry/gear_mesh.hpp"
#include "geometry/gear_spec.hpp"

namespace gearsim {

struct PlanetarySpec {
  GearSpec sun, planet, ring;
  int planets = 3;
};

struct PlanetPlacement {
  double carrier_angle_rad = 0;  // polar angle of the planet centre about the sun axis
  double spin_angle_rad = 0;  // rotation of the planet body about its own axis
};

struct PlanetaryGeometry {
  double centre_distance_m = 0;  // sun–planet = planet–ring operating centre distance
  // Ring fixed, sun in, carrier out: i = 1 + z_r/z_s (Willis).
  double ratio_sun_to_carrier = 0;
  // (z_s + z_r)/N: an integer means the planets can sit at equal spacing.
  double assembly_quotient = 0;
  bool equally_spaced_assembly = false;
  // Gap between neighbouring planets' tip circles, m (negative: they collide).
  double adjacency_clearance_m = 0;
  // Mesh frequency per unit carrier speed relative to the ring: f_mesh = z_r·f_carrier.
  MeshGeometry sun_planet, planet_ring;
  double ring_angle_rad = 0;  // rotation of the ring body so that planet 0 meshes
  std::vector<PlanetPlacement> placements;
  // Largest mismatch, in teeth, between the ring's phase demanded by each planet (0 when the set
  // assembles); reported rather than assumed.
  double phase_mismatch_teeth = 0;
  std::vector<std::string> problems;
};

// Throws InputError when the set cannot be built (wrong kinds, the sun–planet and planet–ring
// centre distances disagree, fewer than one planet).
PlanetaryGeometry analyse_planetary(const PlanetarySpec& spec);

// The tooth layout of a set, all it takes to phase it: tooth counts and the polar angle of each
// gear's tooth 0 in its own frame (rad).
struct PlanetaryLayout {
  int sun_teeth = 0, planet_teeth = 0, ring_teeth = 0, planets = 3;
  double sun_tooth0_rad = 0, planet_tooth0_rad = 0, ring_tooth0_rad = 0;
};

// Planets at equal spacing from +x, the sun unturned: each planet's spin, the ring's turn from
// planet 0, (z_s + z_r)/N and the phase mismatch the other planets leave (fills those fields of
// `g`; analyse_planetary does it for specs, a set of CAD meshes through this).
void phase_planetary(const PlanetaryLayout& layout, PlanetaryGeometry& g);

}  // namespace gearsim

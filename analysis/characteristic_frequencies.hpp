// Characteristic frequencies of a gear train for condition monitoring: shaft rates, mesh frequency
// and its harmonics, local-fault and planet-pass frequencies, each with a key, a name, a value in
// Hz and the formula that gave it. For any single-stage planetary set (any member fixed, any other
// driven) and any external gear pair. Kinematics only: no dynamics, no amplitudes.
#pragma once

#include <string>
#include <vector>

namespace gearsim {

enum class FrequencyKind {
  Shaft,  // a rotation rate of a body (absolute, or relative to the carrier)
  Mesh,  // the mesh frequency and its harmonics
  Fault,  // the rate at which a local defect on one body is struck
  Pass,  // the rate at which planets pass a point fixed to the housing
};

struct CharacteristicFrequency {
  std::string key;  // stable identifier, e.g. "planet_fault"
  std::string name;  // e.g. "planet local fault (one flank)"
  double value_hz = 0;  // always ≥ 0: a rate, not a signed speed
  std::string formula;  // how it was computed, e.g. "f_m/z_p"
  FrequencyKind kind = FrequencyKind::Shaft;
};

enum class PlanetaryMember { Sun, Carrier, Ring };

struct PlanetaryTrainSpec {
  int sun_teeth = 0, planet_teeth = 0, ring_teeth = 0;  // z_s, z_p, z_r (≥ 1)
  int planets = 1;  // N (≥ 1)
  PlanetaryMember fixed = PlanetaryMember::Ring;  // held still
  PlanetaryMember input = PlanetaryMember::Sun;  // driven at input_speed_rad_s
  double input_speed_rad_s = 0;  // signed, rad/s
  int mesh_harmonics = 3;  // harmonics of f_m listed (≥ 1)
};

// Signed angular speeds, rad/s, about the common axis (planet: about its own axis).
struct PlanetarySpeeds {
  double sun_rad_s = 0, carrier_rad_s = 0, ring_rad_s = 0;
  double planet_rad_s = 0;  // absolute spin
  double planet_relative_rad_s = 0;  // spin relative to the carrier
};

struct GearTrainFrequencies {
  std::vector<CharacteristicFrequency> frequencies;  // shafts, mesh and harmonics, faults, passes
  double mesh_hz = 0;  // the fundamental mesh frequency f_m
  // The entry with this key; throws InputError naming the key when absent.
  const CharacteristicFrequency& at(const std::string& key) const;
};

// Willis: (ω_s − ω_c)/(ω_r − ω_c) = −z_r/z_s; planet spin relative to the carrier
// ω_p − ω_c = −(z_s/z_p)(ω_s − ω_c). Throws InputError on teeth or planets < 1, fixed == input,
// or a non-finite speed.
PlanetarySpeeds planetary_speeds(const PlanetaryTrainSpec& spec);

// Keys: sun_shaft, carrier_shaft, ring_shaft (each omitted when that member is fixed),
// planet_spin, planet_spin_relative, mesh, mesh_2 … mesh_H, sun_fault = N·|f_s − f_c|,
// planet_fault = f_m/z_p, planet_fault_both_flanks = 2·f_m/z_p (a planet tooth meets the sun and
// the ring once each per relative turn), ring_fault = N·|f_r − f_c|, planet_pass = N·|f_c| (seen
// from the housing; omitted when the carrier is fixed). With the ring fixed: f_m = z_r·f_c and
// ring_fault = planet_pass = N·f_c.
GearTrainFrequencies planetary_frequencies(const PlanetaryTrainSpec& spec);

struct GearPairSpec {
  int driver_teeth = 0, driven_teeth = 0;  // z_1, z_2 (≥ 1), external mesh
  double driver_speed_rad_s = 0;  // signed, rad/s
  int mesh_harmonics = 3;  // harmonics of f_m listed (≥ 1)
};

// Keys: driver_shaft, driven_shaft, mesh, mesh_2 … mesh_H, and hunting_tooth
// = f_m·gcd(z_1, z_2)/(z_1·z_2), the rate at which the same tooth pair meets again.
GearTrainFrequencies gear_pair_frequencies(const GearPairSpec& spec);

}  // namespace gearsim
